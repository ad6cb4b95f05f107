/* The common convex enclosure and the compatible annulus triangulation.
 *
 * The enclosure is one convex polygon, the same points in every geometry,
 * on a circle well outside all polygons. Two straight bridges, each from a
 * polygon vertex to an enclosure vertex and valid (outside the polygon,
 * disjoint from each other) in every geometry, cut every annulus into two
 * simple polygons with corresponding vertices; the library's own
 * compatible triangulation (the partition method) triangulates each pair,
 * adding Steiner vertices where it must. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "morph/enclosure.h"
#include "base/order.h"
#include "geom/angle.h"
#include "geom/predicates.h"

#define REGULAR_VERTICES 24 /* enclosure corners besides the bridge ends */
#define RADIUS_FACTOR 3.0   /* enclosure radius / farthest polygon vertex */
#define MIN_GAP 0.05        /* radians between enclosure corners */
/* Ribbon: steps round the centre of at most pi / RIBBON_STEPS, radius
 * growing by RIBBON_GROWTH per step, so every step moves strictly outward
 * (1.2 cos(30 deg) > 1) and the two bridges, at the same radii, stay apart. */
#define RIBBON_STEPS 6
#define RIBBON_GROWTH 1.2
#define RIBBON_GAP 0.02     /* radians between the two ribbon ends */

typedef struct enclosure {
    const cm_result *r;
    size_t k, n;
    int32_t *bnd;    /* polygon vertex ids, counter-clockwise */
    double center[2], radius;
    cm_error *err;
} enclosure;

static const double *vertex(const enclosure *e, size_t g, int32_t v)
{
    return e->r->mesh.xy[g] + 2 * (size_t)v;
}

static void circle_point(const enclosure *e, double angle, double p[2])
{
    p[0] = e->center[0] + e->radius * cos(angle);
    p[1] = e->center[1] + e->radius * sin(angle);
}

/* Counter-clockwise order of the polygon vertices: the result's triangles
 * are counter-clockwise, so the boundary runs along 0 -> 1 exactly when
 * some triangle holds that directed edge. */
static void boundary_order(enclosure *e)
{
    const int32_t *tri = e->r->mesh.tri;
    int forward = 0;
    for (size_t t = 0; t < e->r->mesh.nt && !forward; t++)
        for (int c = 0; c < 3; c++)
            if (tri[3 * t + c] == 0 && tri[3 * t + (c + 1) % 3] == 1) forward = 1;
    for (size_t i = 0; i < e->n; i++)
        e->bnd[i] = (int32_t)(forward ? i : (e->n - i) % e->n);
}

/* Segment from polygon vertex bnd[i] to the far point p leaves the polygon
 * into its exterior (exact, O(1)). */
static int bridge_leaves(const enclosure *e, size_t g, size_t i, const double p[2])
{
    size_t n = e->n;
    const double *a = vertex(e, g, e->bnd[i]);
    const double *prev = vertex(e, g, e->bnd[(i + n - 1) % n]);
    const double *next = vertex(e, g, e->bnd[(i + 1) % n]);
    int right_of_next = cm_orient2d(a, next, p) < 0;   /* p beyond edge a->next */
    int right_of_prev = cm_orient2d(prev, a, p) < 0;   /* p beyond edge prev->a */
    int convex = cm_orient2d(prev, a, next) > 0;
    /* Interior cone at a is left of both edges (convex corner) or of
     * either (reflex corner); p must be strictly outside its closure. */
    int outside = convex ? (right_of_next || right_of_prev) : (right_of_next && right_of_prev);
    return outside && cm_orient2d(a, next, p) != 0 && cm_orient2d(prev, a, p) != 0;
}

/* ... and meets the polygon nowhere else (exact, O(n)). */
static int bridge_valid(const enclosure *e, size_t g, size_t i, const double p[2])
{
    size_t n = e->n;
    const double *a = vertex(e, g, e->bnd[i]);
    if (!bridge_leaves(e, g, i, p)) return 0;
    for (size_t j = 0; j < n; j++) {
        if (j == i || (j + 1) % n == i) continue; /* the two edges at a */
        if (cm_segments_intersect(a, p, vertex(e, g, e->bnd[j]), vertex(e, g, e->bnd[(j + 1) % n])))
            return 0;
    }
    return 1;
}

