/* Normalised arc length between pins. Every polygon is walked counter-
 * clockwise from its first pin; the pins split it into P segments, and a
 * vertex in segment s gets the parameter s + (arc length from the segment's
 * start) / (the segment's length), so pins sit at whole numbers in every
 * polygon. The union of all polygons' parameters is the common boundary:
 * at a parameter of its own a polygon contributes its vertex, elsewhere
 * the point at that parameter on its edge. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "correspond/arclength.h"
#include "base/order.h"

void cm_boundary_map_clear(cm_boundary_map *map)
{
    for (size_t g = 0; g < map->k; g++) {
        if (map->xy) free(map->xy[g]);
        if (map->edge) free(map->edge[g]);
        if (map->t) free(map->t[g]);
    }
    free(map->xy), free(map->edge), free(map->t);
    memset(map, 0, sizeof *map);
}

double cm_boundary_map_least_piece(const cm_boundary_map *map)
{
    double least = HUGE_VAL;
    for (size_t g = 0; g < map->k; g++) {
        const double *xy = map->xy[g];
        double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL}, piece = HUGE_VAL;
        for (size_t i = 0; i < map->n; i++) {
            const double *p = xy + 2 * i, *q = xy + 2 * ((i + 1) % map->n);
            for (int c = 0; c < 2; c++) lo[c] = fmin(lo[c], p[c]), hi[c] = fmax(hi[c], p[c]);
            piece = fmin(piece, hypot(q[0] - p[0], q[1] - p[1]));
        }
        double size = hypot(hi[0] - lo[0], hi[1] - lo[1]);
        if (size > 0) least = fmin(least, piece / size);
    }
    return least;
}

double *cm_arc_lengths(const double *xy, size_t n, int reversed, size_t start)
{
    double *arc = malloc((n + 1) * sizeof *arc);
    if (!arc) return NULL;
    arc[0] = 0;
    for (size_t i = 0; i < n; i++) {
        const double *a = xy + 2 * cm_ccw_input((start + i) % n, n, reversed);
        const double *b = xy + 2 * cm_ccw_input((start + i + 1) % n, n, reversed);
        arc[i + 1] = arc[i] + hypot(b[0] - a[0], b[1] - a[1]);
    }
    return arc;
}

/* One polygon, counter-clockwise from its first pin. */
typedef struct walk {
    const double *xy;  /* input coordinates */
    size_t n;
    int reversed;      /* clockwise input */
    size_t start;      /* counter-clockwise position of the first pin */
    double *param;     /* n + 1: the i-th vertex from start; param[n] = P */
    double *sub;       /* NULL (linear along the edges), or n * CM_PARAM_FINE:
                          along the edge from the i-th vertex, increasing
                          from param[i], below param[i + 1] */
} walk;

/* Counter-clockwise position c <-> input index. */
static size_t walk_input(const walk *w, size_t c) { return cm_ccw_input(c, w->n, w->reversed); }
static size_t ccw_position(const walk *w, size_t v) { return w->reversed ? (w->n - v) % w->n : v; }
/* The i-th vertex from the start, as an input index. */
static size_t walk_vertex(const walk *w, size_t i) { return walk_input(w, (w->start + i) % w->n); }
static const double *walk_point(const walk *w, size_t i) { return w->xy + 2 * walk_vertex(w, i); }

/* Pins as counter-clockwise offsets from the first pin of each polygon,
 * sorted along polygon 0 and checked to be in that order everywhere. */
