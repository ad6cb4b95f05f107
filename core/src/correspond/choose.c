/* The start of every polygon's arc length, chosen by Procrustes alignment:
 * with z_j the points of polygon 0 and w_j those of polygon g (both M
 * points evenly spaced by arc length, counter-clockwise, centred), the best
 * similarity w ~ a z (a complex) leaves |w|^2 - |<z, w>|^2 / |z|^2; the start
 * with the smallest share of |w|^2 left is taken. A start that sends every
 * point near its counterpart up to a similarity leaves the map between the
 * polygons little to distort, which is what the meshes' angles need. */
#include <complex.h>
#include <math.h>
#include <stdlib.h>

#include "correspond/choose.h"
#include "correspond/arclength.h"
#include "geom/angle.h"

#define SAMPLES 64
#define COARSE_CANDIDATES 256

/* m points evenly spaced by arc length from counter-clockwise vertex
 * start. arc: cumulative lengths along the counter-clockwise order from
 * vertex 0 (n + 1 entries). */
static void sample_m(const double *xy, size_t n, int reversed, const double *arc, size_t start, size_t m,
                     double complex *out)
{
    double total = arc[n];
    for (size_t j = 0; j < m; j++) {
        double s = fmod(arc[start] + total * (double)j / (double)m, total);
        size_t lo = 0, hi = n; /* the edge c -> c + 1 with arc[c] <= s < arc[c + 1] */
        while (hi - lo > 1) {
            size_t mid = (lo + hi) / 2;
            if (arc[mid] <= s) lo = mid;
            else hi = mid;
        }
        const double *a = xy + 2 * cm_ccw_input(lo, n, reversed), *b = xy + 2 * cm_ccw_input((lo + 1) % n, n, reversed);
        double length = arc[lo + 1] - arc[lo], t = length > 0 ? (s - arc[lo]) / length : 0;
        out[j] = (a[0] + t * (b[0] - a[0])) + I * (a[1] + t * (b[1] - a[1]));
    }
}

/* SAMPLES points as sample_m, centred; returns their mean. */
static double complex sample(const double *xy, size_t n, int reversed, const double *arc, size_t start,
                             double complex *out)
{
    sample_m(xy, n, reversed, arc, start, SAMPLES, out);
    double complex mean = 0;
    for (int j = 0; j < SAMPLES; j++) mean += out[j];
    mean /= SAMPLES;
    for (int j = 0; j < SAMPLES; j++) out[j] -= mean;
    return mean;
}

/* The best similarity image a z of w (SAMPLES centred points each): a,
 * what it leaves of |w|^2 (*left) and |w|^2 itself (*ww). 0 where either
 * is all zero. */
static int similarity_fit(const double complex *z, const double complex *w, double complex *a, double *left,
                          double *ww)
{
    double complex zw = 0;
    double zz = 0;
    *ww = 0;
    for (int j = 0; j < SAMPLES; j++) zw += conj(z[j]) * w[j], zz += creal(z[j] * conj(z[j])), *ww += creal(w[j] * conj(w[j]));
    if (!(zz > 0) || !(*ww > 0)) return 0;
    *a = zw / zz, *left = *ww - creal(zw * conj(zw)) / zz;
    return 1;
}

/* One loop's candidate starts, scored against a target (SAMPLES centred
 * points for the Procrustes fit, or m points in place for the holes). For
 * the outer loops of polygons with holes, the holes' centroids too:
 * polygon 0's centred as the target, the loop's own in place (h each). */
typedef struct start_search {
    const double *xy;
    size_t n;
    int reversed;
    const double *arc;
    const double complex *target;
    size_t m;
    double complex *w; /* scratch for m (or SAMPLES) points */
    const double complex *target_holes, *holes;
    size_t h;
    int holes_tie; /* the holes break the outline's ties only, not in the cost */
    double prior;  /* the turn of the plane chosen for polygon g - 1 (0 for g = 1) */
} start_search;

