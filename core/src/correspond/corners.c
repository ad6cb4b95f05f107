#include <math.h>
#include <stdlib.h>

#include "correspond/arclength.h"
#include "correspond/corners.h"
#include "geom/angle.h"

typedef struct corner {
    size_t position; /* counter-clockwise, from the start */
    double turn;     /* degrees, absolute */
    double at;       /* normalised arc length from the start */
} corner;

static int by_turn(const void *pa, const void *pb)
{
    const corner *a = pa, *b = pb;
    if (a->turn != b->turn) return a->turn > b->turn ? -1 : 1;
    return (a->position > b->position) - (a->position < b->position);
}

static int by_position(const void *pa, const void *pb)
{
    const corner *a = pa, *b = pb;
    return (a->position > b->position) - (a->position < b->position);
}

/* The corners of one polygon, counter-clockwise from counter-clockwise
 * position start. Returns the count; NULL *out when out of memory. */
static size_t find_corners(const double *xy, size_t n, int reversed, size_t start, double degrees, corner **out)
{
    *out = malloc(n * sizeof **out);
    double *arc = cm_arc_lengths(xy, n, reversed, start);
    if (!*out || !arc) {
        free(*out), free(arc), *out = NULL;
        return 0;
    }
    size_t m = 0;
    for (size_t i = 0; i < n; i++) {
        const double *p = xy + 2 * cm_ccw_input((start + i + n - 1) % n, n, reversed);
        const double *v = xy + 2 * cm_ccw_input((start + i) % n, n, reversed);
        const double *q = xy + 2 * cm_ccw_input((start + i + 1) % n, n, reversed);
        /* The corner angle c (or 360 - c) deviates from 180 by the turn. */
        double turn = 180.0 - cm_angle_at(v, p, q) * (180.0 / CM_PI);
        if (turn > degrees) (*out)[m++] = (corner){i, turn, arc[i] / arc[n]};
    }
    free(arc);
    return m;
}

/* Distance of two normalised arc lengths around the loop. */
static double loop_distance(double a, double b)
{
    double d = fabs(a - b);
    return d > 0.5 ? 1.0 - d : d;
}

cm_status cm_correspond_corner_pins(const double *const *polygons, const size_t *counts, size_t k,
                                    const int *orientation, const size_t *starts, double degrees,
                                    size_t **pins, size_t *num_pins, cm_error *err)
{
    *pins = NULL, *num_pins = 0;
    corner **corners = calloc(k, sizeof *corners);
    size_t *found = calloc(k, sizeof *found), m = SIZE_MAX;
    cm_status s = corners && found ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    for (size_t g = 0; s == CM_OK && g < k; g++) {
        int reversed = orientation[g] < 0;
        size_t start = reversed ? (counts[g] - starts[g]) % counts[g] : starts[g];
        found[g] = find_corners(polygons[g], counts[g], reversed, start, degrees, &corners[g]);
        if (!corners[g]) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        else if (found[g] == 0) {
            cm_fail_at(err, (long)g, -1, -1);
            s = cm_fail(err, CM_ERR_ARGUMENT,
                        "polygon %zu has no corner to pin: no vertex turns by more than %g degrees", g, degrees);
        } else if (found[g] < m) m = found[g];
    }
    if (s == CM_OK) {
        *pins = malloc(m * k * sizeof **pins);
        if (!*pins) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
    }
    for (size_t g = 0; s == CM_OK && g < k; g++) {
        /* The m most prominent, back in counter-clockwise order. */
        qsort(corners[g], found[g], sizeof *corners[g], by_turn);
        qsort(corners[g], m, sizeof *corners[g], by_position);
        size_t best = 0;
        double best_cost = HUGE_VAL;
        for (size_t shift = 0; g > 0 && shift < m; shift++) {
            double cost = 0;
            for (size_t j = 0; j < m; j++) {
                double d = loop_distance(corners[0][j].at, corners[g][(j + shift) % m].at);
                cost += d * d;
            }
            if (cost < best_cost) best_cost = cost, best = shift;
        }
        int reversed = orientation[g] < 0;
        size_t n = counts[g], start = reversed ? (n - starts[g]) % n : starts[g];
        for (size_t j = 0; j < m; j++)
            (*pins)[j * k + g] = cm_ccw_input((start + corners[g][(j + best) % m].position) % n, n, reversed);
    }
    if (s == CM_OK) *num_pins = m;
    else free(*pins), *pins = NULL;
    if (corners)
        for (size_t g = 0; g < k; g++) free(corners[g]);
    free(corners), free(found);
    return s;
}
