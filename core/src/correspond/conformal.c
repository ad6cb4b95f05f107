/* The conformal correspondence (conformal.h). The measurements behind its
 * choices (the power, the balancing) are in bench/CORRESPONDENCE.md. */
#include "correspond/conformal.h"

#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "correspond/arclength.h"
#include "correspond/circle.h"
#include "correspond/fe.h"
#include "base/order.h"
#include "geom/angle.h"

/* The mesh of each polygon is split into four until it has this many
 * triangles. */
#define MIN_TRIANGLES 4000
/* The rotation search: the points evenly spaced on the circle it compares
 * the arc lengths at, the evenly spaced turns it tries, and the golden-
 * section steps that refine the best. */
#define SEARCH_SAMPLES 512
#define ROTATIONS 256
#define GOLDEN_STEPS 48
/* The barycentre's iteration: at most this many steps, until the mean is
 * below the tolerance. */
#define BALANCE_ITERATIONS 200
#define BALANCE_TOLERANCE 1e-9

/* A polygon's boundary on the unit circle (circle.h). */
typedef cm_circle disk;

static int balance(disk *d);

static cm_status disk_build(const double *input, size_t n, int reversed, disk *d, int *usable, cm_error *err)
{
    memset(d, 0, sizeof *d);
    cm_fe_mesh m;
    memset(&m, 0, sizeof m);
    double *xy = malloc(2 * n * sizeof *xy), *w = NULL;
    cm_status s = xy ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    for (size_t c = 0; s == CM_OK && c < n; c++) {
        const double *p = input + 2 * cm_ccw_input(c, n, reversed);
        xy[2 * c] = p[0], xy[2 * c + 1] = p[1];
    }
    if (s == CM_OK) s = cm_fe_build(&m, xy, NULL, n, MIN_TRIANGLES, usable, err);
    long sample[CM_FE_SAMPLE], ns = s == CM_OK && *usable ? cm_fe_sample_interior(&m, sample) : 0;
    if (s == CM_OK && ns == 0) *usable = 0;
    if (s == CM_OK && *usable) {
        size_t nb = (size_t)m.nb;
        d->nb = nb;
        d->s = malloc((nb + 1) * sizeof *d->s);
        d->theta = malloc((nb + 1) * sizeof *d->theta);
        d->z = malloc((nb + 1) * sizeof *d->z);
        w = malloc(nb * sizeof *w);
        if (!d->s || !d->theta || !d->z || !w) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        /* seen from the deepest of all interior nodes: a similar polygon's
         * mesh is the similar image, and its deepest node the same */
        long *inner = s == CM_OK ? malloc((size_t)m.nv * sizeof *inner) : NULL, ni = 0;
        if (s == CM_OK && !inner) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        for (long v = 0; inner && v < m.nv; v++)
            if (!m.fixed[v]) inner[ni++] = v;
        if (s == CM_OK) s = cm_fe_harmonic_measure(&m, cm_fe_deepest(&m, n, inner, ni), 1, w, err);
        free(inner);
        if (s == CM_OK) {
            double acc = 0, first = CM_PI * w[0];
            d->s[0] = 0;
            for (size_t j = 0; j < nb; j++) {
                const double *p = m.xy + 2 * m.bnode[j], *q = m.xy + 2 * m.bnode[(j + 1) % nb];
                d->s[j + 1] = d->s[j] + hypot(q[0] - p[0], q[1] - p[1]);
                d->z[j] = p[0] + I * p[1];
                /* node j at the middle of its share of the measure */
                double t = 2 * CM_PI * (acc + 0.5 * w[j]) - first;
                d->theta[j] = j ? fmax(t, d->theta[j - 1]) : 0.0;
                acc += w[j];
            }
            double total = d->s[nb];
            for (size_t j = 0; j <= nb; j++) d->s[j] /= total;
            d->s[nb] = 1.0, d->theta[nb] = 2 * CM_PI, d->z[nb] = d->z[0];
            if (balance(d)) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        }
    }
    free(xy), free(w);
    cm_fe_free(&m);
    if (s != CM_OK || !*usable) cm_circle_free(d);
    return s;
}

