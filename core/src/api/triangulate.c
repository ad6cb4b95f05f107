/* The public entry points: validate, build, check, measure. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/capsplit.h"
#include "api/halfedge.h"
#include "api/input.h"
#include "api/quality.h"
#include "api/result.h"
#include "base/clock.h"
#include "base/deadline.h"
#include "base/progress.h"
#include "geom/angle.h"
#include "construct/holes.h"
#include "construct/holes_overlay.h"
#include "construct/overlay.h"
#include "correspond/annulus.h"
#include "correspond/bound.h"
#include "correspond/choose.h"
#include "correspond/conformal.h"
#include "correspond/corners.h"
#include "correspond/split.h"
#include "construct/partition.h"
#include "geom/polytri.h"
#include "remesh/remesh.h"

void cm_options_init(cm_options *options)
{
    memset(options, 0, sizeof *options);
    options->method = CM_METHOD_PARTITION;
    options->remesh = 1;
    options->min_angle_deg = 25.0;
    options->max_steiner = -1;
    options->k_split = 0;
    options->area_every = 0;
    options->smoothing = CM_SMOOTH_COMBINED;
    options->max_iterations = 0;
    options->restarts = 1;
    options->ceiling = 1;
    options->remesher = CM_REMESHER_GREEDY;
}

/* The remeshing options; a message on r when one is out of range. */
static cm_status check_remesh_options(cm_result *r, const cm_options *o)
{
    if (!(o->min_angle_deg > 0 && o->min_angle_deg < 60))
        return cm_fail(&r->error, CM_ERR_ARGUMENT, "min_angle_deg must be in (0, 60), got %g", o->min_angle_deg);
    if (o->max_steiner < -1)
        return cm_fail(&r->error, CM_ERR_ARGUMENT, "max_steiner must be >= -1, got %ld", o->max_steiner);
    if (o->k_split < 0)
        return cm_fail(&r->error, CM_ERR_ARGUMENT, "k_split must be >= 0, got %d", o->k_split);
    if (o->area_every < 0)
        return cm_fail(&r->error, CM_ERR_ARGUMENT, "area_every must be >= 0, got %d", o->area_every);
    if (o->max_iterations < 0)
        return cm_fail(&r->error, CM_ERR_ARGUMENT, "max_iterations must be >= 0, got %d", o->max_iterations);
    if (o->restarts < 0)
        return cm_fail(&r->error, CM_ERR_ARGUMENT, "restarts must be >= 0, got %d", o->restarts);
    if (!(o->time_limit >= 0 && o->time_limit < HUGE_VAL))
        return cm_fail(&r->error, CM_ERR_ARGUMENT, "time_limit must be >= 0 seconds, got %g", o->time_limit);
    if ((unsigned)o->remesher > (unsigned)CM_REMESHER_MAP)
        return cm_fail(&r->error, CM_ERR_ARGUMENT, "unknown remesher %d", (int)o->remesher);
    if ((unsigned)o->smoothing > (unsigned)CM_SMOOTH_COMBINED)
        return cm_fail(&r->error, CM_ERR_ARGUMENT, "unknown smoothing %d", (int)o->smoothing);
    return CM_OK;
}

/* Internal order is counter-clockwise: for clockwise input, internal vertex
 * j is input vertex (n - j) % n (vertex 0 stays first). */
static int32_t input_index(int32_t j, size_t n, int clockwise)
{
    return clockwise && j > 0 && (size_t)j < n ? (int32_t)(n - (size_t)j) : j;
}

/* Each polygon geoms[g] triangulated into tris[g]: copied from given[g]
 * (NULL: none), else its constrained Delaunay triangulation if delaunay,
 * else by ear clipping alone. */
static cm_status triangulate_each(cm_result *r, const double *const *geoms, size_t k, size_t n,
                                  const int32_t *const *given, int delaunay, cm_progress *progress,
                                  int32_t *const *tris)
{
    int32_t *idx = malloc(n * sizeof *idx);
    if (!idx) return cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    for (size_t i = 0; i < n; i++) idx[i] = (int32_t)i;
    cm_status s = CM_OK;
    for (size_t g = 0; s == CM_OK && g < k; g++) {
        int t = 0;
        if (given)
            memcpy(tris[g], given[g], 3 * (n - 2) * sizeof *tris[g]);
        else if (delaunay)
            t = cm_polygon_triangulate(geoms[g], idx, (long)n, tris[g], progress);
        else
            t = cm_polygon_ear_clip(geoms[g], idx, (long)n, tris[g], progress);
        if (t == CM_CANCELLED) s = cm_fail_status(&r->error, CM_ERR_CANCELLED);
        else if (t < 0) s = cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
        else if (t > 0) s = cm_fail(&r->error, CM_ERR_INTERNAL, "polygon %zu: ear clipping found no ear", g);
        else if (cm_progress_report(progress, CM_STAGE_TRIANGULATE, (double)(g + 1) / (double)k))
            s = cm_fail_status(&r->error, CM_ERR_CANCELLED);
    }
    free(idx);
    return s;
}

/* The first compatible triangulation, by the chosen method. tris: each
 * polygon's triangulation, the Delaunay one if delaunay (the overlay's
 * input), else any (the partition only walks them); a partition that
 * falls back to the overlay then makes the Delaunay ones in their place. */
static cm_status construct(cm_result *r, const double *const *geoms, int32_t *const *tris, int delaunay,
                           size_t k, size_t n, const cm_on_edges *on, const cm_options *o, cm_progress *progress)
{
    const int32_t *const *given = (const int32_t *const *)tris;
    if (o->method == CM_METHOD_OVERLAY) {
        size_t centroids = 0;
        return cm_overlay(geoms, given, k, n, &r->mesh, &centroids, &r->error);
    }
    cm_partition_stats ps;
    cm_status s = on ? cm_partition_on_edges(geoms, given, k, n, on, progress, &r->mesh, &ps, &r->error)
                     : cm_partition(geoms, given, k, n, progress, &r->mesh, &ps, &r->error);
    r->stats.fallback_count = ps.fallback_count;
    if (s != CM_ERR_INTERNAL && s != CM_ERR_PRECISION) return s;
    /* A piece the overlay could not place in doubles (a sliver thinner
     * than their spacing): the whole input has room where the piece had
     * none, so the guaranteed construction runs on all of it. */
    cm_mesh_clear(&r->mesh);
    cm_error_init(&r->error);
    if (!delaunay && (s = triangulate_each(r, geoms, k, n, NULL, 1, progress, tris)) != CM_OK) return s;
    size_t centroids = 0;
    r->stats.fallback_count++;
    return cm_overlay(geoms, given, k, n, &r->mesh, &centroids, &r->error);
}

/* The ceiling of the k polygons geoms (n vertices each, counter-clockwise;
 * tris: NULL or their triangulations) into r's stats; the quadruple in
 * input numbering. */
static cm_status take_ceiling(cm_result *r, const double *const *geoms, const int32_t *const *tris, size_t k,
                              size_t n, int clockwise, cm_progress *progress)
{
    double t = cm_seconds_now();
    cm_bound b;
    cm_status s = cm_bound_compute_memo(r->bounds, geoms, tris, k, n, progress, &b, &r->error);
    if (s != CM_OK) return s;
    r->stats.corner_fan_cap_deg = b.corner_fan_deg;
    r->stats.correspondence_bound_deg = b.correspondence_deg;
    r->stats.ceiling_deg = fmin(b.corner_fan_deg, b.correspondence_deg);
    r->stats.modulus_distortion = b.distortion;
    for (int i = 0; i < 4; i++)
        r->stats.distortion_quad[i] = b.quad[i] < 0 ? -1 : input_index((int32_t)b.quad[i], n, clockwise);
    r->stats.seconds_ceiling += cm_seconds_now() - t;
    return CM_OK;
}

/* on: where the boundary vertices lie on the inputs (NULL: all input
 * vertices, the index correspondence and the pieces of polygons with
 * holes). given: NULL, or each polygon's cm_polygon_triangulate already
 * made. */
static cm_status build_first(cm_result *r, const double *const *polygons, const int32_t *const *given, size_t k,
                             size_t n, int clockwise, const cm_on_edges *on, const cm_options *o, cm_progress *progress)
{
    cm_status s = CM_ERR_NO_MEMORY;
    double **geoms = calloc(k, sizeof *geoms);
    int32_t **tris = calloc(k, sizeof *tris);
    /* the partition only walks the triangulations (visibility, the same
     * whatever the triangulation): ear clipping alone serves it unless the
     * ceiling or the overlay takes them */
    int delaunay = (given && !clockwise) || o->ceiling || o->method == CM_METHOD_OVERLAY;
    if (!geoms || !tris) goto done;
    for (size_t g = 0; g < k; g++) {
        geoms[g] = malloc(2 * n * sizeof *geoms[g]);
        tris[g] = malloc(3 * (n - 2) * sizeof *tris[g]);
        if (!geoms[g] || !tris[g]) goto done;
        for (size_t j = 0; j < n; j++) {
            size_t i = (size_t)input_index((int32_t)j, n, clockwise);
            geoms[g][2 * j] = polygons[g][2 * i];
            geoms[g][2 * j + 1] = polygons[g][2 * i + 1];
        }
    }
    /* given: made on these very polygons */
    s = triangulate_each(r, (const double *const *)geoms, k, n, given && !clockwise ? given : NULL, delaunay,
                         progress, tris);
    if (s != CM_OK) goto done;
    if (o->ceiling) {
        s = take_ceiling(r, (const double *const *)geoms, (const int32_t *const *)tris, k, n, clockwise, progress);
        if (s != CM_OK) goto done;
    }
    s = construct(r, (const double *const *)geoms, tris, delaunay, k, n, on, o, progress);
done:
    if (geoms)
        for (size_t g = 0; g < k; g++) free(geoms[g]);
    if (tris)
        for (size_t g = 0; g < k; g++) free(tris[g]);
    free(geoms), free(tris);
    return s;
}

/* A result within this share of a certified cap has reached it: the cap
 * is rounded up by 1e-9 (cm_corner_fan_cap), and a corner bisected to the
 * last bit ends 1e-15 to 1e-11 below its half. Results 1e-7 below it are
 * not there yet: another pairing may still reach it to the last digits. */
#define CM_CAP_REACHED 3e-9

/* Records the construction's quality, then runs Algorithm 1 on r->mesh
 * (internal counter-clockwise order) when asked; splits: NULL, or the
 * boundary splits it may make (cm_remesh_boundary). */
static cm_status remesh_stage(cm_result *r, size_t n, const cm_options *o, cm_remesh_boundary *splits,
                              cm_progress *progress)
{
    size_t k = r->mesh.k;
    r->quality_before = calloc(k, sizeof *r->quality_before);
    if (!r->quality_before) return cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    for (size_t g = 0; g < k; g++) cm_mesh_quality(&r->mesh, g, &r->quality_before[g]);
    r->stats.steiner_before_remesh = r->mesh.nv - n;
    r->stats.pairings_built = 1;
    if (!o->remesh) return CM_OK;
    /* A rescue that cannot beat the result it competes with is not
     * remeshed, and stays unkept: the corner-fan cap certifies its
     * pairing's whole reach (the boundary points the remesher adds or
     * slides stay inside input edges, where the corner is straight). */
    if (r->beat_deg > 0 && o->ceiling && r->stats.corner_fan_cap_deg <= r->beat_deg * (1 + CM_CAP_REACHED)) {
        r->greedy_angle_deg = r->polished_angle_deg = -1;
        return CM_OK;
    }
    if (cm_progress_report(progress, CM_STAGE_REMESH, 0.0)) return cm_fail_status(&r->error, CM_ERR_CANCELLED);
    double t = cm_seconds_now();
    cm_remesh_report report = {0};
    r->stats.pairings_remeshed = 1;
    /* Nothing above the ceiling can be reached: aim no higher. */
    cm_status s = cm_remesh(&r->mesh, n, o, o->ceiling ? r->stats.ceiling_deg : 60.0, r->beat_deg, splits, r->resume,
                            progress, &report, &r->error);
    r->stats.seconds_remesh = cm_seconds_now() - t;
    r->stats.remesh_iterations = report.iterations;
    r->stats.remesh_aim_deg = report.target_deg;
    r->greedy_angle_deg = report.min_angle_deg;
    r->polished_angle_deg = report.polished_deg, r->restart_wanted = report.restart_wanted;
    return s;
}

