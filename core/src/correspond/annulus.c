/* The annulus correspondence (annulus.h). */
#include "correspond/annulus.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/keymap.h"
#include "base/mesh.h"
#include "correspond/arclength.h"
#include "correspond/circle.h"
#include "correspond/fe.h"
#include "geom/angle.h"

/* The mesh of each polygon is split into four until it has this many
 * triangles; the turn search as conformal.c's. */
#define MIN_TRIANGLES 8000
#define SEARCH_SAMPLES 512
#define ROTATIONS 256
#define GOLDEN_STEPS 48

/* One polygon on its round annulus: each loop on its circle (counter-
 * clockwise from the loop's vertex 0), the angle of each loop's vertex 0
 * on the annulus (the outer loop's 0), each loop's perimeter. */
typedef struct ring {
    cm_circle loop[2];
    double offset[2], perimeter[2];
} ring;

static void ring_free(ring *g)
{
    cm_circle_free(&g->loop[0]), cm_circle_free(&g->loop[1]);
}

/* J grad u . e on triangle t, J the quarter turn: the flux of u through
 * the segment e, and the change of u's conjugate along it. */
static double conjugate_change(const cm_fe_mesh *m, long t, const double e[2])
{
    double d[3][2], a2 = cm_fe_tri(m, t, d), gx = 0, gy = 0;
    for (int i = 0; i < 3; i++) gx += m->u[m->tri[3 * t + i]] * d[i][0], gy += m->u[m->tri[3 * t + i]] * d[i][1];
    return -(gx * e[0] + gy * e[1]) / a2;
}

static void midpoint(const cm_fe_mesh *m, int32_t a, int32_t b, double out[2])
{
    out[0] = 0.5 * (m->xy[2 * a] + m->xy[2 * b]), out[1] = 0.5 * (m->xy[2 * a + 1] + m->xy[2 * b + 1]);
}

/* Each triangle side's neighbour across it (3 nt: side i from corner i to
 * corner i + 1; -1 on the boundary). 0 or CM_NO_MEMORY. */
static int neighbours(const cm_fe_mesh *m, long *across)
{
    cm_keymap side = {0};
    if (cm_keymap_reserve(&side, 3 * (size_t)m->nt)) return CM_NO_MEMORY;
    for (long x = 0; x < 3 * m->nt; x++) {
        across[x] = -1;
        int added;
        int64_t *first = cm_keymap_put(&side, cm_pair_key(m->tri[x], m->tri[x % 3 == 2 ? x - 2 : x + 1]), &added);
        if (!first) {
            cm_keymap_free(&side);
            return CM_NO_MEMORY;
        }
        if (added) *first = x;
        else across[x] = (long)*first, across[*first] = x;
    }
    cm_keymap_free(&side);
    return 0;
}

/* The change of u's conjugate from the middle of hole edge `from` (a side
 * of triangle start) to the middle of the outer loop's first edge met, a
 * side of the triangle reached (breadth-first through the triangles);
 * *outer_side: that side (3 t + i). -1 in *outer_side where none is
 * reached. 0 or CM_NO_MEMORY. */