/* The disk turned by the automorphism that puts the barycentre of arc
 * length at the centre (Douady-Earle: sum of s-weights times points on
 * the circle = 0), so that two polygons' disks agree up to a rotation when
 * the polygons are similar, whichever interior node each was seen from;
 * by halving steps towards the mean, composed. Angles stay from 0 at
 * vertex 0, non-decreasing. */
static int balance(disk *d)
{
    size_t nb = d->nb;
    /* the nodes on the circle and their weights, the same every step */
    double complex *at = malloc(nb * sizeof *at);
    double *weight = malloc(nb * sizeof *weight);
    if (!at || !weight) {
        free(at), free(weight);
        return -1;
    }
    for (size_t j = 0; j < nb; j++) {
        at[j] = cexp(I * d->theta[j]);
        weight[j] = 0.5 * ((j + 1 < nb ? d->s[j + 1] : 1.0) - (j ? d->s[j - 1] : d->s[nb - 1] - 1.0));
    }
    double complex a = 0;
    for (int it = 0; it < BALANCE_ITERATIONS; it++) {
        double complex mean = 0;
        for (size_t j = 0; j < nb; j++) mean += weight[j] * (at[j] - a) / (1 - conj(a) * at[j]);
        if (cabs(mean) < BALANCE_TOLERANCE) break;
        double complex b = 0.5 * mean;
        a = (b + a) / (1 + conj(a) * b);
    }
    double prev = 0, first = 0;
    for (size_t j = 0; j < nb; j++) {
        double complex w = at[j];
        double t = carg((w - a) / (1 - conj(a) * w));
        if (j == 0) first = t;
        t = j ? prev + fmax(0.0, remainder(t - prev, 2 * CM_PI)) : t;
        d->theta[j] = t - first, prev = t;
    }
    for (size_t j = 1; j < nb; j++) d->theta[j] = fmin(fmax(d->theta[j], d->theta[j - 1]), 2 * CM_PI);
    free(at), free(weight);
    return 0;
}

/* The search's view of one pair: m angles evenly spaced on the circle, as
 * points, polygon 0's arc length there and its point in the plane
 * (centred), and the disk of polygon g; the h hole centres of polygon 0
 * (centred as z0) and of polygon g. */
typedef struct search {
    const double complex *w;
    const double *s0;
    const double complex *z0;
    size_t m;
    const disk *g;
    const double complex *holes0, *holes_g;
    size_t h;
    double prior; /* the turn of the plane chosen for polygon g - 1 (0 for g = 1) */
} search;

/* How far the correspondence is from arc length with polygon g's disk
 * turned by rho onto polygon 0's (cm_circle_cost). */
static double cost(const void *ctx, double rho)
{
    const search *q = ctx;
    return cm_circle_cost(q->w, q->s0, q->m, q->g, rho);
}

/* The similarity of the plane closest to the correspondence of turn rho
 * (cm_circle_plane_fit). */
static void plane_fit(const search *q, double rho, double complex *a, double complex *centre)
{
    cm_circle_plane_fit(q->w, q->z0, q->m, q->g, rho, a, centre);
}

/* The angle by which the correspondence of turn rho turns the plane. */
static double plane_angle(const search *q, double rho)
{
    double complex a, centre;
    plane_fit(q, rho, &a, &centre);
    return carg(a);
}

/* How far the turn of the plane by angle is from the one polygon g - 1's
 * pairing made, in [0, pi]: sections of a part that twists as it goes (a
 * helical gear) pair each a little further round, not back. */
static double turn_from_prior(const search *q, double angle)
{
    return fabs(remainder(angle - q->prior, 2 * CM_PI));
}

/* That for the correspondence of turn rho. */
static double plane_turn(const void *ctx, double rho)
{
    const search *q = ctx;
    return turn_from_prior(q, plane_angle(q, rho));
}

/* How far the similarity a z + centre puts polygon 0's hole centres from
 * polygon g's nearest ones: the sum of the squared distances. */
static double holes_off_under(const search *q, double complex a, double complex centre)
{
    double sum = 0;
    for (size_t i = 0; i < q->h; i++) {
        double nearest = HUGE_VAL;
        for (size_t j = 0; j < q->h; j++) nearest = fmin(nearest, cabs(centre + a * q->holes0[i] - q->holes_g[j]));
        sum += nearest * nearest;
    }
    return sum;
}

