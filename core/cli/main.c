#define _POSIX_C_SOURCE 200809L /* sigaction, clock_gettime */

#include <errno.h>
#include <getopt.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <compatmesh/compatmesh.h>

#include "cli_common.h"
#include "outdir.h"
#include "read_polygon.h"
#include "write_mesh.h"
#include "write_report.h"
#include "write_svg.h"

static const char *const EXIT_STATUS_HELP =
    "Exit status:\n"
    "  0    success\n"
    "  1    internal failure: the library failed or ran out of memory, or an\n"
    "       output could not be written (DIR or its parent not writable, ...)\n"
    "  2    bad input or usage: unknown option, fewer than two inputs,\n"
    "       unreadable or malformed input file, vertex counts that differ, a\n"
    "       polygon that is not simple, or DIR exists and is not a directory\n"
    "  130  interrupted\n";

static void print_error(const cli_error *error)
{
    fprintf(stderr, "compatmesh: %s\n", error->message);
}

/* ---- options: one table per subcommand drives parsing and --help ------ */

typedef struct option_spec {
    const char *name;  /* long name, without "--" */
    int key;           /* the short letter, or >= 256 for long-only options */
    const char *value; /* what the value is called in --help; NULL: a flag */
    const char *help;  /* may hold '\n' to continue on an indented line */
} option_spec;

enum { MAX_OPTIONS = 32, OPTION_HELP_COLUMN = 24 };

/* Receives each option (key) or positional argument (key 0) in order. */
typedef int (*option_handler)(void *context, int key, const char *value,
                              cli_error *error);

static const option_spec *find_option(const option_spec *specs, size_t count, int key)
{
    for (size_t i = 0; i < count; i++)
        if (specs[i].key == key) return &specs[i];
    return NULL;
}

/* getopt_long's '?': an unknown long option (optopt 0), a value given to a
 * flag (--flag=value; optopt is the flag's key), or an unknown short option
 * (optopt is the letter; the word at optind - 1 may be another argument). */
static void describe_bad_option(const char *word, const char *command,
                                const option_spec *specs, size_t count,
                                cli_error *error)
{
    const option_spec *flag = optopt ? find_option(specs, count, optopt) : NULL;
    const char *equals = strchr(word, '=');
    int length = equals ? (int)(equals - word) : (int)strlen(word);
    if (strncmp(word, "--", 2) == 0 && optopt == 0)
        cli_error_set(error, "%s: unknown option '%.*s' (see 'compatmesh %s --help')",
                      command, length, word, command);
    else if (strncmp(word, "--", 2) == 0 && flag && equals &&
             strncmp(flag->name, word + 2, (size_t)length - 2) == 0)
        cli_error_set(error, "%s: option '--%s' takes no value", command, flag->name);
    else
        cli_error_set(error, "%s: unknown option '-%c' (see 'compatmesh %s --help')",
                      command, optopt, command);
}

/* Wraps getopt_long so that every problem becomes one clear message naming
 * the command. Options and positional arguments may be mixed; "--" ends the
 * options. */
static int parse_options(int argc, char **argv, const char *command,
                         const option_spec *specs, size_t count,
                         option_handler handle, void *context, cli_error *error)
{
    struct option long_options[MAX_OPTIONS + 1] = {{0}};
    char short_options[3 * MAX_OPTIONS + 3] = "-:"; /* in order; report ':' */
    size_t used = 2;
    for (size_t i = 0; i < count && i < MAX_OPTIONS; i++) {
        long_options[i] = (struct option){specs[i].name,
                                          specs[i].value ? required_argument : no_argument,
                                          NULL, specs[i].key};
        if (specs[i].key < 256) {
            short_options[used++] = (char)specs[i].key;
            if (specs[i].value) short_options[used++] = ':';
        }
    }
    short_options[used] = '\0';
    opterr = 0;
    optind = 0; /* glibc: start afresh */
    int key, code = CLI_EXIT_OK;
    while (code == CLI_EXIT_OK &&
           (key = getopt_long(argc, argv, short_options, long_options, NULL)) != -1) {
        if (key == '?') {
            describe_bad_option(argv[optind - 1], command, specs, count, error);
            code = CLI_EXIT_USAGE;
        } else if (key == ':') {
            const option_spec *spec = find_option(specs, count, optopt);
            cli_error_set(error, "%s: option '--%s' needs a value %s", command,
                          spec ? spec->name : "?", spec ? spec->value : "");
            code = CLI_EXIT_USAGE;
        } else {
            code = handle(context, key == 1 ? 0 : key, optarg, error);
        }
    }
    for (int i = optind; code == CLI_EXIT_OK && i < argc; i++)
        code = handle(context, 0, argv[i], error); /* what followed "--" */
    return code;
}