/* Renumbers the polygon vertices back into input order (clockwise input). */
static void restore_input_order(cm_mesh *m, size_t n)
{
    for (size_t g = 0; g < m->k; g++) {
        double *xy = m->xy[g];
        for (size_t j = 1; j < n - j; j++) {
            size_t i = n - j;
            double x = xy[2 * j], y = xy[2 * j + 1];
            xy[2 * j] = xy[2 * i], xy[2 * j + 1] = xy[2 * i + 1];
            xy[2 * i] = x, xy[2 * i + 1] = y;
        }
    }
    for (size_t t = 0; t < 3 * m->nt; t++) m->tri[t] = input_index(m->tri[t], n, 1);
}

/* The constructions compute points in floating point: on input spanning
 * magnitudes beyond about 1e+-150, their products overflow or underflow and
 * the exact check rejects the result. Say so in an internal failure's
 * message, so that the user knows to rescale. */
static cm_status hint_at_range(cm_result *r, cm_status s, const double *const *polygons,
                               size_t k, size_t n)
{
    if (s != CM_ERR_INTERNAL) return s;
    double lo = INFINITY, hi = 0;
    for (size_t g = 0; g < k; g++)
        for (size_t i = 0; i < 2 * n; i++) {
            double a = fabs(polygons[g][i]);
            if (a > 0 && a < lo) lo = a;
            if (a > hi) hi = a;
        }
    if (hi > 1e150 || lo < 1e-150) {
        char *msg = r->error.message;
        size_t used = strlen(msg);
        snprintf(msg + used, sizeof r->error.message - used,
                 " (the coordinates span magnitudes %.0e to %.0e; scale the input nearer to 1)",
                 lo, hi);
    }
    return s;
}

/* Where r->boundary's vertices lie on the inputs (the partition's rule on
 * input edges): its loop l, boundary vertices at[l] .. at[l + 1] - 1,
 * keeps input loop l's vertices (those with t == 0), so the input loops'
 * starts are counts of those. on->loop_start is one block to free. */
static cm_status on_edges_init(cm_result *r, const size_t *at, size_t num_loops, cm_on_edges *on)
{
    const cm_boundary_map *b = &r->boundary;
    size_t k = b->k, **loop_start = malloc(k * sizeof *loop_start + k * (num_loops + 1) * sizeof **loop_start);
    if (!loop_start) return cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    for (size_t g = 0; g < k; g++) {
        size_t *ls = loop_start[g] = (size_t *)(loop_start + k) + g * (num_loops + 1);
        ls[0] = 0;
        for (size_t l = 0; l < num_loops; l++) {
            ls[l + 1] = ls[l];
            for (size_t i = at[l]; i < at[l + 1]; i++) ls[l + 1] += b->t[g][i] == 0;
        }
    }
    *on = (cm_on_edges){(const int32_t *const *)b->edge, (const double *const *)b->t,
                        (const size_t *const *)loop_start, num_loops, NULL};
    return CM_OK;
}

/* The input polygons r->boundary's labels refer to (as given to
 * cm_correspond_arclength), for the points the remesher adds on the
 * common boundary's edges. */
typedef struct edge_inputs {
    const double *const *polygons;
    const size_t *counts;
    const int *orientation;
} edge_inputs;

/* The middle of a piece's parameters t0 (its end at a) and t1 (at b) on
 * its input edge, nudged by ulps for step > 0 (cm_kmesh_between's
 * steps). 0 when that is not strictly between them, else 1. */
static int piece_middle(double t0, double t1, int step, double *t)
{
    double mid = 0.5 * (t0 + t1), towards = step % 2 ? t0 : t1;
    for (int i = 0; i < (step + 1) / 2; i++) mid = nextafter(mid, towards);
    if (!(fmin(t0, t1) < mid && mid < fmax(t0, t1))) return 0;
    *t = mid;
    return 1;
}

/* cm_kmesh_between on r->boundary's labels: the middle parameter of the
 * input edge the piece lies on. */
static int edge_between(void *ctx, size_t g, int32_t ea, double ta, int32_t eb, double tb, int step, int32_t *e,
                        double *t, double xy[2])
{
    const edge_inputs *in = ctx;
    double t0, t1;
    cm_boundary_piece(ea, ta, eb, tb, in->counts[g], in->orientation[g] < 0, e, &t0, &t1);
    if (!piece_middle(t0, t1, step, t)) return 0;
    cm_edge_point(in->polygons[g], in->counts[g], *e, *t, xy);
    return 1;
}

/* cm_remesh_boundary's place on r->boundary's labels. */
static void edge_place(void *ctx, size_t g, int32_t e, double t, double xy[2])
{
    const edge_inputs *in = ctx;
    cm_edge_point(in->polygons[g], in->counts[g], e, t, xy);
}

/* CM_CORRESPOND_AUTO and _SIMILARITY: the correspondence is chosen. */
static int chosen_mode(const cm_options *o)
{
    return o->correspondence == CM_CORRESPOND_AUTO || o->correspondence == CM_CORRESPOND_SIMILARITY;
}

/* After boundary splits: r->boundary and the counts become the remeshed
 * boundary's, the mesh's first n vertices. 0 or -1 out of memory. */
static int take_split_boundary(cm_result *r, size_t n)
{
    cm_boundary_map *b = &r->boundary;
    for (size_t g = 0; g < b->k; g++) {
        double *xy = realloc(b->xy[g], 2 * n * sizeof *xy);
        if (!xy) return -1;
        memcpy(xy, r->mesh.xy[g], 2 * n * sizeof *xy);
        b->xy[g] = xy;
    }
    b->n = r->n = r->stats.n = n;
    return 0;
}

/* tris: NULL, or the polygons' triangulations (cm_polygon_triangulate's)
 * when already made. edges: NULL, or the inputs of r->boundary when the
 * remesher may split its edges. */
static cm_status run_pipeline(cm_result *r, const double *const *polygons, const size_t *counts,
                              size_t k, const int32_t *const *tris, const edge_inputs *edges, const cm_options *o)
{
    cm_progress progress;
    cm_progress_init(&progress, o->progress, o->progress_user);
    double t0 = cm_seconds_now();
    if (cm_progress_report(&progress, CM_STAGE_VALIDATE, 0.0)) return cm_fail_status(&r->error, CM_ERR_CANCELLED);
    int clockwise = 0;
    cm_status s = cm_input_validate(polygons, counts, k, &r->error, &clockwise);
    if (s != CM_OK) return s;
    size_t n = counts[0];
    r->n = n;
    r->stats.n = n, r->stats.k = k, r->stats.reversed_input = clockwise;
    double t1 = cm_seconds_now();
    r->stats.seconds_validate = t1 - t0;
    if (cm_progress_report(&progress, CM_STAGE_TRIANGULATE, 0.0)) return cm_fail_status(&r->error, CM_ERR_CANCELLED);

    double ceiling_before = r->stats.seconds_ceiling;
    cm_on_edges on_edges, *on = NULL;
    if (r->boundary.n == n && r->boundary.k == k && !clockwise) { /* the arc-length path's boundaries */
        size_t whole[2] = {0, n};
        if ((s = on_edges_init(r, whole, 1, &on_edges)) != CM_OK) return s;
        on = &on_edges;
    }
    s = build_first(r, polygons, tris, k, n, clockwise, on, o, &progress);
    if (on) free((void *)on->loop_start);
    if (s != CM_OK) return hint_at_range(r, s, polygons, k, n);
    r->stats.seconds_build = cm_seconds_now() - t1 - (r->stats.seconds_ceiling - ceiling_before);
    cm_remesh_boundary splits = {edge_between, (void *)edges, r->boundary.edge, r->boundary.t, n,
                                 chosen_mode(o) ? edge_place : NULL, o->max_edge, 0};
    s = remesh_stage(r, n, o, edges && on ? &splits : NULL, &progress);
    if (s != CM_OK) return hint_at_range(r, s, polygons, k, n);
    /* boundary points added or slid along their edges */
    if ((splits.n > n || splits.slid) && take_split_boundary(r, n = splits.n))
        return cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    /* slid: the ceiling of the correspondence made */
    if (splits.slid && o->ceiling &&
        (s = take_ceiling(r, (const double *const *)r->boundary.xy, NULL, k, n, 0, &progress)) != CM_OK)
        return s;
    if (clockwise) restore_input_order(&r->mesh, n);
    double t2 = cm_seconds_now();
    if (cm_progress_report(&progress, CM_STAGE_CHECK, 0.0)) return cm_fail_status(&r->error, CM_ERR_CANCELLED);

    int32_t *boundary = malloc(n * sizeof *boundary);
    if (!boundary) return cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    for (size_t j = 0; j < n; j++) boundary[j] = input_index((int32_t)j, n, clockwise);
    s = cm_halfedge_build_and_check(r, boundary, NULL, 1);
    free(boundary);
    if (s == CM_ERR_NO_MEMORY) return cm_fail_status(&r->error, s);
    if (s != CM_OK) return hint_at_range(r, s, polygons, k, n);
    r->stats.seconds_check = cm_seconds_now() - t2;

    /* without remeshing the mesh is the one remesh_stage measured */
    s = cm_result_measure(r, o->remesh ? NULL : r->quality_before);
    if (s != CM_OK) return s;
    if (cm_progress_report(&progress, CM_STAGE_DONE, 0.0)) return cm_fail_status(&r->error, CM_ERR_CANCELLED);
    return CM_OK;
}

static cm_status check_correspondence_options(cm_result *r, const cm_options *o)
{
    if ((unsigned)o->correspondence > (unsigned)CM_CORRESPOND_SIMILARITY)
        return cm_fail(&r->error, CM_ERR_ARGUMENT, "unknown correspondence %d", (int)o->correspondence);
    if (o->num_pins && !o->pins) return cm_fail(&r->error, CM_ERR_ARGUMENT, "num_pins is %zu but pins is NULL", o->num_pins);
    if (o->num_pins && o->correspondence == CM_CORRESPOND_INDEX)
        return cm_fail(&r->error, CM_ERR_ARGUMENT,
                       "pins need the arclength correspondence (with index, vertex i is vertex i)");
    if (!(o->pin_corners_deg >= 0 && o->pin_corners_deg < 180))
        return cm_fail(&r->error, CM_ERR_ARGUMENT, "pin_corners_deg is %g; expected 0 (off) or an angle in (0, 180)",
                       o->pin_corners_deg);
    if (o->pin_corners_deg > 0 && o->correspondence == CM_CORRESPOND_INDEX)
        return cm_fail(&r->error, CM_ERR_ARGUMENT,
                       "corner pins need the arclength or auto correspondence (with index, vertex i is vertex i)");
    if (o->pin_corners_deg > 0 && o->num_pins)
        return cm_fail(&r->error, CM_ERR_ARGUMENT, "give either pins or pin_corners_deg, not both");
    if (!(o->max_edge >= 0 && o->max_edge < HUGE_VAL))
        return cm_fail(&r->error, CM_ERR_ARGUMENT, "max_edge is %g; expected 0 (off) or a positive length",
                       o->max_edge);
    return CM_OK;
}

/* The correspondence bound of arc length from every polygon's first
 * vertex, for CM_CORRESPOND_AUTO to report what its choice bought. */
static cm_status bound_before(cm_result *r, const double *const *polygons, const size_t *counts, size_t k,
                              const int *orientation)
{
    double t = cm_seconds_now();
    cm_boundary_map from_first = {0};
    cm_bound b;
    cm_status s = cm_correspond_arclength(polygons, counts, k, orientation, NULL, 0, &from_first, &r->error);
    if (s == CM_OK)
        s = cm_bound_compute_memo(r->bounds, (const double *const *)from_first.xy, NULL, k, from_first.n, NULL, &b,
                                  &r->error);
    if (s == CM_OK) r->stats.correspondence_bound_before_deg = b.correspondence_deg;
    cm_boundary_map_clear(&from_first);
    r->stats.seconds_ceiling += cm_seconds_now() - t;
    return s;
}

/* A conformal pairing whose boundary has a piece shorter than this share
 * of its polygon's size is not taken: a conformal map crowds a long thin
 * part beyond what tempering undoes, and pieces of a few units in the last
 * place leave the construction no double for a Steiner vertex beside them
 * (two sections of a thin-walled part, OpenCASCADE's TR12J: 354 boundary
 * points within ulps of each other, the partition stuck and the overlay
 * failing after minutes; auto with the similarity choice meshes it in
 * 6.5 s). The bench's 201 pairs have 2.8e-6 at least. */
#define CM_CROWDED_PIECE 1e-9

/* The conformal correspondence's boundaries into out (*found = 0 when it
 * cannot be had, out then untouched, or is crowded, out then cleared), its
 * parameter tempered by power (conformal.h): the others' points on a
 * polygon's edges where the conformal parameter puts them, or with
 * `linear` where it would be if it were linear between the polygon's
 * vertices. with_holes: for the outer loops of polygons with holes, the
 * polygons (their hole centres choose between turns that fit alike). */
