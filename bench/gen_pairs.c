/* cm_gen_pairs: writes the demo and benchmark polygon pairs as .xy files.
 *
 *   cm_gen_pairs --out DIR [--set demo|bench] [--font PATH]
 *
 * Each polygon goes to DIR/NAME_a.xy, DIR/NAME_b.xy (and NAME_c.xy for a
 * triple), one "x y" line per vertex, counter-clockwise, vertices in
 * correspondence by line number. DIR/pairs.txt lists one pair per line:
 * the pair name, then its file names.
 *
 * Glyph outlines come from a TrueType font through FreeType: the outer
 * contour of a glyph, curves flattened, then resampled by arc length to n
 * points keeping the sharp corners, so two glyphs get the same n. The other
 * shapes come from tests/core/random_polygons.h. Every polygon written is
 * checked simple with the exact brute-force test there.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include "random_polygons.h"

#define DEFAULT_FONT "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
#define MAX_K 3
#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* ---- flattened glyph outlines ------------------------------------------ */

/* All contours of one glyph as polylines, in em units. node[i] marks the
 * on-curve points of the font, the only places a corner can be. */
typedef struct glyph_path {
    double *xy;
    unsigned char *node;
    int count, cap;
    int *start; /* first point of each contour */
    int contours, contour_cap;
    double scale; /* font units -> em */
    double pen[2];
} glyph_path;

static int path_grow(glyph_path *p)
{
    int cap = p->cap ? 2 * p->cap : 256;
    double *xy = realloc(p->xy, sizeof(double) * 2 * cap);
    if (!xy)
        return -1;
    p->xy = xy;
    unsigned char *node = realloc(p->node, cap);
    if (!node)
        return -1;
    p->node = node;
    p->cap = cap;
    return 0;
}

static int path_add(glyph_path *p, double x, double y, int node)
{
    if (p->count == p->cap && path_grow(p) != 0)
        return -1;
    p->xy[2 * p->count] = x;
    p->xy[2 * p->count + 1] = y;
    p->node[p->count++] = (unsigned char)node;
    p->pen[0] = x;
    p->pen[1] = y;
    return 0;
}

static void path_free(glyph_path *p)
{
    free(p->xy);
    free(p->node);
    free(p->start);
}

static int on_move(const FT_Vector *to, void *user)
{
    glyph_path *p = user;
    if (p->contours == p->contour_cap) {
        int cap = p->contour_cap ? 2 * p->contour_cap : 8;
        int *start = realloc(p->start, sizeof(int) * cap);
        if (!start)
            return 1;
        p->start = start;
        p->contour_cap = cap;
    }
    p->start[p->contours++] = p->count;
    return path_add(p, to->x * p->scale, to->y * p->scale, 1) ? 1 : 0;
}

static int on_line(const FT_Vector *to, void *user)
{
    glyph_path *p = user;
    return path_add(p, to->x * p->scale, to->y * p->scale, 1) ? 1 : 0;
}

/* Enough steps that a curve turns only a few degrees per step. */
static int curve_steps(const double *ctrl, int points)
{
    double len = 0;
    for (int i = 1; i < points; i++)
        len += hypot(ctrl[2 * i] - ctrl[2 * i - 2], ctrl[2 * i + 1] - ctrl[2 * i - 1]);
    int steps = (int)ceil(len / 0.005);
    return steps < 8 ? 8 : steps > 64 ? 64 : steps;
}