static void print_options(FILE *out, const option_spec *specs, size_t count)
{
    for (size_t i = 0; i < count; i++) {
        int width;
        if (specs[i].key < 256)
            width = fprintf(out, "  -%c, --%s", specs[i].key, specs[i].name);
        else
            width = fprintf(out, "      --%s", specs[i].name);
        if (specs[i].value) width += fprintf(out, " %s", specs[i].value);
        if (width >= OPTION_HELP_COLUMN - 1) {
            fputc('\n', out);
            width = 0;
        }
        fprintf(out, "%*s", OPTION_HELP_COLUMN - width, "");
        for (const char *c = specs[i].help; *c; c++) {
            fputc(*c, out);
            if (*c == '\n') fprintf(out, "%*s", OPTION_HELP_COLUMN, "");
        }
        fputc('\n', out);
    }
}

/* ---- Ctrl-C: stop the computation cleanly, leaving no output ---------- */

static volatile sig_atomic_t interrupted;

static void on_interrupt(int signal_number)
{
    (void)signal_number;
    interrupted = 1;
}

static void catch_interrupts(void)
{
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, NULL);
    sigaction(SIGTERM, &action, NULL);
}

static int cancel_if_interrupted(void *user, double fraction, const char *stage)
{
    (void)user, (void)fraction, (void)stage;
    return interrupted;
}

static double seconds_now(void)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)now.tv_sec + 1e-9 * (double)now.tv_nsec;
}

/* ---- triangulate ------------------------------------------------------- */

enum {
    OPTION_NO_REMESH = 256,
    OPTION_MIN_ANGLE,
    OPTION_MAX_STEINER,
    OPTION_K_SPLIT,
    OPTION_AREA_EVERY,
    OPTION_SMOOTHING,
    OPTION_MAX_ITERATIONS
};

static const option_spec triangulate_options[] = {
    {"out-dir", 'o', "DIR",
     "where the outputs go (required); DIR is created if\n"
     "missing (its parent must exist); files in DIR named\n"
     "like an output are replaced, other files are kept"},
    {"format", 'f', "FMT", "mesh file format: off (default), obj or ply (ASCII)"},
    {"method", 'm', "NAME",
     "how the first compatible triangulation is built:\n"
     "partition (default): minimum-link paths, few or no\n"
     "Steiner vertices (paper section 2); overlay: the\n"
     "Aronov-Seidel-Souvaine overlay, many Steiner vertices"},
    {"no-remesh", OPTION_NO_REMESH, NULL,
     "keep the first compatible triangulation as built\n"
     "(remeshing is on by default)"},
    {"min-angle", OPTION_MIN_ANGLE, "DEG",
     "remeshing target smallest angle in (0, 60), default\n"
     "25; near a sharp input corner of angle c the aim is\n"
     "c/2"},
    {"max-steiner", OPTION_MAX_STEINER, "N",
     "most Steiner vertices refinement may add; default\n"
     "2n + 100; 0: no refinement"},
    {"k-split", OPTION_K_SPLIT, "N",
     "edges split per refinement round; default 0: about\n"
     "1% of the triangles"},
    {"area-every", OPTION_AREA_EVERY, "N",
     "area equalisation (eq. 4) every N refinement\n"
     "rounds; default 0: never"},
    {"smoothing", OPTION_SMOOTHING, "NAME",
     "laplacian, angle, weighted or combined (default):\n"
     "weighted angle-based, Laplacian where it fails"},
    {"max-iterations", OPTION_MAX_ITERATIONS, "N",
     "cap on refinement rounds; default 0: none"},
    {"help", 'h', NULL, "show this help and exit"},
};
static const size_t triangulate_option_count =
    sizeof triangulate_options / sizeof triangulate_options[0];

static const struct {
    const char *name;
    cm_method method;
} methods[] = {{"partition", CM_METHOD_PARTITION}, {"overlay", CM_METHOD_OVERLAY}};