/* What a start's fit says besides its cost: how far its pairing turns
 * the plane from polygon g - 1's (radians, in (-pi, pi]); how far the
 * holes fit (their squared distances' share) and how much of that a turn
 * by half a start's step accounts for. */
typedef struct start_fit {
    double turn, holes, reach;
} start_fit;

/* A start's cost, and its fit when fit is not NULL. */
typedef double (*start_cost)(const start_search *q, size_t start, start_fit *fit);

/* Starts whose costs' square roots lie within this of the least one's
 * fit alike (a share of the loop's size for the Procrustes fit). Where
 * such starts lie apart (a disc, a regular polygon, an outline a turn
 * takes onto itself), the holes break the tie where they only do that
 * (those whose holes fit within half a step's reach of the best of them),
 * and then the one whose pairing turns the plane least from polygon
 * g - 1's is taken: two sections of a pipe pair without a twist, of a
 * flange turned a little by the little turn, sections of a part that
 * twists as it goes each a little further round. */
#define START_TIE 1e-4

/* Of the candidates (every stride-th start) that fit as well as `best`
 * (START_TIE on cost; with holes_tie, the holes too), the one that turns
 * least, where some of them lie apart from best; else best. */
static size_t least_turning(const start_search *q, start_cost cost, size_t stride, size_t best, double best_cost)
{
    size_t n = q->n, least_at = best;
    double tie = sqrt(fmax(best_cost, 0)) + START_TIE; /* rounding may leave a cost a little below 0 */
    double holes = HUGE_VAL, least_turn = HUGE_VAL;
    int apart = 0;
    start_fit f;
    for (size_t c = 0; c < n; c += stride) {
        double e = cost(q, c, &f);
        if (!(e <= tie * tie)) continue;
        size_t d = c > best ? c - best : best - c;
        apart |= d > 2 * stride && n - d > 2 * stride;
        if (q->holes_tie) holes = fmin(holes, f.holes);
    }
    for (size_t c = 0; apart && c < n; c += stride) {
        double e = cost(q, c, &f);
        if (!(e <= tie * tie) || (q->holes_tie && f.holes > holes + f.reach)) continue;
        if (fabs(f.turn) < least_turn) least_turn = fabs(f.turn), least_at = c;
    }
    return least_at;
}

/* The counter-clockwise start of least cost: every vertex, or
 * COARSE_CANDIDATES of them, then the neighbourhood of the best. With
 * by_turn, of the candidates apart that fit alike (least_turning), the
 * one that turns least, and its neighbourhood. */
static size_t best_start(const start_search *q, start_cost cost, int by_turn)
{
    size_t n = q->n, stride = n > COARSE_CANDIDATES ? n / COARSE_CANDIDATES : 1, best = 0;
    double best_cost = HUGE_VAL;
    for (size_t c = 0; c < n; c += stride) {
        double e = cost(q, c, NULL);
        if (e < best_cost) best_cost = e, best = c;
    }
    if (by_turn && best_cost < HUGE_VAL) {
        size_t chosen = least_turning(q, cost, stride, best, best_cost);
        if (chosen != best) best = chosen, best_cost = cost(q, best, NULL);
    }
    size_t centre = best;
    for (size_t d = 1; stride > 1 && d < stride; d++)
        for (int side = -1; side <= 1; side += 2) {
            size_t c = (centre + n + (size_t)side * d) % n;
            double e = cost(q, c, NULL);
            if (e < best_cost) best_cost = e, best = c;
        }
    return best;
}

/* The mean of a loop's n vertices. */
static double complex vertex_mean(const double *xy, size_t n)
{
    double complex c = 0;
    for (size_t i = 0; i < n; i++) c += xy[2 * i] + I * xy[2 * i + 1];
    return c / (double)n;
}

/* The centroid of a loop of n vertices (its area's; the vertex mean where
 * the area vanishes); *area, if not NULL, receives its signed area. */