/* That under the similarity closest to the correspondence of turn rho. */
static double holes_off(const void *ctx, double rho)
{
    const search *q = ctx;
    double complex a, centre;
    plane_fit(q, rho, &a, &centre);
    return holes_off_under(q, a, centre);
}

/* The turn of least cost: the best of ROTATIONS evenly spaced, then
 * golden-section search around it (the cost is V-shaped at a similar
 * copy's turn). Where turns that fit alike (CM_CIRCLE_TURN_TIE) lie apart
 * (a disc, a regular polygon, a shape a turn takes onto itself), the holes
 * choose among them (those that put the hole centres nearest, within what
 * one step of the turns moves them), and then the least turn of the plane
 * (from polygon g - 1's), refined by the same measure where its
 * neighbours fit alike too: two sections of a pipe pair without a twist,
 * of a flange turned a little by the little turn. */
static double best_turn(const search *q)
{
    double costs[ROTATIONS], step = 2 * CM_PI / ROTATIONS, best_cost = HUGE_VAL, least;
    int best = 0;
    for (int r = 0; r < ROTATIONS; r++) {
        costs[r] = cost(q, 2 * CM_PI * r / ROTATIONS);
        if (costs[r] < best_cost) best_cost = costs[r], best = r;
    }
    double tie = sqrt(fmax(best_cost, 0)) + CM_CIRCLE_TURN_TIE, tie2 = tie * tie; /* rounding may leave it below 0 */
    int apart = 0, least_at = best;
    for (int r = 0; r < ROTATIONS; r++) {
        int d = abs(r - best);
        apart |= costs[r] <= tie2 && d > 2 && d < ROTATIONS - 2;
    }
    if (apart) {
        /* the hole centres' offsets that one step of the turns, or the
         * tie's spread, accounts for */
        double off[ROTATIONS], turn[ROTATIONS], least_off = HUGE_VAL, most_off = 0, least_turn = HUGE_VAL, size = 0;
        double reach = 0;
        double complex a, centre;
        plane_fit(q, 2 * CM_PI * best / ROTATIONS, &a, &centre);
        for (size_t i = 0; i < q->m; i++) size += creal(q->z0[i] * conj(q->z0[i]));
        for (size_t i = 0; i < q->h; i++) reach = fmax(reach, cabs(a * q->holes0[i]) * step);
        reach += CM_CIRCLE_TURN_TIE * cabs(a) * sqrt(size / (double)q->m);
        for (int r = 0; r < ROTATIONS; r++) { /* one fit per turn that ties gives both measures */
            if (!(costs[r] <= tie2)) continue;
            plane_fit(q, 2 * CM_PI * r / ROTATIONS, &a, &centre);
            off[r] = holes_off_under(q, a, centre), turn[r] = turn_from_prior(q, carg(a));
            least_off = fmin(least_off, off[r]), most_off = fmax(most_off, off[r]);
        }
        double within = least_off + (double)q->h * reach * reach;
        for (int r = 0; r < ROTATIONS; r++)
            if (costs[r] <= tie2 && off[r] <= within && turn[r] < least_turn) least_turn = turn[r], least_at = r;
        double at = 2 * CM_PI * least_at / ROTATIONS;
        if (costs[(least_at + 1) % ROTATIONS] <= tie2 && costs[(least_at + ROTATIONS - 1) % ROTATIONS] <= tie2) {
            int by_holes = most_off > within; /* else the holes do not tell the turns apart */
            double rho = cm_circle_golden_least(by_holes ? holes_off : plane_turn, q, at - step, at + step, GOLDEN_STEPS,
                                                &least);
            return least < (by_holes ? off[least_at] : least_turn) ? rho : at;
        }
    }
    double at = 2 * CM_PI * least_at / ROTATIONS;
    double rho = cm_circle_golden_least(cost, q, at - step, at + step, GOLDEN_STEPS, &least);
    return least < costs[least_at] ? rho : at;
}

