/* Glyph outlines read with FreeType and resampled by arc length, shared by
 * cm_gen_pairs and cm_font_soak so both see the same polygons.
 *
 *   glyph_outline(face, code, &o)  the outer contour (largest area) of a
 *                                  glyph, curves flattened, counter-clockwise,
 *                                  sharp corners marked
 *   glyph_contours(face, code, o, max)  every contour of it, the largest
 *                                  first, then top to bottom
 *   resample(&o, n, xy)            n points along it: every corner kept, the
 *                                  pieces between sampled evenly by arc
 *                                  length, snapped to the grid of
 *                                  random_polygons.h and checked simple
 *   resample_arclength(&o, n, xy)  n points at equal arc length from the
 *                                  outline's bottom-left point (corners
 *                                  not kept): the plain arc-length
 *                                  correspondence between two outlines
 */
#ifndef CM_BENCH_GLYPH_OUTLINE_H
#define CM_BENCH_GLYPH_OUTLINE_H

#include <math.h>
#include <stdlib.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include "random_polygons.h"

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
static inline int glyph_outline(FT_Face face, unsigned long code, outline *o)
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

/* Every contour of a glyph (at most max), each counter-clockwise with its
 * corners marked: the largest first (the outer loop of a glyph with
 * holes), then the others from the top down (by their centroids' y, then
 * x), so that the holes of two glyphs pair up in reading order. Returns
 * the number of contours, -1 on failure. */
static inline int glyph_contours(FT_Face face, unsigned long code, outline *out, int max)
{
    FT_Outline_Funcs funcs = {on_move, on_line, on_conic, on_cubic, 0, 0};
    glyph_path p = {0};
    p.scale = 1.0 / face->units_per_EM;
    int count = 0;
    double key[64];
    if (max > 64 || FT_Load_Char(face, code, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) != 0 ||
        face->glyph->format != FT_GLYPH_FORMAT_OUTLINE ||
        FT_Outline_Decompose(&face->glyph->outline, &funcs, &p) != 0 || p.contours > max)
        goto fail;
    for (int c = 0; c < p.contours; c++, count++) {
        outline *o = &out[count];
        if (take_contour(&p, c, o) != 0) goto fail;
        double area = contour_area2(o->xy, o->count);
        if (area < 0) reverse_outline(o);
        mark_corners(o);
        if (count > 0 && fabs(area) > contour_area2(out[0].xy, out[0].count)) {
            outline t = out[0];
            out[0] = *o, *o = t;
        }
    }
    for (int c = 1; c < count; c++) { /* the holes: top to bottom, then left to right */
        double cx = 0, cy = 0;
        for (int i = 0; i < out[c].count; i++) cx += out[c].xy[2 * i], cy += out[c].xy[2 * i + 1];
        key[c] = -(cy / out[c].count) * 1e3 + cx / out[c].count;
    }
    for (int c = 2; c < count; c++) /* insertion sort of the holes */
        for (int d = c; d > 1 && key[d] < key[d - 1]; d--) {
            outline t = out[d];
            out[d] = out[d - 1], out[d - 1] = t;
            double k = key[d];
            key[d] = key[d - 1], key[d - 1] = k;
        }
    path_free(&p);
    return count;
fail:
    for (int c = 0; c < count; c++) outline_free(&out[c]);
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

/* n points at equal arc length along the whole outline, the first at its
 * bottom-left point (slid by a fraction of the spacing when a sampling is
 * not simple after snapping). Two outlines sampled so correspond by
 * normalised arc length from their bottom-left points. Inline: cm_font_soak
 * includes this header and does not use it. */
static inline int resample_arclength(const outline *o, int n, double *xy)
{
    int start = bottom_left(o->xy, o->count);
    double total = piece_len(o, start, start);
    for (int attempt = 0; attempt < 8; attempt++) {
        for (int j = 0; j < n; j++)
            point_along(o, start, total * (j + attempt / 8.0) / n, xy + 2 * j);
        rp_snap_all(xy, n);
        if (rp_is_simple(xy, n) && rp_signed_area2(xy, n) > 0)
            return 0;
    }
    return -1;
}

#endif
