/* report.json: what was computed, how long it took and how good it is. */
#ifndef CM_CLI_WRITE_REPORT_H
#define CM_CLI_WRITE_REPORT_H

#include <stddef.h>

#include <compatmesh/compatmesh.h>

#include "cli_common.h"

typedef struct report_info {
    const cm_result *result;   /* a successful result */
    const char *method;        /* e.g. "overlay" */
    int remesh;                /* 1 if the result was remeshed */
    cm_correspondence correspondence;
    double max_edge;           /* > 0: boundary edges split to this length */
    double time_limit;         /* > 0: the remesher's CPU time limit (s) */
    double seconds_total;      /* wall time of the whole computation */
    const char *const *inputs; /* k input paths, as given */
    const char *const *outputs;/* k mesh paths, as they are after commit */
    int ceiling;               /* 1 if the core computed the ceiling */
} report_info;

/* Writes the report as one JSON object (see the "report.json" section of
 * `compatmesh triangulate --help`). Returns CLI_EXIT_OK or, with error set,
 * CLI_EXIT_INTERNAL. */
int write_report(const char *path, const report_info *info, cli_error *error);

/* The morph's report.json: the triangulation's counts, then per frame its
 * file, time t, smallest angle and number of inverted triangles. */
typedef struct morph_report_info {
    const cm_result *result;
    const char *method;         /* triangulation method */
    const char *morph;          /* "convex" or "linear" */
    const char *const *inputs;  /* k input paths */
    size_t frame_count;
    const char *const *outputs; /* frame paths, as they are after commit */
    const double *t;
    const double *min_angle_deg;
    const size_t *inverted;
} morph_report_info;

int write_morph_report(const char *path, const morph_report_info *info, cli_error *error);

/* The sweep's report: the triangulation's counts, the volume mesh's counts,
 * its height and why, the shape of its cells and the warnings printed. */
typedef struct sweep_report_info {
    const cm_result *result;
    const cm_sweep *sweep;
    const char *method;         /* triangulation method */
    const char *const *inputs;  /* k input paths */
    const char *output;         /* the volume mesh file */
    int tets;
    int order;                  /* the cells' order in the file, 1 or 2 */
    const char *height_rule;    /* why this height, in words */
    const char *warning;        /* NULL, or the warning printed */
} sweep_report_info;

int write_sweep_report(const char *path, const sweep_report_info *info, cli_error *error);

/* One job of a batch, as it ended. */
typedef struct batch_job_report {
    long line;                   /* in the list */
    const char *name;            /* its folder */
    const char *out_dir;         /* the output directory it was given */
    const char *const *inputs;
    size_t input_count;
    int exit_code;               /* as `triangulate` would have exited */
    const char *message;         /* the one-line error; "" on success */
    size_t steiner;              /* on success */
    const double *min_angle_deg; /* input_count entries, on success */
    double cpu_seconds;          /* user + system time of its process */
} batch_job_report;

/* The batch's batch.json: the list, the workers, the counts by status and
 * every job in list order. */
typedef struct batch_report_info {
    const char *list;
    const char *out_dir;
    long workers;
    int exit_code;
    double wall_seconds;
    const batch_job_report *jobs;
    size_t job_count;
} batch_report_info;

int write_batch_report(const char *path, const batch_report_info *info, cli_error *error);

#endif
