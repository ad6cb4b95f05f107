/* The ceiling (bound.h).
 *
 * Corner fan. In a compatible triangulation the triangles at boundary
 * vertex i are the same m >= 1 triangles in every polygon, and in polygon
 * g they split the corner theta_g into m angles. If every angle of every
 * triangle is at least alpha, each of those m angles is at least alpha
 * and, the other two angles of its triangle being at least alpha, at most
 * 180 - 2 alpha. So m alpha <= min_g theta_g and max_g theta_g <=
 * m (180 - 2 alpha): alpha <= min(min theta / m, (180 - max theta / m) / 2)
 * for that m, and at most the largest of these over m >= 1.
 *
 * Correspondence bound. A compatible triangulation of A and B is a
 * piecewise-linear homeomorphism f: A -> B taking boundary vertex i to
 * vertex i. On each triangle f is affine; if every triangle has all angles
 * >= alpha in both geometries, each piece has dilatation at most
 * K(alpha), the largest dilatation of an affine map between two triangles
 * whose angles are all >= alpha (cm_bound_dilatation says why it is the
 * distance between two corners of the region of such triangle shapes). A
 * K-quasiconformal map changes the conformal modulus M of a quadrilateral
 * (the polygon with four marked boundary vertices) by a factor of at most
 * K. A quadruple whose moduli in A and B differ by r > K(alpha) thus rules
 * out alpha.
 *
 * The moduli are certified by linear finite elements on a mesh of each
 * polygon alone (its constrained Delaunay triangulation split into four
 * until it has CM_BOUND_MIN_TRIANGLES triangles): M is the least Dirichlet
 * energy of a function equal to 0 on the boundary from a to b and 1 from c
 * to d; a piecewise-linear function with those values is admissible, so
 * its energy is at least M, whatever the solver's rounding; the same for
 * the conjugate problem (0 from b to c, 1 from d to a), whose least energy
 * is 1 / M. So M lies in [1 / E', E], and the ratio used is a lower bound
 * over an upper bound. Energies are sums of non-negative per-triangle
 * terms, and a relative margin covers their rounding (and that of the
 * split points on the boundary, off the polygon's edges by an ulp).
 *
 * Which quadruple: one whose moduli differ most, found fast but not
 * certified. Each polygon's vertices are placed on the unit circle by the
 * discrete harmonic measure seen from an interior node (the boundary
 * values of a conformal map onto the disk), in CM_BOUND_VIEWS views from
 * nodes spread out, each quadruple read in the view that separates its
 * corners best (a long polygon's far ends crowd together beyond what
 * doubles resolve); the modulus of a disk
 * quadrilateral is K'(k) / 2 K(k) of its cross-ratio (elliptic integrals
 * by the arithmetic-geometric mean). Every quadruple of CM_BOUND_MARKS
 * evenly spaced vertices is scored, the best few are improved one mark at
 * a time by halving steps, and only those are certified. Another quadruple
 * may distort more: then the true bound is lower still, never higher. */
#include "correspond/bound.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "correspond/fe.h"
#include "geom/angle.h"
#include "geom/polytri.h"

/* The finite element mesh of each polygon is split into four until it has
 * at least this many triangles (a rectangle's moduli come out exact; what
 * the bound loses against bench/correspondence_bound.py is in
 * bench/CEILING.md). */
#define CM_BOUND_MIN_TRIANGLES 1200
/* Marks of the coarse quadruple search, and how many of its best
 * quadruples are refined and certified. */
#define CM_BOUND_MARKS 20
#define CM_BOUND_CANDIDATES 3
/* Interior nodes the polygon is seen from (one conformal map each), and
 * the least gap between corners on the circle a view must resolve. */
#define CM_BOUND_VIEWS 8
#define CM_BOUND_RESOLVED 1e-9
/* Relative margin on every finite element energy (rounding). */
#define CM_BOUND_MARGIN 1e-9

/* ---- the caps' formulas ---------------------------------------------------- */

