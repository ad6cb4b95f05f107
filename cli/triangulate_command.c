/* compatmesh triangulate: the compatible triangulation of the inputs,
 * written as meshes, a report and pictures. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <compatmesh/compatmesh.h>

#include "cli_common.h"
#include "commands.h"
#include "interrupt.h"
#include "options.h"
#include "outdir.h"
#include "progress_line.h"
#include "triangulation.h"
#include "write_mesh.h"
#include "write_report.h"
#include "write_picture.h"

static const option_spec triangulate_options[] = {
    {"out-dir", 'o', "DIR",
     "where the outputs go (required); DIR is created if\n"
     "missing (its parent must exist); files in DIR named\n"
     "like an output are replaced, other files are kept"},
    {"format", 'f', "FMT", "mesh file format: off (default), obj or ply (ASCII)"},
    TRIANGULATION_OPTION_SPECS,
    {"help", 'h', NULL, "show this help and exit"},
};
static const size_t triangulate_option_count =
    sizeof triangulate_options / sizeof triangulate_options[0];

typedef struct triangulate_args {
    triangulation_args tri; /* inputs, method, remesh */
    const char *out_dir;
    mesh_format format;
    int help;
} triangulate_args;

static int handle_triangulate_option(void *context, int key, const char *value,
                                     cli_error *error)
{
    triangulate_args *args = context;
    int code = triangulation_option(&args->tri, "triangulate", key, value, error);
    if (code >= 0) return code;
    switch (key) {
    case 'o':
        args->out_dir = value;
        return CLI_EXIT_OK;
    case 'f':
        if (mesh_format_from_name(value, &args->format) == 0) return CLI_EXIT_OK;
        cli_error_set(error, "triangulate: unknown --format '%s' (known: off, obj, ply)", value);
        return CLI_EXIT_USAGE;
    case 'h':
        args->help = 1;
        return CLI_EXIT_OK;
    default:
        cli_error_set(error, "triangulate: unhandled option %d", key);
        return CLI_EXIT_INTERNAL;
    }
}