static cm_status conformal(cm_result *r, const double *const *polygons, const size_t *counts, size_t k,
                           const int *orientation, const cm_loops *with_holes, int linear, double power,
                           cm_boundary_map *out, int *found)
{
    size_t total = 0, h = with_holes ? with_holes[0].num_loops - 1 : 0;
    for (size_t g = 0; g < k; g++) total += counts[g];
    double *all = malloc(total * sizeof *all), **params = malloc(k * sizeof *params);
    double *all_fine = malloc(total * CM_PARAM_FINE * sizeof *all_fine), **fine = calloc(k, sizeof *fine);
    double *all_centres = malloc((2 * h * k + 1) * sizeof *all_centres), **centres = calloc(k, sizeof *centres);
    cm_status s = all && params && all_fine && fine && all_centres && centres
                      ? CM_OK
                      : cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    for (size_t g = 0, at = 0; s == CM_OK && g < k; at += counts[g], g++) {
        params[g] = all + at, fine[g] = g ? all_fine + at * CM_PARAM_FINE : NULL;
        centres[g] = all_centres + 2 * h * g;
        if (h) cm_correspond_hole_centres(&with_holes[g], centres[g]);
    }
    if (s == CM_OK)
        s = cm_correspond_conformal_memo(r->conformal, polygons, counts, k, orientation,
                                         (const double *const *)centres, h, power, params, fine, found, &r->error);
    if (s == CM_OK && *found)
        s = cm_correspond_params(polygons, counts, k, orientation, (const double *const *)params,
                                 linear ? NULL : (const double *const *)fine, out, &r->error);
    if (s == CM_OK && *found && cm_boundary_map_least_piece(out) < CM_CROWDED_PIECE)
        cm_boundary_map_clear(out), *found = 0;
    free(all), free(params), free(all_fine), free(fine), free(all_centres), free(centres);
    return s;
}

/* The annulus correspondence's boundaries of polygons with one hole into
 * maps[0] (the outer loops) and maps[1] (the holes), its parameter
 * tempered by power and read along every edge (annulus.h);
 * CM_ERR_PRECISION where it cannot be had in doubles or crowds
 * (CM_CROWDED_PIECE); then max_edge's split (0: none). orientation: k L,
 * as cm_input_check_loops gives it; loop_xy, loop_counts,
 * loop_orientation: loop l's k input loops from l k. */
static cm_status annulus(cm_result *r, const cm_loops *polygons, size_t k, const int *orientation,
                         const double *const *loop_xy, const size_t *loop_counts, const int *loop_orientation,
                         double power, double max_edge, cm_boundary_map *maps)
{
    size_t total = 0;
    for (size_t g = 0; g < k; g++) total += polygons[g].loop_sizes[0] + polygons[g].loop_sizes[1];
    double *all = malloc(total * sizeof *all), *all_fine = malloc(total * CM_PARAM_FINE * sizeof *all_fine);
    double **params = malloc(2 * k * sizeof *params), **fine = malloc(2 * k * sizeof *fine);
    const double **loop_params = malloc(2 * k * sizeof *loop_params), **loop_fine = malloc(2 * k * sizeof *loop_fine);
    cm_status s = CM_OK;
    if (!all || !all_fine || !params || !fine || !loop_params || !loop_fine)
        s = cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    for (size_t g = 0, at = 0; s == CM_OK && g < k; g++)
        for (size_t l = 0; l < 2; at += polygons[g].loop_sizes[l], l++) {
            params[2 * g + l] = all + at, fine[2 * g + l] = g ? all_fine + at * CM_PARAM_FINE : NULL;
            loop_params[l * k + g] = params[2 * g + l], loop_fine[l * k + g] = fine[2 * g + l];
        }
    int found = 0;
    if (s == CM_OK) s = cm_correspond_annulus(polygons, k, orientation, power, params, fine, &found, &r->error);
    for (size_t l = 0; s == CM_OK && found && l < 2; l++) {
        s = cm_correspond_params(loop_xy + l * k, loop_counts + l * k, k, loop_orientation + l * k,
                                 loop_params + l * k, loop_fine + l * k, &maps[l], &r->error);
        if (s == CM_OK && cm_boundary_map_least_piece(&maps[l]) < CM_CROWDED_PIECE) found = 0;
    }
    if (s == CM_OK && !found) s = cm_fail(&r->error, CM_ERR_PRECISION, "the annulus pairing cannot be had in doubles");
    for (size_t l = 0; s == CM_OK && max_edge > 0 && l < 2; l++)
        s = cm_boundary_map_split(&maps[l], loop_xy + l * k, loop_counts + l * k, loop_orientation + l * k, max_edge,
                                  &r->error);
    free(all), free(all_fine), free(params), free(fine), free(loop_params), free(loop_fine);
    return s;
}

/* The certified ceiling (the lower of the corner-fan cap and the
 * correspondence bound) of boundaries in correspondence, and the
 * correspondence bound alone (bound_deg, when not NULL). */
static cm_status ceiling_bound_of(cm_result *r, const cm_boundary_map *map, double *deg, double *bound_deg)
{
    cm_bound b;
    cm_status s = cm_bound_compute_memo(r->bounds, (const double *const *)map->xy, NULL, map->k, map->n, NULL, &b,
                                        &r->error);
    *deg = fmin(b.corner_fan_deg, b.correspondence_deg);
    if (bound_deg) *bound_deg = b.correspondence_deg;
    return s;
}

static cm_status ceiling_of(cm_result *r, const cm_boundary_map *map, double *deg)
{
    return ceiling_bound_of(r, map, deg, NULL);
}

/* Ceilings equal up to rounding: the same input corner binds both (the
 * corner-fan cap), which then cannot tell the correspondences apart. */
#define CM_CEILING_TIE 1e-9

/* The pairings auto has for polygons without holes (and outer loops):
 * the conformal parameter or the similarity choice, whichever allows the
 * higher ceiling (the first run); or one of them taken as it is (the
 * rescues, pairing_rescue). Outer loops also have arc length from the
 * similarity's start, fitted to the outer loops alone (LOOP_BY_START);
 * polygons with one hole both loops at once through the round annulus
 * (PAIRING_ANNULUS, annulus.h). */
enum pairing_kind { PAIRING_BY_CEILING, PAIRING_CONFORMAL, PAIRING_SIMILARITY, PAIRING_BY_START, PAIRING_ANNULUS };
typedef struct auto_pairing {
    enum pairing_kind kind;
    int linear;   /* the conformal parameter read linearly between each polygon's vertices, not along every edge */
    double power; /* the conformal parameter's tempering (conformal.h) */
} auto_pairing;

static const auto_pairing by_ceiling = {PAIRING_BY_CEILING, 0, CM_CONFORMAL_POWER};

/* The similarity choice: arc length from the starts that align the loops
 * best up to a similarity (with_holes: their holes too, or with holes_tie
 * only among starts that fit alike, cm_correspond_choose_starts). */
static cm_status similarity_pairing(cm_result *r, const double *const *polygons, const size_t *counts, size_t k,
                                    const int *orientation, const cm_loops *with_holes, int holes_tie,
                                    cm_boundary_map *out)
{
    size_t *starts = malloc(k * sizeof *starts);
    cm_status s = starts ? cm_correspond_choose_starts(polygons, counts, k, orientation, with_holes, holes_tie, starts,
                                                       &r->error)
                         : cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    if (s == CM_OK) s = cm_correspond_arclength(polygons, counts, k, orientation, starts, 1, out, &r->error);
    free(starts);
    return s;
}

/* CM_CORRESPOND_AUTO for polygons without holes or pins, by `pairing`: the
 * conformal correspondence, or the similarity choice where that allows the
 * higher ceiling (a polygon whose corners the similarity fit pairs corner
 * to corner, a disc that would take another polygon's crowding whole);
 * where the ceilings tie (CM_CEILING_TIE), the one with the higher
 * correspondence bound, the distortion the remesher has to work against.
 * For the outer loops of polygons with holes (with_holes), the one that
 * takes every hole where a hole is (cm_correspond_holes_land) where only
 * one does: an outline a turn takes onto itself leaves the turn to the
 * holes, and a pairing turned against them twists the map around them.
 * *found = 0 when the conformal one cannot be had (out then untouched),
 * else *choice says which was kept. */
static cm_status auto_whole(cm_result *r, const double *const *polygons, const size_t *counts, size_t k,
                            const int *orientation, const cm_loops *with_holes, auto_pairing pairing,
                            cm_boundary_map *out, int *found, double *ceiling_deg, cm_correspondence_choice *choice)
{
    cm_status s = conformal(r, polygons, counts, k, orientation, with_holes, pairing.linear, pairing.power, out, found);
    if (s != CM_OK || !*found) return s;
    cm_boundary_map similar = {0};
    double conformal_deg = 0, similar_deg = 0, conformal_bound = 0, similar_bound = 0;
    int conformal_lands = 1, similar_lands = 1; /* the holes where holes are */
    s = similarity_pairing(r, polygons, counts, k, orientation, with_holes, 1, &similar);
    if (s == CM_OK) s = ceiling_bound_of(r, out, &conformal_deg, &conformal_bound);
    if (s == CM_OK && with_holes) s = cm_correspond_holes_land(with_holes, k, out, &conformal_lands, &r->error);
    if (s == CM_OK && with_holes) s = cm_correspond_holes_land(with_holes, k, &similar, &similar_lands, &r->error);
    if (s == CM_OK && !similar_lands) { /* the outline's fit turned against the holes: fit them too */
        cm_boundary_map_clear(&similar);
        s = similarity_pairing(r, polygons, counts, k, orientation, with_holes, 0, &similar);
        if (s == CM_OK) s = cm_correspond_holes_land(with_holes, k, &similar, &similar_lands, &r->error);
    }
    if (s == CM_OK) s = ceiling_bound_of(r, &similar, &similar_deg, &similar_bound);
    *choice = CM_CHOICE_CONFORMAL;
    int tie = fabs(similar_deg - conformal_deg) <= CM_CEILING_TIE * fmax(similar_deg, conformal_deg);
    int similar_wins = tie ? similar_bound > conformal_bound : similar_deg > conformal_deg;
    if (conformal_lands != similar_lands) similar_wins = similar_lands;
    if (s == CM_OK && (pairing.kind == PAIRING_BY_CEILING ? similar_wins : pairing.kind == PAIRING_SIMILARITY)) {
        cm_boundary_map t = *out;
        *out = similar, similar = t;
        *choice = CM_CHOICE_SIMILARITY;
    }
    *ceiling_deg = fmax(conformal_deg, similar_deg);
    cm_boundary_map_clear(&similar);
    return s;
}

/* What correspond_boundary's k loops are: whole polygons (the caller's
 * pins taken, the bound before the choice reported), the outer loops of
 * polygons with holes (auto chooses as for whole polygons, the outer loop
 * filled standing for each: the conformal correspondence sees where the
 * parts of the outline are, arc length from a start does not), or loops
 * paired from a start alone (holes, and outer loops in a rescue:
 * PAIRING_BY_START). */
enum loop_kind { LOOP_WHOLE, LOOP_OUTER, LOOP_BY_START };

/* The boundaries in correspondence for CM_CORRESPOND_ARCLENGTH and _AUTO,
 * of k polygons each checked on its own (orientation as found): for auto,
 * the starts chosen where none are pinned; then the common refinement and
 * the max_edge split. every_vertex: the index correspondence, as pins at
 * every vertex. kind: what the loops are (enum loop_kind). hole_starts:
 * for auto, the starts chosen for a hole (k input vertices), taken in
 * place of the loop's own choice; else NULL. with_holes: for the outer
 * loops of polygons with holes, the polygons (their holes choose between
 * starts an affine map takes alike, and between auto_whole's pairings);
 * else NULL. *choice receives the
 * correspondence made. */