/* Flattens a Bezier curve of degree points - 1 (2 or 3) from the pen. */
static int add_bezier(glyph_path *p, const double *ctrl, int points)
{
    int steps = curve_steps(ctrl, points);
    for (int s = 1; s <= steps; s++) {
        double t = (double)s / steps, u = 1 - t, x, y;
        if (points == 3) {
            x = u * u * ctrl[0] + 2 * u * t * ctrl[2] + t * t * ctrl[4];
            y = u * u * ctrl[1] + 2 * u * t * ctrl[3] + t * t * ctrl[5];
        } else {
            double a = u * u * u, b = 3 * u * u * t, c = 3 * u * t * t, d = t * t * t;
            x = a * ctrl[0] + b * ctrl[2] + c * ctrl[4] + d * ctrl[6];
            y = a * ctrl[1] + b * ctrl[3] + c * ctrl[5] + d * ctrl[7];
        }
        if (path_add(p, x, y, s == steps) != 0)
            return 1;
    }
    return 0;
}

static int on_conic(const FT_Vector *c, const FT_Vector *to, void *user)
{
    glyph_path *p = user;
    double ctrl[6] = {p->pen[0], p->pen[1], c->x * p->scale, c->y * p->scale,
                      to->x * p->scale, to->y * p->scale};
    return add_bezier(p, ctrl, 3);
}

static int on_cubic(const FT_Vector *c1, const FT_Vector *c2,
                    const FT_Vector *to, void *user)
{
    glyph_path *p = user;
    double ctrl[8] = {p->pen[0], p->pen[1], c1->x * p->scale, c1->y * p->scale,
                      c2->x * p->scale, c2->y * p->scale,
                      to->x * p->scale, to->y * p->scale};
    return add_bezier(p, ctrl, 4);
}

/* One closed contour: no repeated closing point, counter-clockwise.
 * corner[i] marks the sharp corners. */
typedef struct outline {
    double *xy;
    unsigned char *corner;
    int count;
} outline;

static void outline_free(outline *o)
{
    free(o->xy);
    free(o->corner);
}

static double contour_area2(const double *xy, int count)
{
    return rp_signed_area2(xy, count);
}

/* Copies contour c of the path, dropping repeated points. */
static int take_contour(const glyph_path *p, int c, outline *o)
{
    int first = p->start[c];
    int end = c + 1 < p->contours ? p->start[c + 1] : p->count;
    o->xy = malloc(sizeof(double) * 2 * (end - first));
    o->corner = calloc(end - first, 1);
    o->count = 0;
    if (!o->xy || !o->corner)
        return -1;
    for (int i = first; i < end; i++) {
        const double *q = p->xy + 2 * i;
        double *last = o->xy + 2 * (o->count - 1);
        if (o->count > 0 && q[0] == last[0] && q[1] == last[1]) {
            o->corner[o->count - 1] |= p->node[i];
            continue;
        }
        o->xy[2 * o->count] = q[0];
        o->xy[2 * o->count + 1] = q[1];
        o->corner[o->count++] = p->node[i];
    }
    while (o->count > 1 && o->xy[0] == o->xy[2 * o->count - 2] &&
           o->xy[1] == o->xy[2 * o->count - 1])
        o->count--; /* the contour closes onto its first point */
    return o->count >= 3 ? 0 : -1;
}

/* Keeps the node flag only where the outline turns by more than 20 degrees:
 * smooth joins of two curves are not corners. */
static void mark_corners(outline *o)
{
    int m = o->count;
    for (int i = 0; i < m; i++) {
        if (!o->corner[i])
            continue;
        const double *a = o->xy + 2 * ((i + m - 1) % m), *b = o->xy + 2 * i;
        const double *c = o->xy + 2 * ((i + 1) % m);
        double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - b[0], vy = c[1] - b[1];
        double cosine = (ux * vx + uy * vy) / (hypot(ux, uy) * hypot(vx, vy));
        o->corner[i] = cosine < cos(20.0 * RP_PI / 180.0);
    }
}

static void reverse_outline(outline *o)
{
    rp_reverse(o->xy, 0, o->count - 1);
    for (int i = 0, j = o->count - 1; i < j; i++, j--) {
        unsigned char t = o->corner[i];
        o->corner[i] = o->corner[j];
        o->corner[j] = t;
    }
}

