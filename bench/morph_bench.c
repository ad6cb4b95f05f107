/* cm_morph_bench: frames per second of the convex-combination morph.
 *
 *   cm_morph_bench [N] [FRAMES]      defaults 1000 and 50
 *
 * Two random stars of N vertices (random_polygons.h, seeds 1 and 2), the
 * second with its correspondence turned by N / 3 so the morph has to
 * twist. Triangulated with the library defaults (partition + remeshing)
 * and without remeshing; for each, the morph's set-up time, the frame rate
 * of the convex-combination morph (UMFPACK numeric factorization and two
 * solves per frame, exact validation of every triangle of the enclosed
 * mesh), the same with intrinsic weights, that of the linear mode, and a
 * sweep. Prints a markdown table.
 * Timing only; the tests check correctness. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "compatmesh/compatmesh.h"
#include "random_polygons.h"

static double now(void)
{
    struct timespec ts;
    timespec_get(&ts, TIME_UTC);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Frames at interior times (the ends are copies, not solves). */
static double frame_rate(cm_morph *m, size_t nv, int frames, size_t *invalid, double *min_angle)
{
    double *xy = malloc(2 * nv * sizeof *xy), t0 = now();
    *invalid = 0, *min_angle = 180;
    for (int f = 0; f < frames; f++) {
        size_t inverted = 0;
        double angle = 0;
        cm_status s = cm_morph_section(m, (f + 0.5) / frames, xy, &inverted, &angle);
        *invalid += s != CM_OK || inverted != 0;
        if (angle < *min_angle) *min_angle = angle;
    }
    double fps = frames / (now() - t0);
    free(xy);
    return fps;
}

int main(int argc, char **argv)
{
    int n = argc > 1 ? atoi(argv[1]) : 1000, frames = argc > 2 ? atoi(argv[2]) : 50;
    double *xy = malloc(4 * (size_t)n * sizeof *xy);
    if (!xy || n < 3 || frames < 1 || rp_star(xy, n, 1) || rp_star(xy + 2 * n, n, 2)) {
        fprintf(stderr, "cm_morph_bench: cannot make the star pair (N = %d)\n", n);
        return 1;
    }
    rp_twist(xy + 2 * n, n, n / 3);
    printf("| N = %d twisted star pair | vertices | triangles | morph set-up (s) | convex fps | invalid frames "
           "| min angle | intrinsic fps | invalid | min angle | linear fps | linear frames with inversions | sweep (s) "
           "| sections |\n",
           n);
    printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (int remesh = 1; remesh >= 0; remesh--) {
        cm_options o;
        cm_options_init(&o);
        o.remesh = remesh;
        cm_result *r = NULL;
        if (cm_triangulate(xy, 2, (size_t)n, &o, &r) != CM_OK) {
            fprintf(stderr, "cm_morph_bench: %s\n", cm_result_message(r));
            return 1;
        }
        size_t nv = cm_result_num_vertices(r), invalid = 0, lin_invalid = 0;
        double t0 = now(), angle = 0, lin_angle = 0;
        cm_morph *m = NULL, *lin = NULL;
        cm_morph_options mo;
        cm_morph_options_init(&mo);
        if (cm_morph_create(r, &mo, &m) != CM_OK) {
            fprintf(stderr, "cm_morph_bench: %s\n", cm_morph_message(m));
            return 1;
        }
        double setup = now() - t0;
        double fps = frame_rate(m, nv, frames, &invalid, &angle);
        cm_morph *intr = NULL;
        size_t intr_invalid = 0;
        double intr_angle = 0, intr_fps = 0;
        mo.method = CM_MORPH_INTRINSIC;
        if (cm_morph_create(r, &mo, &intr) == CM_OK)
            intr_fps = frame_rate(intr, nv, frames, &intr_invalid, &intr_angle);
        else
            intr_invalid = (size_t)frames;
        cm_morph_free(intr);
        mo.method = CM_MORPH_LINEAR;
        cm_morph_create(r, &mo, &lin);
        double lin_fps = frame_rate(lin, nv, frames, &lin_invalid, &lin_angle);
        cm_sweep_options so;
        cm_sweep_options_init(&so);
        cm_sweep *w = NULL;
        t0 = now();
        cm_status s = cm_sweep_create(m, &so, &w);
        double sweep = now() - t0;
        printf("| %s | %zu | %zu | %.3f | %.1f | %zu/%d | %.3g | %.1f | %zu/%d | %.3g | %.0f | %zu/%d | %.2f%s | %zu |\n",
               remesh ? "defaults (remeshed)" : "no remeshing", nv, cm_result_num_triangles(r), setup, fps, invalid,
               frames, angle, intr_fps, intr_invalid, frames, intr_angle, lin_fps, lin_invalid, frames, sweep, s == CM_OK ? "" : " (failed)",
               cm_sweep_num_sections(w));
        cm_sweep_free(w);
        cm_morph_free(lin);
        cm_morph_free(m);
        cm_result_free(r);
    }
    free(xy);
    return 0;
}