static cm_status correspond_boundary(cm_result *r, const double *const *polygons, const size_t *counts, size_t k,
                                     const int *orientation, const cm_options *o, const size_t *every_vertex,
                                     enum loop_kind kind, auto_pairing pairing, const size_t *hole_starts,
                                     const cm_loops *with_holes, cm_boundary_map *out, double *ceiling_deg,
                                     cm_correspondence_choice *choice)
{
    int whole = kind == LOOP_WHOLE;
    *ceiling_deg = -1;
    *choice = every_vertex ? CM_CHOICE_INDEX : CM_CHOICE_ARCLENGTH;
    cm_status s = CM_OK;
    const size_t *pins = every_vertex ? every_vertex : whole ? o->pins : NULL;
    size_t num_pins = every_vertex ? counts[0] : whole ? o->num_pins : 0, *chosen = NULL;
    size_t *affine = NULL;
    if (hole_starts && chosen_mode(o) && num_pins == 0) {
        chosen = malloc(k * sizeof *chosen);
        if (!chosen) return cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
        memcpy(chosen, hole_starts, k * sizeof *chosen);
        pins = chosen, num_pins = 1, *choice = CM_CHOICE_SIMILARITY;
    }
    if (chosen_mode(o) && num_pins == 0 && !(o->pin_corners_deg > 0)) {
        /* Affine images of one another: vertex to vertex, no distortion. */
        int found = 0;
        affine = malloc(counts[0] * k * sizeof *affine);
        s = affine ? cm_correspond_affine_shift(polygons, counts, k, orientation, with_holes, affine, &found, &r->error)
                   : cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
        if (found) pins = affine, num_pins = counts[0], *choice = CM_CHOICE_AFFINE;
    }
    if (s == CM_OK && o->correspondence == CM_CORRESPOND_AUTO && num_pins == 0 && kind != LOOP_BY_START &&
        !(o->pin_corners_deg > 0)) {
        /* Polygons without holes, and outer loops: conformal or similarity
         * (auto_whole). */
        int found = 0;
        s = auto_whole(r, polygons, counts, k, orientation, with_holes, pairing, out, &found, ceiling_deg, choice);
        if (s == CM_OK && !found && pairing.kind == PAIRING_CONFORMAL) /* a rescue's: nothing new to remesh */
            s = cm_fail(&r->error, CM_ERR_PRECISION, "the conformal pairing cannot be had in doubles");
        if (s == CM_OK && found) {
            if (o->ceiling && whole) s = bound_before(r, polygons, counts, k, orientation);
            if (s == CM_OK && o->max_edge > 0)
                s = cm_boundary_map_split(out, polygons, counts, orientation, o->max_edge, &r->error);
            free(affine);
            return s;
        }
    }
    if (s == CM_OK && chosen_mode(o) && num_pins == 0) {
        chosen = malloc(k * sizeof *chosen);
        s = chosen ? cm_correspond_choose_starts(polygons, counts, k, orientation, with_holes, 1, chosen, &r->error)
                   : cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
        pins = chosen, num_pins = 1, *choice = CM_CHOICE_SIMILARITY;
    }
    size_t *corner_pins = NULL;
    if (s == CM_OK && o->pin_corners_deg > 0) {
        /* Arc length from the chosen starts (auto) or from vertex 0. */
        size_t *starts = chosen ? chosen : calloc(k, sizeof *starts);
        s = starts ? cm_correspond_corner_pins(polygons, counts, k, orientation, starts, o->pin_corners_deg,
                                               &corner_pins, &num_pins, &r->error)
                   : cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
        if (starts != chosen) free(starts);
        pins = corner_pins, *choice = CM_CHOICE_CORNERS;
    }
    if (s == CM_OK && chosen && o->ceiling && whole) s = bound_before(r, polygons, counts, k, orientation);
    if (s == CM_OK) s = cm_correspond_arclength(polygons, counts, k, orientation, pins, num_pins, out, &r->error);
    if (s == CM_OK && o->max_edge > 0)
        s = cm_boundary_map_split(out, polygons, counts, orientation, o->max_edge, &r->error);
    free(chosen), free(corner_pins), free(affine);
    return s;
}

/* A failure on the refined boundaries (rounding of a point on an edge next
 * to another edge) located at the input edge it came from. */
static void locate_in_input(cm_result *r, cm_status s)
{
    if (s == CM_OK || s == CM_ERR_NO_MEMORY || s == CM_ERR_CANCELLED || r->error.polygon < 0 ||
        r->error.vertex < 0 || (size_t)r->error.vertex >= r->boundary.n)
        return;
    size_t g = (size_t)r->error.polygon, v = (size_t)r->error.vertex;
    char detail[sizeof r->error.message];
    snprintf(detail, sizeof detail, "%s", r->error.message);
    cm_fail_at(&r->error, (long)g, (long)r->boundary.edge[g][v], -1);
    cm_fail(&r->error, s, "the boundary the arc-length correspondence made, near input vertex %ld of polygon %zu: %s",
            (long)r->boundary.edge[g][v], g, detail);
}

/* Arclength and auto put points on the input edges anyway: where an edge
 * of the common boundary caps what the remesher can reach below its aim
 * (the target, or the ceiling when lower), it is halved compatibly
 * (cm_boundary_map_split_caps), adding at most as many vertices as the
 * boundary has, plus CM_CAP_SPLIT_EXTRA for small ones. The index
 * correspondence keeps its boundary (interior Steiner vertices only). */
#define CM_CAP_SPLIT_EXTRA 100

typedef struct cap_aim {
    cm_result *r;
    double known_deg; /* the ceiling the correspondence's choice computed, or -1 */
    size_t k;
} cap_aim;

/* cm_cap_ceiling without holes: the ceiling of r->boundary (the boundary
 * given), computed only when an edge binds and the choice did not already. */
static double cap_ceiling(void *ctx, const double *const *xy, const size_t *loop_start, size_t num_loops,
                          cm_status *s)
{
    (void)xy, (void)loop_start, (void)num_loops;
    cap_aim *a = ctx;
    double deg = a->known_deg, t = cm_seconds_now();
    *s = CM_OK;
    if (deg < 0) {
        *s = ceiling_of(a->r, &a->r->boundary, &deg);
        a->r->stats.seconds_ceiling += cm_seconds_now() - t;
        if (*s != CM_OK && *s != CM_ERR_NO_MEMORY && *s != CM_ERR_CANCELLED) {
            cm_error_init(&a->r->error); /* a boundary the pipeline's check refuses, saying where */
            *s = CM_OK;
            return -1;
        }
    }
    return deg * CM_PI / 180.0;
}

/* The corner-fan cap (degrees) of polygons with holes, loop by loop (xy:
 * k arrays, loop l from loop_start[l], the material to its left); the
 * correspondence bound needs a simply connected polygon. -1 out of memory. */
static double loops_corner_fan_cap(const double *const *xy, size_t k, const size_t *loop_start, size_t num_loops)
{
    double cap = 60.0;
    const double **loop_xy = malloc(k * sizeof *loop_xy);
    if (!loop_xy) return -1;
    for (size_t l = 0; l < num_loops; l++) {
        for (size_t g = 0; g < k; g++) loop_xy[g] = xy[g] + 2 * loop_start[l];
        cap = fmin(cap, cm_corner_fan_cap(loop_xy, k, loop_start[l + 1] - loop_start[l]));
    }
    free(loop_xy);
    return cap;
}

/* cm_cap_ceiling with holes: the corner fan over every loop, the ceiling
 * the pipeline aims by (run_loops). */
static double holes_cap_ceiling(void *ctx, const double *const *xy, const size_t *loop_start, size_t num_loops,
                                cm_status *s)
{
    cap_aim *a = ctx;
    double deg = loops_corner_fan_cap(xy, a->k, loop_start, num_loops);
    *s = deg < 0 ? cm_fail_status(&a->r->error, CM_ERR_NO_MEMORY) : CM_OK;
    return deg * CM_PI / 180.0;
}

static cm_status split_capped_edges(cm_result *r, const double *const *polygons, const size_t *counts,
                                    const int *orientation, const cm_options *o, double known_ceiling_deg,
                                    int32_t ***tris)
{
    cap_aim a = {r, known_ceiling_deg, r->boundary.k};
    cm_cap_loop loop = {&r->boundary, polygons, counts, orientation};
    return cm_boundary_maps_split_caps(&loop, 1, o->min_angle_deg * CM_PI / 180.0, o->ceiling ? cap_ceiling : NULL,
                                       &a, r->boundary.n + CM_CAP_SPLIT_EXTRA, NULL, tris, &r->error);
}

/* CM_CORRESPOND_ARCLENGTH and _AUTO: the boundaries in correspondence,
 * then the pipeline on them. */
static cm_status run_arclength(cm_result *r, const double *const *polygons, const size_t *counts,
                               size_t k, const cm_options *o, const size_t *every_vertex, auto_pairing pairing)
{
    int *orientation = k ? malloc(k * sizeof *orientation) : NULL;
    size_t *merged_counts = k ? malloc(k * sizeof *merged_counts) : NULL;
    cm_status s = !k || (orientation && merged_counts) ? CM_OK : cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    if (s == CM_OK) s = cm_input_check_polygons(polygons, counts, k, 0, orientation, &r->error);
    double ceiling_deg = -1;
    if (s == CM_OK)
        s = correspond_boundary(r, polygons, counts, k, orientation, o, every_vertex, LOOP_WHOLE, pairing, NULL, NULL,
                                &r->boundary, &ceiling_deg, &r->stats.correspondence_choice);
    int32_t **tris = NULL; /* the merged polygons' triangulations, when the cap split made them */
    if (s == CM_OK && !every_vertex && o->remesh)
        s = split_capped_edges(r, polygons, counts, orientation, o, ceiling_deg, &tris);
    if (s == CM_OK) {
        for (size_t g = 0; g < k; g++) merged_counts[g] = r->boundary.n;
        edge_inputs edges = {polygons, counts, orientation};
        s = run_pipeline(r, (const double *const *)r->boundary.xy, merged_counts, k, (const int32_t *const *)tris,
                         !every_vertex && o->remesh ? &edges : NULL, o);
        locate_in_input(r, s);
    }
    cm_cap_tris_free(tris, k);
    free(orientation), free(merged_counts);
    return s;
}

/* CM_CORRESPOND_INDEX with max_edge: the index contract checked (equal
 * counts, one orientation), then the arc-length path with a pin at every
 * vertex, which keeps vertex i on vertex i and splits the edges. */
static cm_status run_index_split(cm_result *r, const double *const *polygons, const size_t *counts, size_t k,
                                 const cm_options *o)
{
    int clockwise = 0;
    cm_status s = cm_input_validate(polygons, counts, k, &r->error, &clockwise);
    if (s != CM_OK) return s;
    size_t n = counts[0], *every = malloc(n * k * sizeof *every);
    if (!every) return cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    for (size_t j = 0; j < n; j++)
        for (size_t g = 0; g < k; g++) every[j * k + g] = j;
    s = run_arclength(r, polygons, counts, k, o, every, by_ceiling);
    free(every);
    return s;
}

/* A new result handle in *result (NULL when even that fails), and the
 * options to use: *options, or the defaults stored in *defaults. */
static cm_result *new_result(cm_result **result, const cm_options **options, cm_options *defaults)
{
    if (!result) return NULL;
    cm_result *r = calloc(1, sizeof *r);
    *result = r;
    if (!r) return NULL;
    cm_error_init(&r->error);
    if (!*options) {
        cm_options_init(defaults);
        *options = defaults;
    }
    return r;
}

/* Auto's pairing may end far below the remesher's aim, where another
 * pairing does better (the rescues below); 0.6: below 15 degrees at the
 * default aim of 25. */
#define CM_PAIRING_RESCUE_SHARE 0.6

/* Is r, made by auto and remeshed by o, with its smallest angle `angle_deg`
 * below `share` of its aim, and the call's time not up? */
static int below_share(const cm_result *r, const cm_options *o, double angle_deg, double share)
{
    return o->correspondence == CM_CORRESPOND_AUTO && o->remesh && angle_deg < share * r->stats.remesh_aim_deg &&
           !cm_deadline_passed();
}

/* ... after the greedy remesher? */
static int rescue_wanted(const cm_result *r, const cm_options *o, double share)
{
    return below_share(r, o, r->greedy_angle_deg, share);
}

/* ... after the polish (before any restart)? */
static int short_of(const cm_result *r, const cm_options *o, double share)
{
    return below_share(r, o, r->polished_angle_deg, share);
}

/* A result for a rescue's run, sharing r's memos (the caps and the
 * conformal map of the same polygons); NULL without memory for it (r then
 * stands). */
static cm_result *rescue_result(const cm_result *r, const cm_options *o)
{
    cm_result *again = NULL;
    cm_options unused;
    const cm_options *same = o;
    if (!new_result(&again, &same, &unused)) return NULL;
    again->bounds = r->bounds, again->conformal = r->conformal;
    return again;
}

/* The stage times and pairings of `other`'s run added to kept's. */
static void add_costs(cm_result *kept, const cm_result *other)
{
    kept->stats.pairings_built += other->stats.pairings_built;
    kept->stats.pairings_remeshed += other->stats.pairings_remeshed;
    kept->stats.seconds_validate += other->stats.seconds_validate;
    kept->stats.seconds_build += other->stats.seconds_build, kept->stats.seconds_check += other->stats.seconds_check;
    kept->stats.seconds_remesh += other->stats.seconds_remesh;
    kept->stats.seconds_ceiling += other->stats.seconds_ceiling;
}