static double complex loop_centroid(const double *xy, size_t n, double *area)
{
    double a = 0, cx = 0, cy = 0;
    for (size_t i = 0; i < n; i++) {
        const double *p = xy + 2 * i, *q = xy + 2 * ((i + 1) % n);
        double c = p[0] * q[1] - q[0] * p[1];
        a += c, cx += (p[0] + q[0]) * c, cy += (p[1] + q[1]) * c;
    }
    if (area) *area = a / 2;
    return a != 0 ? (cx + I * cy) / (3 * a) : vertex_mean(xy, n);
}

/* The Procrustes residual's share; with holes (unless they only break
 * ties), plus each of polygon 0's hole centroids under the fitted
 * similarity to the loop's nearest one (squared, in the same share): an
 * outer loop that a turn takes onto itself (a rectangle) leaves the turn
 * to the holes. */
static double procrustes_cost(const start_search *q, size_t start, start_fit *fit)
{
    double complex mean = sample(q->xy, q->n, q->reversed, q->arc, start, q->w), a;
    double left, ww, holes = 0, far = 0;
    if (!similarity_fit(q->target, q->w, &a, &left, &ww)) return HUGE_VAL;
    for (size_t i = 0; i < q->h; i++) {
        double nearest = HUGE_VAL;
        for (size_t j = 0; j < q->h; j++) nearest = fmin(nearest, cabs(a * q->target_holes[i] - (q->holes[j] - mean)));
        holes += nearest * nearest, far = fmax(far, cabs(a * q->target_holes[i]));
    }
    if (fit) { /* a start's step turns the plane by about 2 pi / n: half of it moves a hole this far */
        double half_step = far * CM_PI / (double)q->n;
        fit->turn = remainder(carg(a) - q->prior, 2 * CM_PI);
        fit->holes = holes / ww, fit->reach = (double)q->h * half_step * half_step / ww;
    }
    return (q->holes_tie ? left : left + holes) / ww;
}

/* The h hole centroids of a polygon with holes, less `centre`. */
static void hole_centroids(const cm_loops *loops, double complex centre, double complex *out)
{
    for (size_t i = 1, at = loops->loop_sizes[0]; i < loops->num_loops; at += loops->loop_sizes[i++])
        out[i - 1] = loop_centroid(loops->xy + 2 * at, loops->loop_sizes[i], NULL) - centre;
}

/* A double complex is laid out as two doubles, real part first (C11
 * 6.2.5). */
void cm_correspond_hole_centres(const cm_loops *loops, double *out) { hole_centroids(loops, 0, (double complex *)out); }

cm_status cm_correspond_choose_starts(const double *const *polygons, const size_t *counts, size_t k,
                                      const int *orientation, const cm_loops *loops, int holes_tie, size_t *pins,
                                      cm_error *err)
{
    double complex z[SAMPLES], w[SAMPLES];
    size_t h = loops ? loops[0].num_loops - 1 : 0;
    double complex *target_holes = h ? malloc(2 * h * sizeof *target_holes) : NULL, *holes = NULL;
    double *arc0 = cm_arc_lengths(polygons[0], counts[0], orientation[0] < 0, 0);
    if (!arc0 || (h && !target_holes)) {
        free(arc0), free(target_holes);
        return cm_fail_status(err, CM_ERR_NO_MEMORY);
    }
    double complex mean = sample(polygons[0], counts[0], orientation[0] < 0, arc0, 0, z);
    if (h) hole_centroids(&loops[0], mean, target_holes), holes = target_holes + h;
    pins[0] = cm_ccw_input(0, counts[0], orientation[0] < 0);
    free(arc0);
    cm_status s = CM_OK;
    double prior = 0;
    for (size_t g = 1; s == CM_OK && g < k; g++) {
        size_t n = counts[g];
        int reversed = orientation[g] < 0;
        double *arc = cm_arc_lengths(polygons[g], n, reversed, 0);
        if (!arc) {
            s = cm_fail_status(err, CM_ERR_NO_MEMORY);
            break;
        }
        if (h) hole_centroids(&loops[g], 0, holes);
        start_search q = {polygons[g], n, reversed, arc, z, SAMPLES, w, target_holes, holes, h, holes_tie, prior};
        size_t best = best_start(&q, procrustes_cost, 1);
        start_fit f = {0, 0, 0};
        procrustes_cost(&q, best, &f);
        prior = remainder(prior + f.turn, 2 * CM_PI);
        pins[g] = cm_ccw_input(best, n, reversed);
        free(arc);
    }
    free(target_holes);
    return s;
}

