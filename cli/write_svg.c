#include "write_svg.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "outdir.h"

/* Layout in SVG pixels. Very wide polygons are limited in width instead of
 * height so one panel cannot dwarf the others. */
static const double PANEL_HEIGHT = 360.0;
static const double PANEL_MAX_WIDTH = 720.0;
static const double MARGIN = 20.0;
static const double CAPTION_HEIGHT = 40.0;
static const double CAPTION_MIN_WIDTH = 240.0; /* a panel is at least this wide */
static const double POOR_ANGLE_DEG = 20.0;
static const double DEGREES_PER_RADIAN = 57.295779513082321;

static const char *const STYLE =
    "<style>\n"
    ".poor{fill:#fdae61;stroke:none}\n"
    ".worst{fill:#d7191c;stroke:none}\n"
    ".edges{fill:none;stroke:#555;stroke-width:0.4}\n"
    ".boundary{fill:none;stroke:#000;stroke-width:1.6;stroke-linejoin:round}\n"
    ".steiner{fill:none;stroke:#2166ac;stroke-width:3;stroke-linecap:round}\n"
    "text{font-family:sans-serif;font-size:12px;fill:#000}\n"
    "</style>\n";

/* Maps one geometry into its panel. */
typedef struct panel {
    const double *xy;
    double min_x, max_y, scale;
    double left, width, height; /* in pixels */
} panel;

static double pixel_x(const panel *p, size_t v) { return p->left + (p->xy[2 * v] - p->min_x) * p->scale; }
static double pixel_y(const panel *p, size_t v) { return MARGIN + (p->max_y - p->xy[2 * v + 1]) * p->scale; }

static panel make_panel(const double *xy, size_t count, double left)
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
    panel p = {xy, min_x, max_y, scale, left, width * scale, height * scale};
    return p;
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

static void move_to(FILE *file, const panel *p, size_t v)
{
    fprintf(file, "M%.1f %.1f", pixel_x(p, v), pixel_y(p, v));
}

static void line_to(FILE *file, const panel *p, size_t v)
{
    fprintf(file, "L%.1f %.1f", pixel_x(p, v), pixel_y(p, v));
}

static void triangle_outline(FILE *file, const panel *p, const int32_t *t)
{
    move_to(file, p, (size_t)t[0]);
    line_to(file, p, (size_t)t[1]);
    line_to(file, p, (size_t)t[2]);
    fputc('Z', file);
}

/* One path of all triangles whose smallest angle is below POOR_ANGLE_DEG,
 * the worst one excepted (it gets its own colour). */
static void write_poor_triangles(FILE *file, const panel *p, const int32_t *triangles,
                                 size_t count, const double *angles, size_t worst)
{
    int any = 0;
    for (size_t t = 0; t < count; t++) {
        if (t == worst || !(angles[t] < POOR_ANGLE_DEG)) continue;
        if (!any) fputs("<path class=\"poor\" d=\"", file);
        any = 1;
        triangle_outline(file, p, triangles + 3 * t);
    }
    if (any) fputs("\"/>\n", file);
}

/* Every interior edge once: it appears in two triangles, as (a, b) in one
 * and (b, a) in the other, so draw it where a < b. Boundary edges drawn
 * here too end under the thick boundary. */
static void write_edges(FILE *file, const panel *p, const int32_t *triangles, size_t count)
{
    fputs("<path class=\"edges\" d=\"", file);
    for (size_t t = 0; t < count; t++) {
        for (int i = 0; i < 3; i++) {
            int32_t a = triangles[3 * t + i], b = triangles[3 * t + (i + 1) % 3];
            if (a > b) continue;
            move_to(file, p, (size_t)a);
            line_to(file, p, (size_t)b);
        }
    }
    fputs("\"/>\n", file);
}