/* The outer contour of a glyph (largest area), counter-clockwise. */
static int glyph_outline(FT_Face face, unsigned long code, outline *o)
{
    FT_Outline_Funcs funcs = {on_move, on_line, on_conic, on_cubic, 0, 0};
    glyph_path p = {0};
    p.scale = 1.0 / face->units_per_EM;
    int best = -1;
    double best_area = 0;
    if (FT_Load_Char(face, code, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) != 0 ||
        face->glyph->format != FT_GLYPH_FORMAT_OUTLINE ||
        FT_Outline_Decompose(&face->glyph->outline, &funcs, &p) != 0)
        goto fail;
    for (int c = 0; c < p.contours; c++) {
        int end = c + 1 < p.contours ? p.start[c + 1] : p.count;
        double area = fabs(contour_area2(p.xy + 2 * p.start[c], end - p.start[c]));
        if (area > best_area) {
            best_area = area;
            best = c;
        }
    }
    if (best < 0 || take_contour(&p, best, o) != 0)
        goto fail;
    path_free(&p);
    if (contour_area2(o->xy, o->count) < 0)
        reverse_outline(o);
    mark_corners(o);
    return 0;
fail:
    path_free(&p);
    return -1;
}

/* ---- resampling -------------------------------------------------------- */

static double seg_len(const outline *o, int i)
{
    const double *a = o->xy + 2 * i, *b = o->xy + 2 * ((i + 1) % o->count);
    return hypot(b[0] - a[0], b[1] - a[1]);
}

/* Length of the piece from point `from` along to point `to` (wrapping;
 * from == to means the whole loop). */
static double piece_len(const outline *o, int from, int to)
{
    double len = 0;
    int i = from;
    do {
        len += seg_len(o, i);
        i = (i + 1) % o->count;
    } while (i != to);
    return len;
}

/* The point at arc length s from point `from`. */
static void point_along(const outline *o, int from, double s, double *out)
{
    int i = from;
    for (;;) {
        double l = seg_len(o, i);
        if (s <= l || l == 0) {
            const double *a = o->xy + 2 * i, *b = o->xy + 2 * ((i + 1) % o->count);
            double t = l > 0 ? s / l : 0;
            out[0] = a[0] + t * (b[0] - a[0]);
            out[1] = a[1] + t * (b[1] - a[1]);
            return;
        }
        s -= l;
        i = (i + 1) % o->count;
    }
}

/* Splits n points over the pieces in proportion to their lengths, at least
 * one (the corner itself) each: the piece whose spacing is widest gets the
 * next point. */
static void share_points(const double *len, int pieces, int n, int *count)
{
    int used = pieces;
    for (int k = 0; k < pieces; k++)
        count[k] = 1;
    for (; used < n; used++) {
        int widest = 0;
        for (int k = 1; k < pieces; k++)
            if (len[k] / count[k] > len[widest] / count[widest])
                widest = k;
        count[widest]++;
    }
}

/* Vertex nearest the bottom-left corner of the bounding box, in units of
 * the box: a start that falls in a similar place on different glyphs. */
static int bottom_left(const double *xy, int n)
{
    double lo[2] = {xy[0], xy[1]}, hi[2] = {xy[0], xy[1]};
    for (int i = 1; i < n; i++)
        for (int d = 0; d < 2; d++) {
            lo[d] = fmin(lo[d], xy[2 * i + d]);
            hi[d] = fmax(hi[d], xy[2 * i + d]);
        }
    int best = 0;
    double best_score = INFINITY;
    for (int i = 0; i < n; i++) {
        double score = (xy[2 * i] - lo[0]) / (hi[0] - lo[0]) +
                       (xy[2 * i + 1] - lo[1]) / (hi[1] - lo[1]);
        if (score < best_score) {
            best_score = score;
            best = i;
        }
    }
    return best;
}

/* n points along the outline: every corner kept, the pieces between them
 * sampled evenly by arc length. `phase` in [0, 1) slides the samples of a
 * corner-free outline, to try again when a sampling is not simple.
 * Returns -1 when there are more corners than points. */
