/* Morphing through valid sections (paper section 1).
 *
 * Convex-combination morph (Floater and Gotsman, "How to morph tilings
 * injectively", 1999): inside a common convex enclosure every interior
 * vertex is a convex combination of its neighbours, with mean value
 * weights (Floater 2003), positive in a valid triangulation. Interpolating
 * the normalized weights linearly in time keeps them positive, and by
 * Tutte's theorem the solution of the linear system is a valid
 * triangulation at every time. UMFPACK solves the system; its pattern is
 * fixed, so the symbolic analysis is done once. Every section is still
 * checked with exact predicates.
 *
 * CM_MORPH_INTRINSIC interpolates the stars instead of the weights: each
 * corner angle linearly, each edge length geometrically, and takes the
 * mean value coordinates of the interpolated star (the intrinsic
 * interpolation of Surazhsky and Gotsman, 2003). The angles stay in
 * (0, pi), so the weights stay positive and Tutte's theorem still holds. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <umfpack.h>

#include "morph/enclosure.h"
#include "morph/fill_holes.h"
#include "morph/morph.h"
#include "base/progress.h"
#include "geom/angle.h"
#include "geom/polygon_check.h"
#include "geom/predicates.h"

void cm_morph_options_init(cm_morph_options *options)
{
    memset(options, 0, sizeof *options);
    options->method = CM_MORPH_CONVEX;
}

/* Interior vertices' neighbour lists (sorted, unique) from the triangles. */
static cm_status build_neighbours(cm_morph *m)
{
    const cm_mesh *f = &m->full;
    size_t *count = calloc(f->nv + 1, sizeof *count), *fill = NULL;
    int32_t *inc = NULL;
    cm_status s = CM_ERR_NO_MEMORY;
    if (!count) goto done;
    for (size_t j = 0; j < 3 * f->nt; j++) count[f->tri[j] + 1]++;
    for (size_t v = 0; v < f->nv; v++) count[v + 1] += count[v];
    inc = malloc(3 * f->nt * sizeof *inc);
    fill = malloc(f->nv * sizeof *fill);
    m->start = calloc((size_t)m->nu + 1, sizeof *m->start);
    m->nbr = malloc(6 * f->nt * sizeof *m->nbr); /* two per corner at most */
    if (!inc || !fill || !m->start || !m->nbr) goto done;
    memcpy(fill, count, f->nv * sizeof *fill);
    for (size_t j = 0; j < 3 * f->nt; j++) inc[fill[f->tri[j]]++] = (int32_t)(j / 3);
    size_t e = 0;
    for (size_t v = 0; v < f->nv; v++) {
        int32_t row = m->unknown[v];
        if (row < 0) continue;
        size_t first = e;
        for (size_t c = count[v]; c < count[v + 1]; c++)
            for (int q = 0; q < 3; q++) {
                int32_t w = f->tri[3 * (size_t)inc[c] + q];
                if ((size_t)w == v) continue;
                size_t x = first;
                while (x < e && m->nbr[x] != w) x++;
                if (x == e) m->nbr[e++] = w;
            }
        m->start[row + 1] = e;
    }
    s = CM_OK;
done:
    free(count), free(fill), free(inc);
    return s == CM_OK ? s : cm_fail_status(&m->error, s);
}

static size_t find_neighbour(const cm_morph *m, int32_t row, int32_t w)
{
    size_t x = m->start[row];
    while (m->nbr[x] != w) x++;
    return x;
}

/* Normalized mean value weights of every interior vertex in geometry g:
 * w_j = (tan(a_{j-1} / 2) + tan(a_j / 2)) / |v_j - v|, accumulated per
 * triangle (each contributes its angle at v to both of its other vertices). */
/* The smallest tan(a / 2) a weight uses: far below any angle doubles
 * resolve between edges of comparable length, far above underflow once
 * normalised; its inverse the largest. */
#define SLIVER_HALF_TAN 0x1p-60

