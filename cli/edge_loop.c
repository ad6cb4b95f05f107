#include "edge_loop.h"

#include <stdlib.h>

/* Where an edge was read, as the message's prefix. */
static void where(char *out, size_t size, const char *path, long at, int by_index)
{
    if (by_index) snprintf(out, size, "%s: edge %ld", path, at);
    else snprintf(out, size, "%s:%ld", path, at);
}

int edge_loop(const char *path, const loop_edge *edges, size_t count, size_t vertex_count, int base, int by_index,
              long **loop, size_t *length, cli_error *error)
{
    *loop = NULL, *length = 0;
    char at[512];
    if (count == 0) {
        cli_error_set(error, "%s: no edges; expected one closed polyline", path);
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
                              "the polyline branches; expected exactly one closed polyline",
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
    /* Every vertex touched has two edges: walk the loop through edges[0]. */
    size_t n = 0;
    if (code == CLI_EXIT_OK) {
        long v = edges[0].a, e = 0;
        do {
            order[n++] = v;
            v = edges[e].a == v ? edges[e].b : edges[e].a;
            e = incident[v][0] == e ? incident[v][1] : incident[v][0];
        } while (v != edges[0].a && n <= count);
        if (n < count) {
            /* The first edge not on the loop starts another one. */
            char *on = calloc(count, 1);
            if (!on) {
                cli_error_set(error, "%s: out of memory", path);
                code = CLI_EXIT_INTERNAL;
            } else {
                for (size_t i = 0; i < n; i++) on[incident[order[i]][0]] = on[incident[order[i]][1]] = 1;
                size_t other = 0;
                while (on[other]) other++;
                where(at, sizeof at, path, edges[other].where, by_index);
                cli_error_set(error, "%s: this edge is on a second closed polyline (the first has %zu "
                              "vertices); expected exactly one", at, n);
                code = CLI_EXIT_USAGE;
                free(on);
            }
        }
    }
    free(incident);
    if (code != CLI_EXIT_OK) {
        free(order);
        return code;
    }
    *loop = order, *length = n;
    return CLI_EXIT_OK;
}