void cm_correspond_outer_similarity(const cm_boundary_map *outer, double *similarity)
{
    size_t n = outer->n;
    const double *p = outer->xy[0];
    double complex pc = 0;
    for (size_t i = 0; i < n; i++) pc += p[2 * i] + I * p[2 * i + 1];
    pc /= (double)n;
    for (size_t g = 0; g < outer->k; g++) {
        const double *q = outer->xy[g];
        double complex qc = 0, pq = 0;
        double pp = 0;
        for (size_t i = 0; i < n; i++) qc += q[2 * i] + I * q[2 * i + 1];
        qc /= (double)n;
        for (size_t i = 0; i < n; i++) { /* q - qc = a (p - pc), least squares */
            double complex u = p[2 * i] + I * p[2 * i + 1] - pc, v = q[2 * i] + I * q[2 * i + 1] - qc;
            pq += conj(u) * v, pp += creal(u * conj(u));
        }
        double complex a = pp > 0 ? pq / pp : 1, b = qc - a * pc;
        similarity[4 * g] = creal(a), similarity[4 * g + 1] = cimag(a);
        similarity[4 * g + 2] = creal(b), similarity[4 * g + 3] = cimag(b);
    }
}

#define HOLE_SAMPLES_MAX 1024

/* Sum of squared distances from the m points of the loop sampled from
 * counter-clockwise vertex start to the target. */
static double distance_cost(const start_search *q, size_t start, start_fit *fit)
{
    if (fit) fit->turn = fit->holes = fit->reach = 0;
    sample_m(q->xy, q->n, q->reversed, q->arc, start, q->m, q->w);
    double sum = 0;
    for (size_t j = 0; j < q->m; j++) {
        double complex e = q->w[j] - q->target[j];
        sum += creal(e * conj(e));
    }
    return sum;
}

/* Point z of polygon 0's hole carried into polygon g radially: the point
 * of the outer loops' map whose direction from polygon 0's hole centre c0
 * is nearest z's, and z at its share of the way out from c0 to it, go to
 * the same share of the way from polygon g's hole centre cg to that
 * point's partner. 0 (out untouched) where a direction is not defined. */
static int carry_radially(const cm_boundary_map *outer, size_t g, double complex c0, double complex cg,
                          double complex z, double complex *out)
{
    double complex d = z - c0, far = 0;
    double best = -2;
    size_t at = 0;
    if (!(cabs(d) > 0)) return 0;
    for (size_t i = 0; i < outer->n; i++) {
        double complex p = outer->xy[0][2 * i] + I * outer->xy[0][2 * i + 1] - c0;
        if (!(cabs(p) > 0)) continue;
        double cosine = creal(p * conj(d)) / (cabs(p) * cabs(d));
        if (cosine > best) best = cosine, at = i, far = p;
    }
    if (best == -2) return 0;
    double complex q = outer->xy[g][2 * at] + I * outer->xy[g][2 * at + 1];
    *out = cg + cabs(d) / cabs(far) * (q - cg);
    return 1;
}

