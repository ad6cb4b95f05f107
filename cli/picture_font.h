/* The pictures' caption font. The file is the one fontconfig gave
 * "sans-serif" when the tool was configured (cli/CMakeLists.txt), opened
 * here with FreeType and shared by every surface: fontconfig's
 * configuration load and matching, which cairo's toy font face goes
 * through, cost more than the text of a small pair's pictures. If that
 * file cannot be opened, cairo's toy "sans-serif" face is used instead. */
#ifndef CM_CLI_PICTURE_FONT_H
#define CM_CLI_PICTURE_FONT_H

#include <cairo.h>

typedef struct picture_font {
    cairo_font_face_t *face; /* the file's face; NULL: the toy face */
} picture_font;

picture_font picture_font_open(void);

/* Makes the font cr's current font, size PICTURE_FONT_PIXELS. */
void picture_font_use(const picture_font *font, cairo_t *cr);

/* Between two surfaces: the toy face resolves its fontconfig options on
 * first use and keeps them, so the PNG would reuse the SVG's unhinted
 * glyphs unless cairo's font caches are dropped; the file's face needs
 * nothing. */
void picture_font_next_surface(const picture_font *font);

/* Once every context using the font is destroyed: releases the face, and
 * cairo's font caches (and fontconfig's, for the toy face), which would
 * otherwise stay allocated until exit. */
void picture_font_close(picture_font *font);

#endif
