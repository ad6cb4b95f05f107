/* What preview.svg/png and frames.svg/png show, as drawing primitives in
 * pixels: the k meshes side by side, worst triangles highlighted.
 * write_picture.c draws these into both formats, so both pictures agree. */
#ifndef CM_CLI_PICTURE_H
#define CM_CLI_PICTURE_H

#include <stddef.h>
#include <stdint.h>

#include <compatmesh/compatmesh.h>

#include "cli_common.h"

/* How a layer is painted; picture_styles has one entry per value. */
typedef enum picture_style {
    STYLE_POOR,     /* filled: triangles with a smallest angle below 20 degrees */
    STYLE_WORST,    /* filled: each panel's worst triangle */
    STYLE_EDGES,    /* stroked thin: every edge */
    STYLE_BOUNDARY, /* stroked thick: the input loops */
    STYLE_STEINER,  /* dots: the Steiner vertices */
    STYLE_COUNT
} picture_style;

typedef struct style_paint {
    int filled;          /* 1: fill the path, 0: stroke it */
    uint32_t rgb;        /* 0xRRGGBB */
    double width;        /* stroke width in pixels */
    int round;           /* round caps and joins */
} style_paint;

extern const style_paint picture_styles[STYLE_COUNT];

/* Path steps: move to, line to, close the sub-path, a dot at (x, y). */
typedef enum { STEP_MOVE, STEP_LINE, STEP_CLOSE, STEP_DOT } step_kind;

typedef struct path_step {
    step_kind kind;
    double x, y;
} path_step;

/* One path in one style; steps[first .. first + count) of the picture. */
typedef struct picture_layer {
    size_t panel; /* which mesh it belongs to */
    picture_style style;
    size_t first, count;
} picture_layer;

/* A line of text (valid UTF-8, no control characters) with its baseline starting at (x, y). */
typedef struct picture_text {
    size_t panel;
    double x, y;
    char *text;
} picture_text;

enum { PICTURE_FONT_PIXELS = 12 }; /* the caption font (picture_font.h), black */

typedef struct picture {
    double width, height; /* white background */
    size_t panel_count;   /* one per mesh, left to right */
    path_step *steps;
    size_t step_count, step_capacity;
    picture_layer *layers;
    size_t layer_count, layer_capacity;
    picture_text *texts;
    size_t text_count, text_capacity;
} picture;

/* k geometries of one triangle list, e.g. the frames of a morph. */
typedef struct picture_meshes {
    const int32_t *triangles; /* 3 * count, counter-clockwise */
    size_t count;
    size_t n;                 /* boundary vertices 0 .. n-1; the rest: Steiner */
    size_t vertices;
    const double *const *xy;  /* k arrays of 2 * vertices doubles */
    const char *const *names; /* k captions */
    size_t k;
} picture_meshes;

/* One panel per geometry, each scaled to the same height with y pointing
 * up, side by side in rows at most 8192 pixels wide: the triangles whose smallest angle is below 20 degrees orange, each
 * panel's worst triangle red, edges thin, the input boundary thick, Steiner
 * vertices as dots, and a caption "NAME" / "n=.., Steiner .., min angle ..°".
 * Returns CLI_EXIT_OK or, out of memory, CLI_EXIT_INTERNAL with error set
 * (what was built is freed). */
int picture_of_meshes(picture *pic, const picture_meshes *meshes, cli_error *error);

/* The same for the geometries of a successful result, captioned names[g]. */
int picture_of_result(picture *pic, const cm_result *result, const char *const *names,
                      cli_error *error);

void picture_free(picture *pic);

#endif