typedef struct bridge {
    size_t pos;    /* position in bnd */
    double angle;  /* enclosure point */
    size_t nbend;  /* bend vertices between polygon and enclosure */
    double *bend;  /* k * nbend * 2: per geometry, from the polygon out */
} bridge;

/* Vertices in order of their smallest distance from the centre over all
 * geometries, largest first: outermost vertices see the enclosure. */
typedef struct ranked {
    double key;
    size_t pos;
} ranked;

static int ranked_desc(const void *pa, const void *pb)
{
    const ranked *a = pa, *b = pb;
    return (a->key < b->key) - (a->key > b->key);
}

static double angle_gap(double x, double y)
{
    double d = fmod(fabs(x - y), 2 * CM_PI);
    return fmin(d, 2 * CM_PI - d);
}

/* Tries directions for a bridge from bnd[pos]: the vertex's own direction
 * from the centre in each geometry, then a fan. `other` (may be NULL) is a
 * bridge this one must keep clear of. */
static int find_direction(const enclosure *e, size_t pos, const bridge *other, double *angle)
{
    enum { FAN = 64, NEAR = 8 };
    static const double near[NEAR] = {-0.3, -0.1, -0.03, -0.01, 0.01, 0.03, 0.1, 0.3};
    double cand[8 + NEAR + FAN];
    size_t nc = 0;
    for (size_t g = 0; g < e->k && nc < 8; g++) {
        const double *p = vertex(e, g, e->bnd[pos]);
        cand[nc++] = atan2(p[1] - e->center[1], p[0] - e->center[0]);
    }
    /* Beside the other bridge: where few vertices see out in every
     * geometry, the two bridges run nearly parallel. */
    for (int j = 0; other && j < NEAR; j++) cand[nc++] = other->angle + near[j];
    for (int j = 0; j < FAN; j++) cand[nc++] = cand[0] + 2 * CM_PI * (j + 0.5) / FAN;
    for (size_t c = 0; c < nc; c++) {
        double p[2], q[2];
        if (other && (other->pos == pos || angle_gap(cand[c], other->angle) < 0.005)) continue;
        circle_point(e, cand[c], p);
        if (other) circle_point(e, other->angle, q);
        int ok = 1;
        for (size_t g = 0; g < e->k && ok; g++) /* the cheap test everywhere first */
            ok = bridge_leaves(e, g, pos, p);
        for (size_t g = 0; g < e->k && ok; g++) {
            ok = bridge_valid(e, g, pos, p);
            if (ok && other)
                ok = !cm_segments_intersect(vertex(e, g, e->bnd[pos]), p,
                                            vertex(e, g, e->bnd[other->pos]), q);
        }
        if (ok) {
            *angle = cand[c];
            return 1;
        }
    }
    return 0;
}

static size_t cyclic_distance(size_t a, size_t b, size_t n)
{
    size_t d = a > b ? a - b : b - a;
    return d < n - d ? d : n - d;
}

static cm_status find_bridges(enclosure *e, bridge br[2])
{
    size_t n = e->n;
    ranked *order = malloc(n * sizeof *order);
    if (!order) return cm_fail_status(e->err, CM_ERR_NO_MEMORY);
    for (size_t i = 0; i < n; i++) {
        double key = INFINITY;
        for (size_t g = 0; g < e->k; g++) {
            const double *p = vertex(e, g, e->bnd[i]);
            key = fmin(key, hypot(p[0] - e->center[0], p[1] - e->center[1]));
        }
        order[i] = (ranked){key, i};
    }
    qsort(order, n, sizeof *order, ranked_desc);
    int found = 0;
    for (size_t i = 0; i < n && !found; i++)
        if (find_direction(e, order[i].pos, NULL, &br[0].angle)) br[0].pos = order[i].pos, found = 1;
    if (!found) {
        free(order);
        return cm_fail(e->err, CM_ERR_INTERNAL,
                    "enclosure: no polygon vertex sees the enclosure along one straight bridge in every geometry");
    }
    /* The second bridge: far along the boundary first, for balanced pieces. */
    found = 0;
    for (int pass = 0; pass < 2 && !found; pass++)
        for (size_t i = 0; i < n && !found; i++) {
            size_t pos = order[i].pos;
            if (pass == 0 && cyclic_distance(pos, br[0].pos, n) < n / 4) continue;
            if (find_direction(e, pos, &br[0], &br[1].angle)) br[1].pos = pos, found = 1;
        }
    free(order);
    if (!found)
        return cm_fail(e->err, CM_ERR_INTERNAL,
                    "enclosure: no second bridge to the enclosure valid in every geometry "
                    "(first from vertex %ld)", (long)e->bnd[br[0].pos]);
    return CM_OK;
}