static cm_status order_pins(const size_t *pins, size_t num_pins, size_t k, walk *walks,
                            size_t *offset /* num_pins * k */, cm_error *err)
{
    for (size_t j = 0; j < num_pins; j++)
        for (size_t g = 0; g < k; g++)
            if (pins[j * k + g] >= walks[g].n) {
                cm_fail_at(err, (long)g, (long)pins[j * k + g], -1);
                return cm_fail(err, CM_ERR_ARGUMENT, "pin %zu: vertex %zu of polygon %zu is out of range (%zu vertices)",
                               j, pins[j * k + g], g, walks[g].n);
            }
    /* Order of the pins along polygon 0, by insertion (pins are few). */
    size_t *order = malloc(num_pins * sizeof *order);
    if (!order) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    for (size_t j = 0; j < num_pins; j++) {
        size_t c = ccw_position(&walks[0], pins[j * k]), at = j;
        while (at > 0 && ccw_position(&walks[0], pins[order[at - 1] * k]) > c) order[at] = order[at - 1], at--;
        order[at] = j;
    }
    for (size_t g = 0; g < k; g++) {
        walk *w = &walks[g];
        w->start = ccw_position(w, pins[order[0] * k + g]);
        for (size_t s = 0; s < num_pins; s++)
            offset[s * k + g] = (ccw_position(w, pins[order[s] * k + g]) + w->n - w->start) % w->n;
        for (size_t s = 1; s < num_pins; s++) {
            if (offset[s * k + g] > offset[(s - 1) * k + g]) continue;
            size_t a = order[s - 1], b = order[s];
            free(order);
            cm_fail_at(err, (long)g, (long)pins[b * k + g], (long)pins[a * k + g]);
            if (offset[s * k + g] == offset[(s - 1) * k + g])
                return cm_fail(err, CM_ERR_ARGUMENT, "pins %zu and %zu both pin vertex %zu of polygon %zu", a, b,
                               pins[a * k + g], g);
            return cm_fail(err, CM_ERR_ARGUMENT,
                           "pins %zu and %zu cross: along polygon %zu they come in the other order than along polygon 0",
                           a, b, g);
        }
    }
    free(order);
    return CM_OK;
}

/* Parameters of the vertices of w: whole numbers at the pins, strictly
 * increasing (nudged up by an ulp where lengths round together). */
static cm_status parametrise(walk *w, const size_t *offset, size_t stride, size_t num_pins, size_t g,
                             cm_error *err)
{
    size_t n = w->n;
    double *arc = cm_arc_lengths(w->xy, n, w->reversed, w->start);
    if (!arc) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    cm_status s = CM_OK;
    for (size_t seg = 0; seg < num_pins && s == CM_OK; seg++) {
        size_t from = offset[seg * stride], to = seg + 1 < num_pins ? offset[(seg + 1) * stride] : n;
        double length = arc[to] - arc[from];
        w->param[from] = (double)seg;
        for (size_t i = from + 1; i < to; i++) {
            double p = (double)seg + (arc[i] - arc[from]) / length;
            if (p <= w->param[i - 1]) p = nextafter(w->param[i - 1], INFINITY);
            if (!(p < (double)(seg + 1)) || !isfinite(p)) {
                cm_fail_at(err, (long)g, (long)walk_vertex(w, i), -1);
                s = cm_fail(err, CM_ERR_ARGUMENT,
                            "polygon %zu: arc length cannot separate vertex %zu from its neighbours "
                            "(edges too short against the perimeter)", g, walk_vertex(w, i));
                break;
            }
            w->param[i] = p;
        }
    }
    w->param[n] = (double)num_pins;
    free(arc);
    return s;
}

typedef struct entry { double u, room; size_t g, i; } entry;

static int by_parameter(const void *pa, const void *pb)
{
    const entry *a = pa, *b = pb;
    if (a->u != b->u) return a->u < b->u ? -1 : 1;
    return (a->g > b->g) - (a->g < b->g);
}

/* Vertices of different polygons closer in parameter than this share of
 * the parameter gap to their neighbours are one boundary vertex (each
 * polygon its own vertex there): near-coincident vertices would otherwise
 * leave a sliver edge, and polygons sampled alike keep their one-to-one
 * correspondence. */
#define CM_SNAP 0.5

/* The merged boundary: u[j], the parameter of vertex j (strictly
 * increasing), and own[g * total + j], the vertex of polygon g there (its
 * index along the walk) or -1. */
static cm_status merge(const walk *walks, size_t k, double **u, long **own, size_t *n, cm_error *err)
{
    size_t total = 0;
    for (size_t g = 0; g < k; g++) total += walks[g].n;
    entry *e = malloc(total * sizeof *e);
    *u = malloc(total * sizeof **u);
    *own = malloc(k * total * sizeof **own);
    double *room = malloc(total * sizeof *room); /* of each group's first entry */
    if (!e || !*u || !*own || !room) {
        free(e), free(room);
        return cm_fail_status(err, CM_ERR_NO_MEMORY);
    }
    size_t m = 0;
    for (size_t g = 0; g < k; g++) {
        const walk *w = &walks[g];
        for (size_t i = 0; i < w->n; i++) {
            double before = i ? w->param[i] - w->param[i - 1] : w->param[w->n] - w->param[w->n - 1];
            e[m++] = (entry){w->param[i], fmin(before, w->param[i + 1] - w->param[i]), g, i};
        }
    }
    qsort(e, total, sizeof *e, by_parameter);
    for (size_t x = 0; x < k * total; x++) (*own)[x] = -1;
    *n = 0;
    for (size_t x = 0; x < total; x++) {
        size_t j = *n - 1;
        int joins = *n > 0 && (*own)[e[x].g * total + j] < 0 &&
                    e[x].u - (*u)[j] < CM_SNAP * fmin(e[x].room, room[j]);
        if (!joins) j = (*n)++, (*u)[j] = e[x].u, room[j] = e[x].room;
        (*own)[e[x].g * total + j] = (long)e[x].i;
    }
    free(e), free(room);
    return CM_OK;
}

