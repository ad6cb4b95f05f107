/* A picture (picture.h) as PNG, drawn by cairo at one pixel per unit (scaled
 * down to 64 million pixels if larger). */
#ifndef CM_CLI_WRITE_PNG_H
#define CM_CLI_WRITE_PNG_H

#include "cli_common.h"
#include "picture.h"

/* Returns CLI_EXIT_OK or, with error set, CLI_EXIT_INTERNAL. */
int write_png(const char *path, const picture *pic, cli_error *error);

#endif
