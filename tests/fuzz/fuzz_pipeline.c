/* libFuzzer harness for the whole pipeline: bytes -> k polygons ->
 * cm_triangulate_polygons with the default options (partition and
 * remeshing). A CM_OK result must pass the independent exact check of
 * tests/core/result_check.h; a failure must carry a one-line message and
 * no geometry; a self-intersection or repeated-vertex verdict must agree
 * with a brute-force check over all edge pairs.
 *
 * Layout: byte 0: n = 3 + b % 14; byte 1: bit 0 -> 3 polygons, bit 1 ->
 * raw doubles (8 bytes each, so NaN, Inf, 1e300, subnormals occur), bits
 * 2-7 -> scale 2^(4 (b >> 2) - 128) for the small-integer form; then the
 * coordinates, polygon-major: one signed byte each in the small-integer
 * form (a 256 x 256 grid, where touching and collinear cases are common).
 * Missing bytes read as 0. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "result_check.h"

enum { MAX_N = 16, MAX_K = 3 };

typedef struct reader {
    const uint8_t *data;
    size_t size, at;
} reader;

static uint8_t next_byte(reader *in)
{
    return in->at < in->size ? in->data[in->at++] : 0;
}

static double next_double(reader *in)
{
    uint8_t bytes[8];
    for (int i = 0; i < 8; i++) bytes[i] = next_byte(in);
    double value;
    memcpy(&value, bytes, sizeof value);
    return value;
}

static int sign(double v) { return (v > 0) - (v < 0); }

/* Edges pa and pb, collinear, both from p: do they overlap (b folds back
 * onto a)? Signs of coordinate differences are exact. */
static int folds_back(const double *p, const double *a, const double *b)
{
    if (a[0] != p[0]) return sign(b[0] - p[0]) == sign(a[0] - p[0]);
    return sign(b[1] - p[1]) == sign(a[1] - p[1]);
}

/* Do edges i and j of polygon xy (n vertices) meet where a simple polygon's
 * edges may not? Adjacent edges may share only their common vertex. */
static int edges_conflict(const double *xy, size_t n, size_t i, size_t j)
{
    const double *a = xy + 2 * i, *b = xy + 2 * ((i + 1) % n);
    const double *c = xy + 2 * j, *d = xy + 2 * ((j + 1) % n);
    if (!cm_segments_intersect(a, b, c, d)) return 0;
    if ((i + 1) % n == j) return cm_orient2d(a, b, d) == 0 && folds_back(b, a, d);
    if ((j + 1) % n == i) return cm_orient2d(c, d, b) == 0 && folds_back(d, c, b);
    return 1;
}

/* 1 if the polygon has distinct vertices and no conflicting edges. */
static int brute_force_simple(const double *xy, size_t n)
{
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++)
            if (xy[2 * i] == xy[2 * j] && xy[2 * i + 1] == xy[2 * j + 1]) return 0;
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++)
            if (edges_conflict(xy, n, i, j)) return 0;
    return 1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    reader in = {data, size, 0};
    size_t n = 3 + next_byte(&in) % (MAX_N - 2);
    uint8_t flags = next_byte(&in);
    size_t k = flags & 1 ? 3 : 2;
    int raw = (flags & 2) != 0;
    double scale = ldexp(1.0, 4 * (flags >> 2) - 128);
    double xy[MAX_K][2 * MAX_N];
    int finite = 1;
    for (size_t g = 0; g < k; g++)
        for (size_t i = 0; i < 2 * n; i++) {
            xy[g][i] = raw ? next_double(&in) : (int8_t)next_byte(&in) * scale;
            finite &= isfinite(xy[g][i]) != 0;
        }
    const double *polygons[MAX_K] = {xy[0], xy[1], xy[2]};
    size_t counts[MAX_K] = {n, n, n};
    cm_result *r = NULL;
    cm_status status = cm_triangulate_polygons(polygons, counts, k, NULL, &r);
    if (!r) abort();
    if (status == CM_OK) {
        char why[256];
        if (!rc_check(r, polygons, k, n, why, sizeof why)) {
            fprintf(stderr, "invalid result reported as success: %s\n", why);
            abort();
        }
    } else {
        const char *message = cm_result_message(r);
        if (!message[0] || strchr(message, '\n')) abort();
        if (cm_result_num_triangles(r) != 0 || cm_result_vertices(r, 0)) abort();
        /* Raw doubles may mix magnitudes 1e-320 and 1e300 in one polygon;
         * there the construction may give up (CM_ERR_INTERNAL, an honest
         * failure). On the small grid it must always succeed. */
        if ((status == CM_ERR_INTERNAL && !raw) || status == CM_ERR_NO_MEMORY || status == CM_ERR_CANCELLED ||
            status == CM_ERR_ARGUMENT || status == CM_ERR_COUNT_MISMATCH || status == CM_ERR_TOO_FEW_VERTICES) {
            fprintf(stderr, "unexpected status %s: %s\n", cm_status_string(status), message);
            abort();
        }
        if (status == CM_ERR_NOT_FINITE && finite) abort();
        if (status == CM_ERR_SELF_INTERSECTION || status == CM_ERR_REPEATED_VERTEX) {
            long polygon = -1;
            cm_result_error_location(r, &polygon, NULL, NULL);
            if (polygon < 0 || (size_t)polygon >= k || brute_force_simple(xy[polygon], n)) {
                fprintf(stderr, "%s, but the polygon is simple\n", message);
                abort();
            }
        }
    }
    /* Success means every polygon is simple; an orientation mismatch at
     * polygon g means polygons 0..g passed every other check. */
    size_t simple_upto = 0;
    if (status == CM_OK) simple_upto = k;
    if (status == CM_ERR_ORIENTATION_MISMATCH) {
        long polygon = -1;
        cm_result_error_location(r, &polygon, NULL, NULL);
        if (polygon < 1) abort();
        simple_upto = (size_t)polygon + 1;
    }
    for (size_t g = 0; g < simple_upto; g++)
        if (!brute_force_simple(xy[g], n)) {
            fprintf(stderr, "polygon %zu is not simple, status %s\n", g, cm_status_string(status));
            abort();
        }
    cm_result_free(r);
    return 0;
}