static int resample_once(const outline *o, int n, double phase, double *xy)
{
    int pieces = 0, *at = malloc(sizeof(int) * (o->count + 1));
    int *count = malloc(sizeof(int) * (o->count + 1));
    double *len = malloc(sizeof(double) * (o->count + 1));
    int ok = at && count && len;
    for (int i = 0; ok && i < o->count; i++)
        if (o->corner[i])
            at[pieces++] = i;
    if (pieces == 0 && ok)
        at[pieces++] = 0;
    ok = ok && pieces <= n;
    for (int k = 0; ok && k < pieces; k++)
        len[k] = piece_len(o, at[k], at[(k + 1) % pieces]);
    if (ok)
        share_points(len, pieces, n, count);
    for (int k = 0, out = 0; ok && k < pieces; k++) {
        double shift = o->corner[at[k]] ? 0 : phase;
        for (int j = 0; j < count[k]; j++, out++)
            point_along(o, at[k], len[k] * (j + shift) / count[k], xy + 2 * out);
    }
    free(at);
    free(count);
    free(len);
    return ok ? 0 : -1;
}

/* Resamples to n points starting at the bottom-left and checks the result
 * (after snapping to the grid) is simple, trying a few phases. */
static int resample(const outline *o, int n, double *xy)
{
    for (int attempt = 0; attempt < 8; attempt++) {
        if (resample_once(o, n, attempt / 8.0, xy) != 0)
            return -1;
        rp_twist(xy, n, bottom_left(xy, n));
        rp_snap_all(xy, n);
        if (rp_is_simple(xy, n) && rp_signed_area2(xy, n) > 0)
            return 0;
    }
    return -1;
}

/* ---- feature-matched correspondence ----------------------------------- */

/* A user pairing two glyphs pairs their features: the corners of the glyph
 * with the fewest are matched, in order, to as many corners of each other
 * glyph (an order-preserving choice that puts corners at similar places of
 * their bounding boxes), and the points between two matched corners are
 * shared by arc length, the same count in every glyph. Without this, the
 * ends of a U's arms would meet the middle of an S's strokes and no mesh
 * could be good in both. */

enum { MAX_CORNERS = 64 };

typedef struct corner_list {
    int at[MAX_CORNERS]; /* outline point indices, in outline order */
    int count;
    double box[4];       /* x0 y0 x1 y1 of the outline */
} corner_list;

static int list_corners(const outline *o, corner_list *c)
{
    c->count = 0;
    c->box[0] = c->box[2] = o->xy[0];
    c->box[1] = c->box[3] = o->xy[1];
    for (int i = 0; i < o->count; i++) {
        for (int d = 0; d < 2; d++) {
            c->box[d] = fmin(c->box[d], o->xy[2 * i + d]);
            c->box[2 + d] = fmax(c->box[2 + d], o->xy[2 * i + d]);
        }
        if (o->corner[i]) {
            if (c->count == MAX_CORNERS)
                return -1;
            c->at[c->count++] = i;
        }
    }
    return 0;
}

/* Squared distance of two corners in units of their boxes. */
static double corner_cost(const outline *a, const corner_list *ca, int i,
                          const outline *b, const corner_list *cb, int j)
{
    double d = 0;
    for (int k = 0; k < 2; k++) {
        double u = (a->xy[2 * ca->at[i] + k] - ca->box[k]) / (ca->box[2 + k] - ca->box[k]);
        double v = (b->xy[2 * cb->at[j] + k] - cb->box[k]) / (cb->box[2 + k] - cb->box[k]);
        d += (u - v) * (u - v);
    }
    return d;
}

/* Picks, for each of the m corners of `a`, a corner of `b` (m <= its
 * count), in cyclic order, at the least total cost: a dynamic program over
 * every rotation. match[i] is the index into cb->at. */
