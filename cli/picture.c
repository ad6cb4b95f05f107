#include "picture.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "utf8_text.h"

/* Layout in pixels. Very wide polygons are limited in width instead of
 * height so one panel cannot dwarf the others. */
static const double PANEL_HEIGHT = 360.0;
static const double PANEL_MAX_WIDTH = 720.0;
static const double MARGIN = 20.0;
static const double CAPTION_HEIGHT = 40.0;
static const double CAPTION_MIN_WIDTH = 240.0; /* a panel is at least this wide */
/* Many panels (a morph of hundreds of frames) wrap into rows this wide. */
static const double ROW_MAX_WIDTH = 8192.0;
static const double POOR_ANGLE_DEG = 20.0;
static const double DEGREES_PER_RADIAN = 57.295779513082321;

const style_paint picture_styles[STYLE_COUNT] = {
    [STYLE_POOR] = {1, 0xfdae61, 0.0, 0},
    [STYLE_WORST] = {1, 0xd7191c, 0.0, 0},
    [STYLE_EDGES] = {0, 0x555555, 0.4, 0},
    [STYLE_BOUNDARY] = {0, 0x000000, 1.6, 1},
    [STYLE_STEINER] = {0, 0x2166ac, 3.0, 1},
};

/* Maps one geometry into its panel. */
typedef struct panel {
    const double *xy;
    double min_x, max_y, scale;
    double left, top, width, height; /* in pixels */
} panel;

static panel make_panel(const double *xy, size_t count, double left, double top)
{
    double min_x = INFINITY, max_x = -INFINITY, min_y = INFINITY, max_y = -INFINITY;
    for (size_t v = 0; v < count; v++) {
        min_x = fmin(min_x, xy[2 * v]);
        max_x = fmax(max_x, xy[2 * v]);
        min_y = fmin(min_y, xy[2 * v + 1]);
        max_y = fmax(max_y, xy[2 * v + 1]);
    }
    double width = max_x - min_x, height = max_y - min_y;
    /* A valid polygon has positive area, so both extents are positive; the
     * guard only keeps a degenerate input from dividing by zero. */
    double scale = PANEL_HEIGHT / (height > 0 ? height : 1.0);
    if (width * scale > PANEL_MAX_WIDTH) scale = PANEL_MAX_WIDTH / width;
    panel p = {xy, min_x, max_y, scale, left, top, width * scale, height * scale};
    return p;
}

/* Growing the arrays; each returns -1 out of memory. */
static int add_step(picture *pic, step_kind kind, const panel *p, size_t v)
{
    if (pic->step_count == pic->step_capacity) {
        size_t capacity = pic->step_capacity ? 2 * pic->step_capacity : 256;
        path_step *steps = realloc(pic->steps, capacity * sizeof *steps);
        if (!steps) return -1;
        pic->steps = steps, pic->step_capacity = capacity;
    }
    path_step step = {kind, 0, 0};
    if (p) {
        step.x = p->left + (p->xy[2 * v] - p->min_x) * p->scale;
        step.y = p->top + MARGIN + (p->max_y - p->xy[2 * v + 1]) * p->scale;
    }
    pic->steps[pic->step_count++] = step;
    return 0;
}

static int begin_layer(picture *pic, picture_style style)
{
    if (pic->layer_count == pic->layer_capacity) {
        size_t capacity = pic->layer_capacity ? 2 * pic->layer_capacity : 16;
        picture_layer *layers = realloc(pic->layers, capacity * sizeof *layers);
        if (!layers) return -1;
        pic->layers = layers, pic->layer_capacity = capacity;
    }
    pic->layers[pic->layer_count++] = (picture_layer){pic->panel_count, style, pic->step_count, 0};
    return 0;
}

/* Closes the open layer; an empty one is dropped. */
static void end_layer(picture *pic)
{
    picture_layer *layer = &pic->layers[pic->layer_count - 1];
    layer->count = pic->step_count - layer->first;
    if (layer->count == 0) pic->layer_count--;
}

/* Keeps a copy of text, repaired (utf8_text.h): file names can hold any
 * bytes, and cairo needs valid UTF-8. */
