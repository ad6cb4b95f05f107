/* A picture (picture.h) as SVG: one path element per layer, styled by
 * class. */
#ifndef CM_CLI_WRITE_SVG_H
#define CM_CLI_WRITE_SVG_H

#include "cli_common.h"
#include "picture.h"

/* Returns CLI_EXIT_OK or, with error set, CLI_EXIT_INTERNAL. */
int write_svg(const char *path, const picture *pic, cli_error *error);

#endif
