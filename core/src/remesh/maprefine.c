/* Middle-metric refinement (maprefine.h). The metric of geometry g on a
 * triangle's barycentric frame is the Gram matrix M_g = E_g^T E_g of its
 * edge matrix (coordinates over the geometry's scale); the middle metric
 * is their geometric mean: closed form for two (Bhatia, Positive Definite
 * Matrices, 4.1.12), the log-Euclidean mean for more. Angles and the
 * circumcentre follow from the three squared edge lengths alone. */
#include <math.h>
#include <stdlib.h>

#include "remesh/maprefine.h"
#include "remesh/flip.h"
#include "remesh/refine.h"
#include "geom/angle.h"
#include "geom/predicates.h"

/* The circumcentre counts as inside when every barycentric coordinate is
 * at least this: a vertex closer to an edge than that is left to the
 * edge's split. */
#define CM_MID_INSIDE 0.02
/* Triangles thinner than this (radians, in some geometry) are not
 * refined here. */
#define CM_MID_SLIVER 0.02
/* Newton steps on a split's new vertex. */
#define CM_MID_SPLIT_STEPS 8
/* Middle flips gain at least this (radians). */
#define CM_MID_GAIN 1e-9

typedef struct { double xx, xy, yy; } sym2;

static double sdet(sym2 m) { return m.xx * m.yy - m.xy * m.xy; }

/* exp or log of a symmetric positive definite 2x2 (by its eigenvalues). */
static sym2 sym_apply(sym2 m, int logarithm)
{
    double h = 0.5 * (m.xx - m.yy), r = hypot(h, m.xy), mid = 0.5 * (m.xx + m.yy);
    double l1 = mid + r, l2 = mid - r;
    double f1 = logarithm ? log(l1) : exp(l1), f2 = logarithm ? log(l2) : exp(l2);
    if (r < 1e-300) return (sym2){f1, 0, f1};
    /* eigenvector of l1: (cos, sin) of half the angle of (h, xy) */
    double ang = 0.5 * atan2(m.xy, h), c = cos(ang), s = sin(ang);
    return (sym2){f1 * c * c + f2 * s * s, (f1 - f2) * c * s, f1 * s * s + f2 * c * c};
}

/* Squared middle lengths of the sides opposite a, b, c; 0 when flat. */
static int mid_sides(const cm_kmesh *km, int32_t a, int32_t b, int32_t c, double side[3])
{
    sym2 mean = {0, 0, 0};
    sym2 first = {0, 0, 0};
    for (size_t g = 0; g < km->k; g++) {
        const double *pa = cm_kmesh_pos(km, g, a), *pb = cm_kmesh_pos(km, g, b), *pc = cm_kmesh_pos(km, g, c);
        double s = km->scale[g];
        double e1x = (pb[0] - pa[0]) / s, e1y = (pb[1] - pa[1]) / s;
        double e2x = (pc[0] - pa[0]) / s, e2y = (pc[1] - pa[1]) / s;
        sym2 m = {e1x * e1x + e1y * e1y, e1x * e2x + e1y * e2y, e2x * e2x + e2y * e2y};
        if (!(sdet(m) > 0) || e1x * e2y - e1y * e2x <= 0) return -1;
        if (km->k == 2) {
            if (g == 0) {
                first = m;
                continue;
            }
            double sa = sqrt(sqrt(sdet(first))), sb = sqrt(sqrt(sdet(m)));
            /* A # B = sqrt(ab) (B' A + A' B) / sqrt(det(B' A + A' B)),
             * a = det A, A' = sqrt(a), the same for B */
            sym2 sum = {sb * sb * first.xx + sa * sa * m.xx, sb * sb * first.xy + sa * sa * m.xy,
                        sb * sb * first.yy + sa * sa * m.yy};
            double f = sa * sb / sqrt(sdet(sum));
            mean = (sym2){f * sum.xx, f * sum.xy, f * sum.yy};
        } else if (km->k == 1) {
            mean = m;
        } else {
            sym2 l = sym_apply(m, 1);
            mean.xx += l.xx / (double)km->k, mean.xy += l.xy / (double)km->k, mean.yy += l.yy / (double)km->k;
        }
    }
    if (km->k > 2) mean = sym_apply(mean, 0);
    side[0] = mean.xx + mean.yy - 2 * mean.xy; /* |bc|^2 */
    side[1] = mean.yy;                         /* |ac|^2 */
    side[2] = mean.xx;                         /* |ab|^2 */
    return side[0] > 0 && side[1] > 0 && side[2] > 0 ? 0 : -1;
}