static void mean_value_weights(cm_morph *m, size_t g)
{
    const cm_mesh *f = &m->full;
    const double *xy = f->xy[g];
    double *lam = m->lambda[g];
    memset(lam, 0, m->start[m->nu] * sizeof *lam);
    /* The weights do not change with scale, but their products overflow at
     * 1e300 and underflow at 1e-300: edge vectors are scaled by the power
     * of two (exact) that brings the largest coordinate near 1. */
    double largest = 0;
    for (size_t v = 0; v < 2 * f->nv; v++) largest = fmax(largest, fabs(xy[v]));
    int exponent = 0;
    frexp(largest, &exponent);
    double scale = ldexp(1.0, -exponent);
    for (size_t t = 0; t < f->nt; t++)
        for (int c = 0; c < 3; c++) {
            int32_t v = f->tri[3 * t + c], a = f->tri[3 * t + (c + 1) % 3], b = f->tri[3 * t + (c + 2) % 3];
            int32_t row = m->unknown[v];
            if (row < 0) continue;
            const double *p = xy + 2 * (size_t)v, *pa = xy + 2 * (size_t)a, *pb = xy + 2 * (size_t)b;
            double ux = scale * (pa[0] - p[0]), uy = scale * (pa[1] - p[1]);
            double wx = scale * (pb[0] - p[0]), wy = scale * (pb[1] - p[1]);
            double lu = hypot(ux, uy), lw = hypot(wx, wy);
            double cross = ux * wy - uy * wx, dot = ux * wx + uy * wy;
            /* tan(a / 2) = sin a / (1 + cos a) = (1 - cos a) / sin a: the
             * second near a = pi, where 1 + cos a cancels. */
            double half_tan = dot >= 0 ? cross / (lu * lw + dot) : (lu * lw - dot) / cross;
            /* The triangle is counter-clockwise (checked exactly), so its
             * angle at v is in (0, pi); rounded differences of a sliver can
             * still give a cross product of 0 or the wrong sign (angle near
             * 0), or tan(a / 2) near infinity (angle near pi). Any positive
             * weights keep the convex-combination guarantee (and every
             * section is checked exactly), so tan(a / 2) is kept within
             * [2^-60, 2^60], where no weight of a row drowns the others. */
            if (!(half_tan >= SLIVER_HALF_TAN)) half_tan = SLIVER_HALF_TAN;
            if (half_tan > 1 / SLIVER_HALF_TAN) half_tan = 1 / SLIVER_HALF_TAN;
            lam[find_neighbour(m, row, a)] += half_tan / lu;
            lam[find_neighbour(m, row, b)] += half_tan / lw;
        }
    for (int32_t row = 0; row < m->nu; row++) {
        double sum = 0;
        for (size_t x = m->start[row]; x < m->start[row + 1]; x++) sum += lam[x];
        for (size_t x = m->start[row]; x < m->start[row + 1]; x++) lam[x] /= sum;
    }
}

/* Every weight positive and finite (else the system may be singular). */
static cm_status check_weights(cm_morph *m, size_t g)
{
    for (int32_t row = 0; row < m->nu; row++)
        for (size_t x = m->start[row]; x < m->start[row + 1]; x++)
            if (!(m->lambda[g][x] > 0 && isfinite(m->lambda[g][x]))) {
                size_t v = 0;
                while (m->unknown[v] != row) v++;
                return cm_fail(&m->error, CM_ERR_INTERNAL,
                            "morph: mean value weight of vertex %ld towards %d in geometry %zu is %g "
                            "(a triangle too flat for double precision)",
                            (long)v, m->nbr[x], g, m->lambda[g][x]);
            }
    return CM_OK;
}

/* The star shapes for intrinsic weights: per corner at an interior
 * vertex, its angle (in (0, pi) in a valid triangulation) and the log
 * lengths of its two edges, in every geometry. */