static int add_text(picture *pic, double x, double y, const char *text)
{
    if (pic->text_count == pic->text_capacity) {
        size_t capacity = pic->text_capacity ? 2 * pic->text_capacity : 16;
        picture_text *texts = realloc(pic->texts, capacity * sizeof *texts);
        if (!texts) return -1;
        pic->texts = texts, pic->text_capacity = capacity;
    }
    char *copy = utf8_repaired_copy(text, 1);
    if (!copy) return -1;
    pic->texts[pic->text_count++] = (picture_text){pic->panel_count, x, y, copy};
    return 0;
}

/* Angle at a in triangle a b c, in degrees. */
static double corner_angle_deg(const double *a, const double *b, const double *c)
{
    double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
    return atan2(fabs(ux * vy - uy * vx), ux * vx + uy * vy) * DEGREES_PER_RADIAN;
}

/* Smallest angle of every triangle in one geometry; returns the index of the
 * worst triangle. */
static size_t smallest_angles(const double *xy, const int32_t *triangles,
                              size_t count, double *angles)
{
    size_t worst = 0;
    for (size_t t = 0; t < count; t++) {
        const double *a = xy + 2 * triangles[3 * t], *b = xy + 2 * triangles[3 * t + 1],
                     *c = xy + 2 * triangles[3 * t + 2];
        angles[t] = fmin(corner_angle_deg(a, b, c),
                         fmin(corner_angle_deg(b, c, a), corner_angle_deg(c, a, b)));
        if (angles[t] < angles[worst]) worst = t;
    }
    return worst;
}

static int triangle_outline(picture *pic, const panel *p, const int32_t *t)
{
    return add_step(pic, STEP_MOVE, p, (size_t)t[0]) || add_step(pic, STEP_LINE, p, (size_t)t[1]) ||
           add_step(pic, STEP_LINE, p, (size_t)t[2]) || add_step(pic, STEP_CLOSE, NULL, 0);
}

/* All triangles whose smallest angle is below POOR_ANGLE_DEG, the worst one
 * excepted (it gets its own colour), then the worst. */
static int add_highlights(picture *pic, const panel *p, const int32_t *triangles, size_t count,
                          const double *angles, size_t worst)
{
    if (begin_layer(pic, STYLE_POOR)) return -1;
    for (size_t t = 0; t < count; t++) {
        if (t == worst || !(angles[t] < POOR_ANGLE_DEG)) continue;
        if (triangle_outline(pic, p, triangles + 3 * t)) return -1;
    }
    end_layer(pic);
    if (count == 0) return 0;
    if (begin_layer(pic, STYLE_WORST) || triangle_outline(pic, p, triangles + 3 * worst)) return -1;
    end_layer(pic);
    return 0;
}

/* Every interior edge once: it appears in two triangles, as (a, b) in one
 * and (b, a) in the other, so draw it where a < b. Boundary edges drawn
 * here too end under the thick boundary. */
static int add_edges(picture *pic, const panel *p, const int32_t *triangles, size_t count)
{
    if (begin_layer(pic, STYLE_EDGES)) return -1;
    for (size_t t = 0; t < count; t++) {
        for (int i = 0; i < 3; i++) {
            int32_t a = triangles[3 * t + i], b = triangles[3 * t + (i + 1) % 3];
            if (a > b) continue;
            if (add_step(pic, STEP_MOVE, p, (size_t)a) || add_step(pic, STEP_LINE, p, (size_t)b))
                return -1;
        }
    }
    end_layer(pic);
    return 0;
}