/* Write a triangle with vertices 0, 1 and z (Im z > 0); its shape is z,
 * a point of the hyperbolic upper half-plane. The affine map between the
 * triangles z1 and z2 fixing 0 and 1 has Beltrami coefficient of modulus
 * |z2 - z1| / |z2 - conj z1|, so its dilatation is exp of the hyperbolic
 * distance between z1 and z2. The shapes whose angles are all >= alpha
 * form a region bounded by three arcs: arg z = alpha, arg (z - 1) = 180 -
 * alpha, and the circle arc through 0 and 1 where the angle at z is alpha.
 * Each arc is an equidistant curve of a geodesic (the lines Re z = 0 and
 * Re z = 1, the half-circle on [0, 1]), and along such a curve the cosh of
 * the distance to a fixed point is a cosh(s - s0) - b with a > 0 in the
 * arc length s of the geodesic, so it is largest at the ends of an arc. A
 * point's distance to a fixed point is therefore largest over the region
 * at one of its three corners, and (applied twice) the region's diameter
 * is the distance between two corners: the triangles (alpha, alpha, 180 -
 * 2 alpha) and (alpha, 180 - 2 alpha, alpha), z1 = 1/2 + i tan(alpha) / 2
 * and z2 = 1 + cos 2 alpha + i sin 2 alpha. For large K this is about 3/4
 * of D(alpha)^2, the square of the largest dilatation from the
 * equilateral triangle, which two maps through it would give. */
double cm_bound_dilatation(double alpha)
{
    double x = 0.5 + cos(2 * alpha), u = sin(2 * alpha), v = 0.5 * tan(alpha);
    double mu = sqrt((x * x + (u - v) * (u - v)) / (x * x + (u + v) * (u + v)));
    return (1 + mu) / (1 - mu);
}

double cm_bound_angle(double K)
{
    if (!(K > 1.0)) return 60.0;
    double lo = 1e-12, hi = CM_PI / 3;
    for (int i = 0; i < 80; i++) {
        double mid = 0.5 * (lo + hi);
        if (cm_bound_dilatation(mid) >= K) lo = mid;
        else hi = mid;
    }
    return fmin(60.0, hi * 180.0 / CM_PI * (1 + 1e-12));
}

/* Interior angle, degrees in (0, 360), of a counter-clockwise polygon at i. */
static double corner_deg(const double *xy, size_t n, size_t i)
{
    const double *p = xy + 2 * ((i + n - 1) % n), *v = xy + 2 * i, *q = xy + 2 * ((i + 1) % n);
    double ux = q[0] - v[0], uy = q[1] - v[1], wx = p[0] - v[0], wy = p[1] - v[1];
    double a = atan2(ux * wy - uy * wx, ux * wx + uy * wy) * 180.0 / CM_PI;
    return a <= 0 ? a + 360.0 : a;
}

double cm_corner_fan_cap(const double *const *geoms, size_t k, size_t n)
{
    double cap = 60.0;
    for (size_t i = 0; i < n; i++) {
        double lo = 360.0, hi = 0.0;
        for (size_t g = 0; g < k; g++) {
            double a = corner_deg(geoms[g], n, i);
            lo = fmin(lo, a), hi = fmax(hi, a);
        }
        double best = 0.0;
        for (double m = 1; lo / m > best; m++) best = fmax(best, fmin(lo / m, (180.0 - hi / m) / 2));
        cap = fmin(cap, best);
    }
    /* rounded up: a fan of one triangle reaches the corner angle itself */
    return fmin(60.0, cap * (1 + 1e-9));
}

/* Dirichlet energy of the piecewise-linear u, as non-negative per-triangle
 * terms |sum u_i d_i|^2 / (2 * twice the area). */
static double fe_energy(const cm_fe_mesh *m)
{
    double e = 0;
    for (long t = 0; t < m->nt; t++) {
        double d[3][2], a2 = cm_fe_tri(m, t, d), gx = 0, gy = 0;
        for (int i = 0; i < 3; i++) {
            double ui = m->u[m->tri[3 * t + i]];
            gx += ui * d[i][0], gy += ui * d[i][1];
        }
        e += (gx * gx + gy * gy) / (2 * a2);
    }
    return e;
}