cm_status cm_correspond_choose_hole_starts(const double *const *holes, const size_t *counts, size_t k,
                                           const int *orientation, const cm_boundary_map *outer,
                                           const double *similarity, size_t *pins, cm_error *err)
{
    size_t m = 0;
    for (size_t g = 0; g < k; g++) m = counts[g] > m ? counts[g] : m;
    m = m < HOLE_SAMPLES_MAX ? m : HOLE_SAMPLES_MAX;
    double complex *z = malloc(m * sizeof *z), *w = malloc(m * sizeof *w), *mapped = malloc(m * sizeof *mapped);
    double *arc = cm_arc_lengths(holes[0], counts[0], orientation[0] < 0, 0);
    cm_status s = z && w && mapped && arc ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    if (s == CM_OK) sample_m(holes[0], counts[0], orientation[0] < 0, arc, 0, m, z);
    free(arc), arc = NULL;
    pins[0] = cm_ccw_input(0, counts[0], orientation[0] < 0);
    for (size_t g = 1; s == CM_OK && g < k; g++) {
        size_t n = counts[g];
        int reversed = orientation[g] < 0;
        double complex a = similarity[4 * g] + I * similarity[4 * g + 1];
        double complex b = similarity[4 * g + 2] + I * similarity[4 * g + 3];
        double complex c0 = vertex_mean(holes[0], counts[0]), cg = vertex_mean(holes[g], n);
        for (size_t j = 0; j < m; j++)
            if (!carry_radially(outer, g, c0, cg, z[j], &mapped[j])) mapped[j] = a * z[j] + b;
        if (!(arc = cm_arc_lengths(holes[g], n, reversed, 0))) {
            s = cm_fail_status(err, CM_ERR_NO_MEMORY);
            break;
        }
        start_search q = {holes[g], n, reversed, arc, mapped, m, w, NULL, NULL, 0, 0, 0};
        size_t best = best_start(&q, distance_cost, 0);
        pins[g] = cm_ccw_input(best, n, reversed);
        free(arc), arc = NULL;
    }
    free(z), free(w), free(mapped);
    return s;
}

#define AFFINE_MAX_VERTICES 4096
#define AFFINE_TOLERANCE 1e-9

/* Counter-clockwise vertices of a polygon, centred, as complex numbers. */
static void centred(const double *xy, size_t n, int reversed, double complex *out)
{
    double complex mean = 0;
    for (size_t c = 0; c < n; c++) {
        const double *p = xy + 2 * cm_ccw_input(c, n, reversed);
        out[c] = p[0] + I * p[1];
        mean += out[c];
    }
    mean /= (double)n;
    for (size_t c = 0; c < n; c++) out[c] -= mean;
}

/* The share of sum |q|^2 the least-squares affine image of p leaves, q
 * read from position shift: with S = sum p p^T and C = sum q p^T (2 x 2),
 * the residual is sum |q|^2 - tr(C S^-1 C^T) (exact: summed point by
 * point, and a, if not NULL, receives A = C S^-1 row by row). */
static double affine_residual(const double complex *p, const double complex *q, size_t n, size_t shift, int exact,
                              double a[4])
{
    double s00 = 0, s01 = 0, s11 = 0, c00 = 0, c01 = 0, c10 = 0, c11 = 0, qq = 0;
    for (size_t i = 0; i < n; i++) {
        double px = creal(p[i]), py = cimag(p[i]);
        double complex w = q[(i + shift) % n];
        double qx = creal(w), qy = cimag(w);
        s00 += px * px, s01 += px * py, s11 += py * py;
        c00 += qx * px, c01 += qx * py, c10 += qy * px, c11 += qy * py;
        qq += qx * qx + qy * qy;
    }
    double det = s00 * s11 - s01 * s01;
    if (!(det > 0) || !(qq > 0)) return HUGE_VAL;
    /* tr(C S^-1 C^T), S^-1 = [s11 -s01; -s01 s00] / det, row by row of C. */
    double fit = (c00 * (s11 * c00 - s01 * c01) + c01 * (s00 * c01 - s01 * c00) +
                  c10 * (s11 * c10 - s01 * c11) + c11 * (s00 * c11 - s01 * c10)) / det;
    if (!exact) return (qq - fit) / qq;
    /* The difference above cancels to rounding noise near 0: measure the
     * best candidate directly, with A = C S^-1. */
    double a00 = (c00 * s11 - c01 * s01) / det, a01 = (c01 * s00 - c00 * s01) / det;
    double a10 = (c10 * s11 - c11 * s01) / det, a11 = (c11 * s00 - c10 * s01) / det, left = 0;
    if (a) a[0] = a00, a[1] = a01, a[2] = a10, a[3] = a11;
    for (size_t i = 0; i < n; i++) {
        double px = creal(p[i]), py = cimag(p[i]);
        double complex w = q[(i + shift) % n];
        double dx = creal(w) - (a00 * px + a01 * py), dy = cimag(w) - (a10 * px + a11 * py);
        left += dx * dx + dy * dy;
    }
    return left / qq;
}