static int across_ring(const cm_fe_mesh *m, const long *across, const unsigned char *on_outer, long from,
                       double *change, long *outer_side)
{
    long *came = malloc((size_t)m->nt * sizeof *came), *queue = malloc((size_t)m->nt * sizeof *queue);
    if (!came || !queue) {
        free(came), free(queue);
        return CM_NO_MEMORY;
    }
    for (long t = 0; t < m->nt; t++) came[t] = -2; /* unseen; else the side it was entered by */
    long head = 0, tail = 0, found = -1;
    came[from / 3] = from, queue[tail++] = from / 3;
    while (head < tail && found < 0) {
        long t = queue[head++];
        for (int i = 0; i < 3 && found < 0; i++) {
            long x = 3 * t + i;
            long next = across[x] >= 0 ? across[x] / 3 : -1;
            if (on_outer[x]) found = x;
            else if (next >= 0 && came[next] == -2) came[next] = across[x], queue[tail++] = next;
        }
    }
    *outer_side = found, *change = 0;
    /* back from the outer side: in each triangle from the side entered by
     * to the side left by, the conjugate's gradient J grad u */
    for (long leave = found; leave >= 0;) {
        long t = leave / 3, enter = came[t];
        double p[2], q[2], e[2];
        midpoint(m, m->tri[enter], m->tri[enter % 3 == 2 ? enter - 2 : enter + 1], p);
        midpoint(m, m->tri[leave], m->tri[leave % 3 == 2 ? leave - 2 : leave + 1], q);
        e[0] = q[0] - p[0], e[1] = q[1] - p[1];
        *change += conjugate_change(m, t, e);
        leave = enter == from ? -1 : across[enter];
    }
    free(came), free(queue);
    return 0;
}

/* Loop l's circle from the conjugate's values psi at its boundary nodes
 * (node j of the loop counter-clockwise from its vertex 0 is bnode[at(j)];
 * psi non-decreasing, psi[nb] = period). */
static int circle_of(const cm_fe_mesh *m, size_t nb, const long *at, const double *psi, double period, cm_circle *d,
                     double *perimeter)
{
    d->nb = nb;
    d->s = malloc((nb + 1) * sizeof *d->s), d->theta = malloc((nb + 1) * sizeof *d->theta);
    d->z = malloc((nb + 1) * sizeof *d->z);
    if (!d->s || !d->theta || !d->z) return CM_NO_MEMORY;
    d->s[0] = 0, d->theta[0] = 0;
    for (size_t j = 0; j < nb; j++) {
        const double *p = m->xy + 2 * m->bnode[at[j]], *q = m->xy + 2 * m->bnode[at[(j + 1) % nb]];
        d->s[j + 1] = d->s[j] + hypot(q[0] - p[0], q[1] - p[1]);
        d->z[j] = p[0] + I * p[1];
        if (j) d->theta[j] = fmin(fmax(2 * CM_PI * psi[j] / period, d->theta[j - 1]), 2 * CM_PI);
    }
    *perimeter = d->s[nb];
    for (size_t j = 0; j <= nb; j++) d->s[j] /= *perimeter;
    d->s[nb] = 1.0, d->theta[nb] = 2 * CM_PI, d->z[nb] = d->z[0];
    return 0;
}

/* Polygon `p` (loops: the outer one, the hole; orientation of each) on its
 * round annulus. */