static cm_status build_corners(cm_morph *m)
{
    const cm_mesh *f = &m->full;
    size_t nc = 0;
    for (size_t j = 0; j < 3 * f->nt; j++) nc += m->unknown[f->tri[j]] >= 0;
    m->ncorner = nc;
    m->corner_slot = malloc(2 * nc * sizeof *m->corner_slot);
    m->corner_shape = calloc(m->k, sizeof *m->corner_shape);
    m->weights = malloc(m->start[m->nu] * sizeof *m->weights);
    if (!m->corner_slot || !m->corner_shape || !m->weights)
        return cm_fail_status(&m->error, CM_ERR_NO_MEMORY);
    for (size_t g = 0; g < m->k; g++)
        if (!(m->corner_shape[g] = malloc(3 * nc * sizeof *m->corner_shape[g])))
            return cm_fail_status(&m->error, CM_ERR_NO_MEMORY);
    size_t c = 0;
    for (size_t t = 0; t < f->nt; t++)
        for (int q = 0; q < 3; q++) {
            int32_t v = f->tri[3 * t + q], a = f->tri[3 * t + (q + 1) % 3], b = f->tri[3 * t + (q + 2) % 3];
            int32_t row = m->unknown[v];
            if (row < 0) continue;
            m->corner_slot[2 * c] = find_neighbour(m, row, a);
            m->corner_slot[2 * c + 1] = find_neighbour(m, row, b);
            for (size_t g = 0; g < m->k; g++) {
                const double *xy = f->xy[g], *p = xy + 2 * (size_t)v, *pa = xy + 2 * (size_t)a,
                             *pb = xy + 2 * (size_t)b;
                double ux = pa[0] - p[0], uy = pa[1] - p[1], wx = pb[0] - p[0], wy = pb[1] - p[1];
                double *shape = m->corner_shape[g] + 3 * c;
                shape[0] = atan2(ux * wy - uy * wx, ux * wx + uy * wy);
                shape[1] = log(hypot(ux, uy)), shape[2] = log(hypot(wx, wy));
            }
            c++;
        }
    return CM_OK;
}

/* Intrinsic weights at local time s between geometries g and g + 1: mean
 * value coordinates of the interpolated stars. Corner angles stay in
 * (0, pi), so every weight is positive. */
static void intrinsic_weights(cm_morph *m, size_t g, double s)
{
    const double *s0 = m->corner_shape[g], *s1 = m->corner_shape[g + 1];
    double *w = m->weights;
    memset(w, 0, m->start[m->nu] * sizeof *w);
    for (size_t c = 0; c < m->ncorner; c++) {
        double angle = (1 - s) * s0[3 * c] + s * s1[3 * c], half_tan = tan(0.5 * angle);
        w[m->corner_slot[2 * c]] += half_tan * exp(-((1 - s) * s0[3 * c + 1] + s * s1[3 * c + 1]));
        w[m->corner_slot[2 * c + 1]] += half_tan * exp(-((1 - s) * s0[3 * c + 2] + s * s1[3 * c + 2]));
    }
    for (int32_t row = 0; row < m->nu; row++) {
        double sum = 0;
        for (size_t x = m->start[row]; x < m->start[row + 1]; x++) sum += w[x];
        for (size_t x = m->start[row]; x < m->start[row + 1]; x++) w[x] /= sum;
    }
}

/* The triplets of I - Lambda (diagonal first), their compressed-column
 * form and the symbolic factorization. */
static cm_status build_system(cm_morph *m)
{
    size_t ne = m->start[m->nu], nz = (size_t)m->nu;
    m->entry = malloc(ne * sizeof *m->entry);
    if (!m->entry) return cm_fail_status(&m->error, CM_ERR_NO_MEMORY);
    for (size_t x = 0; x < ne; x++) m->entry[x] = m->unknown[m->nbr[x]] >= 0 ? (int32_t)nz++ : -1;
    m->nz = (int)nz;
    m->ti = malloc(nz * sizeof *m->ti), m->tj = malloc(nz * sizeof *m->tj);
    m->map = malloc(nz * sizeof *m->map), m->tx = malloc(nz * sizeof *m->tx);
    m->ap = malloc(((size_t)m->nu + 1) * sizeof *m->ap);
    m->ai = malloc(nz * sizeof *m->ai), m->ax = malloc(nz * sizeof *m->ax);
    m->rhs = malloc(2 * (size_t)m->nu * sizeof *m->rhs);
    m->sol = malloc(2 * (size_t)m->nu * sizeof *m->sol);
    m->pos = malloc(2 * m->full.nv * sizeof *m->pos);
    if (!m->ti || !m->tj || !m->map || !m->tx || !m->ap || !m->ai || !m->ax || !m->rhs || !m->sol || !m->pos)
        return cm_fail_status(&m->error, CM_ERR_NO_MEMORY);
    for (int32_t i = 0; i < m->nu; i++) m->ti[i] = m->tj[i] = i, m->tx[i] = 1.0;
    for (int32_t row = 0; row < m->nu; row++)
        for (size_t x = m->start[row]; x < m->start[row + 1]; x++)
            if (m->entry[x] >= 0) {
                m->ti[m->entry[x]] = row;
                m->tj[m->entry[x]] = m->unknown[m->nbr[x]];
                m->tx[m->entry[x]] = -m->lambda[0][x];
            }
    int st = umfpack_di_triplet_to_col(m->nu, m->nu, m->nz, m->ti, m->tj, m->tx, m->ap, m->ai, m->ax, m->map);
    if (st == UMFPACK_OK)
        st = umfpack_di_symbolic(m->nu, m->nu, m->ap, m->ai, m->ax, &m->symbolic, NULL, NULL);
    if (st == UMFPACK_ERROR_out_of_memory) return cm_fail_status(&m->error, CM_ERR_NO_MEMORY);
    if (st != UMFPACK_OK) return cm_fail(&m->error, CM_ERR_INTERNAL, "morph: UMFPACK analysis failed (status %d)", st);
    return CM_OK;
}

