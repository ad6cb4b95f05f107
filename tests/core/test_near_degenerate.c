/* Near-degenerate geometry through the default pipeline (partition and
 * remeshing): corners 1e-9 degrees from straight, slivers, features of
 * 1e-3 and 1e-9 on an offset of 1e6, polygons of very different scales,
 * vertices a hair from an edge. Each fixture states what it expects: a
 * result valid by the independent exact check (result_check.h), or a
 * failure with a one-line message; "either" fixtures accept a clear error
 * but never an invalid result reported as success. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "random_polygons.h"
#include "result_check.h"

enum expect { MUST_SUCCEED, VALID_OR_ERROR };

static void run(const char *name, const double *a, const double *b, size_t n, enum expect expect,
                int remesh)
{
    const double *xy[2] = {a, b};
    size_t counts[2] = {n, n};
    cm_options o;
    cm_options_init(&o);
    o.remesh = remesh;
    cm_result *r = NULL;
    cm_status s = cm_triangulate_polygons(xy, counts, 2, &o, &r);
    char why[256] = "";
    if (s == CM_OK) {
        CHECK_MSG(rc_check(r, xy, 2, n, why, sizeof why), "%s (remesh %d): invalid result reported as success: %s",
                  name, remesh, why);
    } else {
        CHECK_MSG(expect == VALID_OR_ERROR, "%s (remesh %d): %s: %s", name, remesh, cm_status_string(s),
                  cm_result_message(r));
        const char *m = cm_result_message(r);
        CHECK_MSG(m[0] && !strchr(m, '\n'), "%s: failure without a one-line message", name);
        CHECK(cm_result_num_triangles(r) == 0);
    }
    cm_result_free(r);
}

static void both(const char *name, const double *a, const double *b, size_t n, enum expect expect)
{
    run(name, a, b, n, expect, 1);
    run(name, a, b, n, expect, 0);
}

/* A rectangle with every side split in `per` pieces, each split vertex
 * pushed outwards by `bump` times the side length (0: collinear runs). */
static void bumpy_rect(double *xy, int per, double w, double h, double bump, double ox, double oy)
{
    int i = 0;
    for (int side = 0; side < 4; side++)
        for (int j = 0; j < per; j++, i++) {
            double f = (double)j / per, off = j ? bump : 0;
            double x = side == 0 ? f * w : side == 1 ? w : side == 2 ? (1 - f) * w : 0;
            double y = side == 0 ? 0 : side == 1 ? f * h : side == 2 ? h : (1 - f) * h;
            if (side == 0) y -= off * w;
            if (side == 1) x += off * h;
            if (side == 2) y += off * w;
            if (side == 3) x -= off * h;
            xy[2 * i] = x + ox;
            xy[2 * i + 1] = y + oy;
        }
}

static void test_almost_straight(void)
{
    enum { PER = 5, N = 4 * PER };
    double a[2 * N], b[2 * N];
    /* tan(1e-9 degrees) = 1.745e-11: the corners are 1e-9 degrees from
     * straight, outwards, then inwards (reflex by 1e-9 degrees). */
    double t = tan(1e-9 * RP_PI / 180);
    bumpy_rect(a, PER, 1, 1, t, 0, 0);
    bumpy_rect(b, PER, 2, 1, 0, 0, 0);
    both("1e-9 degrees outwards", a, b, N, MUST_SUCCEED);
    bumpy_rect(a, PER, 1, 1, -t, 0, 0);
    both("1e-9 degrees inwards", a, b, N, MUST_SUCCEED);
    /* Both at once, against a star. */
    double star[2 * N];
    CHECK(rp_star(star, N, 5) == 0);
    both("1e-9 degrees against a star", a, star, N, MUST_SUCCEED);
}

static void test_slivers(void)
{
    const double sliver[] = {0, 0, 1, 0, 2, 1e-9, 1, 2e-9, 0, 1e-9};
    const double pent[] = {0, 0, 1, -0.2, 2, 0.5, 1, 1.5, -0.1, 1};
    both("sliver 1e-9 thick", sliver, pent, 5, MUST_SUCCEED);
    const double needle[] = {0, 0, 1, 0, 1e9, 1, 0, 1};
    const double quad[] = {0, 0, 1, 0, 1.5, 1, 0, 1};
    both("needle 1e9 long", needle, quad, 4, MUST_SUCCEED);
    const double near_edge[] = {0, 0, 4, 0, 4, 4, 2, 4, 4 - 1e-12, 2, 0, 4};
    const double hex2[] = {0, 0, 4, 0, 4, 4, 2, 5, 1, 2, 0, 4};
    both("vertex 1e-12 from an edge", near_edge, hex2, 6, MUST_SUCCEED);
}

static void test_offsets_and_scales(void)
{
    enum { N = 24 };
    double a[2 * N], b[2 * N];
    CHECK(rp_comb(a, N, 3) == 0 && rp_star(b, N, 11) == 0);
    double ca[2 * N], cb[2 * N];
    for (int i = 0; i < 2 * N; i++) { /* features of 1e-3 on an offset of 1e6 */
        ca[i] = 1e6 + 1e-3 * a[i];
        cb[i] = 1e6 + 1e-3 * b[i];
    }
    both("1e-3 features at 1e6", ca, cb, N, MUST_SUCCEED);
    for (int i = 0; i < 2 * N; i++) { /* 1e-9 at 1e6: 15 significant digits */
        ca[i] = 1e6 + 1e-9 * a[i];
        cb[i] = -1e6 + 1e-9 * b[i];
    }
    both("1e-9 features at 1e6", ca, cb, N, VALID_OR_ERROR);
    for (int i = 0; i < 2 * N; i++) { /* very different scales in one call */
        ca[i] = 1e-150 * a[i];
        cb[i] = 1e150 * b[i];
    }
    both("scales 1e-150 and 1e150", ca, cb, N, MUST_SUCCEED);
    for (int i = 0; i < 2 * N; i++) {
        ca[i] = 1e-6 * a[i] + 1e3;
        cb[i] = 1e6 * b[i];
    }
    both("1e-6 at 1e3 and 1e6", ca, cb, N, MUST_SUCCEED);
}

/* Found by fuzzing (tests/fuzz/regressions/pipeline/extreme_range_internal_error):
 * magnitudes from 1e-322 to 1e294 inside one polygon. */
static void test_extreme_range(void)
{
    const double a[] = {0.0, 0.0, 1.8623734600510786e-289, -1.5935549557357777e+294,
                        -2.6126088269340293e+260, 1.6541803121167156e+221, 6.23e-322, 0.0};
    const double b[] = {-6.765728953191907e+46, -6.765728953192395e+46, 4.0328889982143946e-11,
                        4.513438807777116e+70, 1.34645866811137e-309, 0.0, 0.0, 0.0};
    both("magnitudes 1e-322 to 1e294", a, b, 4, VALID_OR_ERROR);
    /* It fails today: the message must say why and what to do. */
    const double *xy[2] = {a, b};
    cm_result *r = NULL;
    if (cm_triangulate_polygons(xy, (size_t[]){4, 4}, 2, NULL, &r) != CM_OK)
        CHECK_MSG(strstr(cm_result_message(r), "span magnitudes 6e-322 to 2e+294; scale the input"),
                  "message: %s", cm_result_message(r));
    cm_result_free(r);
}

int main(void)
{
    test_almost_straight();
    test_slivers();
    test_offsets_and_scales();
    test_extreme_range();
    return check_summary("test_near_degenerate");
}