/* Below this share left by the quick residual a start is checked exactly
 * as another affine start (exact ones leave rounding noise, about 1e-16). */
#define AFFINE_CANDIDATE 1e-12

/* How far the affine map A (2 x 2, row by row) from centred p to centred q
 * takes polygon 0's h hole centroids (from, less polygon 0's outer vertex
 * mean) from polygon g's nearest ones (to): the sum of the squared
 * distances. qm: polygon g's outer vertex mean. */
static double holes_apart(const double complex *from, const double complex *to, size_t h, const double a[4],
                          double complex qm)
{
    double sum = 0;
    for (size_t i = 0; i < h; i++) {
        double complex c = from[i];
        double complex image = qm + a[0] * creal(c) + a[1] * cimag(c) + I * (a[2] * creal(c) + a[3] * cimag(c));
        double nearest = HUGE_VAL;
        for (size_t j = 0; j < h; j++) nearest = fmin(nearest, cabs(image - to[j]));
        sum += nearest * nearest;
    }
    return sum;
}

/* Of the starts that make polygon g's outer loop an exact affine image of
 * polygon 0's (`first` one of them), the one whose map takes polygon 0's
 * holes nearest to polygon g's (loops: NULL without holes), and of those
 * the one whose map turns the plane least from polygon g - 1's (*prior,
 * then the turn taken): an outer loop an affine map takes onto itself (a
 * rectangle, a disc's polygon) leaves the turn to the holes, and then to
 * the least twist. holes: polygon 0's h centroids (hole_centroids, less
 * its outer vertex mean), then room for polygon g's. */
static size_t exact_shift(const double complex *p, const double complex *q, size_t n, size_t first,
                          const cm_loops *loops, size_t g, double complex *holes, double *prior)
{
    size_t h = loops ? loops[0].num_loops - 1 : 0;
    double complex qm = h ? vertex_mean(loops[g].xy, n) : 0;
    if (h) hole_centroids(&loops[g], 0, holes + h);
    double size2 = 0;
    for (size_t i = 0; i < n; i++) size2 += creal(q[i] * conj(q[i]));
    double a[4], least = HUGE_VAL, least_turn = HUGE_VAL, tie = AFFINE_TOLERANCE * AFFINE_TOLERANCE * size2 / (double)n;
    double best_angle = *prior;
    size_t best = first;
    for (size_t s = 0; s < n; s++) {
        if (s != first && !(affine_residual(p, q, n, s, 0, NULL) <= AFFINE_CANDIDATE)) continue;
        if (!(affine_residual(p, q, n, s, 1, a) <= AFFINE_TOLERANCE * AFFINE_TOLERANCE)) continue;
        double apart = h ? holes_apart(holes, holes + h, h, a, qm) : 0, angle = atan2(a[2] - a[1], a[0] + a[3]);
        double turn = fabs(remainder(angle - *prior, 2 * CM_PI));
        if (apart < least - tie || (apart <= least + tie && turn < least_turn))
            least = fmin(least, apart), least_turn = turn, best = s, best_angle = angle;
    }
    *prior = best_angle;
    return best;
}