/* Triangles [first, last) of tri not strictly counter-clockwise in xy. */
static size_t count_inverted(const int32_t *tri, size_t first, size_t last, const double *xy)
{
    size_t bad = 0;
    for (size_t t = first; t < last; t++)
        bad += cm_orient2d(xy + 2 * (size_t)tri[3 * t], xy + 2 * (size_t)tri[3 * t + 1],
                           xy + 2 * (size_t)tri[3 * t + 2]) <= 0;
    return bad;
}

/* Each geometry's centre (cm_morph.centre) and its coordinates about it
 * (framed->xy, k new arrays). Centring rounds, so a geometry that it
 * would fold keeps the origin. */
static cm_status build_frames(cm_morph *m, const cm_result *result, cm_mesh *framed)
{
    const cm_mesh *r = &result->mesh;
    m->centre = malloc(2 * m->k * sizeof *m->centre);
    framed->xy = calloc(m->k, sizeof *framed->xy);
    if (!m->centre || !framed->xy) return cm_fail_status(&m->error, CM_ERR_NO_MEMORY);
    for (size_t g = 0; g < m->k; g++) {
        double *xy = framed->xy[g] = malloc(2 * r->nv * sizeof *xy), *c = m->centre + 2 * g;
        if (!xy) return cm_fail_status(&m->error, CM_ERR_NO_MEMORY);
        for (int d = 0; d < 2; d++) {
            double lo = INFINITY, hi = -INFINITY;
            for (size_t i = d; i < 2 * r->nv; i += 2) lo = fmin(lo, r->xy[g][i]), hi = fmax(hi, r->xy[g][i]);
            c[d] = 0.5 * lo + 0.5 * hi;
        }
        for (size_t i = 0; i < 2 * r->nv; i++) xy[i] = r->xy[g][i] - c[i % 2];
        if (count_inverted(r->tri, 0, r->nt, xy)) {
            c[0] = c[1] = 0;
            memcpy(xy, r->xy[g], 2 * r->nv * sizeof *xy);
        }
    }
    return CM_OK;
}

/* Moves the enclosed mesh's positions (m->pos), found about the centres,
 * to the centre interpolated linearly between geometries g and g + 1 at
 * local time s. A translation keeps every orientation; rounding is
 * checked after. */
static void leave_frame(cm_morph *m, size_t g, double s)
{
    const double *a = m->centre + 2 * g, *b = a + 2;
    double cx = (1 - s) * a[0] + s * b[0], cy = (1 - s) * a[1] + s * b[1];
    for (size_t v = 0; v < m->full.nv; v++) m->pos[2 * v] += cx, m->pos[2 * v + 1] += cy;
}