/* ---- ribbon ------------------------------------------------------------ */

/* Wraps an angle difference into (-pi, pi]. */
static double wrap(double a)
{
    a = fmod(a, 2 * CM_PI);
    if (a > CM_PI) a -= 2 * CM_PI;
    if (a <= -CM_PI) a += 2 * CM_PI;
    return a;
}

/* Segments [p, q] of a bridge path (polygon vertex first) miss every
 * polygon edge; the first segment is checked by bridge_valid. */
static int path_clear(const enclosure *e, size_t g, const double *path, size_t count)
{
    for (size_t s = 1; s + 1 < count; s++)
        for (size_t j = 0; j < e->n; j++)
            if (cm_segments_intersect(path + 2 * s, path + 2 * s + 2, vertex(e, g, e->bnd[j]),
                                      vertex(e, g, e->bnd[(j + 1) % e->n])))
                return 0;
    return 1;
}

static int paths_disjoint(const double *p, const double *q, size_t count)
{
    for (size_t i = 0; i + 1 < count; i++)
        for (size_t j = 0; j + 1 < count; j++)
            if (cm_segments_intersect(p + 2 * i, p + 2 * i + 2, q + 2 * j, q + 2 * j + 2)) return 0;
    return 1;
}

/* The two paths of a ribbon on edge bnd[pos] -> bnd[pos + 1] in geometry
 * g, leaving along the outward normal turned by `turn`, ending at the
 * enclosure angles theta and theta + RIBBON_GAP. path[2] gets
 * RIBBON_STEPS + 4 points each: vertex, exit point, bends, enclosure point.
 * Returns 0 when the exits are not in counter-clockwise order. */
static int ribbon_paths(const enclosure *e, size_t g, size_t pos, double turn, double theta,
                        double far, double path[2][2 * (RIBBON_STEPS + 4)])
{
    const double *a = vertex(e, g, e->bnd[pos]), *b = vertex(e, g, e->bnd[(pos + 1) % e->n]);
    double dx = b[0] - a[0], dy = b[1] - a[1], len = hypot(dx, dy);
    double nx = dy / len, ny = -dx / len; /* right of a -> b: outside */
    double ux = nx * cos(turn) - ny * sin(turn), uy = nx * sin(turn) + ny * cos(turn);
    double psi[2];
    for (int side = 0; side < 2; side++) {
        const double *p = side ? b : a;
        double *q = path[side];
        q[0] = p[0], q[1] = p[1];
        q[2] = p[0] + 2 * far * ux, q[3] = p[1] + 2 * far * uy;
        psi[side] = atan2(q[3] - e->center[1], q[2] - e->center[0]);
    }
    double spread = wrap(psi[1] - psi[0]);
    if (!(spread > 0)) return 0;
    double sweep[2];
    sweep[0] = wrap(theta - psi[0]);
    sweep[1] = sweep[0] + RIBBON_GAP - spread;
    for (int side = 0; side < 2; side++) {
        double *q = path[side], r = 4 * far;
        for (int j = 0; j <= RIBBON_STEPS; j++, r *= RIBBON_GROWTH) {
            double ang = psi[side] + sweep[side] * j / RIBBON_STEPS;
            q[4 + 2 * j] = e->center[0] + r * cos(ang), q[5 + 2 * j] = e->center[1] + r * sin(ang);
        }
        circle_point(e, theta + side * RIBBON_GAP, q + 2 * (RIBBON_STEPS + 3));
    }
    return 1;
}