/* The share of the way along w's edge from its i-th vertex where the
 * parameter is the share s of the way from param[i] to param[i + 1]: s
 * itself where the parameter is linear along the edge. */
static double along_edge(const walk *w, size_t i, double s)
{
    if (!w->sub) return s;
    const double *sub = w->sub + i * CM_PARAM_FINE;
    double v = w->param[i] + s * (w->param[i + 1] - w->param[i]);
    size_t l = 0;
    while (l + 1 < CM_PARAM_FINE && sub[l + 1] <= v) l++;
    double hi = l + 1 < CM_PARAM_FINE ? sub[l + 1] : w->param[i + 1];
    double f = hi > sub[l] ? (v - sub[l]) / (hi - sub[l]) : 0.0;
    double share = ((double)l + fmin(fmax(f, 0.0), 1.0)) / CM_PARAM_FINE;
    return share > 0.0 && share < 1.0 ? share : s;
}

/* Polygon g at the merged parameters: its own vertices where it has one,
 * elsewhere the point on its edge between its own vertices before and
 * after, at the share of their parameters (as merged) the vertex has.
 * own: g's row of merge's table. */
static void fill(const walk *w, const double *u, const long *own, size_t n, size_t pins, double *xy,
                 int32_t *edge, double *t)
{
    /* w's first and last vertex on the merged boundary: before the first
     * (a polygon not pinned at the start), its last vertex one period back
     * is the one before */
    size_t first = 0, last = n - 1;
    while (own[first] < 0) first++;
    while (own[last] < 0) last--;
    /* w's vertex at or before j, where it and the next were merged, and
     * their parameters */
    size_t i = (size_t)own[last], next = first;
    double u_at = u[last] - (double)pins;
    for (size_t j = 0; j < n; j++) {
        if (own[j] >= 0) {
            i = (size_t)own[j], u_at = u[j];
            for (next = j + 1; next < n && own[next] < 0;) next++;
            const double *a = walk_point(w, i);
            xy[2 * j] = a[0], xy[2 * j + 1] = a[1];
            edge[j] = (int32_t)walk_vertex(w, i), t[j] = 0.0;
            continue;
        }
        double u_next = next < n ? u[next] : u[first] + (double)pins;
        double s = along_edge(w, i, (u[j] - u_at) / (u_next - u_at));
        /* Input numbering: a clockwise polygon's edge runs from vertex i + 1
         * back to i. The point is computed from the (edge, t) reported, so
         * P[e] + t (P[e + 1] - P[e]) gives it back bit for bit. */
        edge[j] = (int32_t)(w->reversed ? walk_vertex(w, i + 1) : walk_vertex(w, i));
        t[j] = w->reversed ? 1.0 - s : s;
        const double *a = w->xy + 2 * edge[j], *b = w->xy + 2 * ((size_t)(edge[j] + 1) % w->n);
        xy[2 * j] = a[0] + t[j] * (b[0] - a[0]);
        xy[2 * j + 1] = a[1] + t[j] * (b[1] - a[1]);
    }
}

static cm_status refine(const walk *walks, size_t k, size_t num_pins, cm_boundary_map *out, cm_error *err);

cm_status cm_correspond_arclength(const double *const *polygons, const size_t *counts, size_t k,
                                  const int *orientation, const size_t *pins, size_t num_pins,
                                  cm_boundary_map *out, cm_error *err)
{
    memset(out, 0, sizeof *out);
    size_t *zeros = NULL;
    if (num_pins == 0) { /* the first vertex of every polygon */
        zeros = calloc(k, sizeof *zeros);
        if (!zeros) return cm_fail_status(err, CM_ERR_NO_MEMORY);
        pins = zeros, num_pins = 1;
    }
    walk *walks = calloc(k, sizeof *walks);
    size_t *offset = malloc(num_pins * k * sizeof *offset);
    cm_status s = walks && offset ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    for (size_t g = 0; s == CM_OK && g < k; g++) {
        walks[g] = (walk){polygons[g], counts[g], orientation[g] < 0, 0,
                          malloc((counts[g] + 1) * sizeof(double)), NULL};
        if (!walks[g].param) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
    }
    if (s == CM_OK) s = order_pins(pins, num_pins, k, walks, offset, err);
    for (size_t g = 0; s == CM_OK && g < k; g++) s = parametrise(&walks[g], offset + g, k, num_pins, g, err);
    if (s == CM_OK) s = refine(walks, k, num_pins, out, err);
    if (walks)
        for (size_t g = 0; g < k; g++) free(walks[g].param);
    free(walks), free(offset), free(zeros);
    return s;
}