static const char *const smoothing_names[] = {"laplacian", "angle", "weighted", "combined"};

typedef struct triangulate_args {
    const char **inputs;
    size_t input_count;
    const char *out_dir;
    mesh_format format;
    const char *method_name;
    cm_options options; /* method, remeshing; the progress hook is set later */
    int help;
} triangulate_args;

static int set_method(triangulate_args *args, const char *name, cli_error *error)
{
    for (size_t i = 0; i < sizeof methods / sizeof methods[0]; i++) {
        if (strcmp(name, methods[i].name) == 0) {
            args->method_name = methods[i].name;
            args->options.method = methods[i].method;
            return CLI_EXIT_OK;
        }
    }
    cli_error_set(error, "triangulate: unknown --method '%s' (known: partition, overlay)",
                  name);
    return CLI_EXIT_USAGE;
}

static int set_smoothing(triangulate_args *args, const char *name, cli_error *error)
{
    for (size_t i = 0; i < sizeof smoothing_names / sizeof smoothing_names[0]; i++) {
        if (strcmp(name, smoothing_names[i]) == 0) {
            args->options.smoothing = (cm_smoothing)i;
            return CLI_EXIT_OK;
        }
    }
    cli_error_set(error, "triangulate: unknown --smoothing '%s' "
                  "(known: laplacian, angle, weighted, combined)", name);
    return CLI_EXIT_USAGE;
}

/* A whole decimal number in [low, high]; the message names the option. */
static int parse_long(const char *option, const char *text, long low, long high,
                      long *value, cli_error *error)
{
    char *end;
    errno = 0;
    long parsed = strtol(text, &end, 10);
    if (end == text || *end != '\0' || errno == ERANGE || parsed < low || parsed > high) {
        cli_error_set(error, "triangulate: --%s needs a whole number in [%ld, %ld], got '%s'",
                      option, low, high, text);
        return CLI_EXIT_USAGE;
    }
    *value = parsed;
    return CLI_EXIT_OK;
}

static int parse_int(const char *option, const char *text, int *value, cli_error *error)
{
    long parsed;
    int code = parse_long(option, text, 0, INT_MAX, &parsed, error);
    if (code == CLI_EXIT_OK) *value = (int)parsed;
    return code;
}

static int parse_min_angle(const char *text, double *value, cli_error *error)
{
    char *end;
    double parsed = strtod(text, &end);
    if (end == text || *end != '\0' || !(parsed > 0 && parsed < 60)) {
        cli_error_set(error, "triangulate: --min-angle needs degrees in (0, 60), got '%s'",
                      text);
        return CLI_EXIT_USAGE;
    }
    *value = parsed;
    return CLI_EXIT_OK;
}

static int handle_triangulate_option(void *context, int key, const char *value,
                                     cli_error *error)
{
    triangulate_args *args = context;
    switch (key) {
    case 0:
        args->inputs[args->input_count++] = value;
        return CLI_EXIT_OK;
    case 'o':
        args->out_dir = value;
        return CLI_EXIT_OK;
    case 'f':
        if (mesh_format_from_name(value, &args->format) == 0) return CLI_EXIT_OK;
        cli_error_set(error, "triangulate: unknown --format '%s' (known: off, obj, ply)", value);
        return CLI_EXIT_USAGE;
    case 'm':
        return set_method(args, value, error);
    case OPTION_NO_REMESH:
        args->options.remesh = 0;
        return CLI_EXIT_OK;
    case OPTION_MIN_ANGLE:
        return parse_min_angle(value, &args->options.min_angle_deg, error);
    case OPTION_MAX_STEINER:
        return parse_long("max-steiner", value, 0, LONG_MAX, &args->options.max_steiner, error);
    case OPTION_K_SPLIT:
        return parse_int("k-split", value, &args->options.k_split, error);
    case OPTION_AREA_EVERY:
        return parse_int("area-every", value, &args->options.area_every, error);
    case OPTION_SMOOTHING:
        return set_smoothing(args, value, error);
    case OPTION_MAX_ITERATIONS:
        return parse_int("max-iterations", value, &args->options.max_iterations, error);
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
          "  .obj        an OBJ polyline: 'v x y [z]' lines and exactly one closed\n"
          "              'l' line (its last index repeats the first); the polygon\n"
          "              follows the 'l' order; z, if given, must be the same for\n"
          "              all vertices\n"
          "  any other   one vertex 'x y' per line, the numbers separated by blanks\n"
          "              and/or one comma (\"1.5 2\", \"1.5, 2\", \"1.5,2\"); '#' starts\n"
          "              a comment; blank lines are ignored\n"
          "  The polygons may run clockwise or counter-clockwise, all the same way.\n"
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
          "  DIR/report.json  version, n, k, vertices, steiner, triangles, valid,\n"
          "                   method, remesh, reversed_input, fallback_count,\n"
          "                   steiner_before_remesh, remesh_iterations,\n"
          "                   remesh_aim_deg (the target lowered where the\n"
          "                   input allows less), seconds\n"
          "                   (validate, build, remesh, check, and total: the\n"
          "                   whole computation) and per mesh the input, output,\n"
          "                   min/max angle and the share of triangles whose\n"
          "                   smallest angle is below 10, 15 and 20 degrees, after\n"
          "                   and (before_remesh) before remeshing\n"
          "  DIR/preview.svg  the meshes side by side: boundary thick, Steiner\n"
          "                   vertices as dots, triangles whose smallest angle is\n"
          "                   below 20 degrees orange, each mesh's worst one red\n"
          "\n", out);
    fputs(EXIT_STATUS_HELP, out);
}