static void match_corners(const outline *a, const corner_list *ca, const outline *b,
                          const corner_list *cb, int *match)
{
    int m = ca->count, M = cb->count;
    static double cost[MAX_CORNERS][MAX_CORNERS];
    static int from[MAX_CORNERS][MAX_CORNERS];
    double best = INFINITY;
    for (int r = 0; r < M; r++) {
        /* cost[i][j]: corners 0..i of a matched, i to b's (r + j) % M. */
        for (int i = 0; i < m; i++)
            for (int j = 0; j < M; j++) {
                cost[i][j] = INFINITY;
                if (j < i || j > M - m + i)
                    continue;
                double here = corner_cost(a, ca, i, b, cb, (r + j) % M);
                if (i == 0) {
                    if (j == 0)
                        cost[i][j] = here;
                    continue;
                }
                for (int q = i - 1; q < j; q++)
                    if (cost[i - 1][q] + here < cost[i][j]) {
                        cost[i][j] = cost[i - 1][q] + here;
                        from[i][j] = q;
                    }
            }
        for (int j = m - 1; j < M; j++) {
            if (!(cost[m - 1][j] < best))
                continue;
            best = cost[m - 1][j];
            for (int i = m - 1, q = j; i >= 0; i--) {
                match[i] = (r + q) % M;
                if (i > 0)
                    q = from[i][q];
            }
        }
    }
}

/* Samples the piece of `o` from point `from` to point `to` with `count`
 * points (the first at `from`), each corner inside the piece kept as a
 * point: the sub-pieces between corners share the count by length. */
static int sample_piece(const outline *o, int from, int to, int count, double *xy)
{
    int cut[MAX_CORNERS + 1], nc = 0;
    for (int i = from; nc <= MAX_CORNERS; i = (i + 1) % o->count) {
        if (i == from || o->corner[i])
            cut[nc++] = i;
        if ((i + 1) % o->count == to)
            break;
    }
    if (nc > count)
        return -1;
    double len[MAX_CORNERS + 1];
    int share[MAX_CORNERS + 1];
    for (int k = 0; k < nc; k++)
        len[k] = piece_len(o, cut[k], k + 1 < nc ? cut[k + 1] : to);
    share_points(len, nc, count, share);
    for (int k = 0, out = 0; k < nc; k++)
        for (int j = 0; j < share[k]; j++, out++)
            point_along(o, cut[k], len[k] * j / share[k], xy + 2 * out);
    return 0;
}

/* Resamples k outlines to n points each, in feature-matched
 * correspondence, checking each result simple. Returns -1 when the glyph
 * with the fewest corners has none (nothing to match) or a result is not
 * simple. */
static int resample_matched(const outline *o, int k, int n, double *const *xy)
{
    corner_list c[MAX_K];
    memset(c, 0, sizeof c);
    int fewest = 0;
    for (int g = 0; g < k; g++) {
        if (list_corners(&o[g], &c[g]) != 0)
            return -1;
        if (c[g].count < c[fewest].count)
            fewest = g;
    }
    int m = c[fewest].count;
    if (m == 0)
        return -1;
    int anchor[MAX_K][MAX_CORNERS]; /* point index of matched corner i */
    for (int g = 0; g < k; g++) {
        int match[MAX_CORNERS];
        if (g == fewest)
            for (int i = 0; i < m; i++)
                match[i] = i;
        else
            match_corners(&o[fewest], &c[fewest], &o[g], &c[g], match);
        for (int i = 0; i < m; i++)
            anchor[g][i] = c[g].at[match[i]];
    }
    /* Points per piece: by the mean share of the outline's length. */
    double len[MAX_CORNERS] = {0};
    int count[MAX_CORNERS];
    for (int g = 0; g < k; g++) {
        double total = piece_len(&o[g], 0, 0);
        for (int i = 0; i < m; i++)
            len[i] += piece_len(&o[g], anchor[g][i], anchor[g][(i + 1) % m]) / total;
    }
    if (m > n)
        return -1;
    share_points(len, m, n, count);
    for (int g = 0; g < k; g++) {
        for (int i = 0, out = 0; i < m; out += count[i], i++)
            if (sample_piece(&o[g], anchor[g][i], anchor[g][(i + 1) % m], count[i],
                             xy[g] + 2 * out) != 0)
                return -1;
        rp_snap_all(xy[g], n);
        if (!rp_is_simple(xy[g], n) || rp_signed_area2(xy[g], n) <= 0)
            return -1;
    }
    return 0;
}

