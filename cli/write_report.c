#include "write_report.h"

#include <jansson.h>
#include <math.h>
#include <stdlib.h>

#include "outdir.h"
#include "utf8_text.h"

/* A report is built as a jansson tree, then dumped. The setters below stop
 * at the first failure and remember it, so building needs no checks: a value
 * that is not finite (JSON has none) or out of memory fails the whole report,
 * which is then not written. */
typedef struct tree {
    const char *not_finite; /* the key of the first value that was not */
    int out_of_memory;
} tree;

static int failed(const tree *t) { return t->not_finite || t->out_of_memory; }

/* Takes value (a new reference), NULL meaning out of memory. */
static json_t *keep(tree *t, json_t *value)
{
    if (!value) t->out_of_memory = 1;
    return value;
}

static void set(tree *t, json_t *object, const char *key, json_t *value)
{
    if (!value || !object || failed(t)) {
        if (!value) t->out_of_memory = 1;
        json_decref(value);
        return;
    }
    if (json_object_set_new(object, key, value) != 0) t->out_of_memory = 1;
}

static void append(tree *t, json_t *array, json_t *value)
{
    if (!value || !array || failed(t)) {
        if (!value) t->out_of_memory = 1;
        json_decref(value);
        return;
    }
    if (json_array_append_new(array, value) != 0) t->out_of_memory = 1;
}

static json_t *real(tree *t, const char *key, double value)
{
    if (isfinite(value)) return keep(t, json_real(value));
    if (!t->not_finite) t->not_finite = key;
    return json_null(); /* a placeholder: the report is not written */
}

static void set_real(tree *t, json_t *object, const char *key, double value)
{
    set(t, object, key, real(t, key, value));
}

static void set_count(tree *t, json_t *object, const char *key, size_t value)
{
    set(t, object, key, keep(t, json_integer((json_int_t)value)));
}

static void set_bool(tree *t, json_t *object, const char *key, int value)
{
    set(t, object, key, json_boolean(value));
}

/* File names can hold any bytes: invalid UTF-8 becomes U+FFFD. */
static json_t *text(tree *t, const char *value)
{
    char *copy = utf8_repaired_copy(value, 0);
    json_t *string = copy ? json_string(copy) : NULL;
    free(copy);
    return keep(t, string);
}

static void set_text(tree *t, json_t *object, const char *key, const char *value)
{
    set(t, object, key, text(t, value));
}

static json_t *text_list(tree *t, const char *const *values, size_t count)
{
    json_t *list = keep(t, json_array());
    for (size_t i = 0; i < count; i++) append(t, list, text(t, values[i]));
    return list;
}

/* Writes the tree to path, or says why not. Doubles get 17 significant
 * digits, so every value reads back as the same double. */
static int dump(tree *t, json_t *root, const char *path, cli_error *error)
{
    int code = CLI_EXIT_INTERNAL;
    if (t->not_finite) {
        cli_error_set(error, "%s: %s is not a finite number", path, t->not_finite);
    } else if (t->out_of_memory || !root) {
        cli_error_set(error, "%s: out of memory", path);
    } else {
        FILE *file = output_open(path, error);
        if (file) {
            int written = json_dumpf(root, file, JSON_INDENT(2) | JSON_REAL_PRECISION(17)) == 0;
            fputc('\n', file);
            code = output_close(file, path, error);
            if (code == CLI_EXIT_OK && !written) {
                cli_error_set(error, "cannot write %s", path);
                code = CLI_EXIT_INTERNAL;
            }
        }
    }
    json_decref(root);
    return code;
}

/* The counts every report starts with. */
static json_t *head(tree *t, const cm_stats *stats)
{
    char version[64];
    snprintf(version, sizeof version, "%d.%d.%d", CM_VERSION_MAJOR, CM_VERSION_MINOR,
             CM_VERSION_PATCH);
    json_t *root = keep(t, json_object());
    set_text(t, root, "version", version);
    set_count(t, root, "n", stats->n);
    set_count(t, root, "k", stats->k);
    set_count(t, root, "vertices", stats->vertices);
    set_count(t, root, "steiner", stats->steiner);
    set_count(t, root, "triangles", stats->triangles);
    set_count(t, root, "holes", stats->holes);
    set_count(t, root, "bridges", stats->bridges);
    set_count(t, root, "holes_moved", stats->holes_moved);
    set_count(t, root, "pairings_built", stats->pairings_built);
    set_count(t, root, "pairings_remeshed", stats->pairings_remeshed);
    set_bool(t, root, "time_limit_reached", stats->time_limit_reached);
    return root;
}

