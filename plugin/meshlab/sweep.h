// "Compatible Sweep Between Two Boundaries": the worker behind the filter.
// Takes two layers with one connectivity (the output of the pairing
// filter), builds intermediate sections by the core's convex-combination
// morph and the lateral surface through their boundary loops (a ring per
// loop: the outer one and every hole), and checks every section exactly
// after float rounding: projected onto its best-fitting plane, every
// triangle keeps its orientation and the loops stay simple and apart (so
// the section is an embedded disk, with its holes, also when the end
// planes are not parallel and sections bend).
#ifndef FILTER_COMPATMESH_SWEEP_H
#define FILTER_COMPATMESH_SWEEP_H

#include "filter_error.h"
#include "layers.h"
#include "progress.h"

#include <compatmesh/compatmesh.h>
#include <compatmesh/handles.hh>
#include <compatmesh/plane.hh>

#include <common/ml_mesh_type.h>

#include <string>
#include <vector>

namespace compatmesh_plugin {

// The morph between two compatible layers: each layer mapped to 2D in its
// own plane frame (fit_plane), the pair made a core result
// (cm_result_from_meshes_loops, checked exactly; holes are filled by the
// core's morph and left out of the sections) and morphed by convex
// combinations with intrinsic weights (cm_morph_create, CM_MORPH_INTRINSIC),
// so every 2D section is valid by construction, also for layers turned half
// a turn against each other.
class SectionMorph {
 public:
  // xyz0, xyz1: 3 * vertices doubles of the two layers; triangles: their
  // common faces; boundary: the boundary loops (vertex indices, in order,
  // one loop after another, the outer loop first: loop_sizes[l] each).
  // Throws FilterError naming the layer, vertex or triangle at fault.
  SectionMorph(const std::vector<double> &xyz0, const std::vector<double> &xyz1,
               const std::vector<int32_t> &triangles, const std::vector<int> &boundary,
               const std::vector<std::size_t> &loop_sizes, const std::string &first_name,
               const std::string &second_name);

  friend std::vector<double> section_at(SectionMorph &morph, double t, double *min_angle_deg);
  friend struct SweptVolume swept_volume(SectionMorph &morph, int sections);

 private:
  compatmesh::ResultPtr result_;
  compatmesh::MorphPtr morph_;
  std::vector<double> frames_;  // the layers' planes, as the core's loft takes them (append_loft_frame)
  std::vector<int> order_;  // morph vertex j is layer vertex order_[j]
};

// The section at time t in [0, 1] (3 * vertices doubles, layer vertex
// order): the morph's 2D section lifted into both planes' frames and the
// two 3D points blended, (1 - t) * frame0(p) + t * frame1(p), as the core's
// loft places a sweep's nodes (cm_loft_section): an affine image of the 2D section,
// so the section is planar, in the first layer's plane at t = 0 and the
// second's at t = 1 (for parallel planes: the plane at the blended height).
// min_angle_deg (may be null) receives the 2D section's smallest angle.
// Throws FilterError if the core reports an invalid section.
std::vector<double> section_at(SectionMorph &morph, double t, double *min_angle_deg);

// The volume between the layers in tetrahedra: the core's sweep of the
// morph (sections at morph times t, prisms split into 3 tetrahedra, more
// sections where a cell would not be positive), lofted between the layers'
// planes by the core (cm_sweep_options.frames: every node at time t placed
// as section_at places it, every tetrahedron checked exactly where it then
// is). sections: sections of the sweep,
// both layers included, >= 2. Throws FilterError.
struct SweptVolume {
  std::vector<double> nodes;  // 3 per node
  std::vector<int32_t> tets;  // 4 per tetrahedron, positive volume
  // The boundary's triangles (4 node indices each, the 4th -1), outward,
  // sorted by group: cm_sweep_boundary_faces of the tetrahedra.
  std::vector<int32_t> faces;
  std::vector<std::string> group_names;  // cm_sweep_boundary_group_name
  std::vector<std::size_t> group_offsets;  // cm_sweep_boundary_group_offsets
  std::size_t sections = 0;   // with those the sweep inserted
  double min_dihedral_deg = 0;
};
SweptVolume swept_volume(SectionMorph &morph, int sections);

// Writes the volume as a Gmsh .msh file (format 4.1) through Gmsh
// (export/gmsh_volume.h: the tetrahedra, and the boundary as named
// surfaces), to a temporary file beside path renamed into place when
// complete. Throws FilterError.
void write_msh(const SweptVolume &volume, const std::string &path);

struct SweepOutcome {
  std::vector<LayerData> layers;  // the sections, then the lateral surface
  std::vector<std::string> log;
};

// sections: intermediate sections, >= 1. volume_file: "" or a .msh file
// that receives the swept volume in tetrahedra (swept_volume, write_msh).
// Throws FilterError.
SweepOutcome compatible_sweep(const CMeshO &first, const CMeshO &second,
                              const std::string &first_name, const std::string &second_name,
                              int sections, const std::string &volume_file, ThrottledProgress &progress);

}  // namespace compatmesh_plugin

#endif
