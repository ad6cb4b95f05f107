/* Deterministic polygon generators for tests and benchmarks.
 *
 * Every generator writes a simple, counter-clockwise polygon of n distinct
 * vertices into a caller-provided array xy[2n] (x0, y0, x1, y1, ...) and
 * returns 0, or -1 when it cannot (n too small, or a shape that would not
 * be simple for that n). The same arguments always give the same polygon:
 * randomness comes from a private splitmix64 stream, never rand().
 *
 * Coordinates lie in [-1, 1] and are multiples of 2^-24 (rp_snap), so the
 * orientation test rp_orient below is exact in doubles: differences have at
 * most 26 significant bits, products 52. That makes the brute-force
 * simplicity check rp_is_simple trustworthy for everything made here.
 *
 *   rp_star(xy, n, seed)          random radii in [0.3, 1] at strictly
 *                                 increasing random angles; star-shaped
 *   rp_disc(xy, n)                regular n-gon of radius 1, vertex 0 at (1, 0)
 *   rp_spiral(xy, n, turns)       thick spiral band: outer side going out,
 *                                 inner side coming back; needs
 *                                 n >= rp_spiral_min_n(turns), about 3 turns^2
 *   rp_comb(xy, n, teeth)         a bar with `teeth` teeth pointing up; needs
 *                                 n >= 4 * teeth; spare vertices go along
 *                                 the teeth (about n / 10 teeth reads well)
 *   rp_random_simple(xy, n, seed) random grid points joined into a simple
 *                                 polygon by 2-opt untangling
 *   rp_random_spa(xy, n, seed)    random grid points joined into a simple
 *                                 polygon by space partitioning (Auer and
 *                                 Held); expected O(n log n), for large n
 *   rp_twist(xy, n, shift)        rotates the correspondence: vertex i takes
 *                                 the old vertex (i + shift) mod n
 */
#ifndef CM_TEST_RANDOM_POLYGONS_H
#define CM_TEST_RANDOM_POLYGONS_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Everything is static inline: a test that uses one generator gets no
 * unused-function warnings for the rest. */

#define RP_PI 3.14159265358979323846
#define RP_GRID 16777216.0 /* 2^24 */

/* ---- random numbers ---------------------------------------------------- */

typedef struct rp_rng {
    uint64_t state;
} rp_rng;