static json_t *seconds(tree *t, const cm_stats *stats, double total)
{
    json_t *object = keep(t, json_object());
    set_real(t, object, "validate", stats->seconds_validate);
    set_real(t, object, "build", stats->seconds_build);
    set_real(t, object, "remesh", stats->seconds_remesh);
    set_real(t, object, "check", stats->seconds_check);
    set_real(t, object, "ceiling", stats->seconds_ceiling);
    set_real(t, object, "total", total);
    return object;
}

/* The certified caps on the smallest angle (null when not computed). */
static json_t *ceiling(tree *t, const cm_stats *stats, int computed)
{
    if (!computed) return json_null();
    json_t *object = keep(t, json_object());
    set_real(t, object, "ceiling_deg", stats->ceiling_deg);
    set_real(t, object, "corner_fan_cap_deg", stats->corner_fan_cap_deg);
    set_real(t, object, "correspondence_bound_deg", stats->correspondence_bound_deg);
    set_real(t, object, "modulus_distortion", stats->modulus_distortion);
    json_t *quad = keep(t, json_array());
    for (int i = 0; i < 4; i++) append(t, quad, keep(t, json_integer(stats->distortion_quad[i])));
    set(t, object, "distortion_quad", quad);
    if (stats->correspondence_bound_before_deg > 0)
        set_real(t, object, "correspondence_bound_before_deg",
                 stats->correspondence_bound_before_deg);
    return object;
}

/* The quality fields of one mesh, into object. A successful result has them
 * all; not having them is an internal failure, reported as out of memory
 * would be. */
static void set_quality(tree *t, json_t *object, cm_status status, cm_quality quality)
{
    if (status != CM_OK) {
        t->out_of_memory = 1;
        return;
    }
    set_real(t, object, "min_angle_deg", quality.min_angle_deg);
    set_real(t, object, "max_angle_deg", quality.max_angle_deg);
    set_real(t, object, "pct_triangles_below_10deg", quality.pct_below_10deg);
    set_real(t, object, "pct_triangles_below_15deg", quality.pct_below_15deg);
    set_real(t, object, "pct_triangles_below_20deg", quality.pct_below_20deg);
}

static json_t *mesh_entry(tree *t, const report_info *info, size_t g)
{
    cm_quality quality;
    json_t *entry = keep(t, json_object());
    set_text(t, entry, "input", info->inputs[g]);
    set_text(t, entry, "output", info->outputs[g]);
    set_quality(t, entry, cm_result_quality(info->result, g, &quality), quality);
    json_t *before = keep(t, json_object());
    set_quality(t, before, cm_result_quality_before(info->result, g, &quality), quality);
    set(t, entry, "before_remesh", before);
    if (info->correspondence != CM_CORRESPOND_INDEX || info->max_edge > 0) {
        /* Per boundary vertex: [e, t], the point at t of input edge e -> e + 1. */
        json_t *sources = keep(t, json_array());
        for (size_t i = 0; i < cm_result_stats(info->result)->n && !failed(t); i++) {
            double at;
            long e = cm_result_boundary_source(info->result, g, i, &at);
            json_t *pair = keep(t, json_array());
            append(t, pair, keep(t, json_integer(e)));
            append(t, pair, real(t, "boundary_source", at));
            append(t, sources, pair);
        }
        set(t, entry, "boundary_source", sources);
    }
    return entry;
}