/* Boundary nodes from polygon vertex a to b (counter-clockwise) fixed to val. */
static void fix_arc(cm_fe_mesh *m, long a, long b, double val)
{
    long from = a << m->levels, to = b << m->levels;
    for (long j = from;; j = (j + 1) % m->nb) {
        m->fixed[m->bnode[j]] = 1, m->u[m->bnode[j]] = val;
        if (j == to) break;
    }
}

/* Energy of the problem 0 on a..b, 1 on c..d: at least the modulus. */
static cm_status fe_modulus_upper(cm_fe_mesh *m, const long q[4], double *e, cm_error *err)
{
    memset(m->fixed, 0, (size_t)m->nv);
    memset(m->u, 0, (size_t)m->nv * sizeof *m->u);
    fix_arc(m, q[0], q[1], 0.0);
    fix_arc(m, q[2], q[3], 1.0);
    cm_status s = cm_fe_solve(m, -1, 1, err);
    *e = fe_energy(m) * (1 + CM_BOUND_MARGIN);
    return s;
}

static cm_status fe_modulus_range(cm_fe_mesh *m, const long q[4], double *lower, double *upper, cm_error *err)
{
    long conj[4] = {q[1], q[2], q[3], q[0]};
    double e;
    cm_status s = fe_modulus_upper(m, q, upper, err);
    if (s == CM_OK) s = fe_modulus_upper(m, conj, &e, err);
    *lower = s == CM_OK && e > 0 ? (1 - CM_BOUND_MARGIN) / e : 0.0;
    return s;
}

/* Vertex i's places on the unit circle, angle[e * n + i] in [0, 2 pi) for
 * each of CM_BOUND_VIEWS interior nodes e: the discrete harmonic measure,
 * seen from that node, of the boundary from vertex 0 to vertex i. A
 * conformal map crowds the far ends of a long polygon together beyond what
 * doubles resolve, so the nodes are spread out: the deepest of a sample,
 * then each the sampled node farthest from those chosen. */
static cm_status fe_circle(cm_fe_mesh *m, size_t n, double *angle, cm_error *err)
{
    long sample[CM_FE_SAMPLE], ns = cm_fe_sample_interior(m, sample), source[CM_BOUND_VIEWS];
    if (ns == 0) {
        for (size_t i = 0; i < CM_BOUND_VIEWS * n; i++) angle[i] = 2 * CM_PI * (double)(i % n) / (double)n;
        return CM_OK;
    }
    source[0] = cm_fe_deepest(m, n, sample, ns);
    double best;
    for (int e = 1; e < CM_BOUND_VIEWS; e++) {
        best = -1;
        for (long j = 0; j < ns; j++) {
            const double *p = m->xy + 2 * sample[j];
            double near = INFINITY;
            for (int f = 0; f < e; f++) {
                const double *q = m->xy + 2 * source[f];
                near = fmin(near, (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]));
            }
            if (near > best) best = near, source[e] = sample[j];
        }
    }
    double *w = malloc((size_t)m->nb * sizeof *w);
    if (!w) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    for (int e = 0; e < CM_BOUND_VIEWS; e++) {
        cm_status s = cm_fe_harmonic_measure(m, source[e], e == 0, w, err);
        if (s != CM_OK) {
            free(w);
            return s;
        }
        double acc = 0;
        long step = 1L << m->levels;
        for (long j = 0; j < m->nb; j++) {
            if (j % step == 0) angle[(size_t)e * n + (size_t)(j / step)] = 2 * CM_PI * (acc + 0.5 * w[j]);
            acc += w[j];
        }
    }
    free(w);
    return CM_OK;
}

/* ---- the quadruple search -------------------------------------------------- */

static double agm(double a, double b)
{
    for (int i = 0; i < 64 && fabs(a - b) > 1e-15 * a; i++) {
        double m = 0.5 * (a + b);
        b = sqrt(a * b), a = m;
    }
    return a;
}

/* An arc of the circle from one corner of a quadruple to the next: its
 * length in each view, in [0, 2 pi), and the length of its chord, 2 sin
 * of half of it (NULL: not worked out). */