/* ---- writing ----------------------------------------------------------- */

typedef struct writer {
    const char *dir;
    FILE *list;
    FT_Face face;
    int pairs, failures;
} writer;

static int write_xy(const char *path, const double *xy, int n)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    for (int i = 0; i < n; i++)
        fprintf(f, "%.17g %.17g\n", xy[2 * i], xy[2 * i + 1]);
    return fclose(f) == 0 ? 0 : -1;
}

/* Writes NAME_a.xy, NAME_b.xy, ... and the pairs.txt line. */
static void emit(writer *w, const char *name, double *const *polys, int k, int n)
{
    char path[4096], files[MAX_K][256];
    for (int g = 0; g < k; g++) {
        if (!rp_is_simple(polys[g], n) || rp_signed_area2(polys[g], n) <= 0) {
            fprintf(stderr, "cm_gen_pairs: %s: polygon %c is not simple\n", name, 'a' + g);
            w->failures++;
            return;
        }
        snprintf(files[g], sizeof files[g], "%s_%c.xy", name, 'a' + g);
        snprintf(path, sizeof path, "%s/%s", w->dir, files[g]);
        if (write_xy(path, polys[g], n) != 0) {
            fprintf(stderr, "cm_gen_pairs: cannot write %s: %s\n", path, strerror(errno));
            w->failures++;
            return;
        }
    }
    fprintf(w->list, "%s", name);
    for (int g = 0; g < k; g++)
        fprintf(w->list, " %s", files[g]);
    fputc('\n', w->list);
    w->pairs++;
}

/* Buffers for up to MAX_K polygons of n vertices. */
typedef struct polys {
    double *xy[MAX_K];
} polys;

static int polys_alloc(polys *p, int n)
{
    for (int g = 0; g < MAX_K; g++)
        p->xy[g] = malloc(sizeof(double) * 2 * n);
    return p->xy[0] && p->xy[1] && p->xy[2] ? 0 : -1;
}

static void polys_free(polys *p)
{
    for (int g = 0; g < MAX_K; g++)
        free(p->xy[g]);
}

static void report_failure(writer *w, const char *name, const char *why)
{
    fprintf(stderr, "cm_gen_pairs: %s: %s\n", name, why);
    w->failures++;
}

/* ---- the pairs --------------------------------------------------------- */

/* Glyphs given as a string, one character per polygon, in feature-matched
 * correspondence (each resampled on its own, from its bottom-left, when
 * that fails). */
static void glyph_set(writer *w, const char *name, const char *chars, int n)
{
    polys p = {{0}};
    outline o[MAX_K] = {{0}};
    int k = (int)strlen(chars), ok = k <= MAX_K && polys_alloc(&p, n) == 0;
    for (int g = 0; ok && g < k; g++)
        ok = glyph_outline(w->face, (unsigned char)chars[g], &o[g]) == 0;
    if (ok && resample_matched(o, k, n, p.xy) != 0)
        for (int g = 0; ok && g < k; g++)
            ok = resample(&o[g], n, p.xy[g]) == 0;
    for (int g = 0; g < k; g++)
        outline_free(&o[g]);
    if (ok)
        emit(w, name, p.xy, k, n);
    else
        report_failure(w, name, "glyph outline could not be resampled simple");
    polys_free(&p);
}

