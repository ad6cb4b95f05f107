/* compatmesh morph: sections of the convex-combination morph between the
 * compatibly triangulated inputs, written as frames. */
#define _POSIX_C_SOURCE 200809L /* strdup */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <compatmesh/compatmesh.h>

#include "commands.h"
#include "interrupt.h"
#include "progress_line.h"
#include "options.h"
#include "outdir.h"
#include "triangulation.h"
#include "write_mesh.h"
#include "write_report.h"
#include "write_picture.h"

enum {
    OPTION_MORPH = OPTION_TRIANGULATION_END,
    OPTION_PICTURE_FRAMES,
    MAX_FRAMES = 1000,
    DEFAULT_PICTURE_FRAMES = 12
};

static const option_spec morph_options[] = {
    {"out-dir", 'o', "DIR",
     "where the frames go (required); DIR is created if\n"
     "missing (its parent must exist); files in DIR named\n"
     "like an output are replaced, an earlier morph's\n"
     "frames this one does not write (frame_NNN.off, .obj\n"
     "or .ply) removed, other files kept"},
    {"frames", 'n', "N", "number of frames, 2 to 1000 (default 11), at\n"
                         "t = 0, 1/(N-1), ..., 1"},
    {"morph", OPTION_MORPH, "NAME",
     "convex (default): convex-combination morph, every\n"
     "frame valid; linear: straight vertex paths, for\n"
     "comparison (inverted triangles are counted)"},
    {"format", 'f', "FMT", "frame file format: off (default), obj or ply"},
    {"picture-frames", OPTION_PICTURE_FRAMES, "N",
     "frames drawn in frames.svg/png, 2 to 1000 (default\n"
     "12): evenly spaced, the first and the last among\n"
     "them; all frames when N is at least --frames"},
    TRIANGULATION_OPTION_SPECS,
    {"help", 'h', NULL, "show this help and exit"},
};
static const size_t morph_option_count = sizeof morph_options / sizeof morph_options[0];

typedef struct morph_args {
    triangulation_args tri;
    const char *out_dir;
    size_t frames, picture_frames;
    cm_morph_method morph;
    const char *morph_name;
    mesh_format format;
    int help;
} morph_args;

static int handle_morph_option(void *context, int key, const char *value, cli_error *error)
{
    morph_args *args = context;
    int code = triangulation_option(&args->tri, "morph", key, value, error);
    if (code >= 0) return code;
    long count;
    switch (key) {
    case 'o':
        args->out_dir = value;
        return CLI_EXIT_OK;
    case 'n':
    case OPTION_PICTURE_FRAMES:
        count = parse_whole_number(value, 2, MAX_FRAMES);
        if (count < 0) {
            cli_error_set(error, "morph: --%s '%s' is not a whole number from 2 to %d",
                          key == 'n' ? "frames" : "picture-frames", value, MAX_FRAMES);
            return CLI_EXIT_USAGE;
        }
        *(key == 'n' ? &args->frames : &args->picture_frames) = (size_t)count;
        return CLI_EXIT_OK;
    case OPTION_MORPH:
        if (strcmp(value, "convex") == 0) args->morph = CM_MORPH_CONVEX;
        else if (strcmp(value, "linear") == 0) args->morph = CM_MORPH_LINEAR;
        else {
            cli_error_set(error, "morph: unknown --morph '%s' (known: convex, linear)", value);
            return CLI_EXIT_USAGE;
        }
        args->morph_name = value;
        return CLI_EXIT_OK;
    case 'f':
        if (mesh_format_from_name(value, &args->format) == 0) return CLI_EXIT_OK;
        cli_error_set(error, "morph: unknown --format '%s' (known: off, obj, ply)", value);
        return CLI_EXIT_USAGE;
    case 'h':
        args->help = 1;
        return CLI_EXIT_OK;
    default:
        cli_error_set(error, "morph: unhandled option %d", key);
        return CLI_EXIT_INTERNAL;
    }
}

