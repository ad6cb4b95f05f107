/* cm_boundary_map_smooth: on a square against a clockwise 16-gon square
 * whose parameters crowd eight of its vertices into a twentieth of the
 * boundary (a stretch jump of about 20 at the crowd's ends), the points
 * that are not a polygon's own vertices slide along their input edges and
 * the sum of squared jumps of ln stretch falls below a fifth of what it
 * was; every polygon's own vertices stay bit-identical, every moved point
 * is cm_edge_point of its edge and parameter, in the boundary's order, and
 * no sweep raises the sum. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "correspond/arclength.h"
#include "correspond/smooth.h"
#include "correspond/split.h"

enum { NA = 4, NB = 16 };

static double jump_sum(const cm_boundary_map *map)
{
    double sum = 0, prev = 0;
    for (size_t j = 0; j <= map->n; j++) {
        size_t i = j % map->n, next = (i + 1) % map->n;
        double l[2];
        for (size_t g = 0; g < 2; g++) {
            const double *a = map->xy[g] + 2 * i, *b = map->xy[g] + 2 * next;
            l[g] = hypot(b[0] - a[0], b[1] - a[1]);
        }
        double u = log(l[1] / l[0]);
        if (j > 0) sum += (u - prev) * (u - prev);
        prev = u;
    }
    return sum;
}

/* Own vertices where the input has them, the rest on their edges in
 * order (their parameters strictly monotone along each input edge). */
static int contract_holds(const cm_boundary_map *map, const double *const *in, const size_t *counts,
                          const int *orientation)
{
    for (size_t g = 0; g < 2; g++) {
        size_t own = 0;
        for (size_t j = 0; j < map->n; j++) {
            const double *p = map->xy[g] + 2 * j;
            if (map->t[g][j] == 0) {
                if (memcmp(p, in[g] + 2 * map->edge[g][j], 2 * sizeof(double)) != 0) return 0;
                own++;
                continue;
            }
            double xy[2];
            cm_edge_point(in[g], counts[g], map->edge[g][j], map->t[g][j], xy);
            if (memcmp(p, xy, sizeof xy) != 0 || !(map->t[g][j] > 0 && map->t[g][j] < 1)) return 0;
            size_t next = (j + 1) % map->n;
            if (map->t[g][next] != 0 && map->edge[g][next] == map->edge[g][j] &&
                !((map->t[g][next] - map->t[g][j]) * orientation[g] > 0))
                return 0;
        }
        if (own != counts[g]) return 0;
    }
    return 1;
}

static void test_crowd_graded(void)
{
    double a[2 * NA] = {0, 0, 1, 0, 1, 1, 0, 1}, ccw[2 * NB], b[2 * NB], pa[NA], pb[NB];
    for (int c = 0; c < NB; c++) {
        /* side 2, from (3, 0) counter-clockwise, four vertices a side */
        double s = 0.5 * c;
        int side = c / 4;
        double f = s - 2 * side;
        double x[4] = {3 + f, 5, 5 - f, 3}, y[4] = {0, f, 2, 2 - f};
        ccw[2 * c] = x[side], ccw[2 * c + 1] = y[side];
    }
    for (int i = 0; i < NB; i++) memcpy(b + 2 * i, ccw + 2 * ((NB - i) % NB), 2 * sizeof(double));
    for (int c = 0; c < NA; c++) pa[c] = 0.25 * c;
    for (int c = 0; c < NB; c++) pb[c] = c < 8 ? 0.002 + 0.006 * c : 0.06 + 0.115 * (c - 8);
    const double *in[2] = {a, b};
    const double *params[2] = {pa, pb};
    size_t counts[2] = {NA, NB};
    int orientation[2] = {1, -1};
    cm_error err = {0};
    cm_boundary_map map;
    CHECK(cm_correspond_params(in, counts, 2, orientation, params, &map, &err) == CM_OK);
    CHECK(contract_holds(&map, in, counts, orientation));
    double before = jump_sum(&map);
    size_t n = map.n;
    CHECK(cm_boundary_map_smooth(&map, in, counts, orientation, 1, &err) == CM_OK);
    double one = jump_sum(&map);
    CHECK(cm_boundary_map_smooth(&map, in, counts, orientation, 2000, &err) == CM_OK);
    double many = jump_sum(&map);
    CHECK_MSG(map.n == n && one <= before && many <= one && many < 0.2 * before,
              "sum of squared jumps %g, after one sweep %g, after more %g", before, one, many);
    CHECK(contract_holds(&map, in, counts, orientation));
    cm_boundary_map_clear(&map);
}

int main(void)
{
    test_crowd_graded();
    return check_summary("test_smooth");
}