double cm_mid_angle(const cm_kmesh *km, int32_t a, int32_t b, int32_t c)
{
    double s[3];
    if (mid_sides(km, a, b, c, s)) return 0.0;
    int i = s[0] <= s[1] && s[0] <= s[2] ? 0 : s[1] <= s[2] ? 1 : 2; /* the shortest side */
    double x = s[i], y = s[(i + 1) % 3], z = s[(i + 2) % 3];
    double cosine = (y + z - x) / (2 * sqrt(y * z));
    return acos(fmax(-1.0, fmin(1.0, cosine)));
}

int cm_mid_circumcentre(const cm_kmesh *km, int32_t t, double bary[3])
{
    const int32_t *v = km->tri + 3 * (size_t)t;
    double s[3];
    if (mid_sides(km, v[0], v[1], v[2], s)) return -1;
    double w[3], sum = 0;
    for (int i = 0; i < 3; i++) sum += w[i] = s[i] * (s[(i + 1) % 3] + s[(i + 2) % 3] - s[i]);
    if (!(sum > 0)) return -1;
    for (int i = 0; i < 3; i++) bary[i] = w[i] / sum;
    return 0;
}

static double tri_mid(const cm_kmesh *km, int32_t t)
{
    const int32_t *v = km->tri + 3 * (size_t)t;
    return cm_mid_angle(km, v[0], v[1], v[2]);
}

long cm_mid_flip_queue(cm_kmesh *km, cm_work *edges)
{
    long flips = 0, cap = 50L * km->live_t + 1000;
    for (int32_t c; (c = cm_work_pop(edges)) >= 0;) {
        if (km->tri[c] < 0 || km->opp[c] < 0 || flips >= cap) continue;
        int32_t o = km->opp[c];
        int32_t v0 = km->tri[c], v1 = km->tri[cm_next(c)], v2 = km->tri[cm_prev(c)], v3 = km->tri[o];
        double before = fmin(tri_mid(km, c / 3), tri_mid(km, o / 3));
        double after = fmin(cm_mid_angle(km, v0, v1, v3), cm_mid_angle(km, v3, v2, v0));
        if (!(after > before + CM_MID_GAIN) || !cm_flip_if_valid(km, c)) continue;
        flips++;
        /* the quad's four outer edges */
        int32_t around[4] = {cm_next(c), cm_prev(c), cm_next(o), cm_prev(o)};
        for (int i = 0; i < 4; i++)
            if (km->opp[around[i]] >= 0 && cm_work_push(edges, around[i])) return -1;
    }
    return flips;
}

/* Queues the edges of the triangles around v. 0 or -1. */
static int queue_star(cm_kmesh *km, int32_t v, cm_work *edges, cm_ibuf *star)
{
    long m = cm_kmesh_star(km, v, star);
    if (m < 0) return m == -1 ? -1 : 0;
    for (long i = 0; i < m; i++)
        if (cm_work_push(edges, star->a[i])) return -1;
    return 0;
}

/* Inserts at bary inside t in every geometry if the three new triangles
 * are counter-clockwise in all. Returns the vertex, -2 when not, -1. */
static int32_t insert_at(cm_kmesh *km, int32_t t, const double bary[3], double *pts)
{
    const int32_t *v = km->tri + 3 * (size_t)t;
    for (size_t g = 0; g < km->k; g++) {
        const double *p[3] = {cm_kmesh_pos(km, g, v[0]), cm_kmesh_pos(km, g, v[1]), cm_kmesh_pos(km, g, v[2])};
        double *q = pts + 2 * g;
        q[0] = bary[0] * p[0][0] + bary[1] * p[1][0] + bary[2] * p[2][0];
        q[1] = bary[0] * p[0][1] + bary[1] * p[1][1] + bary[2] * p[2][1];
        for (int i = 0; i < 3; i++) /* triangle i: q replaces vertex i */
            if (cm_orient2d(i == 0 ? q : p[0], i == 1 ? q : p[1], i == 2 ? q : p[2]) <= 0) return -2;
    }
    return cm_kmesh_insert(km, t, pts);
}

int32_t cm_insert_bary(cm_kmesh *km, int32_t t, const double bary[3])
{
    if (!cm_kmesh_tri_live(km, t)) return -2;
    double *pts = malloc(2 * km->k * sizeof *pts);
    if (!pts) return -1;
    int32_t m = insert_at(km, t, bary, pts);
    free(pts);
    return m;
}

int32_t cm_mid_insert(cm_kmesh *km, int32_t t)
{
    double bary[3];
    if (!cm_kmesh_tri_live(km, t) || cm_mid_circumcentre(km, t, bary)) return -2;
    if (fmin(bary[0], fmin(bary[1], bary[2])) < CM_MID_INSIDE) return -2;
    double *pts = malloc(2 * km->k * sizeof *pts);
    if (!pts) return -1;
    int32_t m = insert_at(km, t, bary, pts);
    free(pts);
    return m;
}