/* An edge whose ribbon is valid in every geometry; fills both bridges. */
static cm_status find_ribbon(enclosure *e, double far, bridge br[2])
{
    enum { COUNT = RIBBON_STEPS + 4 };
    static const double turns[] = {0.0, 0.5, -0.5, 1.0, -1.0};
    size_t n = e->n, k = e->k;
    double path[2][2 * COUNT];
    ranked *order = malloc(n * sizeof *order);
    for (int side = 0; side < 2; side++) {
        br[side].nbend = COUNT - 2;
        br[side].bend = malloc(k * (COUNT - 2) * 2 * sizeof(double));
    }
    if (!order || !br[0].bend || !br[1].bend) {
        free(order);
        return cm_fail_status(e->err, CM_ERR_NO_MEMORY);
    }
    for (size_t i = 0; i < n; i++) { /* edges far out in every geometry first */
        double key = INFINITY;
        for (size_t g = 0; g < k; g++) {
            const double *p = vertex(e, g, e->bnd[i]), *q = vertex(e, g, e->bnd[(i + 1) % n]);
            key = fmin(key, hypot(0.5 * (p[0] + q[0]) - e->center[0], 0.5 * (p[1] + q[1]) - e->center[1]));
        }
        order[i] = (ranked){key, i};
    }
    qsort(order, n, sizeof *order, ranked_desc);
    int found = 0;
    for (size_t i = 0; i < n && !found; i++) {
        size_t pos = order[i].pos;
        for (size_t t = 0; t < sizeof turns / sizeof *turns && !found; t++) {
            double theta = 0;
            int ok = 1;
            for (size_t g = 0; g < k && ok; g++) {
                if (g == 0) { /* geometry 0 leaves straight towards A */
                    if (!ribbon_paths(e, 0, pos, turns[t], 0.0, far, path)) { ok = 0; break; }
                    theta = atan2(path[0][3] - e->center[1], path[0][2] - e->center[0]);
                }
                ok = ribbon_paths(e, g, pos, turns[t], theta, far, path) &&
                     bridge_valid(e, g, pos, path[0] + 2) && bridge_valid(e, g, (pos + 1) % n, path[1] + 2) &&
                     path_clear(e, g, path[0], COUNT) && path_clear(e, g, path[1], COUNT) &&
                     paths_disjoint(path[0], path[1], COUNT);
                for (int side = 0; ok && side < 2; side++)
                    memcpy(br[side].bend + g * (COUNT - 2) * 2, path[side] + 2, (COUNT - 2) * 2 * sizeof(double));
            }
            if (ok) {
                found = 1;
                br[0].pos = pos, br[0].angle = theta;
                br[1].pos = (pos + 1) % n, br[1].angle = theta + RIBBON_GAP;
            }
        }
    }
    free(order);
    if (!found)
        return cm_fail(e->err, CM_ERR_INTERNAL,
                    "enclosure: no two polygon vertices see the enclosure in every geometry, and no polygon edge "
                    "sees out along its normal in every geometry");
    return CM_OK;
}

static double normalize_angle(double a)
{
    a = fmod(a, 2 * CM_PI);
    return a < 0 ? a + 2 * CM_PI : a;
}

/* Enclosure corner angles, increasing in [0, 2 pi): the regular ones not
 * too close to a bridge end, and the two bridge ends (*ia, *ib: their
 * indices). */
static size_t enclosure_angles(const bridge br[2], double *angles, size_t *ia, size_t *ib)
{
    double a = normalize_angle(br[0].angle), b = normalize_angle(br[1].angle);
    size_t m = 0;
    angles[m++] = a, angles[m++] = b;
    for (int j = 0; j < REGULAR_VERTICES; j++) {
        double t = 2 * CM_PI * j / REGULAR_VERTICES;
        if (angle_gap(t, a) >= MIN_GAP && angle_gap(t, b) >= MIN_GAP) angles[m++] = t;
    }
    qsort(angles, m, sizeof *angles, cm_compare_doubles);
    for (size_t i = 0; i < m; i++) {
        if (angles[i] == a) *ia = i;
        if (angles[i] == b) *ib = i;
    }
    return m;
}

/* Full-mesh ids of the bends of bridge i (they follow the enclosure). */
static int32_t bend_id(const enclosure *e, size_t m, const bridge br[2], int i, size_t j)
{
    return (int32_t)(e->r->mesh.nv + m + (i ? br[0].nbend : 0) + j);
}

/* Point `id` of the full mesh in geometry g (result, enclosure or bend). */
static const double *point(const enclosure *e, size_t g, int32_t id, size_t m, const double *enc_xy,
                           const bridge br[2])
{
    size_t nv = e->r->mesh.nv, v = (size_t)id;
    if (v < nv) return vertex(e, g, id);
    if (v < nv + m) return enc_xy + 2 * (v - nv);
    v -= nv + m;
    int i = v >= br[0].nbend;
    if (i) v -= br[0].nbend;
    return br[i].bend + 2 * (g * br[i].nbend + v);
}