static void print_triangulate_help(FILE *out)
{
    fputs("Usage: compatmesh triangulate IN1 IN2 [IN3 ...] --out-dir DIR [OPTIONS]\n"
          "\n"
          "Compatibly triangulates k >= 2 simple polygons with the same number of\n"
          "vertices, vertex i of each input corresponding to vertex i of the others.\n"
          "All meshes share one triangle list; the input vertices come first, in\n"
          "input order and bit-identical, then the Steiner vertices.\n"
          "\n"
          "Inputs (chosen by file name extension):\n"
          "  .obj        an OBJ polyline: 'v x y [z]' lines and 'l' lines whose\n"
          "              edges form closed loops (one closed 'l' line per loop, or\n"
          "              one 'l a b' line per edge in any order, as MeshLab writes),\n"
          "              each loop in the order of its first edge; z, if given,\n"
          "              must be the same for all vertices\n"
          "  .ply        a PLY edge mesh (ASCII or binary): element vertex (x, y,\n"
          "              optional z) and element edge (vertex1, vertex2), the edges\n"
          "              forming closed loops, each followed from its first edge\n"
          "  .obj, .ply  several loops give a polygon with holes: the loop of\n"
          "              largest area is the outer one, the holes follow in file\n"
          "              order\n"
          "  any other   one vertex 'x y' per line, the numbers separated by blanks\n"
          "              and/or one comma (\"1.5 2\", \"1.5, 2\", \"1.5,2\"); '#' starts\n"
          "              a comment; blank lines are ignored; a line beginning\n"
          "              with '>' ends a loop (the outer loop first, then the holes)\n"
          "  The polygons may run clockwise or counter-clockwise, all the same way.\n"
          "  With holes every input has the same number of loops, loop j of each\n"
          "  of the same size (vertices correspond by index within each loop),\n"
          "  every loop may run either way (the same way in every input).\n"
          "\n"
          "Options:\n", out);
    print_options(out, triangulate_options, triangulate_option_count);
    fputs("\n"
          "Outputs, written to a temporary directory beside DIR and moved into DIR\n"
          "only when everything succeeded (on failure DIR is left as it was):\n"
          "  DIR/STEM.FMT     one mesh per input, STEM being the input's file name\n"
          "                   without its extension (two inputs with the same stem\n"
          "                   are an error); z = 0; coordinates with 17 significant\n"
          "                   digits, so input vertices read back bit-identical\n"
          "  DIR/report.json  version, n, k, vertices, steiner, triangles, holes\n"
          "                   (per input), bridges (paths cutting them open: two\n"
          "                   per hole, one where the overlay took over), valid,\n"
          "                   method, remesh, reversed_input, fallback_count,\n"
          "                   steiner_before_remesh, remesh_iterations,\n"
          "                   remesh_aim_deg (the target lowered where the\n"
          "                   input allows less), ceiling (null with\n"
          "                   --no-ceiling: ceiling_deg, no compatible\n"
          "                   triangulation can have a larger smallest angle;\n"
          "                   corner_fan_cap_deg, correspondence_bound_deg,\n"
          "                   modulus_distortion, distortion_quad and, for\n"
          "                   auto, correspondence_bound_before_deg: arc length\n"
          "                   from the first vertices), seconds (validate,\n"
          "                   build, remesh, check, ceiling, and total: the\n"
          "                   whole computation)\n"
          "                   and per mesh the input, output, min/max angle and\n"
          "                   the share of triangles whose smallest angle is\n"
          "                   below 10, 15 and 20 degrees, after and\n"
          "                   (before_remesh) before remeshing\n"
          "  DIR/preview.svg  the meshes side by side: boundary thick, Steiner\n"
          "                   vertices as dots, triangles whose smallest angle is\n"
          "                   below 20 degrees orange, each mesh's worst one red\n"
          "  DIR/preview.png  the same picture as PNG (cairo draws both)\n"
          "\n", out);
    fputs(cli_exit_status_help, out);
}