static int compare_edges(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

/* The boundary: the edges of one triangle only, chained into closed
 * loops (the outer loop and every hole). */
static int add_boundary(picture *pic, const panel *p, const int32_t *triangles, size_t count,
                        size_t vertices)
{
    int64_t *edges = malloc((3 * count + 1) * sizeof *edges);
    int32_t *next = malloc((vertices + 1) * sizeof *next);
    int failed = !edges || !next || begin_layer(pic, STYLE_BOUNDARY);
    if (failed) {
        free(edges), free(next);
        return -1;
    }
    for (size_t v = 0; v < vertices; v++) next[v] = -1;
    for (size_t c = 0; c < 3 * count; c++)
        edges[c] = (int64_t)triangles[c] * (int64_t)vertices + triangles[c - c % 3 + (c + 1) % 3];
    qsort(edges, 3 * count, sizeof *edges, compare_edges);
    for (size_t c = 0; c < 3 * count; c++) {
        int64_t a = edges[c] / (int64_t)vertices, b = edges[c] % (int64_t)vertices;
        int64_t twin = b * (int64_t)vertices + a;
        if (!bsearch(&twin, edges, 3 * count, sizeof *edges, compare_edges)) next[a] = (int32_t)b;
    }
    for (size_t start = 0; start < vertices && !failed; start++) {
        if (next[start] < 0) continue;
        failed = add_step(pic, STEP_MOVE, p, start);
        for (int32_t v = next[start], w; !failed && v >= 0 && (size_t)v != start; v = w) {
            failed = add_step(pic, STEP_LINE, p, (size_t)v);
            w = next[v], next[v] = -1;
        }
        next[start] = -1;
        failed = failed || add_step(pic, STEP_CLOSE, NULL, 0);
    }
    if (!failed) end_layer(pic);
    free(edges), free(next);
    return failed ? -1 : 0;
}

static int add_steiner(picture *pic, const panel *p, size_t n, size_t vertices)
{
    if (begin_layer(pic, STYLE_STEINER)) return -1;
    for (size_t v = n; v < vertices; v++)
        if (add_step(pic, STEP_DOT, p, v)) return -1;
    end_layer(pic);
    return 0;
}

static int add_caption(picture *pic, const panel *p, const char *name, size_t n,
                       size_t steiner, double min_angle)
{
    double y = p->top + MARGIN + PANEL_HEIGHT + 16.0;
    char line[128];
    snprintf(line, sizeof line, "n=%zu, Steiner %zu, min angle %.1f\u00b0", n, steiner, min_angle);
    return add_text(pic, p->left, y, name) || add_text(pic, p->left, y + 16.0, line) ? -1 : 0;
}

static int add_panel(picture *pic, const panel *p, const picture_meshes *meshes,
                     const char *name, double *angles)
{
    const int32_t *triangles = meshes->triangles;
    size_t count = meshes->count;
    size_t worst = smallest_angles(p->xy, triangles, count, angles);
    if (add_highlights(pic, p, triangles, count, angles, worst) ||
        add_edges(pic, p, triangles, count) ||
        add_boundary(pic, p, triangles, count, meshes->vertices) ||
        add_steiner(pic, p, meshes->n, meshes->vertices))
        return -1;
    return add_caption(pic, p, name, meshes->n, meshes->vertices - meshes->n,
                       count > 0 ? angles[worst] : 0.0);
}

int picture_of_meshes(picture *pic, const picture_meshes *meshes, cli_error *error)
{
    memset(pic, 0, sizeof *pic);
    double *angles = malloc((meshes->count + 1) * sizeof *angles);
    int failed = !angles;
    const double row_height = MARGIN + PANEL_HEIGHT + CAPTION_HEIGHT;
    double left = MARGIN, top = 0, width = MARGIN;
    for (size_t g = 0; g < meshes->k && !failed; g++) {
        panel p = make_panel(meshes->xy[g], meshes->vertices, left, top);
        double advance = fmax(p.width, CAPTION_MIN_WIDTH) + MARGIN;
        if (left > MARGIN && left + advance > ROW_MAX_WIDTH) { /* next row */
            left = MARGIN, top += row_height;
            p = make_panel(meshes->xy[g], meshes->vertices, left, top);
        }
        failed = add_panel(pic, &p, meshes, meshes->names[g], angles);
        pic->panel_count++;
        left += advance;
        width = fmax(width, left);
    }
    free(angles);
    if (failed) {
        picture_free(pic);
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    pic->width = ceil(width);
    pic->height = top + row_height + MARGIN;
    return CLI_EXIT_OK;
}

int picture_of_result(picture *pic, const cm_result *result, const char *const *names,
                      cli_error *error)
{
    size_t k = cm_result_num_geometries(result);
    const double **xy = malloc((k ? k : 1) * sizeof *xy);
    if (!xy) {
        memset(pic, 0, sizeof *pic);
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    for (size_t g = 0; g < k; g++) xy[g] = cm_result_vertices(result, g);
    picture_meshes meshes = {cm_result_triangles(result), cm_result_num_triangles(result),
                             cm_result_stats(result)->n, cm_result_num_vertices(result),
                             xy, names, k};
    int code = picture_of_meshes(pic, &meshes, error);
    free(xy);
    return code;
}

void picture_free(picture *pic)
{
    for (size_t i = 0; i < pic->text_count; i++) free(pic->texts[i].text);
    free(pic->texts);
    free(pic->steps);
    free(pic->layers);
    memset(pic, 0, sizeof *pic);
}
