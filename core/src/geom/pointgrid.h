/* A uniform grid of points that come and go: the candidates for "which
 * points lie in this box" without scanning them all. Used by ear clipping,
 * where only the reflex vertices inside an ear's bounding box can block it.
 *
 * Exact as a filter: the cell of a coordinate is a monotone function of it
 * (a subtraction and a multiplication, both rounded monotonically), so a
 * point inside a closed box lies in a cell between the box corners' cells.
 * Insert and remove are O(1); memory O(points + cells). */
#ifndef CM_GEOM_POINTGRID_H
#define CM_GEOM_POINTGRID_H

#include <stdint.h>

typedef struct cm_pointgrid {
    double x0, y0, fx, fy; /* cell of x: floor((x - x0) * fx), clamped */
    long nx, ny, count;
    int32_t *head;         /* per cell: first point, -1 none */
    int32_t *next, *prev;  /* per point id, doubly linked within a cell */
    int32_t *cell;         /* per point id: its cell, -1 when absent */
} cm_pointgrid;

/* Room for point ids 0..capacity-1 in the box lo..hi (points outside it
 * fall into the border cells), about `expected` points per cell or fewer.
 * Returns 0 or -1 out of memory. */
int cm_pointgrid_init(cm_pointgrid *g, long capacity, const double lo[2], const double hi[2],
                      long expected);
void cm_pointgrid_clear(cm_pointgrid *g);

void cm_pointgrid_insert(cm_pointgrid *g, long id, double x, double y);
/* No-op if id is absent. */
void cm_pointgrid_remove(cm_pointgrid *g, long id);

/* The cell range covering the closed box [x0, x1] x [y0, y1]: cells
 * (cx, cy) with c[0] <= cx <= c[1], c[2] <= cy <= c[3]; returns their
 * number. Walk a cell with head[cy * nx + cx] and next[]. */
long cm_pointgrid_range(const cm_pointgrid *g, double x0, double y0, double x1, double y1, long c[4]);

#endif