static void glyph_pair(writer *w, const char *chars, int n)
{
    char name[64];
    snprintf(name, sizeof name, "glyph_%c_%c_n%d", chars[0], chars[1], n);
    glyph_set(w, name, chars, n);
}

/* Two unrelated random stars. */
static void star_pair(writer *w, const char *name, int n, uint64_t seed)
{
    polys p;
    if (polys_alloc(&p, n) == 0 && rp_star(p.xy[0], n, 2 * seed) == 0 &&
        rp_star(p.xy[1], n, 2 * seed + 1) == 0)
        emit(w, name, p.xy, 2, n);
    else
        report_failure(w, name, "star generator failed");
    polys_free(&p);
}

/* A star against itself with the correspondence turned by `shift`. */
static void twist_pair(writer *w, const char *name, int n, int shift, uint64_t seed)
{
    polys p;
    if (polys_alloc(&p, n) == 0 && rp_star(p.xy[0], n, seed) == 0) {
        memcpy(p.xy[1], p.xy[0], sizeof(double) * 2 * n);
        rp_twist(p.xy[1], n, shift);
        emit(w, name, p.xy, 2, n);
    } else {
        report_failure(w, name, "star generator failed");
    }
    polys_free(&p);
}

/* A disc whose vertex 0 sits at `angle` (radians): lines up the starts. */
static int disc_from(double *xy, int n, double angle)
{
    if (rp_disc(xy, n) != 0)
        return -1;
    int shift = (int)lround(angle / (2 * RP_PI) * n);
    rp_twist(xy, n, shift);
    return 0;
}

static void spiral_pair(writer *w, const char *name, int n, double turns)
{
    polys p;
    if (polys_alloc(&p, n) == 0 && rp_spiral(p.xy[0], n, turns) == 0 &&
        disc_from(p.xy[1], n, 0) == 0)
        emit(w, name, p.xy, 2, n);
    else
        report_failure(w, name, "spiral generator failed");
    polys_free(&p);
}

/* The comb starts at its bottom-left corner, the disc at 225 degrees. */
static void comb_pair(writer *w, const char *name, int n, int teeth)
{
    polys p;
    if (polys_alloc(&p, n) == 0 && rp_comb(p.xy[0], n, teeth) == 0 &&
        disc_from(p.xy[1], n, 1.25 * RP_PI) == 0)
        emit(w, name, p.xy, 2, n);
    else
        report_failure(w, name, "comb generator failed");
    polys_free(&p);
}

static void random_pair(writer *w, const char *name, int n, uint64_t seed)
{
    polys p;
    if (polys_alloc(&p, n) == 0 && rp_random_simple(p.xy[0], n, seed) == 0 &&
        disc_from(p.xy[1], n, 0) == 0)
        emit(w, name, p.xy, 2, n);
    else
        report_failure(w, name, "random simple polygon generator failed");
    polys_free(&p);
}

static void demo_set(writer *w)
{
    glyph_set(w, "U_S", "US", 60);
    glyph_set(w, "U_S_C", "USC", 60);
    glyph_set(w, "L_T", "LT", 40);
    star_pair(w, "stars", 40, 1);
    twist_pair(w, "twisted_star", 30, 10, 2);
    spiral_pair(w, "spiral_disc", 80, 2);
    comb_pair(w, "comb_disc", 64, 6);
}