/* *result becomes `again` (a run that ended with status s) when `take`
 * says so and s is CM_OK; the costs of both runs summed, the other freed.
 * CM_OK, or CM_ERR_CANCELLED when the second run was cancelled (a second
 * run that failed otherwise, out of memory included, leaves *result as it
 * was). */
static cm_status keep_if(cm_result **result, cm_result *again, cm_status s, int take)
{
    if (s == CM_ERR_CANCELLED) {
        cm_result_free(again);
        return cm_fail_status(&(*result)->error, s);
    }
    if (s == CM_OK && take) {
        cm_result *t = *result;
        *result = again, again = t;
    }
    add_costs(*result, again);
    cm_result_free(again);
    return CM_OK;
}

/* Is again, a rescue's run remeshed without restarts that ended with
 * status s, better than r: a larger smallest angle before any restart, so
 * that r's restarts do not count against it? */
static int better(const cm_result *again, cm_status s, const cm_result *r)
{
    return s == CM_OK && again->polished_angle_deg > r->polished_angle_deg;
}

/* Auto's rescues run without restarts: a restart costs about as much as
 * the run it starts from and is only wanted on the pairing kept. */
static cm_options without_restarts(const cm_options *o)
{
    cm_options once = *o;
    once.restarts = 0;
    return once;
}

/* Auto runs several pairings, each a whole pipeline: where the caller
 * listens, one progress bar spans them all (cm_progress_relay); this
 * moves it on to the next run, named by label (NULL: its number). */
static void next_run(const cm_options *o, const char *label)
{
    if (o->progress == cm_progress_relay_fn) cm_progress_relay_next(o->progress_user, label);
}

/* o with the relay in place of the caller's callback where auto may run
 * several pairings and someone listens; *relayed receives it. */
static const cm_options *relay_progress(const cm_options *o, cm_options *relayed, cm_progress_relay *relay)
{
    if (o->correspondence != CM_CORRESPOND_AUTO || !o->remesh || !o->progress) return o;
    cm_progress_relay_init(relay, o->progress, o->progress_user);
    *relayed = *o;
    relayed->progress = cm_progress_relay_fn, relayed->progress_user = relay;
    return relayed;
}

/* The end of a call whose progress the relay carried: CM_ERR_CANCELLED
 * when the caller cancels at "done" (as a single run's end), else s. */
static cm_status relay_done(cm_result *r, const cm_options *o, cm_status s)
{
    if (s == CM_OK && o->progress == cm_progress_relay_fn && cm_progress_relay_done(o->progress_user))
        return cm_fail_status(&r->error, CM_ERR_CANCELLED);
    return s;
}

/* A rescue's run: `pairing` (of the kind the caller's input takes) of
 * `input` remeshed by o into `again`. */
typedef cm_status (*rescue_run)(cm_result *again, const void *input, const cm_options *o, const void *pairing);

/* The pairing run without restarts, kept in place of *result where it is
 * better (*took); *result stands where no memory is left for the run.
 * angle: NULL, or receives the run's smallest angle before any restart
 * (-1 where it did not run or failed). */
static cm_status rescue_try(cm_result **result, const cm_options *o, rescue_run run, const void *input,
                            const void *pairing, int *took, double *angle)
{
    cm_options once = without_restarts(o);
    cm_result *again = rescue_result(*result, o);
    *took = 0;
    if (angle) *angle = -1;
    if (!again) return CM_OK;
    again->beat_deg = (*result)->polished_angle_deg;
    /* where restarts are asked for, the run keeps where they would start
     * (rescue_restart; NULL without memory: it then runs again whole) */
    if (o->restarts > 0) again->resume = calloc(1, sizeof *again->resume);
    next_run(o, NULL);
    cm_status s = run(again, input, &once, pairing);
    *took = better(again, s, *result);
    if (angle && s == CM_OK) *angle = again->polished_angle_deg;
    return keep_if(result, again, s, *took);
}

/* The pairing a rescue kept (NULL: none) with the restarts o asks for,
 * where its result would start one: built again, and remeshed from where
 * its run left off (cm_remesh_resume), the same as a whole run with
 * restarts up to there. */
static cm_status rescue_restart(cm_result **result, const cm_options *o, rescue_run run, const void *input,
                                const void *pairing)
{
    cm_remesh_resume *resume = (*result)->resume;
    (*result)->resume = NULL;
    cm_result *again;
    if (!pairing || !(o->restarts > 0 && (*result)->restart_wanted) || cm_deadline_passed() ||
        !(again = rescue_result(*result, o))) {
        cm_result_free_resume(resume);
        return CM_OK;
    }
    again->resume = resume;
    next_run(o, "restart");
    return keep_if(result, again, run(again, input, o, pairing), 1);
}

/* The rescues' other tempering powers (conformal.h): nearer the conformal
 * map, nearer arc length. The first is also tried up to a higher share of
 * the aim: of the 23 glyph pairs that every pairing tried up to 0.8 of the
 * aim raised beyond what the rescues up to 0.6 gave, it was the best on 16
 * (bench/CORRESPONDENCE.md), and alone it costs one run, not four. */
#define CM_RESCUE_POWER_MORE 0.3
#define CM_RESCUE_POWER_LESS 0.2
#define CM_POWER_RESCUE_SHARE 0.8
/* Polygons with one hole pair through the annulus first (both loops at
 * once); the outer loops' pairing, as without holes, follows wherever
 * that run ends short of its aim, and the better is kept. On glyph pairs
 * with one hole in 19 fonts (223 rows), against the outer loops first
 * with the annulus as a rescue: 75 higher, 23 lower (all but one still at
 * or above the aim), about the same CPU; up to 0.8 of the aim instead: 64
 * lower, for 0.64 of the CPU (bench/HOLES.md, "The annulus pairing
 * first"). */
#define CM_ANNULUS_RESCUE_SHARE 1.0
/* The last resort's corner pins (pin_corners_deg): corners turning by more
 * than a right angle, the tips and ends of strokes. */
#define CM_RESCUE_CORNERS_DEG 90.0
/* A near miss after every pairing above (its smallest angle after the
 * polish between CM_POWER_SEARCH_FROM and CM_PAIRING_RESCUE_SHARE of its
 * aim): the tempering power searched further, the parameter read along
 * every edge (power_search). The remesher's result is not monotone in the
 * power (tune_FreeSerifItalic_w_L_n160: 0.25 13.50 degrees, 0.35 14.44,
 * 0.4 14.74, 0.425 16.18, 0.45 14.06; 0.425 plus one ulp 14.23), so more
 * draws near the floor often cross it (spiral_disc_n50 14.69 -> 17.02);
 * far below it the pairing is not what holds the result (comb_disc_n250,
 * spiral_disc_n100: the same angle at 1.7 and 2.5 times the CPU), and the
 * search is not run (bench/CORRESPONDENCE.md, "The tempering power
 * searched on near misses"). First the powers above the list's, nearer
 * the conformal map, CM_POWER_SEARCH_STEP apart up to CM_POWER_SEARCH_TOP
 * (beyond, the map crowds past what doubles hold on thin glyphs and the
 * run fails alone); then half a step either side of the power whose run
 * ended highest; each while the result is still short, kept only where
 * better. */
#define CM_POWER_SEARCH_FROM 0.5
#define CM_POWER_SEARCH_STEP 0.05
#define CM_POWER_SEARCH_TOP 0.45
/* At most this many powers run per call (the list's and the search's). */
#define CM_POWER_RUNS 16

/* Auto without holes takes the conformal parameter read along every edge
 * (a faithful pairing) or the similarity choice, whichever allows the
 * higher ceiling; but the ceiling does not tell which the remesher grades
 * better (tune_FreeSerifItalic_T_5_n48: the similarity's ceiling 15.5
 * remeshed to 6.9 degrees, the conformal's 13.3 to 13.3), and the
 * faithful pairing may crowd beyond what it can grade. Where the best
 * result so far ends below a share of its aim, the other pairings are
 * remeshed in turn, each as it is, and the best result is kept: below
 * CM_PAIRING_RESCUE_SHARE the conformal parameter read linearly between
 * each polygon's vertices (coarser: the stretch averaged over an edge;
 * first, so that the result is never below that rescue's alone), below
 * CM_POWER_RESCUE_SHARE the parameter tempered nearer the conformal map,
 * then below CM_PAIRING_RESCUE_SHARE the parameter read along every edge,
 * the similarity choice, and the parameter tempered nearer arc length.
 * Last, still below CM_PAIRING_RESCUE_SHARE, arc length between corner
 * pins (CM_RESCUE_CORNERS_DEG): the parameters above all follow the
 * conformal map or a fit of the whole outline, and where they put one
 * polygon's stroke ends between the other's (URW Bookman V against W at
 * 160 vertices: 10.7 degrees, 17.7 with the tips pinned) only pins put
 * them together; it ends far lower wherever the corners differ, so it
 * comes last and is kept only where better (bench/CORRESPONDENCE.md).
 * Polygons with holes take the same rescues for their outer loops, after
 * arc length from the similarity's start (PAIRING_BY_START;
 * run_loop_pairing says why). Polygons with one hole are paired first
 * through the annulus (run_annulus_first), which pairs both loops at once
 * where every other pairing fills the outline and starts the hole from
 * there; below the aim the outer loops' pairing (by the ceiling) is their
 * first rescue (CM_ANNULUS_RESCUE_SHARE). */
typedef struct polygon_input {
    const double *const *polygons;
    const size_t *counts;
    size_t k;
} polygon_input;

static cm_status run_pairing(cm_result *again, const void *input, const cm_options *o, const void *pairing)
{
    const polygon_input *in = input;
    return run_arclength(again, in->polygons, in->counts, in->k, o, NULL, *(const auto_pairing *)pairing);
}

/* What the rescues remesh: run (taking an auto_pairing) on input; holes:
 * every polygon's holes (with holes PAIRING_BY_START is one of its
 * pairings). */
typedef struct rescue_input {
    rescue_run run;
    const void *input;
    size_t holes; /* every polygon's holes */
} rescue_input;

/* The powers read along every edge run so far, and where each ended (the
 * smallest angle after the polish; -1 where the run failed). */
typedef struct power_runs {
    double power[CM_POWER_RUNS], angle[CM_POWER_RUNS];
    auto_pairing searched[CM_POWER_RUNS]; /* the search's pairings (*kept may point at one) */
    size_t n;
} power_runs;

static void power_ran(power_runs *runs, double power, double angle)
{
    if (runs->n < CM_POWER_RUNS) runs->power[runs->n] = power, runs->angle[runs->n++] = angle;
}

/* The tempering power searched further on a near miss (CM_POWER_SEARCH_FROM
 * says why); *kept and *kept_options become the pairing kept, if the
 * search keeps one. */
static cm_status power_search(cm_result **result, const cm_options *o, const rescue_input *in, power_runs *runs,
                              const auto_pairing **kept, const cm_options **kept_options)
{
    static const double beyond[] = {CM_RESCUE_POWER_MORE + CM_POWER_SEARCH_STEP,
                                    CM_RESCUE_POWER_MORE + 2 * CM_POWER_SEARCH_STEP, CM_POWER_SEARCH_TOP};
    const size_t nb = sizeof beyond / sizeof *beyond;
    if (!short_of(*result, o, CM_PAIRING_RESCUE_SHARE) || short_of(*result, o, CM_POWER_SEARCH_FROM)) return CM_OK;
    cm_status s = CM_OK;
    for (size_t i = 0, tried = 0; s == CM_OK && runs->n < CM_POWER_RUNS && i < nb + 2; i++) {
        if (!short_of(*result, o, CM_PAIRING_RESCUE_SHARE)) break;
        double p;
        if (i < nb) {
            p = beyond[i];
        } else { /* half a step either side of the best so far */
            size_t best = 0;
            for (size_t j = 1; j < runs->n; j++)
                if (runs->angle[j] > runs->angle[best]) best = j;
            if (runs->n == 0 || runs->angle[best] < 0) break;
            p = runs->power[best] + (i == nb ? -0.5 : 0.5) * CM_POWER_SEARCH_STEP;
        }
        /* on a grid of a thousandth: the same power is the same double
         * however it was reached (one ulp of the power moves the result) */
        p = round(p * 1000) / 1000;
        int done = 0;
        for (size_t j = 0; j < runs->n; j++) done |= fabs(runs->power[j] - p) < 1e-9;
        if (done || p <= 0) continue;
        auto_pairing *pairing = &runs->searched[tried++];
        *pairing = (auto_pairing){PAIRING_CONFORMAL, 0, p};
        double ended;
        int took;
        s = rescue_try(result, o, in->run, in->input, pairing, &took, &ended);
        if (took) *kept = pairing, *kept_options = o;
        power_ran(runs, p, ended);
    }
    return s;
}