static void print_morph_help(FILE *out)
{
    fputs("Usage: compatmesh morph IN1 IN2 [IN3 ...] --out-dir DIR [OPTIONS]\n"
          "\n"
          "Compatibly triangulates the inputs (as 'compatmesh triangulate' does, same\n"
          "input formats) and morphs between them: the polygons are surrounded by a\n"
          "common convex enclosure and every interior vertex moves as a convex\n"
          "combination of its neighbours (Floater-Gotsman), so every intermediate\n"
          "section is a valid triangulation. With k > 2 inputs the morph passes\n"
          "through input g at t = g / (k - 1).\n"
          "\n"
          "Options:\n", out);
    print_options(out, morph_options, morph_option_count);
    fputs("\n"
          "Outputs, written to a temporary directory beside DIR and moved into DIR\n"
          "only when everything succeeded:\n"
          "  DIR/frame_000.FMT ...  one section per frame, all with the same faces\n"
          "                         (those of the triangulation), between the\n"
          "                         inputs' planes where every input gives z or\n"
          "                         lies in another plane (a frame between two\n"
          "                         inputs at z 2 and 5 halfway lies at z 3.5),\n"
          "                         else z = 0\n"
          "  DIR/frames.svg         the frames side by side (--picture-frames of\n"
          "                         them)\n"
          "  DIR/frames.png         the same picture as PNG (cairo draws both)\n"
          "  DIR/report.json        counts, morph, and per frame: file, t,\n"
          "                         min_angle_deg, inverted (triangles not strictly\n"
          "                         counter-clockwise, by exact predicates)\n"
          "\n"
          "Exit status (on failure DIR is left as it was):\n"
          "  0    success\n"
          "  1    internal failure (also a convex morph whose section failed its\n"
          "       exact check), or DIR or its parent not writable\n"
          "  2    bad input or usage, as for 'compatmesh triangulate'\n"
          "  130  interrupted\n", out);
}

static int parse_morph_args(int argc, char **argv, morph_args *args, cli_error *error)
{
    memset(args, 0, sizeof *args);
    args->frames = 11;
    args->picture_frames = DEFAULT_PICTURE_FRAMES;
    args->morph = CM_MORPH_CONVEX;
    args->morph_name = "convex";
    args->format = MESH_FORMAT_OFF;
    int code = triangulation_args_init(&args->tri, argc, error);
    if (code != CLI_EXIT_OK) return code;
    code = parse_options(argc, argv, "morph", morph_options, morph_option_count,
                         handle_morph_option, args, error);
    if (code != CLI_EXIT_OK || args->help) return code;
    code = triangulation_args_check(&args->tri, "morph", error);
    if (code == CLI_EXIT_OK && !args->out_dir) {
        cli_error_set(error, "morph: --out-dir DIR is required (see 'compatmesh morph --help')");
        code = CLI_EXIT_USAGE;
    }
    return code;
}

/* Everything one morph run owns. */
typedef struct morph_run {
    const morph_args *args;
    triangulation tri;
    cm_morph *morph;
    double *xy;          /* frames * vertices * 2 */
    double *t, *min_angle_deg;
    size_t *inverted;
    char **names;        /* frame_NNN.FMT */
    char **final_paths;  /* DIR/frame_NNN.FMT */
    char **stale;        /* an earlier morph's frames in DIR this one does not write */
    size_t stale_count;
    staged_output output;
} morph_run;

static void morph_run_free(morph_run *run)
{
    for (size_t f = 0; f < run->args->frames; f++) {
        if (run->names) free(run->names[f]);
        if (run->final_paths) free(run->final_paths[f]);
    }
    free(run->names);
    free(run->final_paths);
    for (size_t i = 0; i < run->stale_count; i++) free(run->stale[i]);
    free(run->stale);
    free(run->xy);
    free(run->t);
    free(run->min_angle_deg);
    free(run->inverted);
    cm_morph_free(run->morph);
    triangulation_free(&run->tri);
    staged_output_discard(&run->output);
}

static int compute_frames(morph_run *run, cli_error *error)
{
    size_t frames = run->args->frames;
    size_t vertices = cm_result_num_vertices(run->tri.result);
    cm_morph_options options;
    cm_morph_options_init(&options);
    options.method = run->args->morph;
    options.progress = cli_progress;
    cm_status status = cm_morph_create(run->tri.result, &options, &run->morph);
    run->xy = malloc(2 * frames * vertices * sizeof *run->xy);
    run->t = malloc(frames * sizeof *run->t);
    run->min_angle_deg = malloc(frames * sizeof *run->min_angle_deg);
    run->inverted = malloc(frames * sizeof *run->inverted);
    if (status == CM_OK && (!run->xy || !run->t || !run->min_angle_deg || !run->inverted))
        status = CM_ERR_NO_MEMORY;
    for (size_t f = 0; status == CM_OK && f < frames; f++) {
        /* The last frame at exactly 1, so it reproduces the last input. */
        run->t[f] = f + 1 == frames ? 1.0 : (double)f / (double)(frames - 1);
        status = cm_morph_section(run->morph, run->t[f], run->xy + 2 * f * vertices,
                                  &run->inverted[f], &run->min_angle_deg[f]);
        if (status == CM_OK && interrupted) status = CM_ERR_CANCELLED;
    }
    cli_progress_done();
    if (status == CM_OK) return CLI_EXIT_OK;
    return core_failure("morph", run->morph ? cm_morph_message(run->morph) : "", status,
                        error);
}