static cm_status ring_build(const cm_loops *p, const int *orientation, ring *out, int *usable, cm_error *err)
{
    memset(out, 0, sizeof *out);
    size_t no = p->loop_sizes[0], nh = p->loop_sizes[1], start[3] = {0, no, no + nh};
    cm_fe_mesh m;
    memset(&m, 0, sizeof m);
    double *xy = malloc(2 * (no + nh) * sizeof *xy);
    cm_status s = xy ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    /* the outer loop counter-clockwise, the hole clockwise, both from
     * their vertex 0 */
    for (size_t c = 0; s == CM_OK && c < no; c++)
        memcpy(xy + 2 * c, p->xy + 2 * cm_ccw_input(c, no, orientation[0] < 0), 2 * sizeof *xy);
    for (size_t i = 0; s == CM_OK && i < nh; i++)
        memcpy(xy + 2 * (no + i), p->xy + 2 * (no + cm_ccw_input(cm_loop_reversed(nh, i), nh, orientation[1] < 0)),
               2 * sizeof *xy);
    if (s == CM_OK) s = cm_fe_build_loops(&m, xy, start, 2, MIN_TRIANGLES, usable, err);
    long *side = NULL, *across = NULL, *at = NULL;
    double *flux = NULL, *psi = NULL;
    unsigned char *on_outer = NULL;
    long nb = s == CM_OK && *usable ? m.nb : 0;
    if (nb) {
        side = malloc((size_t)nb * sizeof *side), at = malloc((size_t)nb * sizeof *at);
        across = malloc(3 * (size_t)m.nt * sizeof *across), on_outer = calloc(3 * (size_t)m.nt, 1);
        flux = malloc((size_t)nb * sizeof *flux), psi = malloc(((size_t)nb + 1) * sizeof *psi);
        if (!side || !at || !across || !on_outer || !flux || !psi || neighbours(&m, across))
            s = cm_fail_status(err, CM_ERR_NO_MEMORY);
    }
    if (s == CM_OK && nb) { /* u: 1 on the outer loop, 0 on the hole */
        for (long v = 0; v < m.nv; v++) m.fixed[v] = 0, m.u[v] = 0;
        for (long j = 0; j < nb; j++) m.fixed[m.bnode[j]] = 1, m.u[m.bnode[j]] = j < m.loop_first[1];
        s = cm_fe_solve(&m, -1, 1, err);
    }
    if (s == CM_OK && nb) { /* the triangle side on each boundary edge */
        long *place = malloc((size_t)m.nv * sizeof *place);
        if (!place) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        for (long v = 0; place && v < m.nv; v++) place[v] = -1;
        for (long j = 0; place && j < nb; j++) place[m.bnode[j]] = j, side[j] = -1;
        for (long x = 0; place && x < 3 * m.nt; x++) {
            long a = place[m.tri[x]], b = place[m.tri[x % 3 == 2 ? x - 2 : x + 1]];
            if (a >= 0 && b >= 0 && cm_fe_next_boundary(&m, a) == b) side[a] = x, on_outer[x] = a < m.loop_first[1];
        }
        free(place);
        for (long j = 0; s == CM_OK && j < nb; j++)
            if (side[j] < 0) *usable = 0;
    }
    if (s == CM_OK && nb && *usable) {
        /* The conjugate's change from the middle of the boundary edge into
         * node j to the middle of the edge out of it, around the node's
         * triangles, is the flux (K u)_j: flux[j], signed so that it grows
         * counter-clockwise along the outer loop (and so clockwise along
         * the hole, as its nodes run). */
        double *r = malloc((size_t)m.nv * sizeof *r), outer = 0, hole = 0, change = 0;
        long first_hole = m.loop_first[1], nbo = first_hole, nbh = nb - first_hole, outer_side = -1;
        if (!r) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        if (r) cm_fe_residual(&m, r);
        for (long j = 0; r && j < nb; j++) flux[j] = r[m.bnode[j]];
        free(r);
        for (long j = 0; j < nbo; j++) outer += flux[j];
        for (long j = first_hole; j < nb; j++) hole -= flux[j];
        if (s == CM_OK && across_ring(&m, across, on_outer, side[first_hole], &change, &outer_side))
            s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        if (s == CM_OK && !(outer > 0 && hole > 0 && outer_side >= 0)) *usable = 0;
        if (s == CM_OK && *usable) {
            /* the outer loop counter-clockwise from its vertex 0: psi at
             * node j is its edge-in's middle plus half its flux */
            long jo = -1;
            psi[0] = 0;
            for (long j = 0; j < nbo; j++) {
                at[j] = j, psi[j + 1] = psi[j] + 0.5 * (flux[j] + flux[(j + 1) % nbo]);
                if (side[j] == outer_side) jo = j;
            }
            /* psi at the hole's vertex 0 (the outer loop's 0): the middle
             * of outer edge jo, less the way across the ring from the
             * middle of the hole's first edge, less half the vertex's flux
             * (from the vertex to that middle) */
            double c = psi[jo] + 0.5 * flux[jo] - change - 0.5 * flux[first_hole];
            out->offset[0] = 0, out->offset[1] = 2 * CM_PI * (c / outer - floor(c / outer));
            if (circle_of(&m, (size_t)nbo, at, psi, outer, &out->loop[0], &out->perimeter[0]))
                s = cm_fail_status(err, CM_ERR_NO_MEMORY);
            /* the hole counter-clockwise from its vertex 0: its nodes
             * backwards, psi rising by the fluxes run backwards */
            psi[0] = 0;
            for (long j = 0; j < nbh; j++) {
                long back = first_hole + (nbh - j) % nbh, before = first_hole + (nbh - j - 1);
                at[j] = back, psi[j + 1] = psi[j] - 0.5 * (flux[back] + flux[before]);
            }
            if (s == CM_OK && circle_of(&m, (size_t)nbh, at, psi, hole, &out->loop[1], &out->perimeter[1]))
                s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        }
    }
    free(xy), free(side), free(across), free(at), free(flux), free(psi), free(on_outer);
    cm_fe_free(&m);
    if (s != CM_OK || !*usable) ring_free(out);
    return s;
}

