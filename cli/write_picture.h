/* A picture (picture.h) as SVG and PNG, both drawn by cairo through one
 * drawing function, so the two files show the same thing. SVG at one user
 * unit (pixel) per unit of the picture, its text as glyph outlines; PNG at
 * one pixel per unit, scaled down to 64 million pixels if larger, encoded
 * by libpng. */
#ifndef CM_CLI_WRITE_PICTURE_H
#define CM_CLI_WRITE_PICTURE_H

#include "cli_common.h"
#include "picture.h"

/* The picture as SVG at svg_path and as PNG at png_path. Returns
 * CLI_EXIT_OK or, with error set, CLI_EXIT_INTERNAL. */
int write_pictures(const char *svg_path, const char *png_path, const picture *pic,
                   cli_error *error);

#endif
