/* A picture (picture.h) as SVG or PNG, both drawn by cairo through one
 * drawing function, so the two files show the same thing. SVG at one user
 * unit (pixel) per unit of the picture, its text as glyph outlines; PNG at
 * one pixel per unit, scaled down to 64 million pixels if larger. */
#ifndef CM_CLI_WRITE_PICTURE_H
#define CM_CLI_WRITE_PICTURE_H

#include "cli_common.h"
#include "picture.h"

/* Each returns CLI_EXIT_OK or, with error set, CLI_EXIT_INTERNAL. */
int write_svg(const char *path, const picture *pic, cli_error *error);
int write_png(const char *path, const picture *pic, cli_error *error);

#endif
