/* A uniform grid of points; see pointgrid.h. */
#include "geom/pointgrid.h"

#include <math.h>
#include <stdlib.h>

static long cell_of(double v, double v0, double f, long n)
{
    double c = (v - v0) * f;
    if (!(c >= 0)) return 0; /* also NaN */
    return c >= (double)n ? n - 1 : (long)c; /* 0 <= c < n: the cast is floor */
}

int cm_pointgrid_init(cm_pointgrid *g, long capacity, const double lo[2], const double hi[2],
                      long expected)
{
    long side = (long)ceil(sqrt((double)(expected > 0 ? expected : 1)));
    if (side < 1) side = 1;
    double w = hi[0] - lo[0], h = hi[1] - lo[1];
    /* square-ish cells, about `expected` of them in all */
    long nx = side, ny = side;
    if (w > 0 && h > 0) {
        double r = sqrt(w / h);
        nx = (long)fmax(1.0, fmin((double)side * r, 4.0 * (double)side));
        ny = (long)fmax(1.0, fmin((double)side / r, 4.0 * (double)side));
    }
    g->x0 = lo[0], g->y0 = lo[1], g->nx = nx, g->ny = ny, g->count = 0;
    g->fx = w > 0 ? (double)nx / w : 0.0;
    g->fy = h > 0 ? (double)ny / h : 0.0;
    size_t cap = (size_t)(capacity > 0 ? capacity : 1);
    g->head = malloc((size_t)(nx * ny) * sizeof *g->head);
    g->next = malloc(cap * sizeof *g->next);
    g->prev = malloc(cap * sizeof *g->prev);
    g->cell = malloc(cap * sizeof *g->cell);
    if (!g->head || !g->next || !g->prev || !g->cell) {
        cm_pointgrid_clear(g);
        return -1;
    }
    for (long c = 0; c < nx * ny; c++) g->head[c] = -1;
    for (long i = 0; i < capacity; i++) g->cell[i] = -1;
    return 0;
}

void cm_pointgrid_clear(cm_pointgrid *g)
{
    free(g->head), free(g->next), free(g->prev), free(g->cell);
    g->head = g->next = g->prev = g->cell = NULL;
}

void cm_pointgrid_insert(cm_pointgrid *g, long id, double x, double y)
{
    long c = cell_of(y, g->y0, g->fy, g->ny) * g->nx + cell_of(x, g->x0, g->fx, g->nx);
    g->cell[id] = (int32_t)c, g->prev[id] = -1, g->next[id] = g->head[c];
    if (g->head[c] >= 0) g->prev[g->head[c]] = (int32_t)id;
    g->head[c] = (int32_t)id;
    g->count++;
}

void cm_pointgrid_remove(cm_pointgrid *g, long id)
{
    long c = g->cell[id];
    if (c < 0) return;
    if (g->prev[id] >= 0) g->next[g->prev[id]] = g->next[id];
    else g->head[c] = g->next[id];
    if (g->next[id] >= 0) g->prev[g->next[id]] = g->prev[id];
    g->cell[id] = -1;
    g->count--;
}

long cm_pointgrid_range(const cm_pointgrid *g, double x0, double y0, double x1, double y1, long c[4])
{
    c[0] = cell_of(x0, g->x0, g->fx, g->nx), c[1] = cell_of(x1, g->x0, g->fx, g->nx);
    c[2] = cell_of(y0, g->y0, g->fy, g->ny), c[3] = cell_of(y1, g->y0, g->fy, g->ny);
    return (c[1] - c[0] + 1) * (c[3] - c[2] + 1);
}
