#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include "triangulation.h"

#include <errno.h>
#include <math.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "interrupt.h"
#include "progress_line.h"

static const struct {
    const char *name;
    cm_method method;
} methods[] = {{"partition", CM_METHOD_PARTITION}, {"overlay", CM_METHOD_OVERLAY}};

static const char *const smoothing_names[] = {"laplacian", "angle", "weighted", "combined"};

int triangulation_args_init(triangulation_args *args, int argc, cli_error *error)
{
    memset(args, 0, sizeof *args);
    cm_options_init(&args->options);
    args->method_name = "partition";
    args->max_input_bytes = DEFAULT_MAX_INPUT_BYTES;
    args->inputs = malloc((size_t)(argc > 0 ? argc : 1) * sizeof *args->inputs);
    if (args->inputs) return CLI_EXIT_OK;
    cli_error_set(error, "out of memory");
    return CLI_EXIT_INTERNAL;
}

void triangulation_args_free(triangulation_args *args)
{
    free(args->inputs);
    free(args->pins);
    free(args->pin_texts);
    args->inputs = NULL, args->pins = NULL, args->pin_texts = NULL;
}

static int set_method(triangulation_args *args, const char *command, const char *name,
                      cli_error *error)
{
    for (size_t i = 0; i < sizeof methods / sizeof methods[0]; i++) {
        if (strcmp(name, methods[i].name) == 0) {
            args->method_name = methods[i].name;
            args->options.method = methods[i].method;
            return CLI_EXIT_OK;
        }
    }
    cli_error_set(error, "%s: unknown --method '%s' (known: partition, overlay)", command,
                  name);
    return CLI_EXIT_USAGE;
}

static int set_smoothing(triangulation_args *args, const char *command, const char *name,
                         cli_error *error)
{
    for (size_t i = 0; i < sizeof smoothing_names / sizeof smoothing_names[0]; i++) {
        if (strcmp(name, smoothing_names[i]) == 0) {
            args->options.smoothing = (cm_smoothing)i;
            return CLI_EXIT_OK;
        }
    }
    cli_error_set(error, "%s: unknown --smoothing '%s' "
                  "(known: laplacian, angle, weighted, combined)", command, name);
    return CLI_EXIT_USAGE;
}

