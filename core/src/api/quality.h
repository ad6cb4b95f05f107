/* The angle statistics a result reports. */
#ifndef CM_API_QUALITY_H
#define CM_API_QUALITY_H

#include "base/mesh.h"
#include "compatmesh/compatmesh.h"

/* Angle statistics of geometry g of mesh. */
void cm_mesh_quality(const cm_mesh *mesh, size_t g, cm_quality *q);

#endif