static cm_status create(cm_morph *m, const cm_result *result, const cm_morph_options *options)
{
    cm_morph_options defaults;
    if (!options) cm_morph_options_init(&defaults), options = &defaults;
    if (!result) return cm_fail(&m->error, CM_ERR_ARGUMENT, "morph: result is NULL");
    if (cm_result_status(result) != CM_OK)
        return cm_fail(&m->error, CM_ERR_ARGUMENT, "morph: the result failed (%s)", cm_result_message(result));
    if ((unsigned)options->method > (unsigned)CM_MORPH_INTRINSIC)
        return cm_fail(&m->error, CM_ERR_ARGUMENT, "morph: unknown method %d", (int)options->method);
    m->method = options->method;
    m->k = result->mesh.k, m->nv = result->mesh.nv, m->nt = result->mesh.nt;
    if (m->method == CM_MORPH_LINEAR) {
        m->result = result;
        return CM_OK;
    }

    cm_progress progress;
    cm_progress_init(&progress, options->progress, options->progress_user);
    if (cm_progress_report(&progress, CM_STAGE_ENCLOSURE, 0.0)) return cm_fail_status(&m->error, CM_ERR_CANCELLED);
    /* The morph runs on the geometries about their own centres (framed, a
     * shallow copy with its own coordinates), so that sections far apart
     * do not stretch one annulus across the distance between them, and a
     * pure translation is morphed as exactly that. */
    cm_result framed = *result;
    framed.mesh.xy = NULL;
    cm_status s = build_frames(m, result, &framed.mesh);
    if (s == CM_OK && result->num_loops > 1) {
        /* Holes filled: the enclosure sees a disk bounded by the outer loop. */
        cm_result disk = {.n = result->loop_start[1]};
        disk.stats.n = disk.n;
        s = cm_fill_holes(&framed, &disk.mesh, &m->error);
        if (s == CM_OK) s = cm_enclosure_build(&disk, &progress, &m->full, &m->boundary, &m->error);
        cm_mesh_clear(&disk.mesh);
    } else if (s == CM_OK) {
        s = cm_enclosure_build(&framed, &progress, &m->full, &m->boundary, &m->error);
    }
    if (framed.mesh.xy)
        for (size_t g = 0; g < m->k; g++) free(framed.mesh.xy[g]);
    free(framed.mesh.xy);
    if (s != CM_OK) return s;
    if (cm_progress_report(&progress, CM_STAGE_MORPH_SYSTEM, 0.0)) return cm_fail_status(&m->error, CM_ERR_CANCELLED);
    m->unknown = malloc(m->full.nv * sizeof *m->unknown);
    m->lambda = calloc(m->k, sizeof *m->lambda);
    if (!m->unknown || !m->lambda) return cm_fail_status(&m->error, CM_ERR_NO_MEMORY);
    for (size_t v = 0; v < m->full.nv; v++) m->unknown[v] = m->boundary[v] ? -1 : m->nu++;
    if ((s = build_neighbours(m)) != CM_OK) return s;
    for (size_t g = 0; g < m->k; g++) {
        if (!(m->lambda[g] = malloc(m->start[m->nu] * sizeof *m->lambda[g])))
            return cm_fail_status(&m->error, CM_ERR_NO_MEMORY);
        mean_value_weights(m, g);
        if ((s = check_weights(m, g)) != CM_OK) return s;
    }
    if (m->method == CM_MORPH_INTRINSIC && (s = build_corners(m)) != CM_OK) return s;
    if ((s = build_system(m)) != CM_OK) return s;
    if (cm_progress_report(&progress, CM_STAGE_MORPH_SYSTEM, 1.0)) return cm_fail_status(&m->error, CM_ERR_CANCELLED);
    m->result = result;
    return CM_OK;
}

cm_status cm_morph_create(const cm_result *result, const cm_morph_options *options,
                          cm_morph **morph)
{
    if (!morph) return CM_ERR_ARGUMENT;
    cm_morph *m = *morph = calloc(1, sizeof **morph);
    if (!m) return CM_ERR_NO_MEMORY;
    return cm_error_close(&m->error, create(m, result, options));
}