static cm_status pairing_rescue(cm_result **result, const cm_options *o, const rescue_input *in)
{
    cm_correspondence_choice first = (*result)->stats.correspondence_choice;
    if (first != CM_CHOICE_CONFORMAL && first != CM_CHOICE_SIMILARITY && first != CM_CHOICE_ANNULUS) return CM_OK;
    static const struct {
        auto_pairing pairing;
        double share;
    } others[] = {{{PAIRING_BY_START, 0, CM_CONFORMAL_POWER}, CM_PAIRING_RESCUE_SHARE},
                  {{PAIRING_CONFORMAL, 1, CM_CONFORMAL_POWER}, CM_PAIRING_RESCUE_SHARE},
                  {{PAIRING_CONFORMAL, 0, CM_RESCUE_POWER_MORE}, CM_POWER_RESCUE_SHARE},
                  {{PAIRING_CONFORMAL, 0, CM_CONFORMAL_POWER}, CM_PAIRING_RESCUE_SHARE},
                  {{PAIRING_SIMILARITY, 0, CM_CONFORMAL_POWER}, CM_PAIRING_RESCUE_SHARE},
                  {{PAIRING_CONFORMAL, 0, CM_RESCUE_POWER_LESS}, CM_PAIRING_RESCUE_SHARE}};
    const auto_pairing *kept = NULL; /* the rescue's pairing *result is, if any */
    cm_status s = CM_OK;
    int took;
    power_runs runs = {0};
    if (first == CM_CHOICE_CONFORMAL) power_ran(&runs, CM_CONFORMAL_POWER, (*result)->polished_angle_deg);
    if (first == CM_CHOICE_ANNULUS && rescue_wanted(*result, o, CM_ANNULUS_RESCUE_SHARE)) {
        s = rescue_try(result, o, in->run, in->input, &by_ceiling, &took, NULL);
        if (took) kept = &by_ceiling;
    }
    for (size_t i = 0; s == CM_OK && i < sizeof others / sizeof *others; i++) {
        const auto_pairing *p = &others[i].pairing;
        if (!rescue_wanted(*result, o, others[i].share) ||
            (p->kind == PAIRING_CONFORMAL && !p->linear && p->power == CM_CONFORMAL_POWER &&
             first != CM_CHOICE_SIMILARITY) ||
            (p->kind == PAIRING_SIMILARITY && first == CM_CHOICE_SIMILARITY) ||
            (p->kind == PAIRING_BY_START && (!in->holes || first == CM_CHOICE_SIMILARITY)))
            continue; /* not wanted, not the input's, or run already */
        double ended;
        s = rescue_try(result, o, in->run, in->input, p, &took, &ended);
        if (took) kept = p;
        if (p->kind == PAIRING_CONFORMAL && !p->linear) power_ran(&runs, p->power, ended);
    }
    cm_options cornered = *o;
    cornered.pin_corners_deg = CM_RESCUE_CORNERS_DEG;
    const cm_options *kept_options = o;
    if (s == CM_OK && rescue_wanted(*result, o, CM_PAIRING_RESCUE_SHARE)) {
        /* a polygon without such a corner fails this run alone */
        s = rescue_try(result, &cornered, in->run, in->input, &by_ceiling, &took, NULL);
        if (took) kept = &by_ceiling, kept_options = &cornered;
    }
    if (s == CM_OK) s = power_search(result, o, in, &runs, &kept, &kept_options);
    return s == CM_OK ? rescue_restart(result, kept_options, in->run, in->input, kept) : s;
}

/* The memos of one call, for what an auto run asks more than once. */
static void memos_start(cm_result *r, const cm_options *o)
{
    r->bounds = o->ceiling ? cm_bound_memo_new() : NULL;
    r->conformal = o->correspondence == CM_CORRESPOND_AUTO ? cm_conformal_memo_new() : NULL;
}

/* r: the call's result, whichever run it came from (all share the memos). */
static void memos_end(cm_result *r)
{
    cm_bound_memo_free(r->bounds), cm_conformal_memo_free(r->conformal);
    r->bounds = NULL, r->conformal = NULL;
}

/* What every call keeps from its start to its end: the default options
 * where the caller gave none, and the progress relay. */
typedef struct call_frame {
    cm_options defaults, relayed;
    cm_progress_relay relay;
    cm_deadline outer; /* the deadline in force before the call */
} call_frame;

/* The start of a call: a result handle in *result, *options the options
 * to use (the defaults where NULL, the relay in place of the caller's
 * progress where auto may run several pairings), checked, and the memos
 * started. NULL where no handle could be made (*s then says why);
 * otherwise *s is CM_OK or what the options' check found. */
static cm_result *call_begin(cm_result **result, const cm_options **options, call_frame *f, cm_status *s)
{
    cm_result *r = new_result(result, options, &f->defaults);
    if (!r) {
        *s = result ? CM_ERR_NO_MEMORY : CM_ERR_ARGUMENT;
        return NULL;
    }
    *options = relay_progress(*options, &f->relayed, &f->relay);
    const cm_options *o = *options;
    *s = CM_OK;
    if (o->method != CM_METHOD_OVERLAY && o->method != CM_METHOD_PARTITION)
        *s = cm_fail(&r->error, CM_ERR_ARGUMENT, "unknown method %d", (int)o->method);
    if (*s == CM_OK) *s = check_remesh_options(r, o);
    if (*s == CM_OK) *s = check_correspondence_options(r, o);
    memos_start(r, o);
    f->outer = cm_deadline_begin(*s == CM_OK ? o->time_limit : 0);
    return r;
}

/* The end of a call that ran to status s: *result (whichever run it came
 * from) told the relay's end, its memos freed, its geometry cleared on
 * failure and its error closed. */
static cm_status call_end(cm_result *const *result, const cm_options *o, call_frame *f, cm_status s)
{
    cm_result *r = *result;
    r->stats.time_limit_reached = cm_deadline_end(f->outer);
    s = relay_done(r, o, s);
    memos_end(r);
    if (s != CM_OK) cm_result_clear_geometry(r);
    return cm_error_close(&r->error, s);
}

cm_status cm_triangulate_polygons(const double *const *polygons, const size_t *counts,
                                  size_t k, const cm_options *options, cm_result **result)
{
    call_frame frame;
    cm_status s;
    cm_result *r = call_begin(result, &options, &frame, &s);
    if (!r) return s;
    if (s == CM_OK && options->correspondence != CM_CORRESPOND_INDEX) {
        const polygon_input input = {polygons, counts, k};
        const rescue_input rescue = {run_pairing, &input, 0};
        s = run_arclength(r, polygons, counts, k, options, NULL, by_ceiling);
        if (s == CM_OK) s = pairing_rescue(result, options, &rescue);
    } else if (s == CM_OK && options->max_edge > 0)
        s = run_index_split(r, polygons, counts, k, options);
    else if (s == CM_OK)
        s = run_pipeline(r, polygons, counts, k, NULL, NULL, options);
    return call_end(result, options, &frame, s);
}

cm_status cm_triangulate(const double *xy, size_t k, size_t n, const cm_options *options,
                         cm_result **result)
{
    if (!xy) return cm_triangulate_polygons(NULL, NULL, k, options, result);
    const double **polygons = malloc((k + 1) * sizeof *polygons);
    size_t *counts = malloc((k + 1) * sizeof *counts);
    cm_status s = CM_ERR_NO_MEMORY;
    if (polygons && counts) {
        for (size_t g = 0; g < k; g++) polygons[g] = xy + 2 * n * g, counts[g] = n;
        s = cm_triangulate_polygons(polygons, counts, k, options, result);
    } else if (result) {
        *result = NULL;
    }
    free(polygons), free(counts);
    return s;
}

/* ---- polygons with holes ----------------------------------------------- */

/* The input loops r->boundary's labels refer to with holes (edges
 * numbered in each polygon's whole array), for the points the remesher
 * adds on the refined loops' edges: loop l of polygon g starts at input
 * vertex start[g (L + 1) + l], orientation[g L + l] its direction as
 * cm_correspond_arclength took it. */
typedef struct loop_edge_inputs {
    const cm_loops *polygons;
    size_t k, L;
    const size_t *start;
    const int *orientation;
} loop_edge_inputs;

/* cm_kmesh_between on the refined loops: the outer loop runs as its map
 * does, a hole against it, so a hole's piece goes from b back to a; the
 * point as edge_between's, on the input loop the labels name. */
static int loop_edge_between(void *ctx, size_t g, int32_t ea, double ta, int32_t eb, double tb, int step,
                             int32_t *e, double *t, double xy[2])
{
    const loop_edge_inputs *in = ctx;
    const size_t *start = in->start + g * (in->L + 1);
    size_t l = cm_loop_of(start, in->L, (size_t)ea), s = start[l], count = start[l + 1] - s;
    double t0, t1;
    if (l == 0)
        cm_boundary_piece(ea - (int32_t)s, ta, eb - (int32_t)s, tb, count, in->orientation[g * in->L] < 0, e, &t0, &t1);
    else
        cm_boundary_piece(eb - (int32_t)s, tb, ea - (int32_t)s, ta, count, in->orientation[g * in->L + l] < 0, e,
                          &t1, &t0);
    if (!piece_middle(t0, t1, step, t)) return 0; /* t0 at a in both cases */
    cm_edge_point(in->polygons[g].xy + 2 * s, count, *e, *t, xy);
    *e += (int32_t)s;
    return 1;
}

/* cm_remesh_boundary's place on the loops' labels. */
static void loop_edge_place(void *ctx, size_t g, int32_t e, double t, double xy[2])
{
    const loop_edge_inputs *in = ctx;
    const size_t *start = in->start + g * (in->L + 1);
    size_t l = cm_loop_of(start, in->L, (size_t)e), s = start[l];
    cm_edge_point(in->polygons[g].xy + 2 * s, start[l + 1] - s, e - (int32_t)s, t, xy);
}

/* After boundary splits with holes: the refined loops' new starts (loop
 * of each boundary vertex read off polygon 0's labels, the loops staying
 * in order), r->boundary's coordinates and perm (the identity) for the
 * new_n boundary vertices. 0, or -1 out of memory. */
static int take_split_loops(cm_result *r, size_t new_n, const loop_edge_inputs *in, size_t *loop_start,
                            int32_t **perm)
{
    int32_t *p = realloc(*perm, new_n * sizeof *p);
    if (!p) return -1;
    *perm = p;
    if (take_split_boundary(r, new_n)) return -1;
    for (size_t v = 0; v < new_n; v++) p[v] = (int32_t)v;
    for (size_t l = 0; l <= in->L; l++) loop_start[l] = 0;
    for (size_t v = 0; v < new_n; v++) loop_start[cm_loop_of(in->start, in->L, (size_t)r->boundary.edge[0][v]) + 1]++;
    for (size_t l = 0; l < in->L; l++) loop_start[l + 1] += loop_start[l];
    return 0;
}

/* Internal vertex j of loop l (material to its left) is input vertex
 * start[l] + j, or start[l] + cm_loop_reversed(m, j) for a reversed loop. */
static int32_t loop_input_index(const size_t *start, const int *reversed, size_t l, size_t j)
{
    size_t m = start[l + 1] - start[l];
    return (int32_t)(start[l] + (reversed[l] ? cm_loop_reversed(m, j) : j));
}

/* Triangulates every piece of the cut and glues them into r->mesh
 * (internal numbering: the n loop vertices first, then the paths' bends).
 * on: NULL, or where the boundary vertices lie on the inputs, internal
 * loop vertex v being boundary vertex perm[v]. */
