#define _POSIX_C_SOURCE 200809L /* strndup */

/* compatmesh sweep: the volume between the compatibly triangulated inputs,
 * stacked sections of their morph joined into prisms (or tetrahedra),
 * written as a finite-element mesh through Gmsh. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include <compatmesh/compatmesh.h>

#include "commands.h"
#include "format_double.h"
#include "interrupt.h"
#include "progress_line.h"
#include "outdir.h"
#include "options.h"
#include "triangulation.h"
#include "write_report.h"
#include "write_volume.h"

enum { OPTION_HEIGHT = OPTION_TRIANGULATION_END, OPTION_HEIGHTS, OPTION_TETS, OPTION_MSH_VERSION, OPTION_REPORT,
       OPTION_WALL_CORNERS, OPTION_RULED, OPTION_ORDER };

static const option_spec sweep_options[] = {
    {"output", 'o', "FILE",
     "the volume mesh (required); the format follows the\n"
     "extension: .msh (Gmsh), .vtk, .vtu (VTK XML, for\n"
     "ParaView), .inp (Abaqus), .bdf (Nastran) or .unv\n"
     "(I-deas universal)"},
    {"sections", 'n', "N|auto",
     "sections per pair of consecutive inputs, both ends\n"
     "included, 2 to 10000 (default 11), or auto: layers\n"
     "about as tall as the triangulation's median edge (in\n"
     "the tallest pair), prisms about as tall as wide; more\n"
     "may be inserted where a prism would not stay valid"},
    {"height", OPTION_HEIGHT, "H", "total height, inputs evenly spaced (default: the\n"
                                   "inputs' z, else the largest diagonal of their\n"
                                   "bounding boxes)"},
    {"heights", OPTION_HEIGHTS, "Z1,Z2,...",
     "the z of every input, strictly increasing; default:\n"
     "the inputs' own z if they all give z (OBJ, PLY, .xy)\n"
     "(unless all z are equal)"},
    {"tets", OPTION_TETS, NULL, "write tetrahedra (each prism split in 3, faces\n"
                                "conforming, diagonals chosen against slivers)\n"
                                "instead of prisms"},
    {"ruled", OPTION_RULED, NULL,
     "a ruled sweep, as a CAD loft: every vertex on a\n"
     "straight line between consecutive inputs, the walls\n"
     "ruled surfaces, where every prism stays valid along\n"
     "them (checked exactly); else the convex morph's\n"
     "sections (the report's \"morph\" says which)"},
    {"msh-version", OPTION_MSH_VERSION, "V", ".msh format version: 4.1 (default) or 2.2"},
    {"order", OPTION_ORDER, "N",
     "1 (default): linear cells; 2: second-order cells, a\n"
     "node at the middle of every edge (straight-sided\n"
     "10-node tetrahedra, 15-node prisms: Abaqus C3D10,\n"
     "C3D15), in every format but .vtu"},
    {"wall-corners", OPTION_WALL_CORNERS, "DEG",
     "split the boundary's walls at the corners where an\n"
     "input's boundary turns by more than DEG degrees (0 to\n"
     "180), one group per face of a swept profile: side_1,\n"
     "side_2, ..., hole_1_1, ...; default: one wall per loop"},
    {"report", OPTION_REPORT, "FILE",
     "also write a JSON report: counts, the height used and\n"
     "why, the cells' smallest and largest dihedral angle,\n"
     "smallest scaled Jacobian, largest aspect ratio, the\n"
     "prisms' flatness and the boundary groups' face counts"},
    TRIANGULATION_OPTION_SPECS,
    {"help", 'h', NULL, "show this help and exit"},
};
static const size_t sweep_option_count = sizeof sweep_options / sizeof sweep_options[0];

typedef struct sweep_args {
    triangulation_args tri;
    const char *output;
    size_t sections;
    double height;          /* 0: not given */
    double *heights;        /* NULL: not given */
    size_t heights_count;
    int tets;
    volume_format format;   /* .msh version, cell order */
    double wall_corner_deg; /* 0: one wall per loop */
    int ruled;
    const char *report;
    int help;
} sweep_args;

/* A finite number, or NAN. */
static double parse_number(const char *text, const char **end)
{
    char *stop;
    errno = 0;
    double value = strtod(text, &stop);
    *end = stop;
    return stop == text || errno == ERANGE || !isfinite(value) ? NAN : value;
}