int write_report(const char *path, const report_info *info, cli_error *error)
{
    static const char *const correspondence[] = {"index", "arclength", "auto", "similarity"};
    tree t = {0};
    const cm_stats *stats = cm_result_stats(info->result);
    json_t *root = head(&t, stats);
    set_bool(&t, root, "valid", 1);
    set_text(&t, root, "method", info->method);
    set_bool(&t, root, "remesh", info->remesh);
    set_text(&t, root, "correspondence", correspondence[info->correspondence]);
    set_text(&t, root, "correspondence_choice", cm_correspondence_choice_name(stats->correspondence_choice));
    if (info->max_edge > 0) set_real(&t, root, "max_edge", info->max_edge);
    if (info->time_limit > 0) set_real(&t, root, "time_limit", info->time_limit);
    set_bool(&t, root, "reversed_input", stats->reversed_input);
    set_count(&t, root, "fallback_count", stats->fallback_count);
    set_count(&t, root, "steiner_before_remesh", stats->steiner_before_remesh);
    set_count(&t, root, "remesh_iterations", stats->remesh_iterations);
    set_real(&t, root, "remesh_aim_deg", stats->remesh_aim_deg);
    set(&t, root, "ceiling", ceiling(&t, stats, info->ceiling));
    set(&t, root, "seconds", seconds(&t, stats, info->seconds_total));
    json_t *meshes = keep(&t, json_array());
    for (size_t g = 0; g < stats->k; g++) append(&t, meshes, mesh_entry(&t, info, g));
    set(&t, root, "meshes", meshes);
    return dump(&t, root, path, error);
}

int write_morph_report(const char *path, const morph_report_info *info, cli_error *error)
{
    tree t = {0};
    const cm_stats *stats = cm_result_stats(info->result);
    json_t *root = head(&t, stats);
    set_text(&t, root, "method", info->method);
    set_text(&t, root, "morph", info->morph);
    set(&t, root, "inputs", text_list(&t, info->inputs, stats->k));
    size_t total = 0;
    for (size_t f = 0; f < info->frame_count; f++) total += info->inverted[f];
    set_count(&t, root, "inverted_total", total);
    json_t *frames = keep(&t, json_array());
    for (size_t f = 0; f < info->frame_count; f++) {
        json_t *frame = keep(&t, json_object());
        set_text(&t, frame, "file", info->outputs[f]);
        set_real(&t, frame, "t", info->t[f]);
        set_real(&t, frame, "min_angle_deg", info->min_angle_deg[f]);
        set_count(&t, frame, "inverted", info->inverted[f]);
        append(&t, frames, frame);
    }
    set(&t, root, "frames", frames);
    return dump(&t, root, path, error);
}

int write_sweep_report(const char *path, const sweep_report_info *info, cli_error *error)
{
    tree t = {0};
    const cm_stats *stats = cm_result_stats(info->result);
    const cm_sweep *sweep = info->sweep;
    json_t *root = head(&t, stats);
    set_text(&t, root, "method", info->method);
    set(&t, root, "inputs", text_list(&t, info->inputs, stats->k));
    set_text(&t, root, "output", info->output);
    set_count(&t, root, "sections", cm_sweep_num_sections(sweep));
    set_count(&t, root, "nodes", cm_sweep_num_nodes(sweep));
    set_count(&t, root, "cells", info->tets ? cm_sweep_num_tets(sweep) : cm_sweep_num_prisms(sweep));
    set_text(&t, root, "cell_type", info->tets ? "tetrahedron" : "prism");
    set_count(&t, root, "cell_order", (size_t)info->order);
    set_real(&t, root, "volume", cm_sweep_volume(sweep));
    set_text(&t, root, "morph", cm_morph_method_name(cm_sweep_morph_method(sweep)));
    json_t *height = keep(&t, json_object());
    set_real(&t, height, "value", cm_sweep_height(sweep));
    set_text(&t, height, "rule", info->height_rule);
    set(&t, root, "height", height);
    cm_sweep_quality q;
    cm_sweep_get_quality(sweep, &q);
    json_t *quality = keep(&t, json_object());
    set_real(&t, quality, "min_dihedral_deg", q.min_dihedral_deg);
    set_real(&t, quality, "max_dihedral_deg", q.max_dihedral_deg);
    set_real(&t, quality, "min_scaled_jacobian", q.min_scaled_jacobian);
    set_real(&t, quality, "max_aspect_ratio", q.max_aspect_ratio);
    set_text(&t, quality, "aspect_ratio_measure",
             info->tets ? "longest edge / (2 sqrt(6) inradius), 1 for the regular tetrahedron"
                        : "longest edge / shortest edge");
    set_real(&t, quality, "max_prism_flatness", q.max_flatness);
    set_real(&t, quality, "flat_ratio", CM_SWEEP_FLAT_RATIO);
    set_count(&t, quality, "flat_prisms", q.flat_prisms);
    set(&t, root, "quality", quality);
    /* The boundary's groups, as the .msh file's surfaces and the .inp
     * file's node sets name them, with their face counts. */
    json_t *boundary = keep(&t, json_object());
    const size_t *offsets = cm_sweep_boundary_group_offsets(sweep, info->tets);
    for (size_t g = 0; g < cm_sweep_num_boundary_groups(sweep); g++)
        set_count(&t, boundary, cm_sweep_boundary_group_name(sweep, g), offsets ? offsets[g + 1] - offsets[g] : 0);
    set(&t, root, "boundary_faces", boundary);
    set(&t, root, "warnings", info->warning ? text_list(&t, &info->warning, 1) : keep(&t, json_array()));
    return dump(&t, root, path, error);
}