void cm_morph_free(cm_morph *m)
{
    if (!m) return;
    cm_mesh_clear(&m->full);
    if (m->lambda)
        for (size_t g = 0; g < m->k; g++) free(m->lambda[g]);
    free(m->lambda);
    if (m->symbolic) umfpack_di_free_symbolic(&m->symbolic);
    free(m->boundary), free(m->unknown), free(m->start), free(m->nbr), free(m->entry);
    free(m->ti), free(m->tj), free(m->map), free(m->tx), free(m->ap), free(m->ai), free(m->ax);
    free(m->rhs), free(m->sol), free(m->pos), free(m->centre);
    if (m->corner_shape)
        for (size_t g = 0; g < m->k; g++) free(m->corner_shape[g]);
    free(m->corner_shape), free(m->corner_slot), free(m->weights);
    free(m);
}

const char *cm_morph_message(const cm_morph *m) { return m ? m->error.message : "no morph"; }

/* Solves for the enclosed mesh at local time s in (0, 1) between
 * geometries g and g + 1; positions in m->pos. */
static cm_status solve_positions(cm_morph *m, size_t g, double s)
{
    const double *l0 = m->lambda[g], *l1 = m->lambda[g + 1], *fixed = m->full.xy[0];
    double *rx = m->rhs, *ry = m->rhs + m->nu;
    int intrinsic = m->method == CM_MORPH_INTRINSIC;
    if (intrinsic) intrinsic_weights(m, g, s);
    for (int32_t row = 0; row < m->nu; row++) {
        rx[row] = ry[row] = 0;
        for (size_t x = m->start[row]; x < m->start[row + 1]; x++) {
            double lam = intrinsic ? m->weights[x] : (1 - s) * l0[x] + s * l1[x];
            if (m->entry[x] >= 0) {
                m->tx[m->entry[x]] = -lam;
            } else { /* enclosure vertex: the same point in every geometry */
                rx[row] += lam * fixed[2 * (size_t)m->nbr[x]];
                ry[row] += lam * fixed[2 * (size_t)m->nbr[x] + 1];
            }
        }
    }
    memset(m->ax, 0, (size_t)m->nz * sizeof *m->ax);
    for (int j = 0; j < m->nz; j++) m->ax[m->map[j]] += m->tx[j];
    void *numeric = NULL;
    int st = umfpack_di_numeric(m->ap, m->ai, m->ax, m->symbolic, &numeric, NULL, NULL);
    for (int c = 0; c < 2 && st == UMFPACK_OK; c++)
        st = umfpack_di_solve(UMFPACK_A, m->ap, m->ai, m->ax, m->sol + c * m->nu, m->rhs + c * m->nu,
                              numeric, NULL, NULL);
    umfpack_di_free_numeric(&numeric);
    if (st == UMFPACK_ERROR_out_of_memory) return cm_fail_status(&m->error, CM_ERR_NO_MEMORY);
    if (st != UMFPACK_OK)
        return cm_fail(&m->error, CM_ERR_INTERNAL, "morph: UMFPACK factorization failed (status %d)", st);
    for (size_t v = 0; v < m->full.nv; v++) {
        int32_t row = m->unknown[v];
        m->pos[2 * v] = row < 0 ? fixed[2 * v] : m->sol[row];
        m->pos[2 * v + 1] = row < 0 ? fixed[2 * v + 1] : m->sol[m->nu + row];
    }
    return CM_OK;
}

/* Exactly: do the section's boundary loops cross or touch (a, b: the first
 * vertices of two such edges)? 1 yes, 0 no, -1 out of memory. */
static int loops_cross(const cm_result *r, const double *xy, long *a, long *b)
{
    if (r->num_loops <= 1) return cm_polygon_find_intersection(xy, (long)r->n, a, b);
    size_t *sizes = malloc(r->num_loops * sizeof *sizes);
    if (!sizes) return -1;
    for (size_t l = 0; l < r->num_loops; l++) sizes[l] = r->loop_start[l + 1] - r->loop_start[l];
    int hit = cm_loops_find_intersection(xy, sizes, r->num_loops, a, b);
    free(sizes);
    return hit;
}