static int parse_heights(sweep_args *args, const char *text, cli_error *error)
{
    free(args->heights);
    args->heights = malloc((strlen(text) / 2 + 1) * sizeof *args->heights);
    args->heights_count = 0;
    if (!args->heights) {
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    const char *p = text;
    for (;;) {
        const char *end;
        double z = parse_number(p, &end);
        if (isnan(z) || (*end != ',' && *end != '\0')) {
            cli_error_set(error, "sweep: --heights '%s': item %zu is not a finite number "
                          "(expected z1,z2,...)", text, args->heights_count + 1);
            return CLI_EXIT_USAGE;
        }
        if (args->heights_count > 0 && !(z > args->heights[args->heights_count - 1])) {
            cli_error_set(error, "sweep: --heights '%s': the heights must increase strictly "
                          "(item %zu is not above item %zu)", text, args->heights_count + 1,
                          args->heights_count);
            return CLI_EXIT_USAGE;
        }
        args->heights[args->heights_count++] = z;
        if (*end == '\0') return CLI_EXIT_OK;
        p = end + 1;
    }
}

static int handle_sweep_option(void *context, int key, const char *value, cli_error *error)
{
    sweep_args *args = context;
    int code = triangulation_option(&args->tri, "sweep", key, value, error);
    if (code >= 0) return code;
    const char *end;
    long count;
    switch (key) {
    case 'o':
        args->output = value;
        return CLI_EXIT_OK;
    case 'n':
        count = strcmp(value, "auto") == 0 ? 0 : parse_whole_number(value, 2, CM_SWEEP_MAX_SECTIONS);
        if (count < 0) {
            cli_error_set(error, "sweep: --sections '%s' is not 'auto' or a whole number from 2 to %d",
                          value, CM_SWEEP_MAX_SECTIONS);
            return CLI_EXIT_USAGE;
        }
        args->sections = (size_t)count; /* 0: auto (cm_sweep_options.sections) */
        return CLI_EXIT_OK;
    case OPTION_HEIGHT:
        args->height = parse_number(value, &end);
        if (!(args->height > 0) || *end != '\0') {
            cli_error_set(error, "sweep: --height '%s' is not a positive number", value);
            return CLI_EXIT_USAGE;
        }
        return CLI_EXIT_OK;
    case OPTION_HEIGHTS:
        return parse_heights(args, value, error);
    case OPTION_TETS:
        args->tets = 1;
        return CLI_EXIT_OK;
    case OPTION_REPORT:
        args->report = value;
        return CLI_EXIT_OK;
    case OPTION_RULED:
        args->ruled = 1;
        return CLI_EXIT_OK;
    case OPTION_WALL_CORNERS:
        args->wall_corner_deg = parse_number(value, &end);
        if (!(args->wall_corner_deg > 0 && args->wall_corner_deg < 180) || *end != '\0') {
            cli_error_set(error, "sweep: --wall-corners '%s' is not an angle between 0 and 180 degrees", value);
            return CLI_EXIT_USAGE;
        }
        return CLI_EXIT_OK;
    case OPTION_ORDER:
        if (strcmp(value, "1") != 0 && strcmp(value, "2") != 0) {
            cli_error_set(error, "sweep: unknown --order '%s' (known: 1, 2)", value);
            return CLI_EXIT_USAGE;
        }
        args->format.order = value[0] - '0';
        return CLI_EXIT_OK;
    case OPTION_MSH_VERSION:
        if (strcmp(value, "4.1") == 0) args->format.msh_version = 4.1;
        else if (strcmp(value, "2.2") == 0) args->format.msh_version = 2.2;
        else {
            cli_error_set(error, "sweep: unknown --msh-version '%s' (known: 4.1, 2.2)", value);
            return CLI_EXIT_USAGE;
        }
        return CLI_EXIT_OK;
    case 'h':
        args->help = 1;
        return CLI_EXIT_OK;
    default:
        cli_error_set(error, "sweep: unhandled option %d", key);
        return CLI_EXIT_INTERNAL;
    }
}

static void print_sweep_help(FILE *out)
{
    fputs("Usage: compatmesh sweep IN1 IN2 [IN3 ...] -o FILE [OPTIONS]\n"
          "\n"
          "Compatibly triangulates the inputs (as 'compatmesh triangulate' does, same\n"
          "input formats), morphs between them with valid sections (see 'compatmesh\n"
          "morph --help'), stacks the sections at increasing z and joins consecutive\n"
          "sections into 6-node prisms, each checked exactly to keep a positive\n"
          "volume, and writes the volume mesh with Gmsh. Input g lies at height\n"
          "z_g; the sections between two inputs are evenly spaced. Inputs in planes\n"
          "other than z = constant are lofted between their planes instead: every\n"
          "node blended between its points in the planes of the inputs around it,\n"
          "every cell checked positive in space (no --height or --heights then).\n"
          "Prisms flatter than 1:10 (a triangle edge over 10 times their height)\n"
          "are warned about on stderr: their tetrahedra cannot avoid small\n"
          "dihedral angles.\n"
          "\n"
          "Options:\n", out);
    print_options(out, sweep_options, sweep_option_count);
    fputs("\n"
          "The file is written to a temporary file beside FILE and renamed into place\n"
          "when complete; on failure nothing is written. One physical group, 'sweep',\n"
          "holds every cell. A .msh file also holds the boundary for boundary\n"
          "conditions, as surfaces with a physical group each: 'bottom' (the first\n"
          "input), 'top' (the last), 'side' (the wall over the outer loop) and\n"
          "'hole_1', 'hole_2', ... (the wall over each hole): the caps' triangles and\n"
          "the prisms' side quads (with --tets the tetrahedra's triangles), each\n"
          "face's normal pointing out of the volume. A .inp file (Abaqus, CalculiX)\n"
          "gets those groups as node sets (*NSET) and as element-face surfaces\n"
          "(*SURFACE, TYPE=ELEMENT) for pressures (*DSLOAD).\n"
          "\n"
          "Exit status (on failure no file is written):\n"
          "  0    success\n"
          "  1    internal failure, or FILE's directory missing or not writable\n"
          "  2    bad input or usage, as for 'compatmesh triangulate', also an\n"
          "       unknown extension or heights that do not increase\n"
          "  130  interrupted\n", out);
}

static int parse_sweep_args(int argc, char **argv, sweep_args *args, cli_error *error)
{
    memset(args, 0, sizeof *args);
    args->sections = 11;
    args->format = (volume_format){4.1, 1};
    int code = triangulation_args_init(&args->tri, argc, error);
    if (code != CLI_EXIT_OK) return code;
    code = parse_options(argc, argv, "sweep", sweep_options, sweep_option_count,
                         handle_sweep_option, args, error);
    if (code != CLI_EXIT_OK || args->help) return code;
    code = triangulation_args_check(&args->tri, "sweep", error);
    if (code != CLI_EXIT_OK) return code;
    if (!args->output) {
        cli_error_set(error, "sweep: -o FILE is required (see 'compatmesh sweep --help')");
        return CLI_EXIT_USAGE;
    }
    if (volume_extension_known(args->output) != 0) {
        cli_error_set(error, "sweep: %s: unknown extension; the format follows it, one of "
                      VOLUME_EXTENSIONS, args->output);
        return CLI_EXIT_USAGE;
    }
    if (args->format.order == 2 && strcasecmp(volume_extension(args->output), "vtu") == 0) {
        cli_error_set(error, "sweep: %s: second-order cells go to the formats Gmsh writes (msh, vtk, inp, bdf, "
                      "unv), not .vtu", args->output);
        return CLI_EXIT_USAGE;
    }
    if (args->height > 0 && args->heights) {
        cli_error_set(error, "sweep: give --height or --heights, not both");
        return CLI_EXIT_USAGE;
    }
    if (args->heights && args->heights_count != args->tri.input_count) {
        cli_error_set(error, "sweep: --heights gives %zu heights for %zu inputs",
                      args->heights_count, args->tri.input_count);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

/* Before any work: the output's directory must exist and be writable, and
 * the output must not be a directory. */
static int check_output(const char *path, cli_error *error)
{
    const char *slash = strrchr(path, '/');
    char *dir = slash ? strndup(path, slash == path ? 1 : (size_t)(slash - path)) : strdup(".");
    if (!dir) {
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    struct stat info;
    int code = CLI_EXIT_OK;
    if (stat(dir, &info) != 0) {
        cli_error_set(error, "cannot write %s: %s: %s", path, dir, strerror(errno));
        code = CLI_EXIT_INTERNAL;
    } else if (!S_ISDIR(info.st_mode)) {
        cli_error_set(error, "cannot write %s: %s is not a directory", path, dir);
        code = CLI_EXIT_INTERNAL;
    } else if (access(dir, W_OK | X_OK) != 0) {
        cli_error_set(error, "cannot write %s: %s: %s", path, dir, strerror(errno));
        code = CLI_EXIT_INTERNAL;
    } else if (stat(path, &info) == 0 && S_ISDIR(info.st_mode)) {
        cli_error_set(error, "cannot write %s: it is a directory", path);
        code = CLI_EXIT_USAGE;
    }
    free(dir);
    return code;
}

/* The inputs' own z as heights, when every input gives z (an OBJ, PLY or
 * .xy file with z) and the z differ; flat drawings (all z equal, or none
 * given) say nothing. */
static int heights_from_inputs(const triangulation *tri, double *heights, cli_error *error)
{
    size_t k = tri->args->input_count, with_z = 0;
    int distinct = 0;
    for (size_t g = 0; g < k; g++) {
        if (!tri->polygons[g].has_z) continue;
        if (with_z > 0 && tri->polygons[g].z != heights[0]) distinct = 1;
        if (with_z == 0) heights[0] = tri->polygons[g].z;
        with_z++;
    }
    if (!distinct) return 0;
    if (with_z < k) {
        cli_error_set(error, "sweep: some inputs give z and some do not; give all of them z "
                      "or use --height / --heights");
        return -1;
    }
    for (size_t g = 0; g < k; g++) {
        heights[g] = tri->polygons[g].z;
        if (g > 0 && !(heights[g] > heights[g - 1])) {
            cli_error_set(error, "sweep: %s lies at z = %.17g, not above %s at z = %.17g; "
                          "the inputs' z must increase (or use --height / --heights)",
                          tri->polygons[g].path, heights[g], tri->polygons[g - 1].path,
                          heights[g - 1]);
            return -1;
        }
    }
    return 1;
}

static int build_sweep(const sweep_args *args, const triangulation *tri, cm_morph **morph,
                       cm_sweep **sweep, const char **height_rule, cli_error *error)
{
    size_t k = args->tri.input_count;
    double *own = malloc(9 * k * sizeof *own); /* the inputs' z, or a loft's frames */
    if (!own) {
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    cm_sweep_options options;
    cm_sweep_options_init(&options);
    options.sections = args->sections;
    options.tets = args->tets;
    options.wall_corner_deg = args->wall_corner_deg;
    options.ruled = args->ruled;
    options.progress = cli_progress;
    /* options.height stays 0 unless given: the core's default, the largest
     * bounding-box diagonal of the sections. */
    *height_rule = "the largest bounding-box diagonal of the sections (default), so prisms are about as tall "
                   "as the sections are wide";
    if (tri->polygons[0].spatial) { /* sections in other planes (every input then is): a loft between them */
        if (args->height > 0 || args->heights) {
            free(own);
            cli_error_set(error, "sweep: the inputs lie in planes other than z = constant, which place them; "
                          "give no --height or --heights");
            return CLI_EXIT_USAGE;
        }
        polygon_frames(tri->polygons, k, own);
        options.frames = own;
        *height_rule = "a loft between the inputs' planes: the distances between their centres";
    } else if (args->heights) {
        options.heights = args->heights, *height_rule = "given by --heights";
    } else if (args->height > 0) {
        options.height = args->height, *height_rule = "given by --height";
    } else {
        int found = heights_from_inputs(tri, own, error);
        if (found < 0) {
            free(own);
            return CLI_EXIT_USAGE;
        }
        if (found) options.heights = own, *height_rule = "the inputs' own z";
    }
    cm_morph_options morph_options;
    cm_morph_options_init(&morph_options);
    morph_options.progress = cli_progress;
    cm_status status = cm_morph_create(tri->result, &morph_options, morph);
    const char *message = *morph ? cm_morph_message(*morph) : "";
    if (status == CM_OK) {
        status = cm_sweep_create(*morph, &options, sweep);
        message = *sweep ? cm_sweep_message(*sweep) : "";
    }
    free(own);
    cli_progress_done();
    if (status == CM_OK) return CLI_EXIT_OK;
    return core_failure("sweep", message, status, error);
}

static int sweep(const sweep_args *args, cli_error *error)
{
    triangulation tri = {0};
    cm_morph *morph = NULL;
    cm_sweep *sweep = NULL;
    const char *height_rule = "";
    int code = check_output(args->output, error);
    if (code == CLI_EXIT_OK && args->report) code = check_output(args->report, error);
    if (code == CLI_EXIT_OK)
        code = refuse_input_as_output(args->output, args->tri.inputs, args->tri.input_count, error);
    if (code == CLI_EXIT_OK) code = triangulation_run(&tri, &args->tri, error);
    if (code == CLI_EXIT_OK) code = build_sweep(args, &tri, &morph, &sweep, &height_rule, error);
    if (code == CLI_EXIT_OK && interrupted) {
        cli_error_set(error, "interrupted; nothing written");
        code = CLI_EXIT_INTERRUPTED;
    }
    if (code == CLI_EXIT_OK) {
        volume_mesh mesh = {cm_sweep_nodes(sweep), cm_sweep_num_nodes(sweep),
                            args->tets ? cm_sweep_tets(sweep) : cm_sweep_prisms(sweep),
                            args->tets ? cm_sweep_num_tets(sweep) : cm_sweep_num_prisms(sweep),
                            args->tets,
                            cm_sweep_boundary_faces(sweep, args->tets),
                            cm_sweep_num_boundary_faces(sweep, args->tets),
                            cm_sweep_num_boundary_groups(sweep), NULL,
                            cm_sweep_boundary_group_offsets(sweep, args->tets),
                            cm_sweep_boundary_cells(sweep, args->tets)};
        const char **names = malloc((mesh.num_groups + 1) * sizeof *names);
        for (size_t g = 0; names && g < mesh.num_groups; g++) names[g] = cm_sweep_boundary_group_name(sweep, g);
        mesh.group_names = names;
        if (names) code = write_volume(args->output, &mesh, &args->format, error);
        else cli_error_set(error, "out of memory"), code = CLI_EXIT_INTERNAL;
        free(names);
        double volume = cm_sweep_volume(sweep);
        char volume_text[64] = "volume beyond the double range";
        if (isfinite(volume)) format_double(volume_text + sprintf(volume_text, "volume "), volume);
        if (code == CLI_EXIT_OK && !cli_quiet())
            printf("wrote %s (%zu sections, %zu %s, %zu %s, %s)\n", args->output, cm_sweep_num_sections(sweep),
                   mesh.num_nodes, args->format.order == 2 ? "corner nodes" : "nodes", mesh.num_cells,
                   args->format.order == 2 ? (args->tets ? "10-node tetrahedra" : "15-node prisms")
                                           : (args->tets ? "tetrahedra" : "prisms"),
                   volume_text);
        if (code == CLI_EXIT_OK && !cli_quiet() && cm_sweep_morph_method(sweep) == CM_MORPH_INTRINSIC)
            printf("the convex morph needed more inserted sections than max_refine; the sections are the "
                   "intrinsic morph's (angles and edge lengths interpolated)\n");
        cm_sweep_quality quality;
        cm_sweep_get_quality(sweep, &quality);
        char warning[256] = "";
        if (code == CLI_EXIT_OK && quality.flat_prisms > 0) {
            snprintf(warning, sizeof warning,
                     "%zu of %zu prisms are flatter than 1:%g (a triangle edge %.3g times the prism's height); "
                     "their tetrahedra have small dihedral angles: give a larger --height, fewer --sections or --sections auto",
                     quality.flat_prisms, cm_sweep_num_prisms(sweep), CM_SWEEP_FLAT_RATIO, quality.max_flatness);
            fprintf(stderr, "compatmesh: sweep: warning: %s\n", warning);
        }
        if (code == CLI_EXIT_OK && args->report) {
            sweep_report_info info = {tri.result, sweep, args->tri.method_name, (const char *const *)args->tri.inputs,
                                      args->output, args->tets, args->format.order, height_rule,
                                      warning[0] ? warning : NULL};
            code = write_sweep_report(args->report, &info, error);
            if (code == CLI_EXIT_OK && !cli_quiet()) printf("wrote %s\n", args->report);
        }
    }
    cm_sweep_free(sweep);
    cm_morph_free(morph);
    if (tri.args) triangulation_free(&tri);
    return code;
}

int run_sweep(int argc, char **argv)
{
    sweep_args args;
    cli_error error = {{0}};
    int code = parse_sweep_args(argc, argv, &args, &error);
    if (code == CLI_EXIT_OK && args.help) print_sweep_help(stdout);
    else if (code == CLI_EXIT_OK) code = sweep(&args, &error);
    if (code != CLI_EXIT_OK) cli_print_error(&error);
    triangulation_args_free(&args.tri);
    free(args.heights);
    return code;
}
