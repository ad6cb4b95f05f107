#include "edge_loop.h"

#include <ctype.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

/* Where an edge was read, as the message's prefix. */
static void where(char *out, size_t size, const char *path, long at, int by_index)
{
    if (by_index) snprintf(out, size, "%s: edge %ld", path, at);
    else snprintf(out, size, "%s:%ld", path, at);
}

/* Does a vertex (x, y, z) of a polyline file lie in the plane z = z0 of the
 * first? Up to the rounding of coordinates computed and written in single
 * precision (MeshLab's sections differ in the last float digits): within
 * 16 float epsilons of the largest of |x|, |y|, |z| and |z0|. The polygon
 * is meshed in x and y; z is only checked. */
static int in_plane_z(double x, double y, double z, double z0)
{
    double scale = fmax(fmax(fabs(x), fabs(y)), fmax(fabs(z), fabs(z0)));
    return fabs(z - z0) <= 16 * FLT_EPSILON * scale;
}

void plane_z_note(plane_z *plane, double x, double y, double z, int given, long where)
{
    plane->given |= given;
    if (!plane->started) plane->z = z, plane->where = where, plane->started = 1, plane->first_given = given;
    else if (!in_plane_z(x, y, z, plane->z)) plane->off = 1;
}

int plane_z_same_columns(const plane_z *plane, int given, const char *path, long where, cli_error *error)
{
    if (!plane->started || !given == !plane->first_given) return CLI_EXIT_OK;
    const char *here = given ? "a z here" : "no z here", *first = given ? "gives none" : "gives one";
    if (plane->by_index)
        cli_error_set(error, "%s: vertex %ld: %s, while vertex %ld %s; give z on every vertex or on none", path,
                      where, here, plane->where, first);
    else
        cli_error_set(error, "%s:%ld: %s, while line %ld %s; give z on every line or on none", path, where, here,
                      plane->where, first);
    return CLI_EXIT_USAGE;
}

int plane_z_take(plane_z *plane, double x, double y, double z, int given, const char *path, long where,
                 cli_error *error)
{
    if (plane_z_same_columns(plane, given, path, where, error)) return CLI_EXIT_USAGE;
    plane_z_note(plane, x, y, z, given, where);
    if (!plane->off) return CLI_EXIT_OK;
    if (plane->by_index)
        cli_error_set(error, "%s: vertex %ld: z = %.17g differs from z = %.17g of vertex %ld; "
                      "the polygon must lie in a plane z = constant", path, where, z, plane->z, plane->where);
    else
        cli_error_set(error, "%s:%ld: z = %.17g differs from z = %.17g on line %ld; "
                      "the polygon must lie in a plane z = constant", path, where, z, plane->z, plane->where);
    return CLI_EXIT_USAGE;
}

/* Twice the area of the loop of m vertices: in the plane z = 0, signed,
 * with stride 2; in space (the length of Newell's vector) with stride 3. */
static double loop_area2(const double *p, size_t stride, const long *loop, size_t m)
{
    double n[3] = {0, 0, 0};
    for (size_t i = 0; i < m; i++) {
        const double *a = p + stride * (size_t)loop[i], *b = p + stride * (size_t)loop[(i + 1) % m];
        n[2] += a[0] * b[1] - a[1] * b[0];
        if (stride == 3) n[0] += a[1] * b[2] - a[2] * b[1], n[1] += a[2] * b[0] - a[0] * b[2];
    }
    return stride == 3 ? hypot(hypot(n[0], n[1]), n[2]) : n[2];
}

/* Moves the loop of largest area to the front of order (loops of sizes). */
static int outer_first(const double *xy, size_t stride, long *order, size_t *sizes, size_t loops)
{
    size_t outer = 0, first = 0, outer_at = 0;
    double largest = -1;
    for (size_t l = 0; l < loops; first += sizes[l++]) {
        double area = fabs(loop_area2(xy, stride, order + first, sizes[l]));
        if (area > largest) largest = area, outer = l, outer_at = first;
    }
    if (outer == 0) return 0;
    size_t m = sizes[outer];
    long *keep = malloc(m * sizeof *keep);
    if (!keep) return -1;
    memcpy(keep, order + outer_at, m * sizeof *keep);
    memmove(order + m, order, outer_at * sizeof *order);
    memcpy(order, keep, m * sizeof *keep);
    free(keep);
    memmove(sizes + 1, sizes, outer * sizeof *sizes);
    sizes[0] = m;
    return 0;
}