typedef struct arc_views {
    double gap[CM_BOUND_VIEWS];
    const double *chord;
} arc_views;

static void arc_between(const double *angle, size_t n, long from, long to, arc_views *arc)
{
    for (int e = 0; e < CM_BOUND_VIEWS; e++) {
        const double *view = angle + (size_t)e * n;
        arc->gap[e] = view[to] - view[from];
        if (arc->gap[e] < 0) arc->gap[e] += 2 * CM_PI;
    }
    arc->chord = NULL;
}

static double chord_of(const arc_views *arc, int view, double gap)
{
    return arc->chord ? arc->chord[view] : 2 * sin(0.5 * gap);
}

/* log of the modulus of the disk quadrilateral with corners at angles
 * t[0] < t[1] < t[2] < t[3] (cyclically), 0 on the arc t0..t1, 1 on
 * t2..t3, given the arcs t0..t1, t1..t2, t2..t3: with the cross-ratio
 * l = |t0t1| |t2t3| / (|t0t2| |t1t3|) (chords)
 * and s = sqrt(l), the half-plane points -1/k, -1, 1, 1/k with k = (1 - s)
 * / (1 + s) = (1 - l) / (1 + s)^2 give M = K'(k) / 2 K(k) = agm(1, k') / 2 agm(1, k). NAN when
 * two corners are too close to tell apart. */
static double log_modulus(const arc_views *const arc[3])
{
    /* the view that separates the four corners best: the largest least
     * gap between consecutive corners */
    const double *g0 = arc[0]->gap, *g1 = arc[1]->gap, *g2 = arc[2]->gap;
    double sep = 0;
    int best = 0;
    for (int e = 0; e < CM_BOUND_VIEWS; e++) {
        /* not fmin: a library call, in the hottest loop */
        double least = INFINITY, g3 = 2 * CM_PI - g0[e] - g1[e] - g2[e];
        if (g0[e] < least) least = g0[e];
        if (g1[e] < least) least = g1[e];
        if (g2[e] < least) least = g2[e];
        if (g3 < least) least = g3;
        if (least > sep) sep = least, best = e;
    }
    if (!(sep > CM_BOUND_RESOLVED)) return NAN;
    double gap[4] = {g0[best], g1[best], g2[best], 2 * CM_PI - g0[best] - g1[best] - g2[best]};
    double ab = chord_of(arc[0], best, gap[0]), bc = chord_of(arc[1], best, gap[1]);
    double cd = chord_of(arc[2], best, gap[2]);
    double da = 2 * sin(0.5 * gap[3]), ac = 2 * sin(0.5 * (gap[0] + gap[1])), bd = 2 * sin(0.5 * (gap[1] + gap[2]));
    /* 1 - l = |t0t3| |t1t2| / (|t0t2| |t1t3|) (Ptolemy) keeps k accurate
     * when it is tiny, where (1 - s) / (1 + s) would round to 0 */
    double s = sqrt(ab * cd / (ac * bd)), mu = da * bc / (ac * bd);
    double k = mu / ((1 + s) * (1 + s)), kp = 2 * sqrt(s) / (1 + s);
    double lo = agm(1, k);
    if (!(lo > 0) || !(kp > 0)) return NAN;
    return log(agm(1, kp) / (2 * lo));
}

/* The arcs between the coarse search's marks, worked out once: polygon g's
 * arc from mark a to mark b at [(g m + a) m + b], its chords in chord. */
typedef struct mark_arcs {
    int m;
    arc_views *arc;
    double *chord;
} mark_arcs;