static inline uint64_t rp_next(rp_rng *rng)
{
    uint64_t z = (rng->state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* Uniform in [0, 1) with 53 random bits. */
static inline double rp_uniform(rp_rng *rng)
{
    return (double)(rp_next(rng) >> 11) * (1.0 / 9007199254740992.0);
}

/* Uniform integer in [0, bound). The modulo bias is irrelevant here. */
static inline uint64_t rp_below(rp_rng *rng, uint64_t bound)
{
    return rp_next(rng) % bound;
}

/* ---- exact-enough geometry --------------------------------------------- */

/* Rounds to the 2^-24 grid, clamped to [-1, 1]. */
static inline double rp_snap(double v)
{
    if (v > 1.0)
        v = 1.0;
    if (v < -1.0)
        v = -1.0;
    return round(v * RP_GRID) / RP_GRID;
}

static inline void rp_snap_all(double *xy, int n)
{
    for (int i = 0; i < 2 * n; i++)
        xy[i] = rp_snap(xy[i]);
}

/* Sign of the turn a -> b -> c: > 0 left (counter-clockwise). Exact for
 * grid coordinates (see the top of this file). */
static inline double rp_orient(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

static inline int rp_sign(double v)
{
    return (v > 0) - (v < 0);
}

/* Is p, known to be collinear with segment ab, within its bounding box? */
static inline int rp_on_segment(const double *a, const double *b, const double *p)
{
    return fmin(a[0], b[0]) <= p[0] && p[0] <= fmax(a[0], b[0]) &&
           fmin(a[1], b[1]) <= p[1] && p[1] <= fmax(a[1], b[1]);
}

/* Do the closed segments ab and cd share any point? */
static inline int rp_segments_meet(const double *a, const double *b,
                            const double *c, const double *d)
{
    int o1 = rp_sign(rp_orient(a, b, c)), o2 = rp_sign(rp_orient(a, b, d));
    int o3 = rp_sign(rp_orient(c, d, a)), o4 = rp_sign(rp_orient(c, d, b));
    if (o1 * o2 < 0 && o3 * o4 < 0)
        return 1;
    return (o1 == 0 && rp_on_segment(a, b, c)) ||
           (o2 == 0 && rp_on_segment(a, b, d)) ||
           (o3 == 0 && rp_on_segment(c, d, a)) ||
           (o4 == 0 && rp_on_segment(c, d, b));
}

/* Twice the signed area; > 0 for counter-clockwise. */
static inline double rp_signed_area2(const double *xy, int n)
{
    double sum = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        sum += xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
    }
    return sum;
}

static inline void rp_reverse(double *xy, int first, int last)
{
    for (; first < last; first++, last--) {
        double x = xy[2 * first], y = xy[2 * first + 1];
        xy[2 * first] = xy[2 * last];
        xy[2 * first + 1] = xy[2 * last + 1];
        xy[2 * last] = x;
        xy[2 * last + 1] = y;
    }
}

/* Does edge i (vertex i to i+1) meet edge j in a way a simple polygon
 * forbids? Neighbouring edges may only share their common vertex. */
static inline int rp_edges_conflict(const double *xy, int n, int i, int j)
{
    const double *a = xy + 2 * i, *b = xy + 2 * ((i + 1) % n);
    const double *c = xy + 2 * j, *d = xy + 2 * ((j + 1) % n);
    if ((i + 1) % n == j) /* b == c: conflict only if d folds back onto ab */
        return rp_orient(a, b, d) == 0 &&
               (d[0] - b[0]) * (a[0] - b[0]) + (d[1] - b[1]) * (a[1] - b[1]) > 0;
    if ((j + 1) % n == i)
        return rp_edges_conflict(xy, n, j, i);
    return rp_segments_meet(a, b, c, d);
}

/* 1 if xy[0..n-1] is a simple polygon with distinct vertices and non-zero
 * area, 0 otherwise. Brute force, O(n^2): for tests, not for the library. */
static inline int rp_is_simple(const double *xy, int n)
{
    if (n < 3)
        return 0;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (xy[2 * i] == xy[2 * j] && xy[2 * i + 1] == xy[2 * j + 1])
                return 0;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (rp_edges_conflict(xy, n, i, j))
                return 0;
    return rp_signed_area2(xy, n) != 0;
}

/* 1 if some vertex lies on the line through its two neighbours. Valid
 * input, but a zero angle there; the random generators avoid it. */
static inline int rp_has_flat_corner(const double *xy, int n)
{
    for (int i = 0; i < n; i++) {
        const double *a = xy + 2 * ((i + n - 1) % n), *b = xy + 2 * i;
        if (rp_orient(a, b, xy + 2 * ((i + 1) % n)) == 0)
            return 1;
    }
    return 0;
}

/* Snaps, makes the polygon counter-clockwise and checks it. */
static inline int rp_finish(double *xy, int n)
{
    rp_snap_all(xy, n);
    if (rp_signed_area2(xy, n) < 0)
        rp_reverse(xy, 1, n - 1); /* keeps vertex 0 first */
    return rp_is_simple(xy, n) ? 0 : -1;
}

/* ---- correspondence ---------------------------------------------------- */

/* Vertex i becomes the old vertex (i + shift) mod n; shift may be negative.
 * Same polygon, rotated correspondence. */
static inline void rp_twist(double *xy, int n, int shift)
{
    if (n <= 0)
        return;
    shift %= n;
    if (shift < 0)
        shift += n;
    /* three reversals rotate in place */
    rp_reverse(xy, 0, shift - 1);
    rp_reverse(xy, shift, n - 1);
    rp_reverse(xy, 0, n - 1);
}

/* ---- shapes ------------------------------------------------------------ */

static inline int rp_disc(double *xy, int n)
{
    if (n < 3)
        return -1;
    for (int i = 0; i < n; i++) {
        double t = 2 * RP_PI * i / n;
        xy[2 * i] = cos(t);
        xy[2 * i + 1] = sin(t);
    }
    return rp_finish(xy, n);
}

/* One attempt at a star: angular gaps in [1, 2) (relative), so every gap
 * is below pi even for n = 3 and the origin sees every edge. */
static inline void rp_star_attempt(double *xy, int n, rp_rng *rng)
{
    double total = 0, angle = 2 * RP_PI * rp_uniform(rng);
    double *gap = xy; /* the x slots hold the gaps until they are used */
    for (int i = 0; i < n; i++)
        total += gap[2 * i] = 1.0 + rp_uniform(rng);
    for (int i = 0; i < n; i++) {
        double r = 0.3 + 0.7 * rp_uniform(rng);
        angle += 2 * RP_PI * gap[2 * i] / total;
        xy[2 * i] = r * cos(angle);
        xy[2 * i + 1] = r * sin(angle);
    }
}

static inline int rp_star(double *xy, int n, uint64_t seed)
{
    if (n < 3)
        return -1;
    rp_rng rng = {seed};
    for (int attempt = 0; attempt < 100; attempt++) {
        rp_star_attempt(xy, n, &rng);
        if (rp_finish(xy, n) == 0)
            return 0; /* snapping can only fail for huge n */
    }
    return -1;
}

/* Cumulative arc length of the spiral r(t) = r0 + b t over t in [0, tmax]
 * at steps + 1 evenly spaced angles (midpoint rule). */
static inline void rp_spiral_lengths(double *len, int steps, double r0, double b,
                              double tmax)
{
    double dt = tmax / steps;
    len[0] = 0;
    for (int i = 1; i <= steps; i++) {
        double r = r0 + b * (i - 0.5) * dt;
        len[i] = len[i - 1] + sqrt(r * r + b * b) * dt;
    }
}

/* Angle at arc length s, by bisection in the table. */
static inline double rp_spiral_angle(const double *len, int steps, double tmax,
                              double s)
{
    int lo = 0, hi = steps;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (len[mid] <= s)
            lo = mid;
        else
            hi = mid;
    }
    double f = len[hi] > len[lo] ? (s - len[lo]) / (len[hi] - len[lo]) : 0;
    return tmax * (lo + f) / steps;
}

/* m points of one side of the band at radius r0 + b t, evenly spaced in
 * arc length, written from t = 0 outwards, or backwards if `back`. */
static inline int rp_spiral_side(double *xy, int m, double r0, double b,
                          double tmax, int back)
{
    int steps = 64 * m + 4096;
    double *len = (double *)malloc(sizeof(double) * (steps + 1));
    if (!len)
        return -1;
    rp_spiral_lengths(len, steps, r0, b, tmax);
    for (int j = 0; j < m; j++) {
        double s = len[steps] * j / (m - 1);
        double t = rp_spiral_angle(len, steps, tmax, s);
        double r = r0 + b * t;
        int slot = back ? m - 1 - j : j;
        xy[2 * slot] = r * cos(t);
        xy[2 * slot + 1] = r * sin(t);
    }
    free(len);
    return 0;
}

/* Fewest vertices for a spiral of `turns` turns: below this the chords cut
 * into the next turn (or, by aliasing, give a shape that is no spiral). */
static inline int rp_spiral_min_n(double turns)
{
    return (int)ceil(3 * turns * turns + 4 * turns + 4);
}

/* The band's centre line is r(t) = p (1 + t / 2 pi), pitch p per turn,
 * width p / 2, so the gap between turns equals the band width. */
static inline int rp_spiral(double *xy, int n, double turns)
{
    if (!(turns > 0) || n < rp_spiral_min_n(turns))
        return -1;
    double pitch = 1.0 / (turns + 1.25), tmax = 2 * RP_PI * turns;
    double b = pitch / (2 * RP_PI);
    int outer = (n + 1) / 2, inner = n / 2;
    if (rp_spiral_side(xy, outer, 1.25 * pitch, b, tmax, 0) ||
        rp_spiral_side(xy + 2 * outer, inner, 0.75 * pitch, b, tmax, 1))
        return -1;
    return rp_finish(xy, n);
}

static inline void rp_put(double *xy, int *count, double x, double y)
{
    xy[2 * *count] = x;
    xy[2 * *count + 1] = y;
    ++*count;
}

/* `extra` points strictly between (x, y0) and (x, y1) on a side of a tooth,
 * bowed by `bow` in x (a sine arch), so no three of them are collinear. */
static inline void rp_comb_side(double *xy, int *count, double x, double y0,
                         double y1, double bow, int extra)
{
    for (int j = 1; j <= extra; j++) {
        double s = (double)j / (extra + 1);
        rp_put(xy, count, x + bow * sin(RP_PI * s), y0 + (y1 - y0) * s);
    }
}

/* The rounded tip of a tooth from (right, top) to (left, top): `extra`
 * points on a half-ellipse of height `rise`. */
static inline void rp_comb_tip(double *xy, int *count, double left, double right,
                        double top, double rise, int extra)
{
    double mid = 0.5 * (left + right), half = 0.5 * (right - left);
    rp_put(xy, count, right, top);
    for (int j = 1; j <= extra; j++) {
        double t = RP_PI * j / (extra + 1);
        rp_put(xy, count, mid + half * cos(t), top + rise * sin(t));
    }
    rp_put(xy, count, left, top);
}

/* Tooth t of `teeth` (numbered left to right) with `extra` points beyond
 * its corners: up the right side, over the tip, down the left side. The
 * sides bend slightly inwards; the outermost sides start at the bottom. */
static inline void rp_comb_tooth(double *xy, int *count, int t, int teeth, int extra)
{
    double unit = 2.0 / (2 * teeth - 1); /* tooth width = gap width */
    double left = -1 + 2 * t * unit, right = left + unit;
    double top = 0.8, base = -0.5, bow = 0.1 * unit;
    double rise = fmin(0.2, 0.5 * unit), side = top - base;
    int tip = (int)lround(extra * unit / (unit + 2 * side));
    int right_side = (extra - tip + 1) / 2, left_side = extra - tip - right_side;
    double right_y0 = t == teeth - 1 ? -1 : base, left_y0 = t == 0 ? -1 : base;
    if (t < teeth - 1)
        rp_put(xy, count, right, base);
    rp_comb_side(xy, count, right, right_y0, top, -bow, right_side);
    rp_comb_tip(xy, count, left, right, top, rise, tip);
    rp_comb_side(xy, count, left, top, left_y0, bow, left_side);
    if (t > 0)
        rp_put(xy, count, left, base);
}

/* Bar along the bottom, `teeth` teeth pointing up, in [-1, 1]^2,
 * starting at the bottom-left corner. Corners take 4 * teeth vertices;
 * the rest go along the teeth. */
static inline int rp_comb(double *xy, int n, int teeth)
{
    if (teeth < 1 || n < 4 * teeth)
        return -1;
    int extra = n - 4 * teeth, count = 0;
    rp_put(xy, &count, -1, -1);
    rp_put(xy, &count, 1, -1);
    for (int t = teeth - 1; t >= 0; t--) /* right to left */
        rp_comb_tooth(xy, &count, t, teeth,
                      extra / teeth + (teeth - 1 - t < extra % teeth));
    return rp_finish(xy, n);
}

/* Index of (x, y) along a Hilbert curve over a 2^bits grid: neighbours in
 * this order are near in the plane, so the first tour has few crossings. */
static inline uint64_t rp_hilbert(uint32_t x, uint32_t y, int bits)
{
    uint64_t d = 0;
    for (uint32_t s = 1u << (bits - 1); s > 0; s >>= 1) {
        uint32_t rx = (x & s) != 0, ry = (y & s) != 0;
        d += (uint64_t)s * s * ((3 * rx) ^ ry);
        if (ry == 0) {
            if (rx == 1) {
                x = s - 1 - (x & (s - 1)) + (x & ~(s - 1));
                y = s - 1 - (y & (s - 1)) + (y & ~(s - 1));
            }
            uint32_t tmp = x;
            x = y;
            y = tmp;
        }
    }
    return d;
}

typedef struct rp_keyed {
    uint64_t key;
    double x, y;
} rp_keyed;

static inline int rp_keyed_cmp(const void *a, const void *b)
{
    uint64_t ka = ((const rp_keyed *)a)->key, kb = ((const rp_keyed *)b)->key;
    return (ka > kb) - (ka < kb);
}

/* n random points of a 2^16 grid in [-1, 1]^2, in Hilbert order (small n:
 * random order, for more tangled and varied shapes). Returns -1 when two
 * points coincide. */
static inline int rp_random_tour(double *xy, int n, rp_rng *rng)
{
    const int bits = 16;
    rp_keyed *pts = (rp_keyed *)malloc(sizeof(rp_keyed) * n);
    if (!pts)
        return -1;
    for (int i = 0; i < n; i++) {
        uint32_t gx = (uint32_t)rp_below(rng, 1u << bits);
        uint32_t gy = (uint32_t)rp_below(rng, 1u << bits);
        pts[i].key = ((uint64_t)gx << bits) | gy;
        pts[i].x = gx / 32768.0 - 1.0; /* exact: 2^-15 steps */
        pts[i].y = gy / 32768.0 - 1.0;
    }
    int result = 0;
    qsort(pts, n, sizeof(rp_keyed), rp_keyed_cmp);
    for (int i = 1; i < n; i++)
        if (pts[i].key == pts[i - 1].key)
            result = -1;
    for (int i = 0; i < n; i++) {
        uint32_t gx = (uint32_t)(pts[i].key >> bits), gy = pts[i].key & 0xFFFF;
        pts[i].key = n > 64 ? rp_hilbert(gx, gy, bits) : rp_next(rng);
    }
    qsort(pts, n, sizeof(rp_keyed), rp_keyed_cmp);
    for (int i = 0; i < n; i++) {
        xy[2 * i] = pts[i].x;
        xy[2 * i + 1] = pts[i].y;
    }
    free(pts);
    return result;
}

/* One sweep of 2-opt: every pair of edges that meet is replaced by the
 * other pairing that reverses the path between them. Each move shortens
 * the tour when the edges cross properly. Returns the number of moves. */
static inline long rp_untangle_pass(double *xy, int n)
{
    long moves = 0;
    for (int i = 0; i < n; i++)
        for (int j = i + 2; j < n; j++) {
            if (i == 0 && j == n - 1)
                continue; /* neighbours through the closing edge */
            const double *a = xy + 2 * i, *b = xy + 2 * (i + 1);
            const double *c = xy + 2 * j, *d = xy + 2 * ((j + 1) % n);
            if (rp_segments_meet(a, b, c, d)) {
                rp_reverse(xy, i + 1, j);
                moves++;
            }
        }
    return moves;
}

static inline int rp_random_simple(double *xy, int n, uint64_t seed)
{
    if (n < 3)
        return -1;
    rp_rng rng = {seed};
    for (int attempt = 0; attempt < 100; attempt++) {
        if (rp_random_tour(xy, n, &rng) != 0)
            continue;
        /* touching (not crossing) edges may not shorten: bound the work */
        for (int pass = 0; pass < 4 * n + 100; pass++)
            if (rp_untangle_pass(xy, n) == 0)
                break;
        if (rp_finish(xy, n) == 0 && !rp_has_flat_corner(xy, n))
            return 0;
    }
    return -1;
}

/* ---- random polygons by space partitioning ------------------------------ */

/* Points of the 2^24 grid as integers (x / 2^24 is the coordinate). A chain
 * from a to b through a set S that lies in a convex region K holding a and
 * b: pick c in S and a line through c meeting segment ab strictly inside;
 * it cuts K into a's part and b's, and the chains a..c and c..b are made
 * in those parts, so they meet only at c (Auer and Held, "Heuristics for
 * the generation of random polygons", 1996). Integer arithmetic keeps
 * every side test exact. */
typedef struct rp_ipt {
    int64_t x, y;
} rp_ipt;

#define RP_SPA_D 1048576 /* the cut's point on ab: a + (b - a) k / RP_SPA_D */

static inline int rp_isign(__int128 v)
{
    return (v > 0) - (v < 0);
}

static inline int rp_iorient(rp_ipt a, rp_ipt b, rp_ipt c)
{
    return rp_isign((__int128)(b.x - a.x) * (c.y - a.y) - (__int128)(b.y - a.y) * (c.x - a.x));
}

/* Side of q against the line through c and a + (b - a) k / RP_SPA_D. */
static inline int rp_cut_side(rp_ipt a, rp_ipt b, int64_t k, rp_ipt c, rp_ipt q)
{
    __int128 px = (__int128)a.x * (RP_SPA_D - k) + (__int128)b.x * k;
    __int128 py = (__int128)a.y * (RP_SPA_D - k) + (__int128)b.y * k;
    __int128 cx = (__int128)c.x * RP_SPA_D, cy = (__int128)c.y * RP_SPA_D;
    __int128 qx = (__int128)q.x * RP_SPA_D, qy = (__int128)q.y * RP_SPA_D;
    return rp_isign((px - cx) * (qy - cy) - (py - cy) * (qx - cx));
}

/* Appends to out (at *len) the chain strictly between a and b through the
 * points of s[0..m-1]. Returns -1 when it cannot cut (every candidate on
 * a line it needs to avoid: the caller draws new points). */
static inline int rp_spa_chain(const rp_ipt *pt, int32_t *s, int m, rp_ipt a, rp_ipt b, int32_t *out,
                               int *len, rp_rng *rng)
{
    while (m > 0) {
        int split = -1;
        int64_t k = 0;
        for (int tries = 0; tries < 16 && split < 0; tries++) {
            int ci = (int)rp_below(rng, (uint64_t)m);
            rp_ipt c = pt[s[ci]];
            if (rp_iorient(a, b, c) == 0) continue;
            k = 1 + (int64_t)rp_below(rng, RP_SPA_D - 1);
            int side_a = rp_cut_side(a, b, k, c, a), ok = side_a != 0;
            for (int i = 0; i < m && ok; i++) ok = i == ci || rp_cut_side(a, b, k, c, pt[s[i]]) != 0;
            if (!ok) continue;
            int32_t t = s[ci];
            s[ci] = s[m - 1], s[m - 1] = t;
            int lo = 0; /* [0, lo): a's side */
            for (int i = 0; i < m - 1; i++)
                if (rp_cut_side(a, b, k, c, pt[s[i]]) == side_a) t = s[i], s[i] = s[lo], s[lo++] = t;
            split = lo;
        }
        if (split < 0) return -1;
        int32_t c = s[m - 1];
        /* a's side first (recursion), then c, then b's side (this loop) */
        if (rp_spa_chain(pt, s, split, a, pt[c], out, len, rng) != 0) return -1;
        out[(*len)++] = c;
        s += split, m -= split + 1, a = pt[c];
    }
    return 0;
}

static inline int rp_random_spa(double *xy, int n, uint64_t seed)
{
    if (n < 3) return -1;
    rp_rng rng = {seed};
    rp_ipt *pt = (rp_ipt *)malloc(sizeof(rp_ipt) * n);
    int32_t *s = (int32_t *)malloc(sizeof(int32_t) * n), *out = (int32_t *)malloc(sizeof(int32_t) * n);
    rp_keyed *keys = (rp_keyed *)malloc(sizeof(rp_keyed) * n);
    int result = -1;
    for (int attempt = 0; attempt < 100 && pt && s && out && keys && result != 0; attempt++) {
        for (int i = 0; i < n; i++) {
            pt[i].x = (int64_t)rp_below(&rng, 1u << 25) - (1 << 24);
            pt[i].y = (int64_t)rp_below(&rng, 1u << 25) - (1 << 24);
            keys[i].key = (uint64_t)(pt[i].x + (1 << 24)) << 26 | (uint64_t)(pt[i].y + (1 << 24));
        }
        qsort(keys, n, sizeof(rp_keyed), rp_keyed_cmp);
        int distinct = 1;
        for (int i = 1; i < n; i++) distinct &= keys[i].key != keys[i - 1].key;
        if (!distinct) continue;
        /* the line through points 0 and 1 parts the rest (none on it) */
        int on_line = 0, left = 0, right = n - 3;
        for (int i = 2; i < n; i++) {
            int o = rp_iorient(pt[0], pt[1], pt[i]);
            on_line |= o == 0;
            if (o > 0) s[left++] = i;
            else s[right--] = i;
        }
        if (on_line) continue;
        int len = 0;
        out[len++] = 0;
        if (rp_spa_chain(pt, s, left, pt[0], pt[1], out, &len, &rng) != 0) continue;
        out[len++] = 1;
        if (rp_spa_chain(pt, s + left, n - 2 - left, pt[1], pt[0], out, &len, &rng) != 0) continue;
        for (int i = 0; i < n; i++) {
            xy[2 * i] = (double)pt[out[i]].x / RP_GRID;
            xy[2 * i + 1] = (double)pt[out[i]].y / RP_GRID;
        }
        if (rp_signed_area2(xy, n) < 0) rp_reverse(xy, 1, n - 1); /* keeps vertex 0 first */
        if (!rp_has_flat_corner(xy, n) && (n > 4096 || rp_is_simple(xy, n))) result = 0;
    }
    free(pt), free(s), free(out), free(keys);
    return result;
}

#endif