int edge_loops(const char *path, const loop_edge *edges, size_t count, const double *xy, size_t stride,
               size_t vertex_count,
               int base, int by_index, long **loops, size_t **sizes, size_t *loop_count, cli_error *error)
{
    *loops = NULL, *sizes = NULL, *loop_count = 0;
    char at[512];
    if (count == 0) {
        cli_error_set(error, "%s: no edges; expected closed polylines", path);
        return CLI_EXIT_USAGE;
    }
    /* The (at most two) edges at every vertex. */
    long (*incident)[2] = malloc(vertex_count * sizeof *incident);
    long *order = malloc((count + 1) * sizeof *order);
    if (!incident || !order) {
        free(incident), free(order);
        cli_error_set(error, "%s: out of memory", path);
        return CLI_EXIT_INTERNAL;
    }
    for (size_t v = 0; v < vertex_count; v++) incident[v][0] = incident[v][1] = -1;
    int code = CLI_EXIT_OK;
    for (size_t e = 0; e < count && code == CLI_EXIT_OK; e++) {
        const loop_edge *edge = &edges[e];
        where(at, sizeof at, path, edge->where, by_index);
        code = CLI_EXIT_USAGE;
        if (edge->a < 0 || edge->b < 0 || (size_t)edge->a >= vertex_count || (size_t)edge->b >= vertex_count)
            cli_error_set(error, "%s: vertex index %ld is out of range (the file has %zu vertices)", at,
                          (edge->a < 0 || (size_t)edge->a >= vertex_count ? edge->a : edge->b) + base,
                          vertex_count);
        else if (edge->a == edge->b)
            cli_error_set(error, "%s: an edge from vertex %ld to itself", at, edge->a + base);
        else
            code = CLI_EXIT_OK;
        for (int end = 0; end < 2 && code == CLI_EXIT_OK; end++) {
            long v = end ? edge->b : edge->a, other = end ? edge->a : edge->b;
            long *slot = incident[v];
            for (int s = 0; s < 2; s++)
                if (slot[s] >= 0) {
                    const loop_edge *o = &edges[slot[s]];
                    if ((o->a == v ? o->b : o->a) == other) {
                        cli_error_set(error, "%s: the edge %ld-%ld is given twice (also at %s %ld)", at,
                                      edge->a + base, edge->b + base, by_index ? "edge" : "line", o->where);
                        code = CLI_EXIT_USAGE;
                    }
                }
            if (code != CLI_EXIT_OK) break;
            if (slot[1] >= 0) {
                cli_error_set(error, "%s: vertex %ld has a third edge (the others at %s %ld and %ld): "
                              "the polyline branches; expected closed polylines",
                              at, v + base, by_index ? "edges" : "lines", edges[slot[0]].where,
                              edges[slot[1]].where);
                code = CLI_EXIT_USAGE;
            } else {
                slot[slot[0] >= 0] = (long)e;
            }
        }
    }
    for (size_t e = 0; e < count && code == CLI_EXIT_OK; e++)
        for (int end = 0; end < 2 && code == CLI_EXIT_OK; end++) {
            long v = end ? edges[e].b : edges[e].a;
            if (incident[v][1] >= 0) continue;
            where(at, sizeof at, path, edges[e].where, by_index);
            cli_error_set(error, "%s: the polyline is not closed: vertex %ld has only this edge", at,
                          v + base);
            code = CLI_EXIT_USAGE;
        }
    /* Every vertex touched has two edges: walk loop after loop, each from
     * the first edge not on an earlier one. */
    size_t n = 0, *size = NULL, loops_found = 0;
    char *on = code == CLI_EXIT_OK ? calloc(count, 1) : NULL;
    if (code == CLI_EXIT_OK && !(on && (size = malloc(count * sizeof *size)))) {
        cli_error_set(error, "%s: out of memory", path);
        code = CLI_EXIT_INTERNAL;
    }
    for (size_t start = 0; code == CLI_EXIT_OK && start < count; start++) {
        if (on[start]) continue;
        size_t first = n;
        long v = edges[start].a, e = (long)start;
        do {
            order[n++] = v;
            on[e] = 1;
            v = edges[e].a == v ? edges[e].b : edges[e].a;
            e = incident[v][0] == e ? incident[v][1] : incident[v][0];
        } while (v != edges[start].a && n <= count);
        size[loops_found++] = n - first;
    }
    free(incident), free(on);
    if (code == CLI_EXIT_OK && outer_first(xy, stride, order, size, loops_found)) {
        cli_error_set(error, "%s: out of memory", path);
        code = CLI_EXIT_INTERNAL;
    }
    if (code != CLI_EXIT_OK) {
        free(order), free(size);
        return code;
    }
    *loops = order, *sizes = size, *loop_count = loops_found;
    return CLI_EXIT_OK;
}

const char *quote_token(const char *token, size_t max_chars, char *out, size_t size)
{
    size_t used = 0;
    for (const unsigned char *p = (const unsigned char *)token; *p; p++) {
        if (used + 8 >= size || (size_t)(p - (const unsigned char *)token) >= max_chars) {
            strcpy(out + used, "...");
            return out;
        }
        if (isprint(*p)) out[used++] = (char)*p;
        else used += (size_t)snprintf(out + used, size - used, "\\x%02X", *p);
    }
    out[used] = '\0';
    return out;
}