static int mark_arcs_make(mark_arcs *t, double *const *angle, size_t k, long n, const long *marks, int m)
{
    size_t count = k * (size_t)m * (size_t)m;
    t->m = m;
    t->arc = malloc(count * sizeof *t->arc);
    t->chord = malloc(count * CM_BOUND_VIEWS * sizeof *t->chord);
    if (!t->arc || !t->chord) {
        free(t->arc), free(t->chord);
        return -1;
    }
    for (size_t g = 0, at = 0; g < k; g++)
        for (int a = 0; a < m; a++)
            for (int b = 0; b < m; b++, at++) {
                if (b <= a) continue; /* marks go round in order */
                arc_views *arc = &t->arc[at];
                double *chord = t->chord + at * CM_BOUND_VIEWS;
                arc_between(angle[g], (size_t)n, marks[a], marks[b], arc);
                for (int e = 0; e < CM_BOUND_VIEWS; e++) chord[e] = 2 * sin(0.5 * arc->gap[e]);
                arc->chord = chord;
            }
    return 0;
}

/* log of the largest modulus ratio over the polygons; -1 when unknown.
 * The arcs come from marks (mark indices j), or are worked out from
 * angle when marks is NULL. */
static double spread(double *const *angle, const mark_arcs *marks, const int *j, size_t k, long n,
                     const long q[4])
{
    double lo = INFINITY, hi = -INFINITY;
    for (size_t g = 0; g < k; g++) {
        arc_views own[3];
        const arc_views *arc[3];
        for (int i = 0; i < 3; i++) {
            if (marks) {
                arc[i] = &marks->arc[((g * (size_t)marks->m) + (size_t)j[i]) * (size_t)marks->m + (size_t)j[i + 1]];
            } else {
                arc_between(angle[g], (size_t)n, q[i], q[i + 1], &own[i]);
                arc[i] = &own[i];
            }
        }
        double l = log_modulus(arc);
        if (isnan(l)) return -1;
        lo = fmin(lo, l), hi = fmax(hi, l);
    }
    return hi - lo;
}

/* Mark i moved by s, if it stays strictly between its neighbours. */
static int moved(const long q[4], int i, long s, long n, long out[4])
{
    long prev = q[(i + 3) % 4], next = q[(i + 1) % 4];
    long gap = (next - prev + n) % n, at = (q[i] - prev + n) % n + s;
    if (at <= 0 || at >= gap) return 0;
    memcpy(out, q, 4 * sizeof *out);
    out[i] = (prev + at) % n;
    return 1;
}

typedef struct candidate {
    long q[4];
    double score;
} candidate;

/* Improves c by moving one mark at a time, steps halving from `step`. */
static void local_search(double *const *angle, size_t k, long n, long step, candidate *c)
{
    for (; step >= 1; step /= 2) {
        for (int improved = 1; improved;) {
            improved = 0;
            for (int i = 0; i < 4; i++)
                for (int sign = -1; sign <= 1; sign += 2) {
                    long q[4];
                    if (!moved(c->q, i, sign * step, n, q)) continue;
                    double r = spread(angle, NULL, NULL, k, n, q);
                    if (r > c->score * (1 + 1e-9)) {
                        memcpy(c->q, q, sizeof q);
                        c->score = r, improved = 1;
                    }
                }
        }
    }
}

/* The best CM_BOUND_CANDIDATES quadruples, refined; returns their count. */
static int search(double *const *angle, size_t k, long n, candidate *best)
{
    int nb = 0, m = n < CM_BOUND_MARKS ? (int)n : CM_BOUND_MARKS;
    long marks[CM_BOUND_MARKS];
    for (int j = 0; j < m; j++) marks[j] = (long)((double)j * (double)n / m) % n;
    /* every arc between marks serves many quadruples; without the memory,
     * each quadruple works out its own */
    mark_arcs table;
    const mark_arcs *arcs = mark_arcs_make(&table, angle, k, n, marks, m) == 0 ? &table : NULL;
    for (int a = 0; a < m; a++)
        for (int b = a + 1; b < m; b++)
            for (int c = b + 1; c < m; c++)
                for (int d = c + 1; d < m; d++) {
                    candidate x = {{marks[a], marks[b], marks[c], marks[d]}, 0};
                    int j[4] = {a, b, c, d};
                    x.score = spread(angle, arcs, j, k, n, x.q);
                    if (x.score <= 0) continue;
                    if (nb == CM_BOUND_CANDIDATES && x.score <= best[nb - 1].score) continue;
                    int at = nb < CM_BOUND_CANDIDATES ? nb++ : nb - 1;
                    best[at] = x;
                    for (int i = at; i > 0 && best[i].score > best[i - 1].score; i--) {
                        candidate t = best[i];
                        best[i] = best[i - 1], best[i - 1] = t;
                    }
                }
    if (arcs) free(table.arc), free(table.chord);
    long step = n / (2 * m) > 1 ? n / (2 * m) : 1;
    for (int i = 0; i < nb; i++) local_search(angle, k, n, step, &best[i]);
    return nb;
}