/* One annulus piece: enclosure corners from index `from` to `to`
 * counter-clockwise, bridge `in` inwards, the polygon clockwise from
 * bnd[br[in].pos] to bnd[br[1 - in].pos], bridge 1 - in outwards. ids[]
 * gets the full-mesh vertex of each piece vertex. */
static size_t piece_ids(const enclosure *e, size_t m, size_t from, size_t to, const bridge br[2], int in,
                        int32_t *ids)
{
    size_t c = 0, nv = e->r->mesh.nv, n = e->n;
    for (size_t i = from;; i = (i + 1) % m) {
        ids[c++] = (int32_t)(nv + i);
        if (i == to) break;
    }
    for (size_t j = br[in].nbend; j-- > 0;) ids[c++] = bend_id(e, m, br, in, j);
    for (size_t p = br[in].pos;; p = (p + n - 1) % n) {
        ids[c++] = e->bnd[p];
        if (p == br[1 - in].pos) break;
    }
    for (size_t j = 0; j < br[1 - in].nbend; j++) ids[c++] = bend_id(e, m, br, 1 - in, j);
    return c;
}

/* Exact check of the enclosed mesh: counter-clockwise everywhere, each
 * directed edge once, and every edge without a twin on the enclosure. */
static int key_less(const void *pa, const void *pb)
{
    uint64_t a = *(const uint64_t *)pa, b = *(const uint64_t *)pb;
    return (a > b) - (a < b);
}

static int has_key(const uint64_t *keys, size_t count, uint64_t key)
{
    return bsearch(&key, keys, count, sizeof *keys, key_less) != NULL;
}

static cm_status check_mesh(enclosure *e, const cm_mesh *m, size_t first_enclosure, size_t ne)
{
    for (size_t g = 0; g < m->k; g++)
        for (size_t t = 0; t < m->nt; t++) {
            const int32_t *v = m->tri + 3 * t;
            if (cm_orient2d(m->xy[g] + 2 * (size_t)v[0], m->xy[g] + 2 * (size_t)v[1],
                            m->xy[g] + 2 * (size_t)v[2]) <= 0)
                return cm_fail(e->err, CM_ERR_INTERNAL,
                            "enclosure: triangle %zu (%d %d %d) not counter-clockwise in geometry %zu",
                            t, v[0], v[1], v[2], g);
        }
    size_t nk = 3 * m->nt;
    uint64_t *keys = malloc(nk * sizeof *keys);
    if (!keys) return cm_fail_status(e->err, CM_ERR_NO_MEMORY);
    for (size_t t = 0; t < m->nt; t++)
        for (int c = 0; c < 3; c++)
            keys[3 * t + c] = (uint64_t)(uint32_t)m->tri[3 * t + c] << 32 |
                              (uint32_t)m->tri[3 * t + (c + 1) % 3];
    qsort(keys, nk, sizeof *keys, key_less);
    cm_status s = CM_OK;
    size_t open = 0;
    for (size_t i = 0; i < nk && s == CM_OK; i++) {
        uint32_t a = (uint32_t)(keys[i] >> 32), b = (uint32_t)keys[i];
        if (i + 1 < nk && keys[i + 1] == keys[i])
            s = cm_fail(e->err, CM_ERR_INTERNAL, "enclosure: edge %u-%u used twice in one direction", a, b);
        else if (!has_key(keys, nk, (uint64_t)b << 32 | a)) {
            int on_enclosure = a >= first_enclosure && a < first_enclosure + ne &&
                               b == first_enclosure + (a - first_enclosure + 1) % ne;
            if (!on_enclosure)
                s = cm_fail(e->err, CM_ERR_INTERNAL, "enclosure: edge %u-%u has one triangle but is not on the enclosure", a, b);
            open++;
        }
    }
    free(keys);
    if (s == CM_OK && open != ne)
        s = cm_fail(e->err, CM_ERR_INTERNAL, "enclosure: %zu boundary edges, expected %zu", open, ne);
    if (s == CM_OK && m->nt != 2 * m->nv - ne - 2) /* Euler: a disk */
        s = cm_fail(e->err, CM_ERR_INTERNAL, "enclosure: the mesh is not a disk (%zu triangles, %zu vertices)", m->nt, m->nv);
    return s;
}

/* The caller's progress seen through one piece: fractions of the piece's
 * triangulation mapped into that piece's half of the enclosure stage. */
typedef struct piece_progress {
    cm_progress *progress;
    int piece;
} piece_progress;

