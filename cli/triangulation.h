/* What every command that starts from input polygons shares: the input
 * files and the triangulation options on the command line, reading the
 * polygons, and running the core with errors pointing at file and line. */
#ifndef CM_CLI_TRIANGULATION_H
#define CM_CLI_TRIANGULATION_H

#include <stddef.h>

#include <compatmesh/compatmesh.h>

#include "cli_common.h"
#include "options.h"
#include "read_polygon.h"

enum {
    OPTION_NO_REMESH = 256,
    OPTION_MIN_ANGLE,
    OPTION_MAX_STEINER,
    OPTION_K_SPLIT,
    OPTION_AREA_EVERY,
    OPTION_SMOOTHING,
    OPTION_REMESHER,
    OPTION_MAX_ITERATIONS,
    OPTION_RESTARTS,
    OPTION_MAX_INPUT_BYTES,
    OPTION_CORRESPONDENCE,
    OPTION_PIN,
    OPTION_PIN_CORNERS,
    OPTION_MAX_EDGE,
    OPTION_NO_CEILING,
    OPTION_TIME_LIMIT,
    OPTION_PROGRESS,
    OPTION_QUIET,
    OPTION_TRIANGULATION_END /* a command's own long options start here */
};

/* The option_spec entries of the triangulation options, for a command's
 * table: TRIANGULATION_OPTION_SPECS has them all (keys 'm' and
 * OPTION_NO_REMESH .. OPTION_QUIET); TRIANGULATION_METHOD_SPECS leaves out
 * --progress and --quiet, for a command that shows its progress its own way. */
#define TRIANGULATION_OPTION_SPECS \
    TRIANGULATION_METHOD_SPECS,    \
    TRIANGULATION_PROGRESS_SPEC,   \
    TRIANGULATION_QUIET_SPEC

#define TRIANGULATION_METHOD_SPECS                                            \
    {"method", 'm', "NAME",                                                   \
     "how the first compatible triangulation is built:\n"                     \
     "partition (default): minimum-link paths, few or no\n"                   \
     "Steiner vertices (paper section 2); overlay: the\n"                     \
     "Aronov-Seidel-Souvaine overlay, many Steiner vertices"},                \
    {"no-remesh", OPTION_NO_REMESH, NULL,                                     \
     "keep the first compatible triangulation as built\n"                     \
     "(remeshing is on by default)"},                                         \
    {"min-angle", OPTION_MIN_ANGLE, "DEG",                                    \
     "remeshing target smallest angle in (0, 60), default\n"                  \
     "25; near a sharp input corner of angle c the aim is\n"                  \
     "c/2"},                                                                  \
    {"max-steiner", OPTION_MAX_STEINER, "N",                                  \
     "most Steiner vertices refinement may add; default\n"                    \
     "2n + 100; 0: no refinement"},                                           \
    {"k-split", OPTION_K_SPLIT, "N",                                          \
     "edges split per refinement round; default 0: about\n"                   \
     "1% of the triangles"},                                                  \
    {"area-every", OPTION_AREA_EVERY, "N",                                    \
     "area equalisation (eq. 4) every N refinement\n"                         \
     "rounds; default 0: never"},                                             \
    {"smoothing", OPTION_SMOOTHING, "NAME",                                   \
     "laplacian, angle, weighted or combined (default):\n"                    \
     "weighted angle-based, Laplacian where it fails"},                       \
    {"remesher", OPTION_REMESHER, "NAME",                                     \
     "greedy (default): Algorithm 1 and forced moves; map:\n"                 \
     "lower the maps' distortion, refine in the metric\n"                     \
     "halfway between the inputs, then Algorithm 1"},                         \
    {"max-iterations", OPTION_MAX_ITERATIONS, "N",                            \
     "cap on refinement rounds; default 0: none"},                            \
    {"restarts", OPTION_RESTARTS, "N",                                        \
     "where the result ends below 0.85 of its aim, split its\n"               \
     "most distorted tenth and remesh again, kept if better;\n"               \
     "default 1, 0: off (on hard pairs half the time)"},                      \
    {"max-input-bytes", OPTION_MAX_INPUT_BYTES, "N",                          \
     "refuse an input file larger than N bytes (default\n"                    \
     "268435456, 256 MiB)"},                                                  \
    {"correspondence", OPTION_CORRESPONDENCE, "NAME",                         \
     "index: vertex i of every input is vertex i (equal\n"                    \
     "counts; the default when the counts are equal);\n"                      \
     "arclength: normalised arc length between pins, each\n"                  \
     "input keeping its vertices and getting the others'\n"                   \
     "on its edges (the default with --pin); auto (the\n"                     \
     "default when the counts differ), with arclength's\n"                    \
     "output: conformal, the inputs' maps onto the disk\n"                    \
     "made to agree (where turns fit alike, as a disc's,\n"                   \
     "the one that puts holes on holes and turns least),\n"                   \
     "their crowding tempered (one hole: both loops at\n"                     \
     "once through the maps onto round annuli, the outer\n"                   \
     "loops' pairing too where that ends short of the\n"                      \
     "aim; more holes: the outer loops so, the holes\n"                       \
     "paired by position where that is one-to-one, each\n"                    \
     "from the start whose points lie nearest, carried\n"                     \
     "radially through the outer loops' pairing); with\n"                     \
     "--pin-corners, arc\n"                                                   \
     "length from the starts that align the inputs best\n"                   \
     "up to a similarity; similarity: that for all\n"                        \
     "inputs"},                                                               \
    {"pin", OPTION_PIN, "I,J[,K...]",                                         \
     "arclength: vertex I of the first input corresponds\n"                   \
     "to vertex J of the second, ... (0-based, in file\n"                     \
     "order; repeat for more pins; default: the first\n"                      \
     "vertices)"},                                                            \
    {"pin-corners", OPTION_PIN_CORNERS, "DEG",                                \
     "pin every vertex whose corner angle deviates from\n"                    \
     "180 degrees by more than DEG, in order; with\n"                          \
     "different corner counts each input keeps as many of\n"                  \
     "its most prominent corners as the input with the\n"                     \
     "fewest has, matched with the cyclic shift that puts\n"                  \
     "them closest in arc length (arclength, auto)"},          \
    {"max-edge", OPTION_MAX_EDGE, "L",                                       \
     "split the boundary edges compatibly (the same number\n"                 \
     "of points on corresponding edges, each input keeping\n"                 \
     "its vertices) until none is longer than L in any\n"                     \
     "input; default: off. arclength and auto, when they\n"                  \
     "remesh, also halve each edge too long for the aim\n"                    \
     "beside a close stretch of boundary (index never)"},                     \
    {"no-ceiling", OPTION_NO_CEILING, NULL,                                   \
     "skip the ceiling (the certified largest smallest\n"                    \
     "angle any compatible triangulation can have; a few\n"                  \
     "ms) and let the remesher aim at the target alone"},                     \
    {"time-limit", OPTION_TIME_LIMIT, "SECONDS",                              \
     "stop remeshing once the run has used this much CPU\n"                  \
     "time and keep the result reached (valid and\n"                         \
     "checked as always; report.json's time_limit_reached\n"                 \
     "says so); the stages before it always run whole, and\n"                \
     "the result depends on the machine's speed; default:\n"                 \
     "no limit"}

