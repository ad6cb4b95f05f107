/* The common convex enclosure around a result's polygons and the
 * compatible triangulation of the annulus between them. Not installed. */
#ifndef CM_ENCLOSURE_H
#define CM_ENCLOSURE_H

#include "api/result.h"
#include "base/error.h"
#include "base/progress.h"

/* Builds the enclosed mesh of result r (k geometries, nv vertices, nt
 * triangles): out gets the result's vertices first (same indices and
 * coordinates), then the enclosure's vertices (the same points in every
 * geometry, strictly convex, counter-clockwise), then the annulus Steiner
 * vertices; the result's triangles first, then the annulus triangles.
 * *boundary receives out->nv flags, 1 on enclosure vertices. The whole mesh
 * is checked exactly: every triangle strictly counter-clockwise in every
 * geometry, every edge shared by two triangles except the enclosure's.
 * Returns CM_OK, CM_ERR_NO_MEMORY, CM_ERR_CANCELLED or CM_ERR_INTERNAL
 * (message on err). */
cm_status cm_enclosure_build(const cm_result *r, cm_progress *progress, cm_mesh *out,
                             unsigned char **boundary, cm_error *err);

#endif