static cm_status build_pieces(cm_result *r, const double *const *geoms, size_t k, size_t n,
                              const cm_pieces *pieces, const cm_on_edges *on, const int32_t *perm,
                              const cm_options *o, cm_progress *progress)
{
    size_t bends = pieces->bends;
    cm_mesh whole = {k, n + bends, 0, calloc(k, sizeof(double *)), NULL, NULL, 0};
    const double **piece_xy = calloc(k, sizeof *piece_xy);
    double *buffer = NULL;
    cm_status s = CM_ERR_NO_MEMORY;
    size_t largest = 0, fallbacks = 0;
    cm_options piece_options = *o;
    piece_options.ceiling = 0; /* a piece's ceiling says nothing about the whole */
    for (size_t p = 0; p < pieces->count; p++)
        if (pieces->start[p + 1] - pieces->start[p] > largest) largest = pieces->start[p + 1] - pieces->start[p];
    buffer = malloc(2 * k * largest * sizeof *buffer);
    int32_t *on_boundary = on ? malloc(largest * sizeof *on_boundary) : NULL;
    cm_on_edges piece_on = on ? *on : (cm_on_edges){0};
    piece_on.vertex = on_boundary;
    if (!whole.xy || !piece_xy || !buffer || (on && !on_boundary)) goto done;
    for (size_t g = 0; g < k; g++) {
        if (!(whole.xy[g] = malloc(2 * (n + bends) * sizeof(double)))) goto done;
        memcpy(whole.xy[g], geoms[g], 2 * n * sizeof(double));
        memcpy(whole.xy[g] + 2 * n, pieces->bend_xy[g], 2 * bends * sizeof(double));
    }
    s = CM_OK;
    for (size_t p = 0; p < pieces->count && s == CM_OK; p++) {
        const int32_t *ids = pieces->vertex + pieces->start[p];
        size_t m = pieces->start[p + 1] - pieces->start[p];
        for (size_t g = 0; g < k; g++) {
            double *xy = buffer + 2 * largest * g;
            for (size_t i = 0; i < m; i++) {
                const double *at = whole.xy[g] + 2 * ids[i]; /* a loop vertex or a bend */
                xy[2 * i] = at[0], xy[2 * i + 1] = at[1];
            }
            piece_xy[g] = xy;
        }
        for (size_t i = 0; on && i < m; i++) on_boundary[i] = (size_t)ids[i] < n ? perm[ids[i]] : -1;
        r->stats.fallback_count = 0;
        s = build_first(r, piece_xy, NULL, k, m, 0, on ? &piece_on : NULL, &piece_options, progress);
        fallbacks += r->stats.fallback_count;
        if (s == CM_OK && cm_holes_glue(&whole, ids, m, &r->mesh) != CM_OK)
            s = cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
        else if (s != CM_OK && s != CM_ERR_NO_MEMORY && s != CM_ERR_CANCELLED) {
            char detail[sizeof r->error.message];
            snprintf(detail, sizeof detail, "%s", r->error.message);
            cm_fail(&r->error, s, "piece %zu of %zu the hole bridges cut: %s", p, pieces->count, detail);
        }
        cm_mesh_clear(&r->mesh);
    }
    r->stats.fallback_count = fallbacks;
done:
    if (s == CM_OK) {
        r->mesh = whole;
    } else {
        cm_mesh_clear(&whole);
        if (s == CM_ERR_NO_MEMORY) cm_fail_status(&r->error, s);
    }
    free(piece_xy), free(buffer), free(on_boundary);
    return s;
}

/* Internal numbering back to input order: loop vertex j of r->mesh moves
 * to position perm[j]; Steiner vertices keep theirs. */
static cm_status permute_loop_vertices(cm_result *r, const int32_t *perm, size_t n)
{
    cm_mesh *m = &r->mesh;
    double *tmp = malloc(2 * n * sizeof *tmp);
    if (!tmp) return cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    for (size_t g = 0; g < m->k; g++) {
        for (size_t j = 0; j < n; j++)
            tmp[2 * perm[j]] = m->xy[g][2 * j], tmp[2 * perm[j] + 1] = m->xy[g][2 * j + 1];
        memcpy(m->xy[g], tmp, 2 * n * sizeof *tmp);
    }
    free(tmp);
    for (size_t t = 0; t < 3 * m->nt; t++)
        if ((size_t)m->tri[t] < n) m->tri[t] = perm[m->tri[t]];
    return CM_OK;
}

/* edges: NULL, or the input loops of r->boundary when the remesher may
 * split its edges (the refined loops of run_loops_arclength). */
static cm_status run_loops(cm_result *r, const cm_loops *polygons, size_t k, const loop_edge_inputs *edges,
                           const cm_options *o)
{
    cm_progress progress;
    cm_progress_init(&progress, o->progress, o->progress_user);
    double t0 = cm_seconds_now();
    if (cm_progress_report(&progress, CM_STAGE_VALIDATE, 0.0)) return cm_fail_status(&r->error, CM_ERR_CANCELLED);
    size_t num_loops = polygons && k ? polygons[0].num_loops : 0;
    int *reversed = malloc((num_loops + 1) * sizeof *reversed);
    size_t *start = malloc((num_loops + 1) * sizeof *start);
    double **geoms = calloc(k + 1, sizeof *geoms);
    int32_t *perm = NULL;
    cm_pieces pieces = {0};
    cm_status s = reversed && start && geoms ? CM_OK : cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    if (s == CM_OK) s = cm_input_validate_loops(polygons, k, &r->error, reversed);
    if (s != CM_OK) goto done;
    start[0] = 0;
    for (size_t l = 0; l < num_loops; l++) start[l + 1] = start[l] + polygons[0].loop_sizes[l];
    size_t n = start[num_loops];
    r->n = n;
    r->stats.n = n, r->stats.k = k, r->stats.holes = num_loops - 1;
    r->stats.reversed_input = reversed[0];
    if (!(perm = malloc(n * sizeof *perm))) goto oom;
    for (size_t l = 0; l < num_loops; l++)
        for (size_t j = 0; j < start[l + 1] - start[l]; j++)
            perm[start[l] + j] = loop_input_index(start, reversed, l, j);
    for (size_t g = 0; g < k; g++) {
        if (!(geoms[g] = malloc(2 * n * sizeof *geoms[g]))) goto oom;
        for (size_t v = 0; v < n; v++)
            geoms[g][2 * v] = polygons[g].xy[2 * perm[v]], geoms[g][2 * v + 1] = polygons[g].xy[2 * perm[v] + 1];
    }
    double t1 = cm_seconds_now();
    r->stats.seconds_validate = t1 - t0;
    if (o->ceiling) {
        double cap = loops_corner_fan_cap((const double *const *)geoms, k, start, num_loops);
        if (cap < 0) goto oom;
        r->stats.corner_fan_cap_deg = r->stats.ceiling_deg = cap;
        r->stats.correspondence_bound_deg = 60.0, r->stats.modulus_distortion = 1.0;
        for (int i = 0; i < 4; i++) r->stats.distortion_quad[i] = -1;
        r->stats.seconds_ceiling = cm_seconds_now() - t1;
    }
    if (cm_progress_report(&progress, CM_STAGE_TRIANGULATE, 0.0)) {
        s = cm_fail_status(&r->error, CM_ERR_CANCELLED);
        goto done;
    }
    /* The bridges' pieces (few Steiner vertices), else, and for the overlay
     * method, the construction that always succeeds. */
    s = o->method == CM_METHOD_OVERLAY ? CM_ERR_INTERNAL
                                       : cm_holes_cut((const double *const *)geoms, k, start, num_loops, &pieces, &r->error);
    r->stats.bridges = pieces.chords;
    cm_on_edges on_edges, *on = NULL;
    if (s == CM_OK && r->boundary.n == n && r->boundary.k == k) { /* the arc-length path's boundaries */
        s = on_edges_init(r, start, num_loops, &on_edges);
        on = s == CM_OK ? &on_edges : NULL;
    }
    if (s == CM_OK) s = build_pieces(r, (const double *const *)geoms, k, n, &pieces, on, perm, o, &progress);
    int splittable = edges && on; /* the labels follow the internal order: no loop reversed */
    for (size_t l = 0; l < num_loops; l++) splittable &= !reversed[l];
    if (on) free((void *)on->loop_start);
    if (s != CM_OK && s != CM_ERR_NO_MEMORY && s != CM_ERR_CANCELLED) {
        cm_mesh_clear(&r->mesh);
        r->stats.fallback_count = 1;
        s = cm_holes_overlay((const double *const *)geoms, k, start, num_loops, &r->mesh, &r->stats.bridges,
                             &r->error);
    }
    if (s != CM_OK) goto done;
    r->stats.seconds_build = cm_seconds_now() - t1 - r->stats.seconds_ceiling;
    r->mesh.loop_start = start, r->mesh.num_loops = num_loops; /* the remesher's boundary */
    cm_remesh_boundary splits = {loop_edge_between, (void *)edges, r->boundary.edge, r->boundary.t, n,
                                 chosen_mode(o) ? loop_edge_place : NULL, o->max_edge, 0};
    s = remesh_stage(r, n, o, splittable ? &splits : NULL, &progress);
    r->mesh.loop_start = NULL, r->mesh.num_loops = 0;
    if (s != CM_OK) goto done;
    if (splits.n > n && take_split_loops(r, n = splits.n, edges, start, &perm)) goto oom;
    if (splits.slid && splits.n == n && take_split_boundary(r, n)) goto oom; /* slid points */
    if ((s = permute_loop_vertices(r, perm, n)) != CM_OK) goto done;
    double t2 = cm_seconds_now();
    if (cm_progress_report(&progress, CM_STAGE_CHECK, 0.0)) {
        s = cm_fail_status(&r->error, CM_ERR_CANCELLED);
        goto done;
    }
    s = cm_halfedge_build_and_check(r, perm, start, num_loops);
    if (s == CM_ERR_NO_MEMORY) cm_fail_status(&r->error, s);
    if (s != CM_OK) goto done;
    r->stats.seconds_check = cm_seconds_now() - t2;
    s = cm_result_measure(r, NULL);
    if (s == CM_OK && cm_progress_report(&progress, CM_STAGE_DONE, 0.0)) s = cm_fail_status(&r->error, CM_ERR_CANCELLED);
    if (s == CM_OK) r->loop_start = start, r->num_loops = num_loops, start = NULL; /* the morph fills the holes */
    goto done;
oom:
    s = cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
done:
    if (geoms)
        for (size_t g = 0; g < k; g++) free(geoms[g]);
    free(geoms), free(reversed), free(start), free(perm);
    cm_pieces_free(&pieces);
    return s;
}

/* CM_CORRESPOND_ARCLENGTH and _AUTO for polygons with holes: loop l of
 * every polygon corresponds to loop l, and within each loop as for a
 * polygon without holes (corner pins and max_edge per loop). Auto pairs
 * the outer loops as polygons without holes (the conformal correspondence
 * of the filled outer loops, or the similarity choice of a start where
 * that allows the higher ceiling: auto_whole), and chooses every hole's
 * start jointly with them: the start whose points lie nearest to polygon
 * 0's hole carried radially through the outer loops' correspondence
 * (cm_correspond_choose_hole_starts; a hole aligned on its own may turn
 * against the outer loop and twist the map around it), then the hole by
 * arc length from there. The caller's pins
 * are refused: they would have to name loops. CM_CORRESPOND_INDEX with
 * max_edge comes here too, as pins at every vertex of each loop. With
 * remeshing (not for index), the edges of every loop whose cap binds are
 * then halved as without holes (cm_boundary_maps_split_caps, the aim
 * lowered to the corner fan over the loops). The
 * refined loops then take the index pipeline, and r->boundary maps every
 * boundary vertex to its input edge, numbered in the polygon's whole array
 * (the edge from a vertex to the next of its loop); with remeshing the
 * remesher may split the loops' edges there too (loop_edge_between). */
