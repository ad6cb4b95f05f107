/* One triangulate run: the inputs and options of `compatmesh triangulate`
 * turned into meshes, report.json and pictures in an output directory that
 * appears all at once or not at all. `triangulate` runs one; `batch` runs
 * one per line of its list. */
#ifndef CM_CLI_TRIANGULATE_JOB_H
#define CM_CLI_TRIANGULATE_JOB_H

#include <stddef.h>

#include "cli_common.h"
#include "triangulation.h"
#include "write_mesh.h"

typedef struct triangulate_job {
    triangulation_args tri; /* inputs, method, remesh */
    const char *out_dir;
    mesh_format format;
    int no_preview; /* no preview.svg / preview.png (and an old one removed) */
} triangulate_job;

/* The --format and --no-preview entries of a command's option table
 * (keys 'f' and OPTION_NO_PREVIEW). */
enum { OPTION_NO_PREVIEW = OPTION_TRIANGULATION_END };
#define TRIANGULATE_FORMAT_SPEC \
    {"format", 'f', "FMT", "mesh file format: off (default), obj or ply (ASCII)"}
#define TRIANGULATE_PREVIEW_SPEC                                        \
    {"no-preview", OPTION_NO_PREVIEW, NULL,                             \
     "write no preview.svg / preview.png (an old one in the\n"          \
     "folder is removed); on a small pair the pictures are\n"           \
     "about a tenth of the time"}

/* Defaults, and room for every argument of argv to be an input. */
int triangulate_job_init(triangulate_job *job, int argc, cli_error *error);

/* Takes a positional argument (key 0), a triangulation option, --format or
 * --no-preview.
 * Returns -1 if key is none of these (the caller handles it), else an exit
 * code. */
int triangulate_job_option(triangulate_job *job, const char *command, int key,
                           const char *value, cli_error *error);

/* What a successful run measured, for a caller that summarises runs. */
typedef struct triangulate_outcome {
    size_t steiner;
    double *min_angle_deg; /* the caller's array of tri.input_count entries */
} triangulate_outcome;

/* Reads the inputs, triangulates them and writes the outputs into out_dir
 * (printing what was written unless --quiet). On success fills *outcome if
 * it is not NULL. Returns the exit code; on failure error says why and
 * out_dir is as it was. */
int triangulate_job_run(const triangulate_job *job, triangulate_outcome *outcome,
                        cli_error *error);

#endif