/* The common refinement of the parametrised walks into out. */
static cm_status refine(const walk *walks, size_t k, size_t num_pins, cm_boundary_map *out, cm_error *err)
{
    double *u = NULL;
    long *own = NULL;
    size_t n = 0;
    size_t total = 0;
    for (size_t g = 0; g < k; g++) total += walks[g].n;
    cm_status s = merge(walks, k, &u, &own, &n, err);
    if (s == CM_OK) {
        out->k = k, out->n = n;
        out->xy = calloc(k, sizeof *out->xy);
        out->edge = calloc(k, sizeof *out->edge);
        out->t = calloc(k, sizeof *out->t);
        if (!out->xy || !out->edge || !out->t) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
    }
    for (size_t g = 0; s == CM_OK && g < k; g++) {
        out->xy[g] = malloc(2 * n * sizeof **out->xy);
        out->edge[g] = malloc(n * sizeof **out->edge);
        out->t[g] = malloc(n * sizeof **out->t);
        if (!out->xy[g] || !out->edge[g] || !out->t[g]) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        else fill(&walks[g], u, own + g * total, n, num_pins, out->xy[g], out->edge[g], out->t[g]);
    }
    if (s != CM_OK) cm_boundary_map_clear(out);
    free(u), free(own);
    return s;
}

/* The boundary rotated to start at the first vertex that is an input
 * vertex of every polygon (as a pinned refinement does), when there is
 * one (*shared = 1): then every polygon's points run from one of its own
 * vertices. */
static cm_status start_at_shared(cm_boundary_map *out, int *shared, cm_error *err)
{
    size_t n = out->n, at = 0;
    for (; at < n; at++) {
        size_t g = 0;
        while (g < out->k && out->t[g][at] == 0.0) g++;
        if (g == out->k) break;
    }
    *shared = at < n;
    if (at == 0 || at == n) return CM_OK;
    double *xy = malloc(2 * n * sizeof *xy), *t = malloc(n * sizeof *t);
    int32_t *edge = malloc(n * sizeof *edge);
    if (!xy || !t || !edge) {
        free(xy), free(t), free(edge);
        return cm_fail_status(err, CM_ERR_NO_MEMORY);
    }
    for (size_t g = 0; g < out->k; g++) {
        for (size_t j = 0; j < n; j++) {
            size_t from = (j + at) % n;
            xy[2 * j] = out->xy[g][2 * from], xy[2 * j + 1] = out->xy[g][2 * from + 1];
            edge[j] = out->edge[g][from], t[j] = out->t[g][from];
        }
        memcpy(out->xy[g], xy, 2 * n * sizeof *xy);
        memcpy(out->edge[g], edge, n * sizeof *edge), memcpy(out->t[g], t, n * sizeof *t);
    }
    free(xy), free(t), free(edge);
    return CM_OK;
}

/* w->sub from fine (counter-clockwise positions, as params), less shift
 * (modulo 1) and lifted next to each edge's first parameter. Left NULL
 * (linear) where they do not increase strictly from param[i] to below
 * param[i + 1]. 0, or -1 out of memory. */
static int walk_sub(walk *w, const double *fine, double shift)
{
    size_t n = w->n;
    double *sub = malloc(n * CM_PARAM_FINE * sizeof *sub);
    if (!sub) return -1;
    for (size_t i = 0; i < n; i++) {
        size_t c = (w->start + i) % n;
        double lo = w->param[i], *row = sub + i * CM_PARAM_FINE;
        row[0] = lo;
        for (size_t l = 1; l < CM_PARAM_FINE; l++) {
            double x = fine[c * CM_PARAM_FINE + l] - shift;
            x = lo + (x - lo) - floor(x - lo);
            if (!(x > row[l - 1] && x < w->param[i + 1])) {
                free(sub);
                return 0;
            }
            row[l] = x;
        }
    }
    w->sub = sub;
    return 0;
}