static int report_piece(void *user, double fraction, const char *stage)
{
    (void)stage;
    const piece_progress *pp = user;
    return cm_progress_report(pp->progress, CM_STAGE_ENCLOSURE, 0.5 * (pp->piece + fraction));
}

static cm_status triangulate_piece(enclosure *e, const int32_t *ids, size_t count, size_t m,
                                   const double *enc_xy, const bridge br[2], int piece_index,
                                   cm_progress *progress, cm_result **out)
{
    size_t k = e->k;
    double **poly = calloc(k, sizeof *poly);
    size_t *counts = malloc(k * sizeof *counts);
    cm_status s = CM_ERR_NO_MEMORY;
    if (!poly || !counts) goto done;
    for (size_t g = 0; g < k; g++) {
        counts[g] = count;
        if (!(poly[g] = malloc(2 * count * sizeof *poly[g]))) goto done;
        for (size_t i = 0; i < count; i++) {
            const double *p = point(e, g, ids[i], m, enc_xy, br);
            poly[g][2 * i] = p[0], poly[g][2 * i + 1] = p[1];
        }
    }
    cm_options o;
    cm_options_init(&o);
    o.method = CM_METHOD_PARTITION;
    o.remesh = 0; /* annulus quality does not reach the sections */
    piece_progress pp = {progress, piece_index};
    if (progress && progress->fn) o.progress = report_piece, o.progress_user = &pp;
    s = cm_triangulate_polygons((const double *const *)poly, counts, k, &o, out);
    if (s == CM_ERR_CANCELLED) cm_fail_status(e->err, s);
    else if (s != CM_OK)
        cm_fail(e->err, s, "enclosure: annulus piece of %zu vertices: %s", count, cm_result_message(*out));
    else if (cm_result_stats(*out)->reversed_input)
        s = cm_fail(e->err, CM_ERR_INTERNAL, "enclosure: annulus piece came out clockwise");
done:
    if (s == CM_ERR_NO_MEMORY) cm_fail_status(e->err, s);
    if (poly)
        for (size_t g = 0; g < k; g++) free(poly[g]);
    free(poly);
    free(counts);
    return s;
}