/* The turn between two annuli: polygon 0's samples on each loop (m points
 * w, arc lengths s0[l], the outer loop's points z0, centred), polygon g's
 * ring, the loops' weights, and the turn of the plane chosen for polygon
 * g - 1 (0 for g = 1). */
typedef struct turn_search {
    const double complex *w;
    const double *s0[2];
    const double complex *z0;
    const ring *r0, *rg;
    double weight[2];
    double prior;
} turn_search;

/* The turn alpha takes polygon g's annulus onto polygon 0's: loop l of g
 * turned by alpha plus the offsets of the loops' starts. */
static double loop_turn(const turn_search *q, int l, double alpha)
{
    return alpha + q->rg->offset[l] - q->r0->offset[l];
}

static double turn_cost(const void *ctx, double alpha)
{
    const turn_search *q = ctx;
    double sum = 0;
    for (int l = 0; l < 2; l++)
        sum += q->weight[l] * cm_circle_cost(q->w, q->s0[l], SEARCH_SAMPLES, &q->rg->loop[l], loop_turn(q, l, alpha));
    return sum;
}

/* The angle by which the pairing of turn alpha turns the plane (the
 * outer loops' closest similarity). */
static double plane_angle(const turn_search *q, double alpha)
{
    double complex a, centre;
    cm_circle_plane_fit(q->w, q->z0, SEARCH_SAMPLES, &q->rg->loop[0], loop_turn(q, 0, alpha), &a, &centre);
    return carg(a);
}

/* How far that is from polygon g - 1's, in [0, pi]. */
static double plane_turn(const void *ctx, double alpha)
{
    const turn_search *q = ctx;
    return fabs(remainder(plane_angle(q, alpha) - q->prior, 2 * CM_PI));
}

/* The least of turn_cost: the best of ROTATIONS evenly spaced, refined by
 * golden section around it. Where turns apart fit alike
 * (CM_CIRCLE_TURN_TIE: a shape a turn takes nearly onto itself), the least
 * turn of the plane chooses among them, as the disk map's search does; and
 * where every turn fits alike (a round ring) it refines the turn too: two
 * sections of a pipe pair without a twist. Elsewhere the cost refines it:
 * two rectangular tubes of other proportions tie at many turns by a share
 * of a per cent of a cost that is large anyway, and the least turn of the
 * plane, refined by the cost, made better meshes there than refined by the
 * plane's turn (bench/HOLES.md, "The annulus pairing first"). */
