#include "write_picture.h"

#include <cairo-svg.h>
#include <cairo.h>
#include <math.h>
#include <png.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "outdir.h"
#include "picture_font.h"

/* Larger pictures (a morph of hundreds of frames) are scaled down to this
 * many pixels: memory grows with them (4 bytes a pixel), and cairo's images
 * stop at 32767 pixels a side. */
static const double PNG_MAX_PIXELS = 64.0 * 1024 * 1024;

static void set_colour(cairo_t *cr, uint32_t rgb)
{
    cairo_set_source_rgb(cr, ((rgb >> 16) & 0xff) / 255.0, ((rgb >> 8) & 0xff) / 255.0,
                         (rgb & 0xff) / 255.0);
}

/* Segments per cairo path in the PNG. Rasterising one path costs more
 * than linearly in its segments once they crowd the pixels (tens of
 * thousands of mesh edges in a panel: seconds), while many short paths
 * cost each about its own bounding box; so the PNG draws a layer as paths
 * of at most this many segments. Filled sub-paths are never cut; a
 * round-jointed stroke is cut anywhere, the round caps at the cut covering
 * the join. The SVG, text that costs the same either way, keeps one path
 * per layer (0: no limit). */
#define PNG_PATH_SEGMENTS 32

static void paint_path(cairo_t *cr, const style_paint *paint)
{
    if (paint->filled) cairo_fill(cr);
    else cairo_stroke(cr);
}

/* A dot is a zero-length round-capped sub-path, which cairo strokes as a
 * disc of the line width. */
static void draw_layer(cairo_t *cr, const picture *pic, const picture_layer *layer,
                       size_t path_segments)
{
    const style_paint *paint = &picture_styles[layer->style];
    set_colour(cr, paint->rgb);
    cairo_set_line_width(cr, paint->width);
    cairo_set_line_cap(cr, paint->round ? CAIRO_LINE_CAP_ROUND : CAIRO_LINE_CAP_BUTT);
    cairo_set_line_join(cr, paint->round ? CAIRO_LINE_JOIN_ROUND : CAIRO_LINE_JOIN_MITER);
    cairo_new_path(cr);
    size_t segments = 0;
    double sx = 0, sy = 0, px = 0, py = 0; /* the sub-path's start, the current point */
    int cut = 0;                           /* the open sub-path was cut */
    for (size_t i = layer->first; i < layer->first + layer->count; i++) {
        const path_step *step = &pic->steps[i];
        int starts = step->kind == STEP_MOVE || step->kind == STEP_DOT;
        int cuttable = starts || (step->kind == STEP_LINE && !paint->filled && paint->round);
        if (path_segments && segments >= path_segments && cuttable) {
            paint_path(cr, paint);
            segments = 0;
            if (!starts) cairo_move_to(cr, px, py), cut = 1;
        }
        switch (step->kind) {
        case STEP_MOVE:
            cairo_move_to(cr, step->x, step->y);
            sx = px = step->x, sy = py = step->y, cut = 0;
            break;
        case STEP_LINE:
            cairo_line_to(cr, step->x, step->y);
            px = step->x, py = step->y, segments++;
            break;
        case STEP_CLOSE: /* a cut sub-path closes to where it began */
            if (cut) cairo_line_to(cr, sx, sy);
            else cairo_close_path(cr);
            px = sx, py = sy, segments++;
            break;
        case STEP_DOT:
            cairo_move_to(cr, step->x, step->y);
            cairo_line_to(cr, step->x, step->y);
            px = sx = step->x, py = sy = step->y, cut = 0, segments++;
            break;
        }
    }
    paint_path(cr, paint);
}

/* The one drawing path of both formats: white background, the layers in
 * order, then the captions. */
static void draw_picture(cairo_t *cr, const picture *pic, const picture_font *font, double scale,
                         size_t path_segments)
{
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_scale(cr, scale, scale);
    for (size_t l = 0; l < pic->layer_count; l++) draw_layer(cr, pic, &pic->layers[l], path_segments);
    picture_font_use(font, cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    for (size_t t = 0; t < pic->text_count; t++) {
        cairo_move_to(cr, pic->texts[t].x, pic->texts[t].y);
        cairo_show_text(cr, pic->texts[t].text);
    }
}

static cairo_status_t write_to_file(void *closure, const unsigned char *data, unsigned int length)
{
    return fwrite(data, 1, length, closure) == length ? CAIRO_STATUS_SUCCESS
                                                      : CAIRO_STATUS_WRITE_ERROR;
}

/* The first error of the context or the surface, once drawing is over: a
 * context or surface in error (too large to allocate, a failed write) does
 * nothing from then on, so one check at the end covers every call. */
static cairo_status_t drawn(cairo_t *cr, cairo_surface_t *surface)
{
    cairo_status_t status = cairo_status(cr);
    cairo_destroy(cr);
    if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(surface);
    return status;
}

/* The SVG surface writes to the file as it draws and when finished. */
static int write_svg(const char *path, const picture *pic, const picture_font *font,
                     cli_error *error)
{
    FILE *file = output_open(path, error);
    if (!file) return CLI_EXIT_INTERNAL;
    cairo_surface_t *surface =
        cairo_svg_surface_create_for_stream(write_to_file, file, pic->width, pic->height);
    cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PX);
    cairo_t *cr = cairo_create(surface);
    draw_picture(cr, pic, font, 1.0, 0);
    cairo_status_t status = drawn(cr, surface);
    cairo_surface_finish(surface);
    if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(surface);
    cairo_surface_destroy(surface);
    int code = output_close(file, path, error);
    if (code == CLI_EXIT_OK && status != CAIRO_STATUS_SUCCESS) {
        cli_error_set(error, "%s: cannot write the SVG: %s", path, cairo_status_to_string(status));
        code = CLI_EXIT_INTERNAL;
    }
    return code;
}

