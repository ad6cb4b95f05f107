#include "picture_font.h"

#include <cairo-ft.h>
#include <fontconfig/fontconfig.h>
#include <stdlib.h>

#include "picture.h"

#ifndef CM_PICTURE_FONT_FILE
#define CM_PICTURE_FONT_FILE ""
#endif
#ifndef CM_PICTURE_FONT_INDEX
#define CM_PICTURE_FONT_INDEX 0
#endif

/* What the cairo face holds, released when cairo destroys it: cairo keeps
 * scaled fonts of a face after its last reference, until its caches drop
 * them. */
typedef struct ft_font {
    FT_Library library;
    FT_Face face;
} ft_font;

static const cairo_user_data_key_t ft_font_key;

static void ft_font_free(void *data)
{
    ft_font *font = data;
    FT_Done_Face(font->face);
    FT_Done_FreeType(font->library);
    free(font);
}

picture_font picture_font_open(void)
{
    picture_font none = {NULL};
    ft_font *font = calloc(1, sizeof *font);
    if (!font) return none;
    if (!CM_PICTURE_FONT_FILE[0] || FT_Init_FreeType(&font->library) != 0) {
        free(font);
        return none;
    }
    if (FT_New_Face(font->library, CM_PICTURE_FONT_FILE, CM_PICTURE_FONT_INDEX, &font->face) != 0) {
        FT_Done_FreeType(font->library);
        free(font);
        return none;
    }
    cairo_font_face_t *face = cairo_ft_font_face_create_for_ft_face(font->face, 0);
    if (cairo_font_face_set_user_data(face, &ft_font_key, font, ft_font_free) !=
        CAIRO_STATUS_SUCCESS) {
        cairo_font_face_destroy(face);
        ft_font_free(font);
        return none;
    }
    picture_font opened = {face};
    return opened;
}

void picture_font_use(const picture_font *font, cairo_t *cr)
{
    if (font->face) cairo_set_font_face(cr, font->face);
    else cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, PICTURE_FONT_PIXELS);
    /* A raster surface leaves hinting to the font: light, as fontconfig's
     * default configuration gives the toy face (10-hinting-slight.conf);
     * vector surfaces draw unhinted outlines whatever is set here. */
    cairo_font_options_t *options = cairo_font_options_create();
    cairo_surface_get_font_options(cairo_get_target(cr), options);
    if (cairo_font_options_get_hint_style(options) == CAIRO_HINT_STYLE_DEFAULT) {
        cairo_font_options_set_hint_style(options, CAIRO_HINT_STYLE_SLIGHT);
        cairo_set_font_options(cr, options);
    }
    cairo_font_options_destroy(options);
}

void picture_font_next_surface(const picture_font *font)
{
    if (!font->face) cairo_debug_reset_static_data();
}

void picture_font_close(picture_font *font)
{
    int toy = !font->face;
    if (font->face) cairo_font_face_destroy(font->face);
    font->face = NULL;
    cairo_debug_reset_static_data();
    if (toy) FcFini();
}
