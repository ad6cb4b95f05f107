#include "triangulate_job.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <compatmesh/compatmesh.h>

#include "outdir.h"
#include "picture.h"
#include "progress_line.h"
#include "write_picture.h"
#include "write_report.h"

int triangulate_job_init(triangulate_job *job, int argc, cli_error *error)
{
    memset(job, 0, sizeof *job);
    job->format = MESH_FORMAT_OFF;
    return triangulation_args_init(&job->tri, argc, error);
}

int triangulate_job_option(triangulate_job *job, const char *command, int key,
                           const char *value, cli_error *error)
{
    int code = triangulation_option(&job->tri, command, key, value, error);
    if (code >= 0) return code;
    if (key == OPTION_NO_PREVIEW) {
        job->no_preview = 1;
        return CLI_EXIT_OK;
    }
    if (key != 'f') return code;
    if (mesh_format_from_name(value, &job->format) == 0) return CLI_EXIT_OK;
    cli_error_set(error, "%s: unknown --format '%s' (known: off, obj, ply)", command, value);
    return CLI_EXIT_USAGE;
}

/* Everything one triangulate run owns, released by triangulate_run_free. */
typedef struct triangulate_run {
    const triangulate_job *args;
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

/* Each input names its output after its stem, so stems must differ. */
static int make_output_names(triangulate_run *run, cli_error *error)
{
    const triangulate_job *args = run->args;
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

#define PREVIEW_SVG "preview.svg"
#define PREVIEW_PNG "preview.png"
static const char *const preview_names[] = {PREVIEW_SVG, PREVIEW_PNG};

/* Before any work: no output may replace an input (commit checks again). */
static int refuse_inputs_early(triangulate_run *run, cli_error *error)
{
    const triangulation_args *tri = &run->args->tri;
    size_t k = tri->input_count;
    int code = CLI_EXIT_OK;
    static const char *const extras[] = {"report.json", PREVIEW_SVG, PREVIEW_PNG};
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
            code = write_mesh(path, run->tri.result, g, &run->tri.polygons[g], run->args->format, error);
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
                        run->tri.options.time_limit, run->tri.seconds_total, run->args->tri.inputs,
                        (const char *const *)run->final_paths, run->args->tri.options.ceiling};
    int code = stage_file(run, "report.json", &path, error);
    if (code == CLI_EXIT_OK) code = write_report(path, &info, error);
    if (code != CLI_EXIT_OK) return code;
    if (run->args->no_preview) {
        staged_output_remove(&run->output, preview_names, 2);
        return CLI_EXIT_OK;
    }
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
    const char *svg = NULL;
    code = stage_file(run, PREVIEW_SVG, &svg, error);
    if (code == CLI_EXIT_OK) code = stage_file(run, PREVIEW_PNG, &path, error);
    if (code == CLI_EXIT_OK) code = write_pictures(svg, path, &pic, error);
    picture_free(&pic);
    return code;
}

static int write_outputs(triangulate_run *run, cli_error *error)
{
    int code = staged_output_begin(&run->output, run->args->out_dir, run->args->tri.inputs,
                                   run->args->tri.input_count, error);
    if (code == CLI_EXIT_OK) code = write_meshes(run, error);
    if (code == CLI_EXIT_OK) code = write_extras(run, error);
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
    if (run->args->no_preview)
        printf("wrote %s/report.json\n", run->output.target);
    else
        printf("wrote %s/report.json, %s/" PREVIEW_SVG " and %s/" PREVIEW_PNG "\n", run->output.target,
               run->output.target, run->output.target);
    if (stats->holes_moved)
        printf("holes paired by position: %zu listed at another place than the first input's "
               "(report.json's boundary_source names each one's input loop)\n", stats->holes_moved);
    const cm_options *o = &run->args->tri.options;
    if (o->ceiling && stats->ceiling_deg < o->min_angle_deg)
        printf("no compatible triangulation of %s can have a smallest angle above %.1f degrees "
               "(target %g)\n", stats->k == 2 ? "this pair" : "these polygons", stats->ceiling_deg,
               o->min_angle_deg);
}

/* What the caller summarises; a successful result has every quality. */
static void fill_outcome(const triangulate_run *run, triangulate_outcome *outcome)
{
    outcome->steiner = cm_result_stats(run->tri.result)->steiner;
    for (size_t g = 0; g < run->args->tri.input_count; g++) {
        cm_quality quality;
        if (cm_result_quality(run->tri.result, g, &quality) != CM_OK) quality.min_angle_deg = 0;
        outcome->min_angle_deg[g] = quality.min_angle_deg;
    }
}

int triangulate_job_run(const triangulate_job *job, triangulate_outcome *outcome,
                        cli_error *error)
{
    size_t k = job->tri.input_count;
    triangulate_run run = {0};
    run.args = job;
    run.stems = calloc(k, sizeof *run.stems);
    run.mesh_names = calloc(k, sizeof *run.mesh_names);
    run.final_paths = calloc(k, sizeof *run.final_paths);
    int code = CLI_EXIT_OK;
    if (!run.stems || !run.mesh_names || !run.final_paths) {
        cli_error_set(error, "out of memory");
        code = CLI_EXIT_INTERNAL;
    }
    if (code == CLI_EXIT_OK) code = make_output_names(&run, error);
    if (code == CLI_EXIT_OK) code = staged_output_check(job->out_dir, error);
    if (code == CLI_EXIT_OK) code = refuse_inputs_early(&run, error);
    if (code == CLI_EXIT_OK) code = triangulation_run(&run.tri, &job->tri, error);
    if (code == CLI_EXIT_OK) code = write_outputs(&run, error);
    if (code == CLI_EXIT_OK && !cli_quiet()) print_summary(&run);
    if (code == CLI_EXIT_OK && outcome) fill_outcome(&run, outcome);
    triangulate_run_free(&run);
    return code;
}
