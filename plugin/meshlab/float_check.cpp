#include "float_check.h"

#include <compatmesh/compatmesh.h>

#include <algorithm>
#include <cmath>

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

double float_min_angle_deg(const std::vector<float> &xyz, const std::vector<int32_t> &triangles)
{
  double least = 180;
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3)
    for (int c = 0; c < 3; c++) {
      const float *a = &xyz[3 * std::size_t(triangles[t + c])], *b = &xyz[3 * std::size_t(triangles[t + (c + 1) % 3])],
                  *d = &xyz[3 * std::size_t(triangles[t + (c + 2) % 3])];
      double u[3], v[3];
      for (int k = 0; k < 3; k++) u[k] = double(b[k]) - a[k], v[k] = double(d[k]) - a[k];
      const double cross[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      const double dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
      least = std::min(least, std::atan2(std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]),
                                         dot) * 180.0 / M_PI);
    }
  return least;
}

}  // namespace compatmesh_plugin