static double best_turn(const turn_search *q)
{
    double costs[ROTATIONS], best_cost = HUGE_VAL, step = 2 * CM_PI / ROTATIONS, least;
    int best = 0;
    for (int r = 0; r < ROTATIONS; r++) {
        costs[r] = turn_cost(q, step * r);
        if (costs[r] < best_cost) best_cost = costs[r], best = r;
    }
    double tie = sqrt(fmax(best_cost, 0)) + CM_CIRCLE_TURN_TIE, tie2 = tie * tie, least_turn = HUGE_VAL;
    int apart = 0, round = 1, least_at = best;
    for (int r = 0; r < ROTATIONS; r++) {
        int d = abs(r - best);
        apart |= costs[r] <= tie2 && d > 2 && d < ROTATIONS - 2;
        round &= costs[r] <= tie2;
    }
    for (int r = 0; apart && r < ROTATIONS; r++) {
        double turn = costs[r] <= tie2 ? plane_turn(q, step * r) : HUGE_VAL;
        if (turn < least_turn) least_turn = turn, least_at = r;
    }
    double at = step * least_at;
    if (round) {
        double alpha = cm_circle_golden_least(plane_turn, q, at - step, at + step, GOLDEN_STEPS, &least);
        return least < least_turn ? alpha : at;
    }
    double alpha = cm_circle_golden_least(turn_cost, q, at - step, at + step, GOLDEN_STEPS, &least);
    return least < costs[least_at] ? alpha : at;
}

cm_status cm_correspond_annulus(const cm_loops *polygons, size_t k, const int *orientation, double power,
                                double *const *params, double *const *fine, int *found, cm_error *err)
{
    *found = 0;
    ring *rings = calloc(k, sizeof *rings);
    double complex *w = malloc(SEARCH_SAMPLES * sizeof *w);
    double *s0 = malloc(2 * SEARCH_SAMPLES * sizeof *s0);
    double complex *z0 = malloc(SEARCH_SAMPLES * sizeof *z0), mean0 = 0;
    cm_status s = rings && w && s0 && z0 ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    int usable = 1;
    for (size_t g = 0; s == CM_OK && usable && g < k; g++)
        s = ring_build(&polygons[g], orientation + 2 * g, &rings[g], &usable, err);
    for (int l = 0; s == CM_OK && usable && l < 2; l++) { /* polygon 0's own arc length */
        size_t n = polygons[0].loop_sizes[l], first = l ? polygons[0].loop_sizes[0] : 0;
        double *arc = cm_arc_lengths(polygons[0].xy + 2 * first, n, orientation[l] < 0, 0);
        if (!arc) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        for (size_t c = 0; arc && c < n; c++) params[l][c] = arc[c] / arc[n];
        free(arc);
    }
    for (size_t i = 0; s == CM_OK && usable && i < SEARCH_SAMPLES; i++) {
        double t = 2 * CM_PI * (double)i / SEARCH_SAMPLES;
        w[i] = cexp(I * t);
        for (int l = 0; l < 2; l++) {
            const cm_circle *d = &rings[0].loop[l];
            s0[l * SEARCH_SAMPLES + i] = cm_circle_lookup(d->theta, d->s, d->nb, t);
        }
        mean0 += z0[i] = cm_circle_point_at(&rings[0].loop[0], s0[i]);
    }
    mean0 /= SEARCH_SAMPLES;
    for (size_t i = 0; s == CM_OK && usable && i < SEARCH_SAMPLES; i++) z0[i] -= mean0;
    double prior = 0;
    double total = usable && rings ? rings[0].perimeter[0] + rings[0].perimeter[1] : 1;
    for (size_t g = 1; s == CM_OK && usable && g < k; g++) {
        turn_search q = {w, {s0, s0 + SEARCH_SAMPLES}, z0, &rings[0], &rings[g],
                         {rings[0].perimeter[0] / total, rings[0].perimeter[1] / total}, prior};
        double alpha = best_turn(&q);
        prior = plane_angle(&q, alpha);
        for (int l = 0; s == CM_OK && l < 2; l++)
            s = cm_circle_place(&rings[0].loop[l], &rings[g].loop[l], loop_turn(&q, l, alpha),
                                polygons[g].loop_sizes[l], power, params[2 * g + l], fine ? fine[2 * g + l] : NULL,
                                err);
    }
    if (s == CM_OK) *found = usable;
    for (size_t g = 0; rings && g < k; g++) ring_free(&rings[g]);
    free(rings), free(w), free(s0), free(z0);
    return s;
}