static int parse_triangulate_args(int argc, char **argv, triangulate_args *args,
                                  cli_error *error)
{
    memset(args, 0, sizeof *args);
    args->format = MESH_FORMAT_OFF;
    int code = triangulation_args_init(&args->tri, argc, error);
    if (code != CLI_EXIT_OK) return code;
    code = parse_options(argc, argv, "triangulate", triangulate_options,
                             triangulate_option_count, handle_triangulate_option,
                             args, error);
    if (code != CLI_EXIT_OK || args->help) return code;
    code = triangulation_args_check(&args->tri, "triangulate", error);
    if (code != CLI_EXIT_OK) return code;
    if (!args->out_dir) {
        cli_error_set(error, "triangulate: --out-dir DIR is required "
                      "(see 'compatmesh triangulate --help')");
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

/* Everything one triangulate run owns, released by triangulate_run_free. */
typedef struct triangulate_run {
    const triangulate_args *args;
    triangulation tri;  /* the polygons read and the core's result */
    char **stems;       /* output names: input file name without extension */
    char **mesh_names;  /* STEM.FMT */
    char **final_paths; /* DIR/STEM.FMT, as reported */
    staged_output output;
} triangulate_run;

static void triangulate_run_free(triangulate_run *run)
{
    size_t k = run->args->tri.input_count;
    for (size_t i = 0; i < k; i++) {
        if (run->stems) free(run->stems[i]);
        if (run->mesh_names) free(run->mesh_names[i]);
        if (run->final_paths) free(run->final_paths[i]);
    }
    triangulation_free(&run->tri);
    free(run->stems);
    free(run->mesh_names);
    free(run->final_paths);
    staged_output_discard(&run->output);
}

/* "dir/a.xy" -> "a"; a leading dot is part of the name (".a" -> ".a"). */
static char *file_stem(const char *path)
{
    const char *name = file_name(path);
    const char *dot = strrchr(name, '.');
    size_t length = dot && dot != name ? (size_t)(dot - name) : strlen(name);
    char *stem = malloc(length + 1);
    if (stem) {
        memcpy(stem, name, length);
        stem[length] = '\0';
    }
    return stem;
}

/* Each input names its output after its stem, so stems must differ. */
static int make_output_names(triangulate_run *run, cli_error *error)
{
    const triangulate_args *args = run->args;
    const char *extension = mesh_format_name(args->format);
    for (size_t i = 0; i < args->tri.input_count; i++) {
        run->stems[i] = file_stem(args->tri.inputs[i]);
        if (!run->stems[i]) {
            cli_error_set(error, "out of memory");
            return CLI_EXIT_INTERNAL;
        }
        if (run->stems[i][0] == '\0') {
            cli_error_set(error, "%s: not a file name", args->tri.inputs[i]);
            return CLI_EXIT_USAGE;
        }
        for (size_t j = 0; j < i; j++) {
            if (strcmp(run->stems[i], run->stems[j]) == 0) {
                cli_error_set(error, "%s and %s would both be written to %s.%s; "
                              "rename one of them", args->tri.inputs[j], args->tri.inputs[i],
                              run->stems[i], extension);
                return CLI_EXIT_USAGE;
            }
        }
        size_t size = strlen(run->stems[i]) + strlen(extension) + 2;
        run->mesh_names[i] = malloc(size);
        if (!run->mesh_names[i]) {
            cli_error_set(error, "out of memory");
            return CLI_EXIT_INTERNAL;
        }
        snprintf(run->mesh_names[i], size, "%s.%s", run->stems[i], extension);
    }
    return CLI_EXIT_OK;
}

/* Before any work: no output may replace an input (commit checks again). */
static int refuse_inputs_early(triangulate_run *run, cli_error *error)
{
    const triangulation_args *tri = &run->args->tri;
    size_t k = tri->input_count;
    int code = CLI_EXIT_OK;
    static const char *const extras[] = {"report.json", "preview.svg", "preview.png"};
    for (size_t i = 0; i < k + 3 && code == CLI_EXIT_OK; i++) {
        const char *name = i < k ? run->mesh_names[i] : extras[i - k];
        char *path = path_join(run->args->out_dir, name);
        if (!path) {
            cli_error_set(error, "out of memory");
            return CLI_EXIT_INTERNAL;
        }
        code = refuse_input_as_output(path, tri->inputs, k, error);
        free(path);
    }
    return code;
}

static int stage_file(triangulate_run *run, const char *name, const char **path,
                      cli_error *error)
{
    *path = staged_output_path(&run->output, name);
    if (*path) return CLI_EXIT_OK;
    cli_error_set(error, "out of memory");
    return CLI_EXIT_INTERNAL;
}

static int write_meshes(triangulate_run *run, cli_error *error)
{
    for (size_t g = 0; g < run->args->tri.input_count; g++) {
        const char *path;
        int code = stage_file(run, run->mesh_names[g], &path, error);
        if (code == CLI_EXIT_OK)
            code = write_mesh(path, run->tri.result, g, run->args->format, error);
        if (code != CLI_EXIT_OK) return code;
        run->final_paths[g] = path_join(run->output.target, run->mesh_names[g]);
        if (!run->final_paths[g]) {
            cli_error_set(error, "out of memory");
            return CLI_EXIT_INTERNAL;
        }
    }
    return CLI_EXIT_OK;
}

static int write_extras(triangulate_run *run, cli_error *error)
{
    const char *path;
    report_info info = {run->tri.result, run->args->tri.method_name, run->args->tri.options.remesh,
                        run->tri.options.correspondence, run->tri.options.max_edge,
                        run->tri.seconds_total, run->args->tri.inputs,
                        (const char *const *)run->final_paths, run->args->tri.options.ceiling};
    int code = stage_file(run, "report.json", &path, error);
    if (code == CLI_EXIT_OK) code = write_report(path, &info, error);
    if (code != CLI_EXIT_OK) return code;
    const char **names = malloc(run->args->tri.input_count * sizeof *names);
    if (!names) {
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    for (size_t g = 0; g < run->args->tri.input_count; g++)
        names[g] = file_name(run->args->tri.inputs[g]);
    picture pic;
    code = picture_of_result(&pic, run->tri.result, names, error);
    free(names);
    if (code != CLI_EXIT_OK) return code;
    code = stage_file(run, "preview.svg", &path, error);
    if (code == CLI_EXIT_OK) code = write_svg(path, &pic, error);
    if (code == CLI_EXIT_OK) code = stage_file(run, "preview.png", &path, error);
    if (code == CLI_EXIT_OK) code = write_png(path, &pic, error);
    picture_free(&pic);
    return code;
}

static int write_outputs(triangulate_run *run, cli_error *error)
{
    int code = staged_output_begin(&run->output, run->args->out_dir, run->args->tri.inputs,
                                   run->args->tri.input_count, error);
    if (code == CLI_EXIT_OK) code = write_meshes(run, error);
    if (code == CLI_EXIT_OK) code = write_extras(run, error);
    if (code == CLI_EXIT_OK && interrupted) {
        cli_error_set(error, "interrupted; nothing written");
        code = CLI_EXIT_INTERRUPTED;
    }
    if (code == CLI_EXIT_OK) code = staged_output_commit(&run->output, error);
    return code;
}

static void print_summary(const triangulate_run *run)
{
    const cm_stats *stats = cm_result_stats(run->tri.result);
    for (size_t g = 0; g < run->args->tri.input_count; g++) {
        cm_quality quality;
        if (cm_result_quality(run->tri.result, g, &quality) != CM_OK) quality.min_angle_deg = 0;
        printf("wrote %s (n=%zu, steiner=%zu, min angle %.1f deg)\n", run->final_paths[g],
               stats->n, stats->steiner, quality.min_angle_deg);
    }
    printf("wrote %s/report.json, %s/preview.svg and %s/preview.png\n", run->output.target,
           run->output.target, run->output.target);
    const cm_options *o = &run->args->tri.options;
    if (o->ceiling && stats->ceiling_deg < o->min_angle_deg)
        printf("no compatible triangulation of %s can have a smallest angle above %.1f degrees "
               "(target %g)\n", stats->k == 2 ? "this pair" : "these polygons", stats->ceiling_deg,
               o->min_angle_deg);
}

static int triangulate(const triangulate_args *args, cli_error *error)
{
    size_t k = args->tri.input_count;
    triangulate_run run = {0};
    run.args = args;
    run.stems = calloc(k, sizeof *run.stems);
    run.mesh_names = calloc(k, sizeof *run.mesh_names);
    run.final_paths = calloc(k, sizeof *run.final_paths);
    int code = CLI_EXIT_OK;
    if (!run.stems || !run.mesh_names || !run.final_paths) {
        cli_error_set(error, "out of memory");
        code = CLI_EXIT_INTERNAL;
    }
    if (code == CLI_EXIT_OK) code = make_output_names(&run, error);
    if (code == CLI_EXIT_OK) code = staged_output_check(args->out_dir, error);
    if (code == CLI_EXIT_OK) code = refuse_inputs_early(&run, error);
    if (code == CLI_EXIT_OK) code = triangulation_run(&run.tri, &args->tri, error);
    if (code == CLI_EXIT_OK) code = write_outputs(&run, error);
    if (code == CLI_EXIT_OK && !cli_quiet()) print_summary(&run);
    triangulate_run_free(&run);
    return code;
}

int run_triangulate(int argc, char **argv)
{
    triangulate_args args;
    cli_error error = {{0}};
    int code = parse_triangulate_args(argc, argv, &args, &error);
    if (code == CLI_EXIT_OK && args.help) print_triangulate_help(stdout);
    else if (code == CLI_EXIT_OK) code = triangulate(&args, &error);
    if (code != CLI_EXIT_OK) cli_print_error(&error);
    triangulation_args_free(&args.tri);
    return code;
}