#define TRIANGULATION_PROGRESS_SPEC                                           \
    {"progress", OPTION_PROGRESS, NULL,                                       \
     "show the stage and how far it is on stderr from the\n"                 \
     "start, also when stderr is not a terminal (then as\n"                  \
     "plain lines: one per stage and per tenth done)"}

#define TRIANGULATION_QUIET_SPEC                                              \
    {"quiet", OPTION_QUIET, NULL,                                             \
     "no progress on stderr and nothing on stdout\n"                         \
     "(errors and warnings are still printed)"}

typedef struct triangulation_args {
    const char **inputs; /* argc entries allocated, input_count used */
    size_t input_count;
    const char *method_name;
    cm_options options; /* method and remeshing; the progress hook is set later */
    long max_input_bytes;
    int correspondence_given;   /* --correspondence was on the command line */
    size_t *pins;               /* pin_values numbers, k per pin once checked */
    size_t pin_values, pin_count;
    const char **pin_texts;     /* as given, for messages */
    int progress, quiet;        /* --progress, --quiet */
} triangulation_args;

/* The default of --max-input-bytes: far above any real section (a
 * 100,000-vertex polygon is 4 MB), far below what would exhaust memory. */
#define DEFAULT_MAX_INPUT_BYTES (256L << 20)

/* Defaults, and room for every argument of argv to be an input. Returns
 * CLI_EXIT_OK or CLI_EXIT_INTERNAL (out of memory). */
int triangulation_args_init(triangulation_args *args, int argc, cli_error *error);
void triangulation_args_free(triangulation_args *args);

/* Takes a positional argument (key 0) or a triangulation option. Returns
 * -1 if key is none of these (the caller handles it), else an exit code. */
int triangulation_option(triangulation_args *args, const char *command, int key,
                         const char *value, cli_error *error);

/* Checks there are at least two inputs and the options agree, then sets
 * the progress display (--progress, --quiet). */
int triangulation_args_check(const triangulation_args *args, const char *command,
                             cli_error *error);

/* The polygons as read and the core's result for them. */
typedef struct triangulation {
    const triangulation_args *args;
    cm_options options;      /* args' options, the correspondence decided */
    polygon_input *polygons; /* args->input_count */
    cm_result *result;
    double seconds_total;    /* the core's whole computation */
} triangulation;

/* Reads every input (same vertex counts) and triangulates them. Errors name
 * the file and line the core blames; the exit code says whose fault it was
 * (CLI_EXIT_USAGE for the input, CLI_EXIT_INTERNAL, CLI_EXIT_INTERRUPTED). */
int triangulation_run(triangulation *t, const triangulation_args *args, cli_error *error);
void triangulation_free(triangulation *t);

/* The error of a failed morph or sweep call: "COMMAND: message" (the
 * core's message, or the status's name if it left none), "interrupted;
 * nothing written" when cancelled. Returns the exit code for status. */
int core_failure(const char *command, const char *message, cm_status status,
                 cli_error *error);

/* CLI exit code for a core status. */
int exit_code_for(cm_status status);

/* "dir/a.xy" -> "a.xy" (borrowed). */
const char *file_name(const char *path);

/* "dir/a.xy" -> "a" in new memory (free it), NULL if out of memory; a
 * leading dot is part of the name (".a" -> ".a"). */
char *file_stem(const char *path);

#endif
