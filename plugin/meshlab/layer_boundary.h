// A MeshLab layer read as one planar polygon, with holes or without: the
// layer is copied into an OpenMesh mesh and read by the OpenMesh adapter,
// so MeshLab inputs are checked exactly like every other input (closed
// polylines, or a disk with one boundary loop per hole and one outside;
// planar; several loops: the largest is the outer one, the holes follow).
#ifndef FILTER_COMPATMESH_LAYER_BOUNDARY_H
#define FILTER_COMPATMESH_LAYER_BOUNDARY_H

#include <common/ml_mesh_type.h>

#include <compatmesh/openmesh.hh>

#include <string>
#include <vector>

namespace compatmesh_plugin {

// The layer as an OpenMesh mesh: vertices in world coordinates (the
// layer's matrix applied; deleted ones skipped, so indices are compacted), faces, and for a mesh without faces its edges,
// each directed along the polyline it belongs to (MeshLab's planar sections
// do not direct them; each loop gets the direction of its first edge). source_index[i] is the layer's vertex index of
// OpenMesh vertex i. Throws compatmesh::Error for faces OpenMesh cannot
// add (non-manifold).
compatmesh::PolyMesh layer_to_openmesh(const CMeshO &layer, std::vector<int> &source_index);

// The layer's polygon. The source_vertex of the result are the layer's
// vertex indices. Throws compatmesh::Error saying what is wrong.
compatmesh::Boundary layer_boundary(const CMeshO &layer, bool &is_disk);

}  // namespace compatmesh_plugin

#endif