cm_status cm_morph_section(cm_morph *m, double t, double *xy, size_t *inverted,
                           double *min_angle_deg)
{
    if (!m) return CM_ERR_ARGUMENT;
    if (!(t >= 0.0 && t <= 1.0)) return cm_fail(&m->error, CM_ERR_ARGUMENT, "morph: t = %g is outside [0, 1]", t);
    if (!m->result) return cm_fail(&m->error, CM_ERR_ARGUMENT, "morph: the handle failed to build");
    double u = t * (double)(m->k - 1), whole = nearbyint(u);
    /* t = g / (k - 1) rounded: geometry g itself. */
    if (fabs(u - whole) <= 4 * DBL_EPSILON * fmax(1.0, u)) u = whole;
    size_t g = (size_t)floor(u);
    if (g > m->k - 2) g = m->k - 2;
    return cm_morph_section_at(m, g, u - (double)g, xy, inverted, min_angle_deg);
}

cm_status cm_morph_section_at(cm_morph *m, size_t g, double s, double *xy, size_t *inverted,
                              double *min_angle_deg)
{
    if (!m) return CM_ERR_ARGUMENT;
    if (!m->result) return cm_fail(&m->error, CM_ERR_ARGUMENT, "morph: the handle failed to build");
    if (!xy) return cm_fail(&m->error, CM_ERR_ARGUMENT, "morph: xy is NULL");
    if (g + 1 >= m->k || !(s >= 0.0 && s <= 1.0))
        return cm_fail(&m->error, CM_ERR_ARGUMENT, "morph: segment %zu, time %g out of range", g, s);
    const cm_mesh *r = &m->result->mesh;
    double t = ((double)g + s) / (double)(m->k - 1); /* for messages */
    if (s == 0.0 || s == 1.0) { /* an input geometry: bit-identical */
        memcpy(xy, r->xy[g + (s == 1.0)], 2 * m->nv * sizeof *xy);
    } else if (m->method == CM_MORPH_LINEAR) {
        const double *p = r->xy[g], *q = r->xy[g + 1];
        for (size_t j = 0; j < 2 * m->nv; j++) xy[j] = (1 - s) * p[j] + s * q[j];
    } else {
        cm_status st = solve_positions(m, g, s);
        if (st != CM_OK) return st;
        leave_frame(m, g, s);
        /* The annulus around the section and the holes' fills only carry
         * the construction: rounding may fold one of their slivers. The
         * section stays valid if its own triangles are counter-clockwise
         * and its loops are simple and disjoint (then they tile the
         * polygon), both checked exactly. */
        size_t bad = count_inverted(m->full.tri, r->nt, m->full.nt, m->pos);
        if (bad) {
            long a, b;
            int crossing = loops_cross(m->result, m->pos, &a, &b);
            if (crossing < 0) return cm_fail_status(&m->error, CM_ERR_NO_MEMORY);
            if (crossing)
                return cm_fail(&m->error, CM_ERR_PRECISION,
                               "morph: %zu triangles of the enclosed mesh invert at t = %.17g and the boundary "
                               "edges %ld and %ld cross: rounding in doubles", bad, t, a, b);
        }
        memcpy(xy, m->pos, 2 * m->nv * sizeof *xy);
    }
    size_t bad = count_inverted(r->tri, 0, m->nt, xy);
    if (inverted) *inverted = bad;
    if (min_angle_deg) {
        double lo = CM_PI;
        for (size_t j = 0; j < m->nt; j++)
            lo = fmin(lo, cm_triangle_min_angle(xy + 2 * (size_t)r->tri[3 * j], xy + 2 * (size_t)r->tri[3 * j + 1],
                                                xy + 2 * (size_t)r->tri[3 * j + 2]));
        *min_angle_deg = lo * 180.0 / CM_PI;
    }
    /* Convex combinations are valid at every t in exact arithmetic
     * (Floater's theorem over the common convex enclosure): what folds is
     * rounding, typically of geometries whose sizes differ by many orders
     * of magnitude, or of a sliver. */
    if (bad && m->method != CM_MORPH_LINEAR)
        return cm_fail(&m->error, CM_ERR_PRECISION,
                       "morph: %zu triangles invert at t = %.17g: rounding in doubles", bad, t);
    cm_error_init(&m->error);
    return CM_OK;
}

const char *cm_morph_method_name(cm_morph_method method)
{
    switch (method) {
    case CM_MORPH_CONVEX: return "convex";
    case CM_MORPH_LINEAR: return "linear";
    case CM_MORPH_INTRINSIC: return "intrinsic";
    }
    return "unknown";
}
