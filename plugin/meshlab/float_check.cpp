#include "float_check.h"

#include <compatmesh/compatmesh.h>

namespace compatmesh_plugin {

std::vector<float> round_to_float(const std::vector<double> &xyz)
{
  return std::vector<float>(xyz.begin(), xyz.end());
}

std::string check_float_geometry(const std::vector<float> &xyz, const std::vector<std::size_t> &loop_sizes,
                                 const compatmesh::PlaneFrame &frame,
                                 const std::vector<int32_t> &triangles)
{
  const std::vector<double> points(xyz.begin(), xyz.end());
  const std::size_t num_vertices = points.size() / 3;
  const std::vector<double> xy = compatmesh::to_plane(frame, points.data(), num_vertices);
  long where = -1, other = -1;
  cm_status status = cm_check_geometry_loops(xy.data(), loop_sizes.data(), loop_sizes.size(), num_vertices,
                                             triangles.data(), triangles.size() / 3, &where, &other);
  const std::string w = std::to_string(where), o = std::to_string(other);
  switch (status) {
    case CM_OK: return "";
    case CM_ERR_ZERO_AREA: return "triangle " + w + " is flat or inverted";
    case CM_ERR_REPEATED_VERTEX: return "boundary vertices " + w + " and " + o + " coincide";
    case CM_ERR_SELF_INTERSECTION: return "boundary edges " + w + " and " + o + " touch or cross";
    case CM_ERR_NOT_FINITE: return "vertex " + w + " is not finite";
    default: return std::string("check failed: ") + cm_status_string(status);
  }
}

}  // namespace compatmesh_plugin
