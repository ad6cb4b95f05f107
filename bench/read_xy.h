/* The benches' reader of the pairs cm_gen_pairs writes: ".xy" files of one
 * "x y" line per vertex (the library's own input checks are not the point
 * of a bench; the command line reads user files). */
#ifndef CM_BENCH_READ_XY_H
#define CM_BENCH_READ_XY_H

#include <stdio.h>
#include <stdlib.h>

/* One "x y" line per vertex. Returns the count, -1 on error. */
static inline int read_xy(const char *path, double **out)
{
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    int n = 0, cap = 256;
    double *xy = malloc(sizeof(double) * 2 * (size_t)cap), x, y;
    while (xy && fscanf(f, "%lf %lf", &x, &y) == 2) {
        if (n == cap) {
            double *t = realloc(xy, sizeof(double) * 4 * (size_t)cap);
            if (!t) break;
            xy = t, cap *= 2;
        }
        xy[2 * n] = x, xy[2 * n + 1] = y, n++;
    }
    fclose(f);
    *out = xy;
    return xy ? n : -1;
}

#endif