typedef struct png_failure {
    jmp_buf jump;
    char message[200];
} png_failure;

static void png_failed(png_structp png, png_const_charp message)
{
    png_failure *failure = png_get_error_ptr(png);
    snprintf(failure->message, sizeof failure->message, "%s", message);
    longjmp(failure->jump, 1);
}

static void png_warned(png_structp png, png_const_charp message)
{
    (void)png, (void)message;
}

/* Encodes cairo's RGB24 image (one native-endian 0x00RRGGBB word a pixel)
 * as 8-bit RGB through libpng, at zlib's fastest level without row filters:
 * cairo's own writer (adaptive filters, level 6) took a third of a small
 * pair's run, and on these line drawings its files are larger. Returns 0
 * or, with failure's message set, -1. */
static int encode_png(FILE *file, cairo_surface_t *surface, png_failure *failure)
{
    int width = cairo_image_surface_get_width(surface);
    int height = cairo_image_surface_get_height(surface);
    int stride = cairo_image_surface_get_stride(surface);
    const unsigned char *data = cairo_image_surface_get_data(surface);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, failure, png_failed,
                                              png_warned);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    unsigned char *volatile row = malloc(3 * (size_t)width);
    int result = -1;
    if (!png || !info || !row) {
        snprintf(failure->message, sizeof failure->message, "out of memory");
    } else if (setjmp(failure->jump) == 0) {
        png_init_io(png, file);
        png_set_compression_level(png, 1);
        png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
        png_set_IHDR(png, info, (png_uint_32)width, (png_uint_32)height, 8, PNG_COLOR_TYPE_RGB,
                     PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
        png_write_info(png, info);
        for (int y = 0; y < height; y++) {
            const uint32_t *pixels = (const uint32_t *)(data + (size_t)y * (size_t)stride);
            for (int x = 0; x < width; x++) {
                row[3 * x] = (unsigned char)(pixels[x] >> 16);
                row[3 * x + 1] = (unsigned char)(pixels[x] >> 8);
                row[3 * x + 2] = (unsigned char)pixels[x];
            }
            png_write_row(png, row);
        }
        png_write_end(png, info);
        result = 0;
    }
    png_destroy_write_struct(png ? &png : NULL, info ? &info : NULL);
    free(row);
    return result;
}

static int write_png(const char *path, const picture *pic, const picture_font *font,
                     cli_error *error)
{
    double pixels = pic->width * pic->height;
    double scale = fmin(pixels > PNG_MAX_PIXELS ? sqrt(PNG_MAX_PIXELS / pixels) : 1.0,
                        32767.0 / fmax(pic->width, pic->height));
    scale = fmin(scale, 1.0);
    cairo_surface_t *surface = cairo_image_surface_create(
        CAIRO_FORMAT_RGB24, (int)ceil(scale * pic->width), (int)ceil(scale * pic->height));
    cairo_t *cr = cairo_create(surface);
    draw_picture(cr, pic, font, scale, PNG_PATH_SEGMENTS);
    cairo_status_t status = drawn(cr, surface);
    int code = CLI_EXIT_INTERNAL;
    if (status != CAIRO_STATUS_SUCCESS) {
        cli_error_set(error, "%s: cannot draw the picture: %s", path,
                      cairo_status_to_string(status));
    } else {
        FILE *file = output_open(path, error);
        if (file) {
            cairo_surface_flush(surface);
            png_failure failure = {.message = ""};
            int encoded = encode_png(file, surface, &failure);
            code = output_close(file, path, error);
            if (code == CLI_EXIT_OK && encoded != 0) {
                cli_error_set(error, "%s: cannot write the PNG: %s", path, failure.message);
                code = CLI_EXIT_INTERNAL;
            }
        }
    }
    cairo_surface_destroy(surface);
    return code;
}

int write_pictures(const char *svg_path, const char *png_path, const picture *pic,
                   cli_error *error)
{
    picture_font font = picture_font_open();
    int code = write_svg(svg_path, pic, &font, error);
    picture_font_next_surface(&font);
    if (code == CLI_EXIT_OK) code = write_png(png_path, pic, &font, error);
    picture_font_close(&font);
    return code;
}