static int set_remesher(triangulation_args *args, const char *command, const char *name, cli_error *error)
{
    if (strcmp(name, "greedy") == 0) args->options.remesher = CM_REMESHER_GREEDY;
    else if (strcmp(name, "map") == 0) args->options.remesher = CM_REMESHER_MAP;
    else {
        cli_error_set(error, "%s: unknown --remesher '%s' (known: greedy, map)", command, name);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

static int set_correspondence(triangulation_args *args, const char *command, const char *name,
                              cli_error *error)
{
    if (strcmp(name, "index") == 0) args->options.correspondence = CM_CORRESPOND_INDEX;
    else if (strcmp(name, "arclength") == 0) args->options.correspondence = CM_CORRESPOND_ARCLENGTH;
    else if (strcmp(name, "auto") == 0) args->options.correspondence = CM_CORRESPOND_AUTO;
    else if (strcmp(name, "similarity") == 0) args->options.correspondence = CM_CORRESPOND_SIMILARITY;
    else {
        cli_error_set(error, "%s: unknown --correspondence '%s' (known: index, arclength, auto, similarity)", command, name);
        return CLI_EXIT_USAGE;
    }
    args->correspondence_given = 1;
    return CLI_EXIT_OK;
}

/* --pin I,J[,K...]: vertex numbers, one per input; counted per input once
 * all inputs are known (triangulation_args_check). */
static int add_pin(triangulation_args *args, const char *command, const char *text, cli_error *error)
{
    const char **texts = realloc(args->pin_texts, (args->pin_count + 1) * sizeof *texts);
    if (!texts) {
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    args->pin_texts = texts;
    args->pin_texts[args->pin_count++] = text;
    for (const char *p = text;;) {
        char *end;
        errno = 0;
        long v = *p >= '0' && *p <= '9' ? strtol(p, &end, 10) : -1;
        if (v < 0 || errno == ERANGE || (*end != ',' && *end != '\0')) {
            cli_error_set(error, "%s: --pin needs vertex numbers separated by commas, got '%s'", command, text);
            return CLI_EXIT_USAGE;
        }
        size_t *pins = realloc(args->pins, (args->pin_values + 1) * sizeof *pins);
        if (!pins) {
            cli_error_set(error, "out of memory");
            return CLI_EXIT_INTERNAL;
        }
        args->pins = pins;
        args->pins[args->pin_values++] = (size_t)v;
        if (*end == '\0') break;
        p = end + 1;
    }
    return CLI_EXIT_OK;
}

/* A whole decimal number in [low, high]; the message names the option. */
static int parse_long(const char *command, const char *option, const char *text, long low,
                      long high, long *value, cli_error *error)
{
    char *end;
    errno = 0;
    long parsed = strtol(text, &end, 10);
    if (end == text || *end != '\0' || errno == ERANGE || parsed < low || parsed > high) {
        cli_error_set(error, "%s: --%s needs a whole number in [%ld, %ld], got '%s'",
                      command, option, low, high, text);
        return CLI_EXIT_USAGE;
    }
    *value = parsed;
    return CLI_EXIT_OK;
}

static int parse_int(const char *command, const char *option, const char *text, int *value,
                     cli_error *error)
{
    long parsed;
    int code = parse_long(command, option, text, 0, INT_MAX, &parsed, error);
    if (code == CLI_EXIT_OK) *value = (int)parsed;
    return code;
}

/* A number in (0, high) (high HUGE_VAL: any finite one above 0); the
 * message names the option and what it needs. */
static int parse_above_zero(const char *command, const char *option, const char *needs, double high,
                            const char *text, double *value, cli_error *error)
{
    char *end;
    double parsed = strtod(text, &end);
    if (end == text || *end != '\0' || !(parsed > 0 && parsed < high)) {
        cli_error_set(error, "%s: --%s needs %s, got '%s'", command, option, needs, text);
        return CLI_EXIT_USAGE;
    }
    *value = parsed;
    return CLI_EXIT_OK;
}

/* Degrees in (0, high). */
static int parse_degrees(const char *command, const char *option, const char *text, double high,
                         double *value, cli_error *error)
{
    char needs[48];
    snprintf(needs, sizeof needs, "degrees in (0, %g)", high);
    return parse_above_zero(command, option, needs, high, text, value, error);
}

int triangulation_option(triangulation_args *args, const char *command, int key,
                         const char *value, cli_error *error)
{
    switch (key) {
    case 0:
        args->inputs[args->input_count++] = value;
        return CLI_EXIT_OK;
    case 'm':
        return set_method(args, command, value, error);
    case OPTION_NO_REMESH:
        args->options.remesh = 0;
        return CLI_EXIT_OK;
    case OPTION_NO_CEILING:
        args->options.ceiling = 0;
        return CLI_EXIT_OK;
    case OPTION_PROGRESS:
        args->progress = 1;
        return CLI_EXIT_OK;
    case OPTION_QUIET:
        args->quiet = 1;
        return CLI_EXIT_OK;
    case OPTION_MIN_ANGLE:
        return parse_degrees(command, "min-angle", value, 60, &args->options.min_angle_deg, error);
    case OPTION_MAX_STEINER:
        return parse_long(command, "max-steiner", value, 0, LONG_MAX, &args->options.max_steiner,
                          error);
    case OPTION_K_SPLIT:
        return parse_int(command, "k-split", value, &args->options.k_split, error);
    case OPTION_AREA_EVERY:
        return parse_int(command, "area-every", value, &args->options.area_every, error);
    case OPTION_SMOOTHING:
        return set_smoothing(args, command, value, error);
    case OPTION_REMESHER:
        return set_remesher(args, command, value, error);
    case OPTION_MAX_ITERATIONS:
        return parse_int(command, "max-iterations", value, &args->options.max_iterations, error);
    case OPTION_RESTARTS:
        return parse_int(command, "restarts", value, &args->options.restarts, error);
    case OPTION_CORRESPONDENCE:
        return set_correspondence(args, command, value, error);
    case OPTION_PIN:
        return add_pin(args, command, value, error);
    case OPTION_MAX_EDGE:
        return parse_above_zero(command, "max-edge", "a positive length", HUGE_VAL, value, &args->options.max_edge,
                                error);
    case OPTION_TIME_LIMIT:
        return parse_above_zero(command, "time-limit", "positive seconds", HUGE_VAL, value,
                                &args->options.time_limit, error);
    case OPTION_PIN_CORNERS:
        return parse_degrees(command, "pin-corners", value, 180, &args->options.pin_corners_deg, error);
    case OPTION_MAX_INPUT_BYTES:
        return parse_long(command, "max-input-bytes", value, 1, LONG_MAX, &args->max_input_bytes,
                          error);
    default:
        return -1;
    }
}

int triangulation_args_check(const triangulation_args *args, const char *command,
                             cli_error *error)
{
    if (args->progress && args->quiet) {
        cli_error_set(error, "%s: give --progress or --quiet, not both", command);
        return CLI_EXIT_USAGE;
    }
    if (args->input_count < 2) {
        cli_error_set(error, "%s: needs at least two input polygons, got %zu "
                      "(see 'compatmesh %s --help')", command, args->input_count, command);
        return CLI_EXIT_USAGE;
    }
    if ((args->pin_count || args->options.pin_corners_deg > 0) && args->correspondence_given &&
        args->options.correspondence == CM_CORRESPOND_INDEX) {
        cli_error_set(error, "%s: --%s needs --correspondence arclength (with index, vertex i is vertex i)",
                      command, args->pin_count ? "pin" : "pin-corners");
        return CLI_EXIT_USAGE;
    }
    if (args->pin_count && args->options.pin_corners_deg > 0) {
        cli_error_set(error, "%s: give --pin or --pin-corners, not both", command);
        return CLI_EXIT_USAGE;
    }
    if (args->pin_values != args->pin_count * args->input_count) {
        for (size_t j = 0; j < args->pin_count; j++) {
            size_t values = 1;
            for (const char *c = args->pin_texts[j]; *c; c++) values += *c == ',';
            if (values != args->input_count) {
                cli_error_set(error, "%s: --pin %s names %zu vertices for %zu inputs", command,
                              args->pin_texts[j], values, args->input_count);
                return CLI_EXIT_USAGE;
            }
        }
    }
    cli_progress_set_mode(args->quiet      ? PROGRESS_QUIET
                          : args->progress ? PROGRESS_ALWAYS
                                           : PROGRESS_AUTO);
    return CLI_EXIT_OK;
}

const char *file_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

char *file_stem(const char *path)
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

static double seconds_now(void)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)now.tv_sec + 1e-9 * (double)now.tv_nsec;
}

/* Once any input is a section in a plane other than z = constant, every
 * input is placed in space (an input in a plane z = constant too, in its
 * plane), the planes' normals and axes carried along the inputs
 * (section_align), so that a loft's sections turn only as much as their
 * planes and its cells are positive. */
static int place_in_space(triangulation *t, cli_error *error)
{
    size_t k = t->args->input_count;
    section_frame *frames = malloc((k + 1) * sizeof *frames);
    if (!frames) goto out_of_memory;
    for (size_t g = 0; g < k; g++) {
        polygon_input *p = &t->polygons[g];
        if (!p->spatial) {
            if (!(p->xyz = malloc((3 * p->count + 1) * sizeof *p->xyz))) goto out_of_memory;
            for (size_t i = 0; i < p->count; i++)
                p->xyz[3 * i] = p->xy[2 * i], p->xyz[3 * i + 1] = p->xy[2 * i + 1], p->xyz[3 * i + 2] = p->z;
            size_t vertex;
            char message[256];
            /* a plane z = constant is fitted exactly: only memory can fail */
            if (section_fit(p->xyz, p->count, p->loop_sizes[0], &p->frame, &vertex, message, sizeof message))
                goto out_of_memory;
            p->spatial = 1;
        }
        frames[g] = p->frame;
    }
    if (section_align(frames, k)) goto out_of_memory;
    for (size_t g = 0; g < k; g++) {
        polygon_input *p = &t->polygons[g];
        p->frame = frames[g];
        section_to_plane(&p->frame, p->xyz, p->count, p->xy);
        for (size_t i = 0; i < 2 * p->count; i++)
            if (!isfinite(p->xy[i])) {
                free(frames);
                cli_error_set(error, "%s: its plane, carried from the inputs before, does not fit in doubles "
                              "(coordinates too large for it)", p->path);
                return CLI_EXIT_USAGE;
            }
    }
    free(frames);
    return CLI_EXIT_OK;
out_of_memory:
    free(frames);
    cli_error_set(error, "out of memory");
    return CLI_EXIT_INTERNAL;
}

static int read_inputs(triangulation *t, cli_error *error)
{
    const triangulation_args *args = t->args;
    for (size_t i = 0; i < args->input_count; i++) {
        int code = read_polygon(args->inputs[i], (size_t)args->max_input_bytes, &t->polygons[i], error);
        if (code != CLI_EXIT_OK) return code;
        if (args->correspondence_given && t->options.correspondence == CM_CORRESPOND_INDEX &&
            t->polygons[i].count != t->polygons[0].count) {
            cli_error_set(error, "%s has %zu vertices but %s has %zu; with --correspondence "
                          "index the vertices correspond by index, so the counts must be equal",
                          args->inputs[i], t->polygons[i].count, args->inputs[0],
                          t->polygons[0].count);
            return CLI_EXIT_USAGE;
        }
    }
    for (size_t i = 0; i < args->input_count; i++)
        if (t->polygons[i].spatial) return place_in_space(t, error);
    return CLI_EXIT_OK;
}

int exit_code_for(cm_status status)
{
    switch (status) {
    case CM_OK: return CLI_EXIT_OK;
    case CM_ERR_NO_MEMORY:
    case CM_ERR_INTERNAL:
    case CM_ERR_PRECISION: return CLI_EXIT_INTERNAL;
    case CM_ERR_CANCELLED: return CLI_EXIT_INTERRUPTED;
    default: return CLI_EXIT_USAGE; /* the input was at fault */
    }
}

int core_failure(const char *command, const char *message, cm_status status,
                 cli_error *error)
{
    size_t length = strlen(command);
    if (message[0] == '\0') message = cm_status_string(status);
    if (status == CM_ERR_CANCELLED)
        cli_error_set(error, "interrupted; nothing written");
    else if (strncmp(message, command, length) == 0 && message[length] == ':')
        cli_error_set(error, "%s", message); /* the core named the step already */
    else
        cli_error_set(error, "%s: %s", command, message);
    return exit_code_for(status);
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
static void describe_failure(const triangulation *t, cm_status status, cli_error *error)
{
    const char *message = t->result ? cm_result_message(t->result) : "";
    if (message[0] == '\0') message = cm_status_string(status);
    long polygon = -1, vertex = -1, other = -1;
    if (t->result) cm_result_error_location(t->result, &polygon, &vertex, &other);
    if (polygon < 0 || (size_t)polygon >= t->args->input_count) {
        cli_error_set(error, "%s", message);
        return;
    }
    const polygon_input *p = &t->polygons[polygon];
    message = without_polygon_prefix(message, polygon);
    if (vertex < 0 || (size_t)vertex >= p->count) {
        cli_error_set(error, "%s: %s", p->path, message);
    } else if (p->by_index) { /* a binary file: no lines */
        cli_error_set(error, "%s: vertex %ld: %s", p->path, p->source_line[vertex], message);
    } else if (other < 0 || (size_t)other >= p->count) {
        cli_error_set(error, "%s:%ld: %s", p->path, p->source_line[vertex], message);
    } else {
        cli_error_set(error, "%s:%ld: %s; vertex %ld is on line %ld", p->path,
                      p->source_line[vertex], message, other, p->source_line[other]);
    }
}

static int compute(triangulation *t, cli_error *error)
{
    size_t k = t->args->input_count;
    const double **xy = malloc(k * sizeof *xy);
    size_t *counts = malloc(k * sizeof *counts);
    if (!xy || !counts) {
        free(xy), free(counts);
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    cm_loops *loops = malloc(k * sizeof *loops);
    if (!loops) {
        free(xy), free(counts);
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    int holes = 0;
    for (size_t g = 0; g < k; g++) {
        const polygon_input *p = &t->polygons[g];
        xy[g] = p->xy, counts[g] = p->count;
        loops[g] = (cm_loops){p->xy, p->loop_sizes, p->loops};
        holes |= p->loops > 1;
    }
    if (!t->args->correspondence_given) /* pins or counts decide */
        t->options.correspondence =
            cm_correspondence_by_counts(loops, k, t->args->pin_count || t->args->options.pin_corners_deg > 0);
    t->options.progress = cli_progress;
    t->options.pins = t->args->pins, t->options.num_pins = t->args->pin_count;
    double start = seconds_now();
    cm_status status = holes ? cm_triangulate_loops(loops, k, &t->options, &t->result)
                             : cm_triangulate_polygons(xy, counts, k, &t->options, &t->result);
    cli_progress_done();
    t->seconds_total = seconds_now() - start;
    free(xy), free(counts), free(loops);
    if (status == CM_OK) return CLI_EXIT_OK;
    if (status == CM_ERR_CANCELLED) cli_error_set(error, "interrupted; nothing written");
    else describe_failure(t, status, error);
    return exit_code_for(status);
}

int triangulation_run(triangulation *t, const triangulation_args *args, cli_error *error)
{
    memset(t, 0, sizeof *t);
    t->args = args;
    t->polygons = calloc(args->input_count ? args->input_count : 1, sizeof *t->polygons);
    if (!t->polygons) {
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    t->options = args->options;
    int code = read_inputs(t, error);
    if (code == CLI_EXIT_OK) code = compute(t, error);
    return code;
}

void triangulation_free(triangulation *t)
{
    if (t->polygons)
        for (size_t i = 0; i < t->args->input_count; i++) polygon_input_free(&t->polygons[i]);
    free(t->polygons);
    cm_result_free(t->result);
    memset(t, 0, sizeof *t);
}