static int compare_edges(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

/* The boundary: the edges of one triangle only, chained into closed
 * loops (the outer loop and every hole). Returns -1 out of memory. */
static int write_boundary(FILE *file, const panel *p, const int32_t *triangles, size_t count,
                          size_t vertices)
{
    int64_t *edges = malloc((3 * count + 1) * sizeof *edges);
    int32_t *next = malloc((vertices + 1) * sizeof *next);
    if (!edges || !next) {
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
    fputs("<path class=\"boundary\" d=\"", file);
    for (size_t start = 0; start < vertices; start++) {
        if (next[start] < 0) continue;
        move_to(file, p, start);
        for (int32_t v = next[start], w; v >= 0 && (size_t)v != start; v = w) {
            line_to(file, p, (size_t)v);
            w = next[v], next[v] = -1;
        }
        next[start] = -1;
        fputs("Z", file);
    }
    fputs("\"/>\n", file);
    free(edges), free(next);
    return 0;
}

/* Dots as zero-length round-capped segments: one element for all of them. */
static void write_steiner(FILE *file, const panel *p, size_t n, size_t vertices)
{
    if (vertices <= n) return;
    fputs("<path class=\"steiner\" d=\"", file);
    for (size_t v = n; v < vertices; v++) {
        move_to(file, p, v);
        fputs("h0", file);
    }
    fputs("\"/>\n", file);
}

/* Text content for XML: markup characters escaped; bytes that are not
 * well-formed UTF-8 or not allowed in XML become U+FFFD. */
static void xml_text(FILE *file, const char *text)
{
    const unsigned char *p = (const unsigned char *)text;
    size_t remaining = strlen(text);
    while (remaining > 0) {
        size_t length = utf8_sequence_length(p, remaining);
        if (length == 0 || (*p < 0x20 && *p != '\t')) {
            fputs("&#xFFFD;", file);
            length = length ? length : 1;
        } else if (*p == '&') fputs("&amp;", file);
        else if (*p == '<') fputs("&lt;", file);
        else if (*p == '>') fputs("&gt;", file);
        else fwrite(p, 1, length, file);
        p += length;
        remaining -= length;
    }
}

static void write_caption(FILE *file, const panel *p, const char *name, size_t n,
                          size_t steiner, double min_angle)
{
    double y = MARGIN + PANEL_HEIGHT + 16.0;
    fprintf(file, "<text x=\"%.2f\" y=\"%.2f\">", p->left, y);
    xml_text(file, name);
    fprintf(file, "</text>\n<text x=\"%.2f\" y=\"%.2f\">n=%zu, Steiner %zu, "
                  "min angle %.1f&#176;</text>\n",
            p->left, y + 16.0, n, steiner, min_angle);
}

static int write_panel(FILE *file, const panel *p, const svg_meshes *meshes,
                       const char *name, double *angles)
{
    const int32_t *triangles = meshes->triangles;
    size_t count = meshes->count;
    size_t worst = smallest_angles(p->xy, triangles, count, angles);
    fputs("<g>\n", file);
    write_poor_triangles(file, p, triangles, count, angles, worst);
    if (count > 0) {
        fputs("<path class=\"worst\" d=\"", file);
        triangle_outline(file, p, triangles + 3 * worst);
        fputs("\"/>\n", file);
    }
    write_edges(file, p, triangles, count);
    if (write_boundary(file, p, triangles, count, meshes->vertices)) return -1;
    write_steiner(file, p, meshes->n, meshes->vertices);
    write_caption(file, p, name, meshes->n, meshes->vertices - meshes->n,
                  count > 0 ? angles[worst] : 0.0);
    fputs("</g>\n", file);
    return 0;
}

int write_svg_meshes(const char *path, const svg_meshes *meshes, cli_error *error)
{
    size_t k = meshes->k;
    panel *panels = malloc((k ? k : 1) * sizeof *panels);
    double *angles = malloc((meshes->count + 1) * sizeof *angles);
    if (!panels || !angles) {
        free(panels);
        free(angles);
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    double left = MARGIN;
    for (size_t g = 0; g < k; g++) {
        panels[g] = make_panel(meshes->xy[g], meshes->vertices, left);
        left += fmax(panels[g].width, CAPTION_MIN_WIDTH) + MARGIN;
    }
    int code = CLI_EXIT_INTERNAL;
    FILE *file = output_open(path, error);
    if (file) {
        double width = ceil(left), height = MARGIN + PANEL_HEIGHT + CAPTION_HEIGHT + MARGIN;
        fprintf(file, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" "
                      "height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n",
                width, height, width, height);
        fputs(STYLE, file);
        fputs("<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n", file);
        int failed = 0;
        for (size_t g = 0; g < k && !failed; g++)
            failed = write_panel(file, &panels[g], meshes, meshes->names[g], angles);
        fputs("</svg>\n", file);
        code = output_close(file, path, error);
        if (failed && code == CLI_EXIT_OK) {
            cli_error_set(error, "out of memory");
            code = CLI_EXIT_INTERNAL;
        }
    }
    free(panels);
    free(angles);
    return code;
}

int write_svg(const char *path, const cm_result *result, const char *const *names,
              cli_error *error)
{
    size_t k = cm_result_num_geometries(result);
    const double **xy = malloc((k ? k : 1) * sizeof *xy);
    if (!xy) {
        cli_error_set(error, "out of memory");
        return CLI_EXIT_INTERNAL;
    }
    for (size_t g = 0; g < k; g++) xy[g] = cm_result_vertices(result, g);
    svg_meshes meshes = {cm_result_triangles(result), cm_result_num_triangles(result),
                         cm_result_stats(result)->n, cm_result_num_vertices(result),
                         xy, names, k};
    int code = write_svg_meshes(path, &meshes, error);
    free(xy);
    return code;
}