cm_status cm_correspond_conformal(const double *const *polygons, const size_t *counts, size_t k,
                                  const int *orientation, const double *const *hole_centres, size_t holes,
                                  double power, double *const *params, double *const *fine, int *found,
                                  cm_error *err)
{
    *found = 0;
    disk *disks = calloc(k, sizeof *disks);
    double complex *w0 = malloc(SEARCH_SAMPLES * sizeof *w0);
    cm_status s = disks && w0 ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    int usable = 1;
    for (size_t g = 0; s == CM_OK && usable && g < k; g++)
        s = disk_build(polygons[g], counts[g], orientation[g] < 0, &disks[g], &usable, err);
    if (s == CM_OK && usable) {
        double *arc = cm_arc_lengths(polygons[0], counts[0], orientation[0] < 0, 0);
        if (!arc) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        for (size_t c = 0; arc && c < counts[0]; c++) params[0][c] = arc[c] / arc[counts[0]];
        free(arc);
    }
    double *s0 = malloc(SEARCH_SAMPLES * sizeof *s0);
    double complex *z0 = malloc(SEARCH_SAMPLES * sizeof *z0), mean0 = 0;
    double complex *centres = holes ? malloc(2 * holes * sizeof *centres) : NULL;
    if (s == CM_OK && (!s0 || !z0 || (holes && !centres))) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
    for (size_t i = 0; s == CM_OK && usable && i < SEARCH_SAMPLES; i++) {
        double t = 2 * CM_PI * (double)i / SEARCH_SAMPLES;
        w0[i] = cexp(I * t);
        s0[i] = cm_circle_lookup(disks[0].theta, disks[0].s, disks[0].nb, t);
        mean0 += z0[i] = cm_circle_point_at(&disks[0], s0[i]);
    }
    mean0 /= SEARCH_SAMPLES;
    for (size_t i = 0; s == CM_OK && usable && i < SEARCH_SAMPLES; i++) z0[i] -= mean0;
    for (size_t j = 0; s == CM_OK && j < holes; j++)
        centres[j] = hole_centres[0][2 * j] + I * hole_centres[0][2 * j + 1] - mean0;
    double prior = 0;
    for (size_t g = 1; s == CM_OK && usable && g < k; g++) {
        for (size_t j = 0; j < holes; j++)
            centres[holes + j] = hole_centres[g][2 * j] + I * hole_centres[g][2 * j + 1];
        search q = {w0, s0, z0, SEARCH_SAMPLES, &disks[g], centres, holes ? centres + holes : NULL, holes, prior};
        double rho = best_turn(&q);
        prior = plane_angle(&q, rho);
        s = cm_circle_place(&disks[0], &disks[g], rho, counts[g], power, params[g], fine ? fine[g] : NULL, err);
    }
    free(s0), free(z0), free(centres);
    if (s == CM_OK) *found = usable;
    for (size_t g = 0; disks && g < k; g++) cm_circle_free(&disks[g]);
    free(disks), free(w0);
    return s;
}

/* ---- memo -------------------------------------------------------------------- */

/* One call's polygons and result. */
typedef struct memo_entry {
    int held, found;
    double power;
    size_t holes;     /* hole centres per polygon */
    double *centres;  /* 2 holes k: the hole centres, polygon after polygon */
    size_t k, total;  /* polygons; their vertices in all */
    size_t *counts;   /* k */
    int *orientation; /* k */
    double *xy;       /* 2 total: the polygons one after another */
    double *params;   /* total */
    double *fine;     /* (total - counts[0]) CM_PARAM_FINE: polygons 1 .. k - 1 */
} memo_entry;

/* Calls remembered: auto's rescues ask for three powers and come back to
 * the first (the similarity choice's run reads it again). */
#define CM_CONFORMAL_MEMO_CALLS 4

struct cm_conformal_memo {
    memo_entry at[CM_CONFORMAL_MEMO_CALLS];
    size_t next; /* the entry the next call computed replaces: the oldest */
};

cm_conformal_memo *cm_conformal_memo_new(void) { return calloc(1, sizeof(cm_conformal_memo)); }

static void memo_clear(memo_entry *memo)
{
    free(memo->counts), free(memo->orientation), free(memo->xy), free(memo->params), free(memo->fine);
    free(memo->centres);
    memset(memo, 0, sizeof *memo);
}

void cm_conformal_memo_free(cm_conformal_memo *memo)
{
    for (size_t i = 0; memo && i < CM_CONFORMAL_MEMO_CALLS; i++) memo_clear(&memo->at[i]);
    free(memo);
}

