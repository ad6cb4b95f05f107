// MeshLab keeps float coordinates: a result computed in doubles is only
// handed over after its float-rounded coordinates pass the core's exact
// validity check.
#ifndef FILTER_COMPATMESH_FLOAT_CHECK_H
#define FILTER_COMPATMESH_FLOAT_CHECK_H

#include <compatmesh/plane.hh>

#include <cstdint>
#include <string>
#include <vector>

namespace compatmesh_plugin {

// Rounds 3D points to float (what the layer will store).
std::vector<float> round_to_float(const std::vector<double> &xyz);

// Checks one geometry as MeshLab will store it.
//   xyz:       3 * num_vertices floats, the boundary loops first (one
//              after another, outer first: loop_sizes[l] vertices each, in
//              order), as in the core's output
//   frame:     the plane the triangles are counter-clockwise in
//   triangles: 3 * num_triangles indices
// Projects the float points into the plane (in double) and runs
// cm_check_geometry_loops. Returns "" when valid, else a one-line reason naming
// the triangle, vertices or edges.
std::string check_float_geometry(const std::vector<float> &xyz, const std::vector<std::size_t> &loop_sizes,
                                 const compatmesh::PlaneFrame &frame,
                                 const std::vector<int32_t> &triangles);

// The smallest angle (degrees) of the triangles as MeshLab stores them:
// the float points, in space, each angle atan2(|u x v|, u . v) in double.
// Where edges are a few float units long the rounding moves it by degrees
// from the double result's.
double float_min_angle_deg(const std::vector<float> &xyz, const std::vector<int32_t> &triangles);

}  // namespace compatmesh_plugin

#endif