/* "ok", "bad_input" or "internal_failure" for a job's exit code. */
static const char *batch_job_status(int exit_code)
{
    return exit_code == CLI_EXIT_OK ? "ok" : exit_code == CLI_EXIT_USAGE ? "bad_input"
                                                                      : "internal_failure";
}

static json_t *batch_job_entry(tree *t, const batch_job_report *job)
{
    int ok = job->exit_code == CLI_EXIT_OK;
    json_t *entry = keep(t, json_object());
    set(t, entry, "line", keep(t, json_integer(job->line)));
    set_text(t, entry, "name", job->name);
    set_text(t, entry, "out_dir", job->out_dir);
    set(t, entry, "inputs", text_list(t, job->inputs, job->input_count));
    set_text(t, entry, "status", batch_job_status(job->exit_code));
    set(t, entry, "exit_code", keep(t, json_integer(job->exit_code)));
    set(t, entry, "message", ok ? json_null() : text(t, job->message));
    set(t, entry, "steiner", ok ? keep(t, json_integer((json_int_t)job->steiner)) : json_null());
    json_t *angles = ok ? keep(t, json_array()) : json_null();
    for (size_t g = 0; ok && g < job->input_count; g++)
        append(t, angles, real(t, "min_angle_deg", job->min_angle_deg[g]));
    set(t, entry, "min_angle_deg", angles);
    set_real(t, entry, "cpu_seconds", job->cpu_seconds);
    return entry;
}

int write_batch_report(const char *path, const batch_report_info *info, cli_error *error)
{
    char version[64];
    snprintf(version, sizeof version, "%d.%d.%d", CM_VERSION_MAJOR, CM_VERSION_MINOR,
             CM_VERSION_PATCH);
    tree t = {0};
    json_t *root = keep(&t, json_object());
    set_text(&t, root, "version", version);
    set_text(&t, root, "list", info->list);
    set_text(&t, root, "out_dir", info->out_dir);
    set(&t, root, "workers", keep(&t, json_integer(info->workers)));
    size_t counts[3] = {0, 0, 0}; /* ok, bad input, internal failure */
    double cpu = 0;
    json_t *jobs = keep(&t, json_array());
    for (size_t i = 0; i < info->job_count; i++) {
        int code = info->jobs[i].exit_code;
        counts[code == CLI_EXIT_OK ? 0 : code == CLI_EXIT_USAGE ? 1 : 2]++;
        cpu += info->jobs[i].cpu_seconds;
        append(&t, jobs, batch_job_entry(&t, &info->jobs[i]));
    }
    set_count(&t, root, "jobs_total", info->job_count);
    set_count(&t, root, "ok", counts[0]);
    set_count(&t, root, "bad_input", counts[1]);
    set_count(&t, root, "internal_failure", counts[2]);
    set(&t, root, "exit_code", keep(&t, json_integer(info->exit_code)));
    set_real(&t, root, "cpu_seconds", cpu);
    set_real(&t, root, "wall_seconds", info->wall_seconds);
    set(&t, root, "jobs", jobs);
    return dump(&t, root, path, error);
}