static int memo_matches(const memo_entry *memo, const double *const *polygons, const size_t *counts,
                        size_t k, const int *orientation, const double *const *hole_centres, size_t holes,
                        double power)
{
    if (!memo->held || memo->k != k || memo->power != power || memo->holes != holes ||
        memcmp(memo->counts, counts, k * sizeof *counts) || memcmp(memo->orientation, orientation, k * sizeof *orientation))
        return 0;
    for (size_t g = 0, at = 0; g < k; at += counts[g], g++)
        if (memcmp(memo->xy + 2 * at, polygons[g], 2 * counts[g] * sizeof *memo->xy) ||
            (holes && memcmp(memo->centres + 2 * holes * g, hole_centres[g], 2 * holes * sizeof *memo->centres)))
            return 0;
    return 1;
}

/* Copies the parameters between the memo and the caller: to the caller
 * when recall, else into the memo. */
static void memo_copy(memo_entry *memo, double *const *params, double *const *fine, int recall)
{
    for (size_t g = 0, at = 0; g < memo->k; at += memo->counts[g], g++) {
        size_t c = memo->counts[g], fine_at = (at - memo->counts[0]) * CM_PARAM_FINE;
        double *kept = memo->params + at, *kept_fine = g ? memo->fine + fine_at : NULL;
        memcpy(recall ? params[g] : kept, recall ? kept : params[g], c * sizeof *kept);
        if (g) memcpy(recall ? fine[g] : kept_fine, recall ? kept_fine : fine[g], c * CM_PARAM_FINE * sizeof *kept);
    }
}

/* Remembers a call's polygons and result (silently not, out of memory). */
static void memo_store(memo_entry *memo, const double *const *polygons, const size_t *counts, size_t k,
                       const int *orientation, const double *const *hole_centres, size_t holes, double power,
                       double *const *params, double *const *fine, int found)
{
    memo_clear(memo);
    size_t total = 0;
    for (size_t g = 0; g < k; g++) total += counts[g];
    memo->counts = malloc(k * sizeof *memo->counts);
    memo->orientation = malloc(k * sizeof *memo->orientation);
    memo->xy = malloc(2 * total * sizeof *memo->xy);
    memo->params = malloc(total * sizeof *memo->params);
    memo->fine = malloc(((total - counts[0]) * CM_PARAM_FINE + 1) * sizeof *memo->fine);
    memo->centres = malloc((2 * holes * k + 1) * sizeof *memo->centres);
    if (!memo->counts || !memo->orientation || !memo->xy || !memo->params || !memo->fine || !memo->centres) {
        memo_clear(memo);
        return;
    }
    memcpy(memo->counts, counts, k * sizeof *counts);
    memcpy(memo->orientation, orientation, k * sizeof *orientation);
    memo->k = k, memo->total = total, memo->found = found, memo->power = power, memo->holes = holes;
    for (size_t g = 0, at = 0; g < k; at += counts[g], g++) {
        memcpy(memo->xy + 2 * at, polygons[g], 2 * counts[g] * sizeof *memo->xy);
        if (holes) memcpy(memo->centres + 2 * holes * g, hole_centres[g], 2 * holes * sizeof *memo->centres);
    }
    if (found) memo_copy(memo, params, fine, 0);
    memo->held = 1;
}

cm_status cm_correspond_conformal_memo(cm_conformal_memo *memo, const double *const *polygons, const size_t *counts,
                                       size_t k, const int *orientation, const double *const *hole_centres,
                                       size_t holes, double power, double *const *params, double *const *fine,
                                       int *found, cm_error *err)
{
    for (size_t i = 0; memo && fine && k && i < CM_CONFORMAL_MEMO_CALLS; i++) {
        memo_entry *e = &memo->at[i];
        if (!memo_matches(e, polygons, counts, k, orientation, hole_centres, holes, power)) continue;
        *found = e->found;
        if (*found) memo_copy(e, params, fine, 1);
        return CM_OK;
    }
    cm_status s = cm_correspond_conformal(polygons, counts, k, orientation, hole_centres, holes, power, params, fine,
                                          found, err);
    if (memo && fine && k && s == CM_OK) {
        memo_store(&memo->at[memo->next], polygons, counts, k, orientation, hole_centres, holes, power, params, fine,
                   *found);
        memo->next = (memo->next + 1) % CM_CONFORMAL_MEMO_CALLS;
    }
    return s;
}