cm_status cm_correspond_affine_shift(const double *const *polygons, const size_t *counts, size_t k,
                                     const int *orientation, const cm_loops *loops, size_t *pins, int *found,
                                     cm_error *err)
{
    *found = 0;
    size_t n = counts[0];
    for (size_t g = 1; g < k; g++)
        if (counts[g] != n) return CM_OK;
    if (n > AFFINE_MAX_VERTICES) return CM_OK;
    size_t h = loops ? loops[0].num_loops - 1 : 0;
    double complex *p = malloc(n * sizeof *p), *q = malloc(n * sizeof *q);
    double complex *holes = h ? malloc(2 * h * sizeof *holes) : NULL;
    size_t *shift = malloc(k * sizeof *shift);
    if (!p || !q || !shift || (h && !holes)) {
        free(p), free(q), free(holes), free(shift);
        return cm_fail_status(err, CM_ERR_NO_MEMORY);
    }
    centred(polygons[0], n, orientation[0] < 0, p);
    if (h) hole_centroids(&loops[0], vertex_mean(loops[0].xy, n), holes);
    int all = 1;
    double prior = 0; /* the turn of the plane chosen for polygon g - 1 */
    shift[0] = 0;
    for (size_t g = 1; g < k && all; g++) {
        centred(polygons[g], n, orientation[g] < 0, q);
        double best = HUGE_VAL;
        for (size_t s = 0; s < n; s++) {
            double left = affine_residual(p, q, n, s, 0, NULL);
            if (left < best) best = left, shift[g] = s;
        }
        all = best < HUGE_VAL && affine_residual(p, q, n, shift[g], 1, NULL) <= AFFINE_TOLERANCE * AFFINE_TOLERANCE;
        if (all) shift[g] = exact_shift(p, q, n, shift[g], loops, g, holes, &prior);
    }
    if (all) {
        for (size_t i = 0; i < n; i++)
            for (size_t g = 0; g < k; g++)
                pins[i * k + g] = cm_ccw_input((i + shift[g]) % n, n, orientation[g] < 0);
        *found = 1;
    }
    free(p), free(q), free(holes), free(shift);
    return CM_OK;
}

/* z, a point inside polygon 0's outer loop, carried into polygon g by its
 * mean value coordinates over the outer loops' corresponding points
 * (Floater's: they reproduce the boundary's correspondence and vary
 * smoothly inside). tan_half: scratch for outer->n values. 0 (out
 * untouched) where z lies on that boundary. */
static int carry_mean_value(const cm_boundary_map *outer, size_t g, double complex z, double *tan_half,
                            double complex *out)
{
    size_t n = outer->n;
    const double *p = outer->xy[0], *q = outer->xy[g];
    for (size_t a = 0; a < n; a++) { /* tan of half the angle at z from point a to a + 1 */
        size_t b = (a + 1) % n;
        double complex s = p[2 * a] + I * p[2 * a + 1] - z, t = p[2 * b] + I * p[2 * b + 1] - z;
        double cross = cimag(conj(s) * t), dot = creal(conj(s) * t);
        if (!(cabs(s) > 0) || (cross == 0 && dot <= 0)) return 0; /* on a vertex or an edge */
        tan_half[a] = cross != 0 ? (cabs(s) * cabs(t) - dot) / cross : 0;
    }
    double complex sum = 0;
    double weights = 0;
    for (size_t a = 0; a < n; a++) {
        double w = (tan_half[(a + n - 1) % n] + tan_half[a]) / cabs(p[2 * a] + I * p[2 * a + 1] - z);
        sum += w * (q[2 * a] + I * q[2 * a + 1]), weights += w;
    }
    if (!(fabs(weights) > 0) || !isfinite(creal(sum / weights)) || !isfinite(cimag(sum / weights))) return 0;
    *out = sum / weights;
    return 1;
}

/* The hole of polygon g nearest to point z (centres: its holes' L - 1
 * centroids). */
static size_t nearest_hole(const double complex *centres, size_t holes, double complex z)
{
    size_t best = 0;
    for (size_t j = 1; j < holes; j++)
        if (cabs(centres[j] - z) < cabs(centres[best] - z)) best = j;
    return best;
}

/* Scratch for matching the h holes of polygon 0 and polygon g. */
typedef struct hole_match {
    size_t h;
    double *tan_half;                 /* outer->n */
    double complex *carried, *centres; /* h each */
    double *radius;                   /* h: polygon g's holes' */
    size_t *to, *back;                /* h each */
} hole_match;