/* Walks of the given parameters, each less shift[g] (modulo 1). */
static cm_status param_walks(const double *const *polygons, const size_t *counts, size_t k, const int *orientation,
                             const double *const *params, const double *const *fine, const double *shift, walk *walks,
                             cm_error *err)
{
    for (size_t g = 0; g < k; g++) {
        size_t n = counts[g], start = 0;
        walk *w = &walks[g];
        double *shifted = malloc(n * sizeof *shifted);
        *w = (walk){polygons[g], n, orientation[g] < 0, 0, malloc((n + 1) * sizeof(double)), NULL};
        if (!w->param || !shifted) {
            free(shifted);
            return cm_fail_status(err, CM_ERR_NO_MEMORY);
        }
        for (size_t c = 0; c < n; c++) {
            double p = params[g][c] - shift[g];
            shifted[c] = p < 0 ? p + 1.0 : p;
            if (shifted[c] >= 1.0) shifted[c] = 0.0; /* -tiny + 1 rounded up */
            if (shifted[c] < shifted[start]) start = c;
        }
        w->start = start;
        for (size_t i = 0; i < n; i++) { /* from the least, nudged to increase */
            double p = shifted[(start + i) % n];
            w->param[i] = i && p <= w->param[i - 1] ? nextafter(w->param[i - 1], INFINITY) : p;
        }
        free(shifted);
        w->param[n] = w->param[0] + 1.0;
        if (!(w->param[n - 1] < w->param[n]) || !(w->param[0] >= 0) || !isfinite(w->param[n])) {
            cm_fail_at(err, (long)g, (long)walk_vertex(w, n - 1), -1);
            return cm_fail(err, CM_ERR_ARGUMENT, "polygon %zu: the correspondence cannot separate vertex %zu from "
                           "its neighbours (edges too short against the perimeter)", g, walk_vertex(w, n - 1));
        }
        if (fine && fine[g] && walk_sub(w, fine[g], shift[g])) return cm_fail_status(err, CM_ERR_NO_MEMORY);
    }
    return CM_OK;
}

cm_status cm_correspond_params(const double *const *polygons, const size_t *counts, size_t k,
                               const int *orientation, const double *const *params, const double *const *fine,
                               cm_boundary_map *out, cm_error *err)
{
    memset(out, 0, sizeof *out);
    walk *walks = calloc(k, sizeof *walks);
    double *shift = calloc(k, sizeof *shift);
    cm_status s = walks && shift ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    int shared = 0;
    /* The merge does not join across the end of the parameter range: all
     * parameters are turned to put the end in the middle of the widest gap
     * between them. */
    size_t total = 0;
    for (size_t g = 0; g < k; g++) total += counts[g];
    double *all = s == CM_OK ? malloc(total * sizeof *all) : NULL;
    if (s == CM_OK && !all) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
    if (all) {
        for (size_t g = 0, at = 0; g < k; at += counts[g], g++) memcpy(all + at, params[g], counts[g] * sizeof *all);
        qsort(all, total, sizeof *all, cm_compare_doubles);
        double gap = all[0] + 1.0 - all[total - 1], middle = 0.5 * (all[total - 1] + all[0] + 1.0);
        for (size_t x = 1; x < total; x++)
            if (all[x] - all[x - 1] > gap) gap = all[x] - all[x - 1], middle = 0.5 * (all[x] + all[x - 1]);
        for (size_t g = 0; g < k; g++) shift[g] = middle - floor(middle);
        free(all);
    }
    /* Twice at most: as given, then, when no vertex is every polygon's,
     * each polygon turned so that its vertex nearest to 0 is there. */
    for (int pass = 0; s == CM_OK && !shared && pass < 2; pass++) {
        if (pass) {
            cm_boundary_map_clear(out);
            for (size_t g = 0; g < k; g++) {
                free(walks[g].param), walks[g].param = NULL;
                free(walks[g].sub), walks[g].sub = NULL;
                for (size_t c = 0; c < counts[g]; c++) {
                    double p = params[g][c], d = p < 0.5 ? p : p - 1.0;
                    if (c == 0 || fabs(d) < fabs(shift[g])) shift[g] = d;
                }
            }
        }
        s = param_walks(polygons, counts, k, orientation, params, fine, shift, walks, err);
        if (s == CM_OK) s = refine(walks, k, 1, out, err);
        if (s == CM_OK) s = start_at_shared(out, &shared, err);
    }
    if (s != CM_OK) cm_boundary_map_clear(out);
    if (walks)
        for (size_t g = 0; g < k; g++) free(walks[g].param), free(walks[g].sub);
    free(walks), free(shift);
    return s;
}