/* The name of frame f in format fmt, as write_frames gives it. */
static void frame_name(char *name, size_t size, size_t f, mesh_format fmt)
{
    snprintf(name, size, "frame_%03zu.%s", f, mesh_format_name(fmt));
}

static int write_frames(morph_run *run, cli_error *error)
{
    const morph_args *args = run->args;
    const cm_result *result = run->tri.result;
    size_t vertices = cm_result_num_vertices(result);
    run->names = calloc(args->frames, sizeof *run->names);
    run->final_paths = calloc(args->frames, sizeof *run->final_paths);
    if (!run->names || !run->final_paths) {
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    /* Inputs in space (sections in other planes, or every input giving its
     * z): each frame between their planes, as the sweep's layers; xyz holds
     * a frame, then the planes (polygon_frames). */
    size_t k = args->tri.input_count;
    int in_space = 1;
    for (size_t g = 0; g < k; g++) in_space &= run->tri.polygons[g].spatial || run->tri.polygons[g].has_z;
    double *xyz = in_space ? malloc((3 * vertices + 9 * k) * sizeof *xyz) : NULL;
    if (in_space && !xyz) {
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    if (xyz) polygon_frames(run->tri.polygons, k, xyz + 3 * vertices);
    for (size_t f = 0; f < args->frames; f++) {
        char name[64];
        frame_name(name, sizeof name, f, args->format);
        run->names[f] = malloc(strlen(name) + 1);
        const char *path = staged_output_path(&run->output, name);
        if (!run->names[f] || !path) {
            free(xyz);
            cli_error_set(error, "out of memory");
            return CLI_EXIT_INTERNAL;
        }
        strcpy(run->names[f], name);
        const double *xy = run->xy + 2 * f * vertices;
        if (xyz) section_in_space(result, run->tri.polygons, xyz + 3 * vertices, k, run->t[f], xy, xyz);
        int code = write_triangle_mesh(path, xyz ? NULL : xy, xyz, vertices, cm_result_triangles(result),
                                       cm_result_num_triangles(result), args->format, error);
        if (code != CLI_EXIT_OK) {
            free(xyz);
            return code;
        }
        run->final_paths[f] = path_join(run->output.target, name);
        if (!run->final_paths[f]) {
            free(xyz);
            cli_error_set(error, "out of memory");
            return CLI_EXIT_INTERNAL;
        }
    }
    free(xyz);
    return CLI_EXIT_OK;
}

/* frames.svg and frames.png, one picture drawn into both: --picture-frames
 * evenly spaced frames, since drawing is most of a long morph's cost and a
 * picture of hundreds of panels shows nothing more. */
static int write_frame_pictures(morph_run *run, const char *svg, const char *png,
                                cli_error *error)
{
    size_t all = run->args->frames;
    size_t frames = run->args->picture_frames < all ? run->args->picture_frames : all;
    const cm_result *result = run->tri.result;
    size_t vertices = cm_result_num_vertices(result);
    const double **xy = malloc(frames * sizeof *xy);
    char **captions = calloc(frames, sizeof *captions);
    int code = CLI_EXIT_INTERNAL;
    if (!xy || !captions) {
        cli_error_set(error, "out of memory");
        goto done;
    }
    for (size_t p = 0; p < frames; p++) {
        size_t f = (p * (all - 1) + (frames - 1) / 2) / (frames - 1); /* rounded */
        xy[p] = run->xy + 2 * f * vertices;
        captions[p] = malloc(64);
        if (!captions[p]) {
            cli_error_set(error, "out of memory");
            goto done;
        }
        snprintf(captions[p], 64, "t = %.3f, %zu inverted", run->t[f], run->inverted[f]);
    }
    picture_meshes meshes = {cm_result_triangles(result), cm_result_num_triangles(result),
                             cm_result_stats(result)->n, vertices, xy,
                             (const char *const *)captions, frames};
    picture pic;
    code = picture_of_meshes(&pic, &meshes, error);
    if (code == CLI_EXIT_OK) code = write_pictures(svg, png, &pic, error);
    picture_free(&pic);
done:
    if (captions)
        for (size_t f = 0; f < frames; f++) free(captions[f]);
    free(captions);
    free(xy);
    return code;
}

/* Is name a frame some morph writes (frame_NNN in any frame format)? Then
 * *f and *fmt say which. */
static int frame_of(const char *name, size_t *f, mesh_format *fmt)
{
    static const mesh_format formats[] = {MESH_FORMAT_OFF, MESH_FORMAT_OBJ, MESH_FORMAT_PLY};
    char *end;
    if (strncmp(name, "frame_", 6) != 0 || name[6] < '0' || name[6] > '9') return 0;
    unsigned long n = strtoul(name + 6, &end, 10);
    if (*end != '.' || n >= MAX_FRAMES) return 0;
    for (size_t i = 0; i < sizeof formats / sizeof *formats; i++) {
        char own[64];
        frame_name(own, sizeof own, n, formats[i]);
        if (strcmp(own, name) == 0) return *f = n, *fmt = formats[i], 1;
    }
    return 0;
}

/* An earlier morph's frames in DIR that this run does not write (frames
 * past this run's count, or in another format) go on commit: report.json
 * describes the frames beside it, and a tool reading frame_* reads one
 * morph. */
static int remove_stale_frames(morph_run *run, cli_error *error)
{
    DIR *dir = opendir(run->output.target);
    if (!dir) return CLI_EXIT_OK; /* a new directory, or none readable to clear */
    int code = CLI_EXIT_OK;
    for (struct dirent *e; code == CLI_EXIT_OK && (e = readdir(dir));) {
        size_t f;
        mesh_format fmt;
        if (!frame_of(e->d_name, &f, &fmt) || (f < run->args->frames && fmt == run->args->format)) continue;
        char **more = realloc(run->stale, (run->stale_count + 1) * sizeof *more);
        char *copy = more ? strdup(e->d_name) : NULL;
        if (more) run->stale = more;
        if (!copy) {
            cli_error_set(error, "out of memory");
            code = CLI_EXIT_INTERNAL;
        } else {
            run->stale[run->stale_count++] = copy;
        }
    }
    closedir(dir);
    staged_output_remove(&run->output, (const char *const *)run->stale, run->stale_count);
    return code;
}

static int write_outputs(morph_run *run, cli_error *error)
{
    int code = staged_output_begin(&run->output, run->args->out_dir, run->args->tri.inputs,
                                   run->args->tri.input_count, error);
    if (code == CLI_EXIT_OK) code = write_frames(run, error);
    const char *report = NULL, *svg = NULL, *png = NULL;
    if (code == CLI_EXIT_OK) {
        report = staged_output_path(&run->output, "report.json");
        svg = staged_output_path(&run->output, "frames.svg");
        png = staged_output_path(&run->output, "frames.png");
    }
    if (code == CLI_EXIT_OK && (!report || !svg || !png)) {
        cli_error_set(error, "out of memory");
        code = CLI_EXIT_INTERNAL;
    }
    if (code == CLI_EXIT_OK) {
        morph_report_info info = {run->tri.result, run->args->tri.method_name,
                                  run->args->morph_name, run->args->tri.inputs,
                                  run->args->frames, (const char *const *)run->final_paths,
                                  run->t, run->min_angle_deg, run->inverted};
        code = write_morph_report(report, &info, error);
    }
    if (code == CLI_EXIT_OK) code = write_frame_pictures(run, svg, png, error);
    if (code == CLI_EXIT_OK) code = remove_stale_frames(run, error);
    if (code == CLI_EXIT_OK) code = staged_output_commit(&run->output, error);
    return code;
}

static void print_summary(const morph_run *run)
{
    size_t inverted = 0;
    double worst = 180.0;
    for (size_t f = 0; f < run->args->frames; f++) {
        inverted += run->inverted[f];
        if (run->min_angle_deg[f] < worst) worst = run->min_angle_deg[f];
    }
    printf("wrote %zu frames to %s (%s morph, min angle %.1f deg, %zu inverted "
           "triangles in all)\n", run->args->frames, run->output.target,
           run->args->morph_name, worst, inverted);
    printf("wrote %s/report.json, %s/frames.svg and %s/frames.png\n", run->output.target,
           run->output.target, run->output.target);
}

static int morph(const morph_args *args, cli_error *error)
{
    morph_run run = {0};
    run.args = args;
    int code = staged_output_check(args->out_dir, error);
    if (code == CLI_EXIT_OK) code = triangulation_run(&run.tri, &args->tri, error);
    if (code == CLI_EXIT_OK) code = compute_frames(&run, error);
    if (code == CLI_EXIT_OK) code = write_outputs(&run, error);
    if (code == CLI_EXIT_OK && !cli_quiet()) print_summary(&run);
    morph_run_free(&run);
    return code;
}

int run_morph(int argc, char **argv)
{
    morph_args args;
    cli_error error = {{0}};
    int code = parse_morph_args(argc, argv, &args, &error);
    if (code == CLI_EXIT_OK && args.help) print_morph_help(stdout);
    else if (code == CLI_EXIT_OK) code = morph(&args, &error);
    if (code != CLI_EXIT_OK) cli_print_error(&error);
    triangulation_args_free(&args.tri);
    return code;
}
