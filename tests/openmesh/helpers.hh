// Shared by the OpenMesh adapter tests: the check harness and a few meshes.
#ifndef CM_TEST_OPENMESH_HELPERS_HH
#define CM_TEST_OPENMESH_HELPERS_HH

#include <compatmesh/openmesh.hh>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "check.h"  // tests/core: CHECK, CHECK_MSG, check_summary

using compatmesh::PolyMesh;
using compatmesh::TriMesh;
using Points = std::vector<std::array<double, 3>>;

// Passes when f throws compatmesh::Error with this status and a message
// containing fragment.
template <class F>
void check_error(const char *file, int line, F &&f, cm_status status, const std::string &fragment)
{
  try {
    f();
  } catch (const compatmesh::Error &e) {
    if (e.status() == status && std::string(e.what()).find(fragment) != std::string::npos) {
      check_passed++;
    } else {
      check_failed++;
      std::fprintf(stderr, "%s:%d: expected %s containing \"%s\", got %s: %s\n", file, line,
                   cm_status_string(status), fragment.c_str(), cm_status_string(e.status()), e.what());
    }
    return;
  }
  check_failed++;
  std::fprintf(stderr, "%s:%d: expected an error containing \"%s\", nothing was thrown\n", file, line,
               fragment.c_str());
}
#define CHECK_ERROR(expr, status, fragment) check_error(__FILE__, __LINE__, [&] { expr; }, status, fragment)

// Eight vertices around the origin in the xy plane, counter-clockwise,
// slightly irregular so that no diagonals meet by symmetry.
inline Points octagon(double inner_radius = 2.0)
{
  Points points;
  for (int i = 0; i < 8; i++) {
    double angle = 2.0 * M_PI * (i + 0.1 * (i % 3)) / 8;
    double radius = (i % 2 ? inner_radius : 2.0) * (1.0 + 0.03 * i);
    points.push_back({{radius * std::cos(angle), radius * std::sin(angle), 0.0}});
  }
  return points;
}
inline Points star() { return octagon(0.6); }

template <class Mesh>
std::vector<OpenMesh::VertexHandle> add_vertices(Mesh &mesh, const Points &points)
{
  std::vector<OpenMesh::VertexHandle> handles;
  for (const auto &p : points) handles.push_back(mesh.add_vertex(typename Mesh::Point(p[0], p[1], p[2])));
  return handles;
}

// The polygon as one face.
inline PolyMesh face_mesh(const Points &points)
{
  PolyMesh mesh;
  mesh.add_face(add_vertices(mesh, points));
  return mesh;
}

// The polygon as vertices only (what OpenMesh reads from an OBJ polyline).
inline PolyMesh vertex_mesh(const Points &points)
{
  PolyMesh mesh;
  add_vertices(mesh, points);
  return mesh;
}

// The polygon as edges without faces, built with the low-level kernel (no
// OpenMesh reader or add_* call makes one).
inline PolyMesh polyline_mesh(const Points &points)
{
  PolyMesh mesh;
  auto v = add_vertices(mesh, points);
  for (std::size_t i = 0; i < v.size(); i++) mesh.new_edge(v[i], v[(i + 1) % v.size()]);
  return mesh;
}

// A disk: the polygon fanned from an interior vertex at the centroid, plus
// the polygon's vertices first so polygon vertex i is mesh vertex i.
inline TriMesh fan_mesh(const Points &points)
{
  TriMesh mesh;
  auto v = add_vertices(mesh, points);
  std::array<double, 3> c{{0, 0, 0}};
  for (const auto &p : points)
    for (int k = 0; k < 3; k++) c[k] += p[k] / double(points.size());
  auto centre = mesh.add_vertex(TriMesh::Point(c[0], c[1], c[2]));
  for (std::size_t i = 0; i < v.size(); i++) mesh.add_face(v[i], v[(i + 1) % v.size()], centre);
  return mesh;
}

inline Points reversed(Points points)
{
  std::reverse(points.begin() + 1, points.end());
  return points;
}

// Rotates about a fixed skew axis and shifts, so the plane is no coordinate plane.
inline Points tilted(const Points &points)
{
  const double a = 0.7, b = 0.4;  // rotation about x by a, then about y by b
  Points out;
  for (const auto &p : points) {
    double y = std::cos(a) * p[1] - std::sin(a) * p[2], z = std::sin(a) * p[1] + std::cos(a) * p[2];
    double x = std::cos(b) * p[0] + std::sin(b) * z;
    z = -std::sin(b) * p[0] + std::cos(b) * z;
    out.push_back({{x + 10.0, y - 3.0, z + 5.0}});
  }
  return out;
}

// The adapter's tool run on the meshes with the auto correspondence.
inline void run_auto(compatmesh::CompatibleTriangulationT<PolyMesh> &tool, const std::vector<PolyMesh> &meshes)
{
  for (const PolyMesh &m : meshes) tool.add_mesh(m);
  cm_options options;
  cm_options_init(&options);
  options.correspondence = CM_CORRESPOND_AUTO;
  tool.set_options(options);
  tool.run();
}

#endif