/* Polygon 0's hole centroids carried into polygon g through `outer`
 * (carry_mean_value), each matched to polygon g's nearest hole (to) and
 * back. 1 when the match is one-to-one (each the other's nearest), and
 * *farthest the largest distance from a carried centroid to its hole's
 * centroid over that hole's radius; 0 otherwise. */
static int match_holes_of(const cm_loops *polygons, size_t g, const cm_boundary_map *outer, hole_match *m,
                          double *farthest)
{
    size_t h = m->h;
    for (size_t pass = 0; pass < 2; pass++) { /* polygon 0's holes carried, then polygon g's */
        const cm_loops *poly = &polygons[pass ? g : 0];
        size_t at = poly->loop_sizes[0];
        for (size_t j = 0; j < h; j++) {
            const double *xy = poly->xy + 2 * at;
            size_t n = poly->loop_sizes[j + 1];
            double area;
            double complex c = loop_centroid(xy, n, &area);
            at += n;
            if (pass)
                m->centres[j] = c, m->radius[j] = sqrt(fabs(area) / CM_PI); /* the disc of its area */
            else if (!carry_mean_value(outer, g, c, m->tan_half, &m->carried[j]))
                return 0;
        }
    }
    int matched = 1;
    *farthest = 0;
    for (size_t j = 0; j < h; j++) m->to[j] = nearest_hole(m->centres, h, m->carried[j]);
    for (size_t j = 0; j < h; j++) m->back[j] = nearest_hole(m->carried, h, m->centres[j]);
    for (size_t j = 0; j < h; j++) {
        matched &= m->back[m->to[j]] == j;
        *farthest = fmax(*farthest, cabs(m->carried[j] - m->centres[m->to[j]]) / m->radius[m->to[j]]);
    }
    return matched;
}

static int hole_match_init(hole_match *m, size_t h, size_t n)
{
    m->h = h;
    m->tan_half = malloc(n * sizeof *m->tan_half), m->radius = malloc(h * sizeof *m->radius);
    m->carried = malloc(h * sizeof *m->carried), m->centres = malloc(h * sizeof *m->centres);
    m->to = malloc(h * sizeof *m->to), m->back = malloc(h * sizeof *m->back);
    return m->tan_half && m->radius && m->carried && m->centres && m->to && m->back;
}

static void hole_match_free(hole_match *m)
{
    free(m->tan_half), free(m->radius), free(m->carried), free(m->centres), free(m->to), free(m->back);
}

cm_status cm_correspond_match_holes(const cm_loops *polygons, size_t k, const cm_boundary_map *outer,
                                    size_t *order, size_t *moved, cm_error *err)
{
    size_t L = polygons[0].num_loops, h = L - 1;
    *moved = 0;
    for (size_t g = 0; g < k; g++)
        for (size_t l = 0; l < L; l++) order[g * L + l] = l;
    if (h < 2) return CM_OK;
    hole_match m;
    cm_status s = hole_match_init(&m, h, outer->n) ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    double unused;
    for (size_t g = 1; s == CM_OK && g < k; g++) {
        if (!match_holes_of(polygons, g, outer, &m, &unused)) continue; /* keep the input's order */
        for (size_t j = 0; j < h; j++) {
            order[g * L + 1 + j] = 1 + m.to[j];
            *moved += m.to[j] != j;
        }
    }
    hole_match_free(&m);
    return s;
}

cm_status cm_correspond_holes_land(const cm_loops *polygons, size_t k, const cm_boundary_map *outer, int *land,
                                   cm_error *err)
{
    size_t h = polygons[0].num_loops - 1;
    hole_match m;
    *land = 1;
    if (!h) return CM_OK;
    cm_status s = hole_match_init(&m, h, outer->n) ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    for (size_t g = 1; s == CM_OK && g < k && *land; g++) {
        double farthest;
        *land = match_holes_of(polygons, g, outer, &m, &farthest) && farthest <= 1;
    }
    hole_match_free(&m);
    return s;
}