/* Keeps the open transaction if the smallest angle (all geometries) of
 * the triangles it changed did not drop, else undoes it. 1 kept, 0
 * undone, -1 out of memory. */
static int settle(cm_kmesh *km)
{
    double before, after;
    if (cm_kmesh_tx_region(km, &before, &after)) {
        cm_kmesh_tx_commit(km);
        return -1;
    }
    if (after >= before) {
        cm_kmesh_tx_commit(km);
        return 1;
    }
    return cm_kmesh_tx_rollback(km) ? -1 : 0;
}

typedef struct { double key; int32_t t; } candidate;

static int by_key(const void *pa, const void *pb)
{
    const candidate *a = pa, *b = pb;
    return (a->key > b->key) - (a->key < b->key);
}

long cm_mid_refine(cm_kmesh *km, double share, long budget, cm_mapopt_weights w)
{
    double *pts = malloc(2 * km->k * sizeof *pts);
    candidate *cand = NULL;
    cm_work edges = {0};
    cm_ibuf star = {0};
    long inserted = 0, status = 0;
    if (!pts) return -1;
    /* toward the middle Delaunay triangulation first, kept as the
     * insertions below are */
    if (cm_kmesh_tx_begin(km)) goto oom;
    if (cm_flip_queue_all(km, &edges) || cm_mid_flip_queue(km, &edges) < 0) {
        cm_kmesh_tx_commit(km);
        goto oom;
    }
    if (settle(km) < 0) goto oom;
    for (;;) {
        if (km->live_v - km->n >= budget) break;
        free(cand);
        cand = malloc((size_t)(km->nt > 0 ? km->nt : 1) * sizeof *cand);
        if (!cand) goto oom;
        size_t nc = 0;
        for (int32_t t = 0; t < km->nt; t++) {
            if (!cm_kmesh_tri_live(km, t)) continue;
            double want = share * (km->tkey[t] - km->slack[t]), have = tri_mid(km, t);
            /* a sliver in some geometry: splits would copy it (the
             * midpoint of its long side is next to its apex); Algorithm
             * 1's splits with smoothing remove those */
            if (km->tkey[t] > CM_MID_SLIVER && have < want) cand[nc++] = (candidate){have / want, t};
        }
        if (nc == 0) break;
        qsort(cand, nc, sizeof *cand, by_key);
        long round = km->live_t / 50 > 1 ? km->live_t / 50 : 1, done = 0;
        uint32_t stamp = cm_kmesh_new_stamp(km);
        for (size_t i = 0; i < nc && done < round && km->live_v - km->n < budget; i++) {
            int32_t t = cand[i].t;
            if (!cm_kmesh_tri_live(km, t)) continue;
            const int32_t v[3] = {km->tri[3 * t], km->tri[3 * t + 1], km->tri[3 * t + 2]};
            if (km->mark[v[0]] == stamp || km->mark[v[1]] == stamp || km->mark[v[2]] == stamp) continue;
            double bary[3];
            if (cm_mid_circumcentre(km, t, bary)) continue;
            int lo = bary[0] <= bary[1] && bary[0] <= bary[2] ? 0 : bary[1] <= bary[2] ? 1 : 2;
            if (bary[lo] < CM_MID_INSIDE && km->opp[3 * t + lo] < 0) continue;
            if (cm_kmesh_tx_begin(km)) goto oom;
            int32_t m = bary[lo] >= CM_MID_INSIDE ? insert_at(km, t, bary, pts) : cm_refine_split(km, 3 * t + lo);
            if (m >= 0 && (cm_mapopt_vertex(km, w, m, CM_MID_SPLIT_STEPS, &star) < 0 ||
                           queue_star(km, m, &edges, &star) || cm_mid_flip_queue(km, &edges) < 0))
                m = -1;
            if (m < 0) {
                cm_kmesh_tx_commit(km); /* nothing changed, or out of memory */
                if (m == -1) goto oom;
                continue;
            }
            int kept = settle(km);
            if (kept < 0) goto oom;
            if (!kept) {
                for (int j = 0; j < 3; j++) km->mark[v[j]] = stamp; /* not again this round */
                continue;
            }
            done++, inserted++;
            if (cm_kmesh_star(km, m, &star) == -1) goto oom;
            km->mark[m] = stamp;
            for (size_t j = 0; j < star.n; j++) km->mark[km->tri[cm_next(star.a[j])]] = stamp;
        }
        if (done == 0) break;
    }
    status = inserted;
    goto out;
oom:
    status = -1;
out:
    free(pts), free(cand);
    cm_work_free(&edges), cm_ibuf_free(&star);
    return status;
}