/* ---- driver ------------------------------------------------------------------ */

cm_status cm_bound_compute(const double *const *geoms, const int32_t *const *tris, size_t k,
                           size_t n, cm_progress *progress, cm_bound *out, cm_error *err)
{
    out->corner_fan_deg = cm_corner_fan_cap(geoms, k, n);
    out->correspondence_deg = 60.0, out->distortion = 1.0;
    for (int i = 0; i < 4; i++) out->quad[i] = -1;
    if (n < 4) return CM_OK; /* a triangle has no quadrilateral */
    cm_fe_mesh *mesh = calloc(k, sizeof *mesh);
    double **angle = calloc(k, sizeof *angle);
    cm_status s = mesh && angle ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    int usable = 1;
    for (size_t g = 0; g < k && s == CM_OK && usable; g++) {
        s = cm_fe_build(&mesh[g], geoms[g], tris ? tris[g] : NULL, n, CM_BOUND_MIN_TRIANGLES, &usable, err);
        if (s == CM_OK && usable && !(angle[g] = malloc(CM_BOUND_VIEWS * n * sizeof *angle[g])))
            s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        if (s == CM_OK && usable) s = fe_circle(&mesh[g], n, angle[g], err);
        if (s == CM_OK && cm_progress_check(progress)) s = cm_fail_status(err, CM_ERR_CANCELLED);
    }
    candidate best[CM_BOUND_CANDIDATES];
    int nc = s == CM_OK && usable ? search(angle, k, (long)n, best) : 0;
    double *lo = nc ? malloc(2 * k * sizeof *lo) : NULL, *hi = lo ? lo + k : NULL;
    if (nc && !lo) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
    for (int c = 0; c < nc && s == CM_OK; c++) {
        int dup = 0;
        for (int d = 0; d < c; d++) dup |= !memcmp(best[c].q, best[d].q, sizeof best[c].q);
        if (dup) continue;
        double ratio = 0;
        for (size_t g = 0; g < k && s == CM_OK; g++) {
            s = fe_modulus_range(&mesh[g], best[c].q, &lo[g], &hi[g], err);
            if (s == CM_OK && cm_progress_check(progress)) s = cm_fail_status(err, CM_ERR_CANCELLED);
        }
        for (size_t g = 0; g < k && s == CM_OK; g++)
            for (size_t h = 0; h < k; h++)
                if (hi[h] > 0 && lo[g] / hi[h] > ratio) ratio = lo[g] / hi[h];
        if (s == CM_OK && ratio > out->distortion) {
            out->distortion = ratio;
            memcpy(out->quad, best[c].q, sizeof out->quad);
        }
    }
    free(lo);
    if (s == CM_OK) out->correspondence_deg = cm_bound_angle(out->distortion);
    for (size_t g = 0; mesh && g < k; g++) cm_fe_free(&mesh[g]);
    for (size_t g = 0; angle && g < k; g++) free(angle[g]);
    free(mesh), free(angle);
    return s;
}

cm_status cm_bound_modulus(const double *xy, const int32_t *tri, size_t n, const long quad[4],
                           double *lower, double *upper, cm_error *err)
{
    cm_fe_mesh m;
    int usable;
    *lower = 0, *upper = INFINITY;
    cm_status s = cm_fe_build(&m, xy, tri, n, CM_BOUND_MIN_TRIANGLES, &usable, err);
    if (s == CM_OK && usable) s = fe_modulus_range(&m, quad, lower, upper, err);
    cm_fe_free(&m);
    return s;
}

/* ---- memo -------------------------------------------------------------------- */