static void bench_set(writer *w)
{
    static const char *glyphs[] = {"US", "CG", "LT", "2Z"};
    static const int glyph_n[] = {40, 80, 160, 320};
    static const int star_n[] = {16, 50, 100, 250, 500, 1000, 2000};
    static const int spiral_n[] = {50, 100, 250, 500, 1000, 2000};
    static const double spiral_turns[] = {2, 3, 4, 5, 6, 8};
    static const int twist_n[] = {16, 100, 500};
    static const int comb_n[] = {50, 100, 250, 500, 1000};
    static const int random_n[] = {16, 50, 100, 250};
    char name[64];
    for (int g = 0; g < COUNT(glyphs); g++)
        for (int i = 0; i < COUNT(glyph_n); i++)
            glyph_pair(w, glyphs[g], glyph_n[i]);
    for (int i = 0; i < COUNT(star_n); i++) {
        snprintf(name, sizeof name, "star_n%d", star_n[i]);
        star_pair(w, name, star_n[i], (uint64_t)star_n[i]);
    }
    for (int i = 0; i < COUNT(spiral_n); i++) {
        int n = spiral_n[i];
        snprintf(name, sizeof name, "spiral_disc_n%d", n);
        spiral_pair(w, name, n, spiral_turns[i]);
    }
    for (int i = 0; i < COUNT(twist_n); i++) {
        snprintf(name, sizeof name, "twisted_star_n%d", twist_n[i]);
        twist_pair(w, name, twist_n[i], twist_n[i] / 3, 1000 + (uint64_t)twist_n[i]);
    }
    for (int i = 0; i < COUNT(comb_n); i++) {
        snprintf(name, sizeof name, "comb_disc_n%d", comb_n[i]);
        int teeth = comb_n[i] / 10 < 24 ? comb_n[i] / 10 : 24;
        comb_pair(w, name, comb_n[i], teeth);
    }
    for (int i = 0; i < COUNT(random_n); i++) {
        snprintf(name, sizeof name, "random_disc_n%d", random_n[i]);
        random_pair(w, name, random_n[i], 2000 + (uint64_t)random_n[i]);
    }
}

/* ---- main -------------------------------------------------------------- */

static int usage(void)
{
    fprintf(stderr, "usage: cm_gen_pairs --out DIR [--set demo|bench] [--font PATH]\n");
    return 2;
}

static int make_dir(const char *dir)
{
    if (mkdir(dir, 0777) == 0 || errno == EEXIST)
        return 0;
    fprintf(stderr, "cm_gen_pairs: cannot create %s: %s\n", dir, strerror(errno));
    return -1;
}

static int open_font(const char *font, FT_Library *lib, FT_Face *face)
{
    if (FT_Init_FreeType(lib) != 0) {
        fprintf(stderr, "cm_gen_pairs: FreeType failed to start\n");
        return -1;
    }
    if (FT_New_Face(*lib, font, 0, face) != 0) {
        fprintf(stderr, "cm_gen_pairs: cannot open font %s (Debian package "
                        "fonts-dejavu-core, or pass --font)\n", font);
        FT_Done_FreeType(*lib);
        return -1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    const char *out = NULL, *set = "bench", *font = DEFAULT_FONT;
    for (int i = 1; i < argc; i++) {
        if (i + 1 < argc && strcmp(argv[i], "--out") == 0)
            out = argv[++i];
        else if (i + 1 < argc && strcmp(argv[i], "--set") == 0)
            set = argv[++i];
        else if (i + 1 < argc && strcmp(argv[i], "--font") == 0)
            font = argv[++i];
        else
            return usage();
    }
    int demo = strcmp(set, "demo") == 0;
    if (!out || (!demo && strcmp(set, "bench") != 0))
        return usage();

    FT_Library lib;
    writer w = {out, NULL, NULL, 0, 0};
    char list[4096];
    snprintf(list, sizeof list, "%s/pairs.txt", out);
    if (make_dir(out) != 0 || open_font(font, &lib, &w.face) != 0)
        return 1;
    w.list = fopen(list, "w");
    if (!w.list) {
        fprintf(stderr, "cm_gen_pairs: cannot write %s: %s\n", list, strerror(errno));
        return 1;
    }
    if (demo)
        demo_set(&w);
    else
        bench_set(&w);
    int closed = fclose(w.list);
    FT_Done_Face(w.face);
    FT_Done_FreeType(lib);
    printf("cm_gen_pairs: wrote %d %s pairs to %s\n", w.pairs, set, out);
    return w.failures || closed != 0 ? 1 : 0;
}