static cm_status run_loops_arclength(cm_result *r, const cm_loops *polygons, size_t k, const cm_options *o,
                                     enum loop_kind outer, auto_pairing pairing)
{
    if (o->num_pins)
        return cm_fail(&r->error, CM_ERR_ARGUMENT,
                       "pins are not taken for polygons with holes; pin_corners_deg and the auto "
                       "correspondence work loop by loop");
    if (!polygons || k < 2) return cm_input_check_loops(polygons, k, NULL, &r->error);
    size_t L = polygons[0].num_loops;
    /* loop l's k input loops: xy, count and loop_orientation from l k */
    int *orientation = malloc((k * L + 1) * sizeof *orientation), *loop_orientation = malloc(k * L * sizeof(int));
    size_t *start = malloc(k * (L + 1) * sizeof *start), *count = malloc(k * L * sizeof *count);
    size_t *sizes = malloc((L + 1) * sizeof *sizes), *order = malloc(k * L * sizeof *order);
    const double **xy = malloc(k * L * sizeof *xy);
    cm_boundary_map *maps = calloc(L + 1, sizeof *maps);
    cm_loops *refined = malloc(k * sizeof *refined);
    cm_status s = orientation && loop_orientation && start && count && sizes && order && xy && maps && refined
                      ? CM_OK
                      : cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    int index_split = o->correspondence == CM_CORRESPOND_INDEX;
    size_t *every = NULL;
    if (s == CM_OK && !index_split) s = cm_input_check_loops(polygons, k, orientation, &r->error);
    if (s == CM_OK && index_split) { /* equal sizes and directions, then vertex i on vertex i */
        int *reversed = malloc(L * sizeof *reversed);
        s = reversed ? cm_input_validate_loops(polygons, k, &r->error, reversed) : cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
        /* Every polygon runs each loop the same way: outer counter-clockwise
         * unless reversed, holes clockwise unless reversed. */
        for (size_t g = 0; s == CM_OK && g < k; g++)
            for (size_t l = 0; l < L; l++) orientation[g * L + l] = (l == 0) == !reversed[l] ? 1 : -1;
        free(reversed);
        size_t largest = 0;
        for (size_t l = 0; l < L; l++) largest = polygons[0].loop_sizes[l] > largest ? polygons[0].loop_sizes[l] : largest;
        if (s == CM_OK && !(every = malloc(largest * k * sizeof *every))) s = cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
        for (size_t j = 0; s == CM_OK && j < largest; j++)
            for (size_t g = 0; g < k; g++) every[j * k + g] = j;
    }
    for (size_t i = 0; order && i < k * L; i++) order[i] = i % L; /* loop l of every polygon pairs with loop l */
    for (size_t g = 0; s == CM_OK && g < k; g++) {
        start[g * (L + 1)] = 0;
        for (size_t l = 0; l < L; l++) start[g * (L + 1) + l + 1] = start[g * (L + 1) + l] + polygons[g].loop_sizes[l];
    }
    size_t n = 0;
    double unused_ceiling; /* the holes' ceiling is the corner fan */
    cm_correspondence_choice loop_choice;
    int joint = chosen_mode(o);
    double *similarity = NULL;
    size_t *hole_starts = NULL;
    if (s == CM_OK && joint && (!(similarity = malloc(4 * k * sizeof *similarity)) ||
                                !(hole_starts = malloc(k * sizeof *hole_starts))))
        s = cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    if (s == CM_OK && pairing.kind == PAIRING_ANNULUS) { /* both loops at once, each paired with its own */
        for (size_t l = 0; l < L; l++)
            for (size_t g = 0; g < k; g++) {
                xy[l * k + g] = polygons[g].xy + 2 * start[g * (L + 1) + l];
                count[l * k + g] = polygons[g].loop_sizes[l], loop_orientation[l * k + g] = orientation[g * L + l];
            }
        /* affine images of one another pair vertex to vertex, as the outer
         * loops' pairing finds them */
        size_t *shift = malloc(count[0] * k * sizeof *shift);
        int affine = 0;
        s = shift ? cm_correspond_affine_shift(xy, count, k, loop_orientation, polygons, shift, &affine, &r->error)
                  : cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
        free(shift);
        if (s == CM_OK && affine) pairing = by_ceiling;
        else if (s == CM_OK) {
            s = annulus(r, polygons, k, orientation, xy, count, loop_orientation, pairing.power, o->max_edge, maps);
            r->stats.correspondence_choice = CM_CHOICE_ANNULUS;
        }
    }
    for (size_t l = 0; s == CM_OK && pairing.kind != PAIRING_ANNULUS && l < L; l++) {
        const double **lxy = xy + l * k;
        size_t *lcount = count + l * k;
        int *lorientation = loop_orientation + l * k;
        if (joint && l == 1) {
            s = cm_correspond_match_holes(polygons, k, &maps[0], order, &r->stats.holes_moved, &r->error);
            cm_correspond_outer_similarity(&maps[0], similarity);
        }
        for (size_t g = 0; g < k; g++) {
            size_t from = order[g * L + l];
            lxy[g] = polygons[g].xy + 2 * start[g * (L + 1) + from];
            lcount[g] = polygons[g].loop_sizes[from], lorientation[g] = orientation[g * L + from];
        }
        if (s == CM_OK && joint && l > 0)
            s = cm_correspond_choose_hole_starts(lxy, lcount, k, lorientation, &maps[0], similarity, hole_starts,
                                                 &r->error);
        if (s == CM_OK)
            s = correspond_boundary(r, lxy, lcount, k, lorientation, o, every, l ? LOOP_BY_START : outer, pairing,
                                    joint && l ? hole_starts : NULL, l ? NULL : polygons, &maps[l], &unused_ceiling,
                                    &loop_choice);
        if (l == 0) r->stats.correspondence_choice = loop_choice; /* the outer loop's (cm_stats) */
        if (s != CM_OK && s != CM_ERR_NO_MEMORY && s != CM_ERR_CANCELLED) {
            char detail[sizeof r->error.message];
            snprintf(detail, sizeof detail, "%s", r->error.message);
            long g = r->error.polygon, v = r->error.vertex;
            size_t from = g >= 0 && (size_t)g < k ? order[(size_t)g * L + l] : l; /* the input's loop */
            if (g >= 0 && (size_t)g < k && v >= 0) cm_fail_at(&r->error, g, (long)start[(size_t)g * (L + 1) + from] + v, -1);
            cm_fail(&r->error, s, "%s %zu: %s", l ? "hole" : "outer loop", from, detail);
        }
    }
    if (s == CM_OK && !index_split && o->remesh) { /* edges whose cap binds, halved in every loop */
        cm_cap_loop *loops = malloc(L * sizeof *loops);
        cap_aim a = {r, -1, k};
        size_t total = 0;
        for (size_t l = 0; loops && l < L; l++)
            loops[l] = (cm_cap_loop){&maps[l], xy + l * k, count + l * k, loop_orientation + l * k}, total += maps[l].n;
        s = loops ? cm_boundary_maps_split_caps(loops, L, o->min_angle_deg * CM_PI / 180.0,
                                                o->ceiling ? holes_cap_ceiling : NULL, &a, total + CM_CAP_SPLIT_EXTRA,
                                                NULL, NULL, &r->error)
                  : cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
        free(loops);
    }
    for (size_t l = 0; s == CM_OK && l < L; l++) sizes[l] = maps[l].n, n += maps[l].n;
    /* The refined loops one after another, as the index pipeline takes them. */
    cm_boundary_map *b = &r->boundary;
    if (s == CM_OK) {
        b->k = k, b->n = n;
        b->xy = calloc(k, sizeof *b->xy), b->edge = calloc(k, sizeof *b->edge), b->t = calloc(k, sizeof *b->t);
        if (!b->xy || !b->edge || !b->t) s = cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    }
    for (size_t g = 0; s == CM_OK && g < k; g++) {
        b->xy[g] = malloc(2 * n * sizeof *b->xy[g]), b->edge[g] = malloc(n * sizeof *b->edge[g]);
        b->t[g] = malloc(n * sizeof *b->t[g]);
        if (!b->xy[g] || !b->edge[g] || !b->t[g]) {
            s = cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
            break;
        }
        for (size_t l = 0, at = 0; l < L; at += maps[l].n, l++) {
            /* The maps run every loop counter-clockwise; holes are listed
             * clockwise from the same start, so a hole given clockwise
             * (the usual way) keeps its input order. */
            size_t m = maps[l].n;
            for (size_t i = 0; i < m; i++) {
                size_t from = l ? cm_loop_reversed(m, i) : i;
                b->xy[g][2 * (at + i)] = maps[l].xy[g][2 * from];
                b->xy[g][2 * (at + i) + 1] = maps[l].xy[g][2 * from + 1];
                b->t[g][at + i] = maps[l].t[g][from];
                b->edge[g][at + i] = (int32_t)start[g * (L + 1) + order[g * L + l]] + maps[l].edge[g][from];
            }
        }
        refined[g] = (cm_loops){b->xy[g], sizes, L};
    }
    if (s == CM_OK) {
        cm_options by_index = *o;
        by_index.correspondence = CM_CORRESPOND_INDEX;
        by_index.pin_corners_deg = 0, by_index.max_edge = 0;
        loop_edge_inputs edges = {polygons, k, L, start, orientation};
        s = run_loops(r, refined, k, !index_split && o->remesh ? &edges : NULL, &by_index);
        locate_in_input(r, s);
    }
    for (size_t l = 0; maps && l < L; l++) cm_boundary_map_clear(&maps[l]);
    free(orientation), free(loop_orientation), free(start), free(count), free(sizes), free(order), free(xy), free(maps),
        free(refined);
    free(every), free(similarity), free(hole_starts);
    return s;
}

/* Auto with holes pairs the outer loops as polygons without holes (one
 * hole: the annulus first, run_annulus_first), and where the result ends
 * short of its aim takes the same rescues (pairing_rescue), first arc
 * length from the similarity's start (PAIRING_BY_START): the
 * hole starts, chosen under the outer loops' similarity, may fit one
 * pairing of the outer loops and not the other, since a conformal pairing
 * of the filled outlines knows nothing of the holes. */
typedef struct loop_input {
    const cm_loops *polygons;
    size_t k;
} loop_input;

static cm_status run_loop_pairing(cm_result *again, const void *input, const cm_options *o, const void *pairing)
{
    const loop_input *in = input;
    const auto_pairing *p = pairing; /* a loop paired from its start takes no pairing */
    return run_loops_arclength(again, in->polygons, in->k, o, p->kind == PAIRING_BY_START ? LOOP_BY_START : LOOP_OUTER,
                               *p);
}

cm_correspondence cm_correspondence_by_counts(const cm_loops *polygons, size_t k, int pinned)
{
    if (pinned) return CM_CORRESPOND_ARCLENGTH;
    for (size_t g = 1; polygons && g < k; g++)
        for (size_t l = 0; l < polygons[g].num_loops && l < polygons[0].num_loops; l++)
            if (polygons[g].loop_sizes[l] != polygons[0].loop_sizes[l]) return CM_CORRESPOND_AUTO;
    return CM_CORRESPOND_INDEX;
}

/* Has every polygon exactly one hole? */
static int one_hole(const cm_loops *polygons, size_t k)
{
    int one = polygons && k > 0;
    for (size_t g = 0; one && g < k; g++) one = polygons[g].num_loops == 2;
    return one;
}

/* Auto's first run for polygons with one hole: the annulus pairing of
 * both loops; where it cannot be had (the map not in doubles), the outer
 * loops' pairing in a fresh result. */
static cm_status run_annulus_first(cm_result **result, const cm_loops *polygons, size_t k, const cm_options *o)
{
    static const auto_pairing annulus_pairing = {PAIRING_ANNULUS, 0, CM_CONFORMAL_POWER};
    cm_status s = run_loops_arclength(*result, polygons, k, o, LOOP_OUTER, annulus_pairing);
    if (s == CM_OK || s == CM_ERR_CANCELLED || s == CM_ERR_NO_MEMORY) return s;
    cm_result *fresh = rescue_result(*result, o);
    if (!fresh) return cm_fail_status(&(*result)->error, CM_ERR_NO_MEMORY);
    add_costs(fresh, *result);
    cm_result_free(*result);
    *result = fresh;
    next_run(o, NULL);
    return run_loops_arclength(fresh, polygons, k, o, LOOP_OUTER, by_ceiling);
}

cm_status cm_triangulate_loops(const cm_loops *polygons, size_t k, const cm_options *options,
                               cm_result **result)
{
    int holes = 0;
    for (size_t g = 0; polygons && g < k; g++) holes |= polygons[g].num_loops != 1;
    if (polygons && k && !holes) { /* hole-free: exactly cm_triangulate_polygons */
        const double **xy = malloc(k * sizeof *xy);
        size_t *counts = malloc(k * sizeof *counts);
        cm_status s = CM_ERR_NO_MEMORY;
        if (xy && counts) {
            for (size_t g = 0; g < k; g++)
                xy[g] = polygons[g].xy, counts[g] = polygons[g].loop_sizes ? polygons[g].loop_sizes[0] : 0;
            s = cm_triangulate_polygons(xy, counts, k, options, result);
        } else if (result) {
            *result = NULL;
        }
        free(xy), free(counts);
        return s;
    }
    call_frame frame;
    cm_status s;
    cm_result *r = call_begin(result, &options, &frame, &s);
    if (!r) return s;
    const loop_input input = {polygons, k};
    const rescue_input rescue = {run_loop_pairing, &input, polygons ? polygons[0].num_loops - 1 : 0};
    if (s == CM_OK && options->correspondence == CM_CORRESPOND_AUTO && one_hole(polygons, k))
        s = run_annulus_first(result, polygons, k, options);
    else if (s == CM_OK && (options->correspondence != CM_CORRESPOND_INDEX || options->max_edge > 0))
        s = run_loops_arclength(r, polygons, k, options, LOOP_OUTER, by_ceiling);
    else if (s == CM_OK) s = run_loops(r, polygons, k, NULL, options);
    if (s == CM_OK) s = pairing_rescue(result, options, &rescue);
    return call_end(result, options, &frame, s);
}