/* Computations remembered; a run asks for a handful at most. */
#define CM_BOUND_MEMO_SIZE 8

typedef struct memo_entry {
    size_t k, n;
    double *xy;   /* k polygons' 2 n coordinates, one after another */
    int32_t *tri; /* their triangulations, 3 (n - 2) each */
    cm_bound b;
} memo_entry;

struct cm_bound_memo {
    memo_entry entry[CM_BOUND_MEMO_SIZE];
    int count, next; /* entries held; the one replaced next */
};

cm_bound_memo *cm_bound_memo_new(void) { return calloc(1, sizeof(cm_bound_memo)); }

void cm_bound_memo_free(cm_bound_memo *memo)
{
    if (!memo) return;
    for (int e = 0; e < memo->count; e++) free(memo->entry[e].xy), free(memo->entry[e].tri);
    free(memo);
}

static int memo_matches(const memo_entry *e, const double *const *geoms, const int32_t *const *tris, size_t k,
                        size_t n)
{
    if (e->k != k || e->n != n) return 0;
    for (size_t g = 0; g < k; g++)
        if (memcmp(e->xy + 2 * n * g, geoms[g], 2 * n * sizeof *e->xy) ||
            memcmp(e->tri + 3 * (n - 2) * g, tris[g], 3 * (n - 2) * sizeof *e->tri))
            return 0;
    return 1;
}

/* Remembers b for these polygons (silently not, out of memory). */
static void memo_store(cm_bound_memo *memo, const double *const *geoms, const int32_t *const *tris, size_t k,
                       size_t n, const cm_bound *b)
{
    double *xy = malloc(2 * n * k * sizeof *xy);
    int32_t *tri = malloc(3 * (n - 2) * k * sizeof *tri);
    if (!xy || !tri) {
        free(xy), free(tri);
        return;
    }
    for (size_t g = 0; g < k; g++) {
        memcpy(xy + 2 * n * g, geoms[g], 2 * n * sizeof *xy);
        memcpy(tri + 3 * (n - 2) * g, tris[g], 3 * (n - 2) * sizeof *tri);
    }
    memo_entry *e = &memo->entry[memo->next];
    if (memo->count == CM_BOUND_MEMO_SIZE) free(e->xy), free(e->tri);
    else memo->count++;
    *e = (memo_entry){k, n, xy, tri, *b};
    memo->next = (memo->next + 1) % CM_BOUND_MEMO_SIZE;
}

cm_status cm_bound_compute_memo(cm_bound_memo *memo, const double *const *geoms, const int32_t *const *tris,
                                size_t k, size_t n, cm_progress *progress, cm_bound *out, cm_error *err)
{
    if (!memo || n < 4 || k == 0) return cm_bound_compute(geoms, tris, k, n, progress, out, err);
    /* the triangulations cm_fe_build would make, made here to key on */
    int32_t *own = NULL, **made = NULL;
    if (!tris) {
        own = malloc(3 * (n - 2) * k * sizeof *own + n * sizeof(int32_t));
        made = malloc(k * sizeof *made);
        int32_t *idx = own ? own + 3 * (n - 2) * k : NULL;
        for (size_t i = 0; idx && i < n; i++) idx[i] = (int32_t)i;
        for (size_t g = 0; own && made && g < k; g++) {
            made[g] = own + 3 * (n - 2) * g;
            if (cm_polygon_triangulate(geoms[g], idx, (long)n, made[g], NULL) != 0) break;
            if (g + 1 == k) tris = (const int32_t *const *)made;
        }
    }
    cm_status s = CM_OK;
    int hit = 0;
    for (int e = 0; tris && e < memo->count && !hit; e++)
        if (memo_matches(&memo->entry[e], geoms, tris, k, n)) *out = memo->entry[e].b, hit = 1;
    if (!hit) {
        /* tris still NULL: cm_fe_build meets what failed above, and says so */
        s = cm_bound_compute(geoms, tris, k, n, progress, out, err);
        if (s == CM_OK && tris) memo_store(memo, geoms, tris, k, n, out);
    }
    free(own), free(made);
    return s;
}