static int parse_triangulate_args(int argc, char **argv, triangulate_args *args,
                                  cli_error *error)
{
    memset(args, 0, sizeof *args);
    args->format = MESH_FORMAT_OFF;
    cm_options_init(&args->options);
    args->method_name = "partition";
    args->inputs = malloc((size_t)argc * sizeof *args->inputs);
    if (!args->inputs) {
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    int code = parse_options(argc, argv, "triangulate", triangulate_options,
                             triangulate_option_count, handle_triangulate_option,
                             args, error);
    if (code != CLI_EXIT_OK || args->help) return code;
    if (args->input_count < 2) {
        cli_error_set(error, "triangulate: needs at least two input polygons, got %zu "
                      "(see 'compatmesh triangulate --help')", args->input_count);
        return CLI_EXIT_USAGE;
    }
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
    polygon_input *polygons;
    char **stems;       /* output names: input file name without extension */
    char **mesh_names;  /* STEM.FMT */
    char **final_paths; /* DIR/STEM.FMT, as reported */
    cm_result *result;
    double seconds_total;
    staged_output output;
} triangulate_run;

static void triangulate_run_free(triangulate_run *run)
{
    size_t k = run->args->input_count;
    for (size_t i = 0; i < k; i++) {
        if (run->polygons) polygon_input_free(&run->polygons[i]);
        if (run->stems) free(run->stems[i]);
        if (run->mesh_names) free(run->mesh_names[i]);
        if (run->final_paths) free(run->final_paths[i]);
    }
    free(run->polygons);
    free(run->stems);
    free(run->mesh_names);
    free(run->final_paths);
    cm_result_free(run->result);
    staged_output_discard(&run->output);
}

static const char *file_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
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
    for (size_t i = 0; i < args->input_count; i++) {
        run->stems[i] = file_stem(args->inputs[i]);
        if (!run->stems[i]) {
            cli_error_set(error, "out of memory");
            return CLI_EXIT_INTERNAL;
        }
        if (run->stems[i][0] == '\0') {
            cli_error_set(error, "%s: not a file name", args->inputs[i]);
            return CLI_EXIT_USAGE;
        }
        for (size_t j = 0; j < i; j++) {
            if (strcmp(run->stems[i], run->stems[j]) == 0) {
                cli_error_set(error, "%s and %s would both be written to %s.%s; "
                              "rename one of them", args->inputs[j], args->inputs[i],
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

static int read_inputs(triangulate_run *run, cli_error *error)
{
    const triangulate_args *args = run->args;
    for (size_t i = 0; i < args->input_count; i++) {
        int code = read_polygon(args->inputs[i], &run->polygons[i], error);
        if (code != CLI_EXIT_OK) return code;
        if (run->polygons[i].count != run->polygons[0].count) {
            cli_error_set(error, "%s has %zu vertices but %s has %zu; the polygons' "
                          "vertices correspond by index, so the counts must be equal",
                          args->inputs[i], run->polygons[i].count, args->inputs[0],
                          run->polygons[0].count);
            return CLI_EXIT_USAGE;
        }
    }
    return CLI_EXIT_OK;
}

static int exit_code_for(cm_status status)
{
    switch (status) {
    case CM_OK: return CLI_EXIT_OK;
    case CM_ERR_NO_MEMORY:
    case CM_ERR_INTERNAL: return CLI_EXIT_INTERNAL;
    case CM_ERR_CANCELLED: return CLI_EXIT_INTERRUPTED;
    default: return CLI_EXIT_USAGE; /* the input was at fault */
    }
}

/* The core's message without its "polygon N: " prefix (the file name says
 * which polygon), or the message unchanged if it has no such prefix. */
static const char *without_polygon_prefix(const char *message, long polygon)
{
    char prefix[48];
    int length = snprintf(prefix, sizeof prefix, "polygon %ld: ", polygon);
    return strncmp(message, prefix, (size_t)length) == 0 ? message + length : message;
}

/* The core's message, prefixed with the file and line of the vertex it
 * blames, so the user can go straight to the line to fix. */
static void describe_failure(const triangulate_run *run, cm_status status,
                             cli_error *error)
{
    const char *message = run->result ? cm_result_message(run->result) : "";
    if (message[0] == '\0') message = cm_status_string(status);
    long polygon = -1, vertex = -1, other = -1;
    if (run->result) cm_result_error_location(run->result, &polygon, &vertex, &other);
    if (polygon < 0 || (size_t)polygon >= run->args->input_count) {
        cli_error_set(error, "%s", message);
        return;
    }
    const polygon_input *p = &run->polygons[polygon];
    message = without_polygon_prefix(message, polygon);
    if (vertex < 0 || (size_t)vertex >= p->count) {
        cli_error_set(error, "%s: %s", p->path, message);
    } else if (other < 0 || (size_t)other >= p->count) {
        cli_error_set(error, "%s:%ld: %s", p->path, p->source_line[vertex], message);
    } else {
        cli_error_set(error, "%s:%ld: %s; vertex %ld is on line %ld", p->path,
                      p->source_line[vertex], message, other, p->source_line[other]);
    }
}

static int compute(triangulate_run *run, cli_error *error)
{
    size_t k = run->args->input_count, n = run->polygons[0].count;
    double *xy = malloc(2 * k * n * sizeof *xy + 1);
    if (!xy) {
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    for (size_t g = 0; g < k; g++)
        memcpy(xy + 2 * g * n, run->polygons[g].xy, 2 * n * sizeof *xy);
    cm_options options = run->args->options;
    options.progress = cancel_if_interrupted;
    double start = seconds_now();
    cm_status status = cm_triangulate(xy, k, n, &options, &run->result);
    run->seconds_total = seconds_now() - start;
    free(xy);
    if (status == CM_OK) return CLI_EXIT_OK;
    if (status == CM_ERR_CANCELLED) cli_error_set(error, "interrupted; nothing written");
    else describe_failure(run, status, error);
    return exit_code_for(status);
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
    for (size_t g = 0; g < run->args->input_count; g++) {
        const char *path;
        int code = stage_file(run, run->mesh_names[g], &path, error);
        if (code == CLI_EXIT_OK)
            code = write_mesh(path, run->result, g, run->args->format, error);
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
    report_info info = {run->result, run->args->method_name, run->args->options.remesh,
                        run->seconds_total, run->args->inputs,
                        (const char *const *)run->final_paths};
    int code = stage_file(run, "report.json", &path, error);
    if (code == CLI_EXIT_OK) code = write_report(path, &info, error);
    if (code == CLI_EXIT_OK) code = stage_file(run, "preview.svg", &path, error);
    if (code != CLI_EXIT_OK) return code;
    const char **names = malloc(run->args->input_count * sizeof *names);
    if (!names) {
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    for (size_t g = 0; g < run->args->input_count; g++)
        names[g] = file_name(run->args->inputs[g]);
    code = write_svg(path, run->result, names, error);
    free(names);
    return code;
}

static int write_outputs(triangulate_run *run, cli_error *error)
{
    int code = staged_output_begin(&run->output, run->args->out_dir, error);
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
    const cm_stats *stats = cm_result_stats(run->result);
    for (size_t g = 0; g < run->args->input_count; g++) {
        cm_quality quality;
        if (cm_result_quality(run->result, g, &quality) != CM_OK) quality.min_angle_deg = 0;
        printf("wrote %s (n=%zu, steiner=%zu, min angle %.1f deg)\n", run->final_paths[g],
               stats->n, stats->steiner, quality.min_angle_deg);
    }
    printf("wrote %s/report.json and %s/preview.svg\n", run->output.target,
           run->output.target);
}

static int triangulate(const triangulate_args *args, cli_error *error)
{
    size_t k = args->input_count;
    triangulate_run run = {0};
    run.args = args;
    run.polygons = calloc(k, sizeof *run.polygons);
    run.stems = calloc(k, sizeof *run.stems);
    run.mesh_names = calloc(k, sizeof *run.mesh_names);
    run.final_paths = calloc(k, sizeof *run.final_paths);
    int code = CLI_EXIT_OK;
    if (!run.polygons || !run.stems || !run.mesh_names || !run.final_paths) {
        cli_error_set(error, "out of memory");
        code = CLI_EXIT_INTERNAL;
    }
    if (code == CLI_EXIT_OK) code = make_output_names(&run, error);
    if (code == CLI_EXIT_OK) code = staged_output_check(args->out_dir, error);
    if (code == CLI_EXIT_OK) code = read_inputs(&run, error);
    if (code == CLI_EXIT_OK) code = compute(&run, error);
    if (code == CLI_EXIT_OK) code = write_outputs(&run, error);
    if (code == CLI_EXIT_OK) print_summary(&run);
    triangulate_run_free(&run);
    return code;
}

static int run_triangulate(int argc, char **argv)
{
    triangulate_args args;
    cli_error error = {{0}};
    int code = parse_triangulate_args(argc, argv, &args, &error);
    if (code == CLI_EXIT_OK && args.help) print_triangulate_help(stdout);
    else if (code == CLI_EXIT_OK) code = triangulate(&args, &error);
    if (code != CLI_EXIT_OK) print_error(&error);
    free(args.inputs);
    return code;
}

/* ---- subcommands --------------------------------------------------------- */

typedef struct subcommand {
    const char *name;
    const char *summary;
    int (*run)(int argc, char **argv); /* argv[0] is the subcommand's name */
} subcommand;

static const subcommand subcommands[] = {
    {"triangulate", "compatibly triangulate k >= 2 polygons", run_triangulate},
};
static const size_t subcommand_count = sizeof subcommands / sizeof subcommands[0];

static void print_main_help(FILE *out)
{
    fputs("Usage: compatmesh COMMAND [ARGUMENTS]\n"
          "       compatmesh --help | --version\n"
          "\n"
          "Compatible triangulations of planar polygons whose vertices correspond\n"
          "by index (Surazhsky & Gotsman, \"High Quality Compatible Triangulations\").\n"
          "\n"
          "Commands:\n", out);
    for (size_t i = 0; i < subcommand_count; i++)
        fprintf(out, "  %-14s%s\n", subcommands[i].name, subcommands[i].summary);
    fputs("\n"
          "Options:\n"
          "  -h, --help    show this help and exit\n"
          "      --version show the version and exit\n"
          "\n"
          "Run 'compatmesh COMMAND --help' for the arguments of a command.\n"
          "\n", out);
    fputs(EXIT_STATUS_HELP, out);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fputs("compatmesh: missing command (see 'compatmesh --help')\n", stderr);
        return CLI_EXIT_USAGE;
    }
    const char *command = argv[1];
    if (strcmp(command, "--help") == 0 || strcmp(command, "-h") == 0) {
        print_main_help(stdout);
        return CLI_EXIT_OK;
    }
    if (strcmp(command, "--version") == 0) {
        printf("compatmesh %d.%d.%d\n", CM_VERSION_MAJOR, CM_VERSION_MINOR,
               CM_VERSION_PATCH);
        return CLI_EXIT_OK;
    }
    for (size_t i = 0; i < subcommand_count; i++) {
        if (strcmp(command, subcommands[i].name) == 0) {
            catch_interrupts();
            return subcommands[i].run(argc - 1, argv + 1);
        }
    }
    fprintf(stderr, "compatmesh: unknown %s '%s' (see 'compatmesh --help')\n",
            command[0] == '-' ? "option" : "command", command);
    return CLI_EXIT_USAGE;
}