cm_status cm_enclosure_build(const cm_result *r, cm_progress *progress, cm_mesh *out,
                             unsigned char **boundary, cm_error *err)
{
    enclosure e = {.r = r, .k = r->mesh.k, .n = r->stats.n, .err = err};
    size_t k = e.k, nv = r->mesh.nv, n = e.n;
    cm_result *piece[2] = {NULL, NULL};
    double angles[REGULAR_VERTICES + 2], *enc_xy = NULL;
    int32_t *ids[2] = {NULL, NULL};
    size_t count[2];
    memset(out, 0, sizeof *out);
    *boundary = NULL;
    e.bnd = malloc(n * sizeof *e.bnd);
    if (!e.bnd) return cm_fail_status(e.err, CM_ERR_NO_MEMORY);
    boundary_order(&e);

    /* Centre and radius from every geometry, so one enclosure fits all. */
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (size_t g = 0; g < k; g++)
        for (size_t i = 0; i < n; i++)
            for (int c = 0; c < 2; c++)
                lo[c] = fmin(lo[c], vertex(&e, g, (int32_t)i)[c]), hi[c] = fmax(hi[c], vertex(&e, g, (int32_t)i)[c]);
    e.center[0] = 0.5 * (lo[0] + hi[0]), e.center[1] = 0.5 * (lo[1] + hi[1]);
    double far = 0;
    for (size_t g = 0; g < k; g++)
        for (size_t i = 0; i < n; i++) {
            const double *p = vertex(&e, g, (int32_t)i);
            far = fmax(far, hypot(p[0] - e.center[0], p[1] - e.center[1]));
        }
    e.radius = RADIUS_FACTOR * far;

    bridge br[2] = {{0}, {0}};
    cm_status s = find_bridges(&e, br);
    if (s == CM_ERR_INTERNAL) { /* no straight pair: a ribbon, further out */
        e.radius = 4 * far * pow(RIBBON_GROWTH, RIBBON_STEPS) * 1.25;
        s = find_ribbon(&e, far, br);
    }
    if (s != CM_OK) goto done;
    size_t nbend = br[0].nbend + br[1].nbend;
    size_t ia = 0, ib = 0, m = enclosure_angles(br, angles, &ia, &ib);
    s = CM_ERR_NO_MEMORY;
    enc_xy = malloc(2 * m * sizeof *enc_xy);
    ids[0] = malloc((m + n + nbend + 2) * sizeof *ids[0]);
    ids[1] = malloc((m + n + nbend + 2) * sizeof *ids[1]);
    if (!enc_xy || !ids[0] || !ids[1]) goto fail_memory;
    for (size_t i = 0; i < m; i++) circle_point(&e, angles[i], enc_xy + 2 * i);
    /* Strictly convex, and every polygon strictly inside (exact). */
    for (size_t i = 0; i < m; i++) {
        const double *p = enc_xy + 2 * i, *q = enc_xy + 2 * ((i + 1) % m), *w = enc_xy + 2 * ((i + 2) % m);
        if (cm_orient2d(p, q, w) <= 0) {
            s = cm_fail(e.err, CM_ERR_INTERNAL, "enclosure: corner %zu is not strictly convex", (i + 1) % m);
            goto done;
        }
        for (size_t g = 0; g < k; g++)
            for (size_t v = 0; v < n; v++)
                if (cm_orient2d(p, q, vertex(&e, g, (int32_t)v)) <= 0) {
                    s = cm_fail(e.err, CM_ERR_INTERNAL, "enclosure: vertex %zu of geometry %zu is not inside", v, g);
                    goto done;
                }
    }
    count[0] = piece_ids(&e, m, ia, ib, br, 1, ids[0]);
    count[1] = piece_ids(&e, m, ib, ia, br, 0, ids[1]);
    for (int p = 0; p < 2; p++) {
        s = triangulate_piece(&e, ids[p], count[p], m, enc_xy, br, p, progress, &piece[p]);
        if (s != CM_OK) goto done;
    }

    /* Assemble: result, enclosure, bends, then each piece's Steiner
     * vertices. */
    size_t steiner[2], total = nv + m + nbend;
    for (int p = 0; p < 2; p++) steiner[p] = cm_result_num_vertices(piece[p]) - count[p], total += steiner[p];
    size_t nt = r->mesh.nt + cm_result_num_triangles(piece[0]) + cm_result_num_triangles(piece[1]);
    out->k = k, out->nv = total, out->nt = nt;
    out->xy = calloc(k, sizeof *out->xy);
    out->tri = malloc(3 * nt * sizeof *out->tri);
    *boundary = calloc(total, 1);
    if (!out->xy || !out->tri || !*boundary) goto fail_memory;
    for (size_t i = nv; i < nv + m; i++) (*boundary)[i] = 1;
    for (size_t g = 0; g < k; g++) {
        if (!(out->xy[g] = malloc(2 * total * sizeof *out->xy[g]))) goto fail_memory;
        memcpy(out->xy[g], r->mesh.xy[g], 2 * nv * sizeof(double));
        for (size_t v = nv; v < nv + m + nbend; v++)
            memcpy(out->xy[g] + 2 * v, point(&e, g, (int32_t)v, m, enc_xy, br), 2 * sizeof(double));
        size_t base = nv + m + nbend;
        for (int p = 0; p < 2; p++) {
            memcpy(out->xy[g] + 2 * base, cm_result_vertices(piece[p], g) + 2 * count[p],
                   2 * steiner[p] * sizeof(double));
            base += steiner[p];
        }
    }
    memcpy(out->tri, r->mesh.tri, 3 * r->mesh.nt * sizeof *out->tri);
    size_t t = r->mesh.nt, base = nv + m + nbend;
    for (int p = 0; p < 2; p++) {
        const int32_t *pt = cm_result_triangles(piece[p]);
        for (size_t j = 0; j < 3 * cm_result_num_triangles(piece[p]); j++) {
            size_t v = (size_t)pt[j];
            out->tri[3 * t + j] = v < count[p] ? ids[p][v] : (int32_t)(base + v - count[p]);
        }
        t += cm_result_num_triangles(piece[p]);
        base += steiner[p];
    }
    s = check_mesh(&e, out, nv, m);
    goto done;
fail_memory:
    s = cm_fail_status(e.err, CM_ERR_NO_MEMORY);
done:
    if (s != CM_OK) {
        cm_mesh_clear(out);
        free(*boundary);
        *boundary = NULL;
    }
    cm_result_free(piece[0]);
    cm_result_free(piece[1]);
    free(ids[0]), free(ids[1]), free(enc_xy), free(e.bnd), free(br[0].bend), free(br[1].bend);
    return s;
}
