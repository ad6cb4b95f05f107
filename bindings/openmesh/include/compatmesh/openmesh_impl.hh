// Template definitions for compatmesh/openmesh.hh; include that header instead.
#ifndef COMPATMESH_OPENMESH_IMPL_HH
#define COMPATMESH_OPENMESH_IMPL_HH

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

namespace compatmesh {
namespace detail {

using OpenMesh::EdgeHandle;
using OpenMesh::FaceHandle;
using OpenMesh::HalfedgeHandle;
using OpenMesh::VertexHandle;

inline Error bad_mesh(const std::string &message) { return Error(CM_ERR_ARGUMENT, message); }

inline std::string str(long value) { return std::to_string(value); }

// Vertex lists are rotated to start at their lowest index, so that two
// meshes numbered alike give polygons that correspond.
inline void start_at_lowest(std::vector<VertexHandle> &loop)
{
  auto lowest = std::min_element(loop.begin(), loop.end(),
                                 [](VertexHandle a, VertexHandle b) { return a.idx() < b.idx(); });
  std::rotate(loop.begin(), lowest, loop.end());
}

template <class Range>
long count(const Range &range)
{
  long n = 0;
  for (auto it = range.begin(); it != range.end(); ++it) n++;
  return n;
}

// The boundary loops of a planar surface (a disk, or a disk with holes),
// each in the direction of its faces, each starting at its lowest index.
template <class Mesh>
std::vector<std::vector<VertexHandle>> face_loops(const Mesh &mesh)
{
  long used = 0;
  for (VertexHandle vh : mesh.vertices()) {
    if (mesh.is_isolated(vh)) continue;
    if (!mesh.is_manifold(vh))
      throw bad_mesh("vertex " + str(vh.idx()) +
                     " is not manifold (two fans of faces meet there); need a disk, with holes or without");
    used++;
  }

  // Connected parts, by a search over the edges.
  std::vector<char> reached(mesh.n_vertices(), 0);
  long parts = 0;
  for (VertexHandle start : mesh.vertices()) {
    if (mesh.is_isolated(start) || reached[start.idx()]) continue;
    parts++;
    std::vector<VertexHandle> stack{start};
    reached[start.idx()] = 1;
    while (!stack.empty()) {
      VertexHandle vh = stack.back();
      stack.pop_back();
      for (HalfedgeHandle heh : mesh.voh_range(vh)) {
        VertexHandle to = mesh.to_vertex_handle(heh);
        if (!reached[to.idx()]) reached[to.idx()] = 1, stack.push_back(to);
      }
    }
  }
  if (parts > 1)
    throw bad_mesh("the mesh has " + str(parts) + " connected parts; need one disk, with holes or without");

  std::vector<char> seen(mesh.n_halfedges(), 0);
  std::vector<std::vector<VertexHandle>> loops;
  for (HalfedgeHandle start : mesh.halfedges()) {
    if (!mesh.is_boundary(start) || seen[start.idx()]) continue;
    std::vector<VertexHandle> loop;
    HalfedgeHandle heh = start;
    do {
      seen[heh.idx()] = 1;
      loop.push_back(mesh.from_vertex_handle(heh));
      heh = mesh.next_halfedge_handle(heh);
    } while (heh != start && heh.is_valid() && loop.size() <= mesh.n_halfedges());
    // Boundary half-edges run against the faces: reverse to follow them.
    std::reverse(loop.begin(), loop.end());
    start_at_lowest(loop);
    loops.push_back(std::move(loop));
  }
  if (loops.empty()) throw bad_mesh("the mesh is closed (no boundary loop); need a disk");

  // A connected surface with b boundary loops is planar (a disk with b - 1
  // holes) exactly when its Euler characteristic is 2 - b.
  const long holes = long(loops.size()) - 1;
  long euler = used - count(mesh.edges()) + count(mesh.faces());
  if (euler != 1 - holes)
    throw bad_mesh("the mesh is not a disk" + std::string(holes ? " with holes" : "") +
                   ": its Euler characteristic is " + str(euler) + " (with " + str(holes + 1) +
                   " boundary loops it must be " + str(1 - holes) + "), so it has handles");
  return loops;
}

// Closed polylines given by edges, each edge's first half-edge pointing
// along its polyline; each loop starts at its lowest index.
template <class Mesh>
std::vector<std::vector<VertexHandle>> polylines(const Mesh &mesh)
{
  std::vector<HalfedgeHandle> out(mesh.n_vertices());
  std::vector<int> n_out(mesh.n_vertices(), 0), n_in(mesh.n_vertices(), 0);
  for (EdgeHandle eh : mesh.edges()) {
    HalfedgeHandle heh = mesh.halfedge_handle(eh, 0);
    VertexHandle from = mesh.from_vertex_handle(heh), to = mesh.to_vertex_handle(heh);
    if (from == to) throw bad_mesh("edge " + str(eh.idx()) + " is a loop at vertex " + str(from.idx()));
    out[from.idx()] = heh;
    n_out[from.idx()]++;
    n_in[to.idx()]++;
  }
  for (VertexHandle vh : mesh.vertices()) {
    int i = vh.idx();
    if (n_out[i] + n_in[i] == 0) continue;
    if (n_out[i] != 1 || n_in[i] != 1)
      throw bad_mesh("the edges are not closed polylines: vertex " + str(i) + " has " +
                     str(n_in[i]) + " incoming and " + str(n_out[i]) +
                     " outgoing edges (each edge's first half-edge must point along its polyline)");
  }
  std::vector<char> taken(mesh.n_vertices(), 0);
  std::vector<std::vector<VertexHandle>> loops;
  for (VertexHandle first : mesh.vertices()) {
    if (n_out[first.idx()] == 0 || taken[first.idx()]) continue;
    std::vector<VertexHandle> loop;
    VertexHandle vh = first;
    do {
      taken[vh.idx()] = 1;
      loop.push_back(vh);
      vh = mesh.to_vertex_handle(out[vh.idx()]);
    } while (vh != first);
    // Found from its lowest vertex, so it already starts there.
    loops.push_back(std::move(loop));
  }
  return loops;
}

// Twice the area of a planar loop in space (the length of Newell's vector).
template <class Mesh>
double loop_area(const Mesh &mesh, const std::vector<VertexHandle> &loop)
{
  double sum[3] = {0, 0, 0};
  for (std::size_t i = 0; i < loop.size(); i++) {
    const auto &p = mesh.point(loop[i]), &q = mesh.point(loop[(i + 1) % loop.size()]);
    sum[0] += double(p[1]) * q[2] - double(p[2]) * q[1];
    sum[1] += double(p[2]) * q[0] - double(p[0]) * q[2];
    sum[2] += double(p[0]) * q[1] - double(p[1]) * q[0];
  }
  return std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
}

// The outer loop (largest area; the first of equal ones) first, then the
// holes by their lowest vertex index: an order that depends on the mesh
// alone, so two meshes built alike give loops that correspond.
template <class Mesh>
void outer_first(const Mesh &mesh, std::vector<std::vector<VertexHandle>> &loops)
{
  if (loops.size() < 2) return;
  std::sort(loops.begin(), loops.end(), [](const std::vector<VertexHandle> &a, const std::vector<VertexHandle> &b) {
    return a.front().idx() < b.front().idx();
  });
  std::size_t outer = 0;
  double largest = loop_area(mesh, loops[0]);
  for (std::size_t l = 1; l < loops.size(); l++) {
    double area = loop_area(mesh, loops[l]);
    if (area > largest) largest = area, outer = l;
  }
  std::rotate(loops.begin(), loops.begin() + outer, loops.begin() + outer + 1);
}

template <class Mesh>
Boundary boundary_of(const Mesh &mesh, const std::vector<std::vector<VertexHandle>> &loops,
                     double relative_tolerance, NormalSign sign)
{
  std::vector<double> xyz;
  std::vector<int> source;
  std::vector<std::size_t> sizes;
  for (const std::vector<VertexHandle> &loop : loops) {
    sizes.push_back(loop.size());
    for (VertexHandle vh : loop) {
      const auto &p = mesh.point(vh);
      for (int c = 0; c < 3; c++) xyz.push_back(double(p[c]));
      source.push_back(vh.idx());
    }
  }
  return make_boundary(std::move(xyz), std::move(source), std::move(sizes), relative_tolerance, sign);
}

[[noreturn]] inline void mismatch(const std::string &what)
{
  throw Error(CM_ERR_INTERNAL, "OpenMesh connectivity differs from the core's: " + what);
}

}  // namespace detail

template <class Mesh>
Boundary read_boundary(const Mesh &mesh, double relative_tolerance)
{
  std::vector<std::vector<OpenMesh::VertexHandle>> loops;
  if (mesh.n_faces() > 0) {
    loops = detail::face_loops(mesh);
  } else if (mesh.n_edges() > 0) {
    loops = detail::polylines(mesh);
  } else {
    loops.emplace_back();
    for (OpenMesh::VertexHandle vh : mesh.vertices()) loops[0].push_back(vh);
  }
  detail::outer_first(mesh, loops);
  return detail::boundary_of(mesh, loops, relative_tolerance,
                             mesh.n_faces() > 0 ? NormalSign::FollowWinding : NormalSign::Canonical);
}

template <class Mesh>
Mesh result_to_mesh(const cm_result *result, std::size_t g, const Boundary *boundary)
{
  using namespace OpenMesh;
  if (!result || cm_result_status(result) != CM_OK)
    throw Error(CM_ERR_ARGUMENT, "result_to_mesh: the result is not a success");
  if (g >= cm_result_num_geometries(result))
    throw Error(CM_ERR_ARGUMENT, "result_to_mesh: no geometry " + std::to_string(g));
  const std::size_t n = cm_result_stats(result)->n, nv = cm_result_num_vertices(result),
                    nh = cm_result_num_halfedges(result), nt = cm_result_num_triangles(result);
  // Boundary vertex v is the point at t of input edge e -> e + 1 (t == 0:
  // input vertex e; the index correspondence: e == v).
  std::vector<long> edge(n);
  std::vector<double> along(n);
  for (std::size_t v = 0; v < n; v++) {
    edge[v] = cm_result_boundary_source(result, g, v, &along[v]);
    if (boundary && (edge[v] < 0 || std::size_t(edge[v]) >= boundary->size()))
      throw Error(CM_ERR_ARGUMENT, "result_to_mesh: the boundary has " + std::to_string(boundary->size()) +
                                       " vertices, the result's geometry " + std::to_string(g) + " needs vertex " +
                                       std::to_string(edge[v]));
  }
  const double *xy = cm_result_vertices(result, g);
  const int32_t *next = cm_result_halfedge_next(result), *to = cm_result_halfedge_to_vertex(result),
                *face = cm_result_halfedge_face(result), *vertex_he = cm_result_vertex_halfedge(result),
                *face_he = cm_result_face_halfedge(result);

  using Scalar = typename Mesh::Point::value_type;
  Mesh mesh;
  mesh.reserve(nv, nh / 2, nt);
  for (std::size_t v = 0; v < nv; v++) {
    std::array<double, 3> p;
    if (boundary && v < n) {
      const double *a = &boundary->xyz[3 * edge[v]], *b = &boundary->xyz[3 * boundary->next(std::size_t(edge[v]))];
      for (int c = 0; c < 3; c++) p[c] = along[v] == 0 ? a[c] : a[c] + along[v] * (b[c] - a[c]);
    } else if (boundary)
      p = boundary->frame.to_space(xy[2 * v], xy[2 * v + 1]);
    else
      p = {{xy[2 * v], xy[2 * v + 1], 0.0}};
    mesh.new_vertex(typename Mesh::Point(Scalar(p[0]), Scalar(p[1]), Scalar(p[2])));
  }
  // add_face would number edges in its own order; building the arrays
  // directly gives OpenMesh the core's numbering. new_edge(a, b) creates
  // half-edge 2e pointing to b and 2e + 1 pointing to a.
  for (std::size_t e = 0; e < nh / 2; e++)
    mesh.new_edge(VertexHandle(to[2 * e + 1]), VertexHandle(to[2 * e]));
  for (std::size_t f = 0; f < nt; f++) mesh.new_face();
  for (std::size_t h = 0; h < nh; h++) {
    HalfedgeHandle heh{int(h)};
    mesh.set_next_halfedge_handle(heh, HalfedgeHandle(next[h]));
    if (face[h] >= 0)
      mesh.set_face_handle(heh, FaceHandle(face[h]));
    else
      mesh.set_boundary(heh);
  }
  for (std::size_t f = 0; f < nt; f++) mesh.set_halfedge_handle(FaceHandle(int(f)), HalfedgeHandle(face_he[f]));
  for (std::size_t v = 0; v < nv; v++)
    mesh.set_halfedge_handle(VertexHandle(int(v)), HalfedgeHandle(vertex_he[v]));

  VPropHandleT<int> input_index, source_vertex;
  mesh.add_property(input_index, kInputIndexProperty);
  mesh.add_property(source_vertex, kSourceVertexProperty);
  mesh.property(input_index).set_persistent(true);
  mesh.property(source_vertex).set_persistent(true);
  for (std::size_t v = 0; v < nv; v++) {
    VertexHandle vh{int(v)};
    mesh.property(input_index, vh) = v < n ? int(v) : -1;
    int own = v < n && along[v] == 0 ? int(edge[v]) : -1; /* an input vertex, not a point on an edge */
    mesh.property(source_vertex, vh) = own < 0 ? -1 : boundary ? boundary->source_vertex[own] : own;
  }

  check_same_connectivity(result, mesh);
  return mesh;
}

template <class Mesh>
void check_same_connectivity(const cm_result *result, const Mesh &mesh)
{
  using namespace OpenMesh;
  using detail::mismatch;
  const std::size_t n = cm_result_stats(result)->n, nv = cm_result_num_vertices(result),
                    nh = cm_result_num_halfedges(result), nt = cm_result_num_triangles(result);
  const int32_t *next = cm_result_halfedge_next(result), *to = cm_result_halfedge_to_vertex(result),
                *face = cm_result_halfedge_face(result), *vertex_he = cm_result_vertex_halfedge(result),
                *face_he = cm_result_face_halfedge(result), *triangles = cm_result_triangles(result);
  if (mesh.n_vertices() != nv || mesh.n_halfedges() != nh || mesh.n_edges() != nh / 2 ||
      mesh.n_faces() != nt)
    mismatch("element counts");

  for (std::size_t h = 0; h < nh; h++) {
    HalfedgeHandle heh{int(h)};
    std::string at = "half-edge " + std::to_string(h) + ": ";
    if (mesh.to_vertex_handle(heh).idx() != to[h]) mismatch(at + "to-vertex");
    if (mesh.opposite_halfedge_handle(heh).idx() != int(h ^ 1)) mismatch(at + "opposite");
    if (mesh.next_halfedge_handle(heh).idx() != next[h]) mismatch(at + "next");
    if (mesh.prev_halfedge_handle(mesh.next_halfedge_handle(heh)) != heh) mismatch(at + "prev");
    if (mesh.face_handle(heh).idx() != face[h]) mismatch(at + "face");
    if (mesh.is_boundary(heh) != (face[h] < 0)) mismatch(at + "boundary flag");
  }

  for (std::size_t f = 0; f < nt; f++) {
    FaceHandle fh{int(f)};
    if (mesh.halfedge_handle(fh).idx() != face_he[f]) mismatch("face " + std::to_string(f) + ": half-edge");
    // The circulator, from the face's half-edge, must meet the triangle's corners in order.
    std::vector<int> corners;
    for (HalfedgeHandle heh : mesh.fh_range(fh)) corners.push_back(mesh.from_vertex_handle(heh).idx());
    if (corners.size() != 3 || corners[0] != triangles[3 * f] || corners[1] != triangles[3 * f + 1] ||
        corners[2] != triangles[3 * f + 2])
      mismatch("face " + std::to_string(f) + ": corners");
  }

  std::size_t outgoing = 0;
  for (std::size_t v = 0; v < nv; v++) {
    VertexHandle vh{int(v)};
    std::string at = "vertex " + std::to_string(v) + ": ";
    if (mesh.halfedge_handle(vh).idx() != vertex_he[v]) mismatch(at + "half-edge");
    if (mesh.is_boundary(vh) != (v < n)) mismatch(at + "boundary flag");
    for (HalfedgeHandle heh : mesh.voh_range(vh)) {
      if (mesh.from_vertex_handle(heh) != vh) mismatch(at + "outgoing half-edges");
      if (++outgoing > nh) mismatch(at + "outgoing half-edges do not close");
    }
  }
  if (outgoing != nh) mismatch("the vertices' fans miss half-edges");
}

template <class InMesh, class OutMesh>
void CompatibleTriangulationT<InMesh, OutMesh>::run()
{
  meshes_.clear();
  boundaries_.clear();
  result_.reset();
  std::vector<Boundary> boundaries;
  for (std::size_t i = 0; i < inputs_.size(); i++) {
    try {
      boundaries.push_back(read_boundary(*inputs_[i], planarity_tolerance_));
    } catch (const Error &e) {
      throw Error(e.status(), "mesh " + std::to_string(i) + ": " + e.what(), long(i), e.vertex(),
                  e.other_vertex());
    }
  }
  align_boundaries(boundaries);
  cm_options options = options_;
  if (!correspondence_given_)
    options.correspondence =
        correspondence_by_counts(boundaries, options.num_pins > 0 || options.pin_corners_deg > 0);
  ResultPtr result = triangulate(boundaries, options, progress_);
  std::vector<OutMesh> meshes;
  meshes.reserve(boundaries.size());
  for (std::size_t g = 0; g < boundaries.size(); g++)
    meshes.push_back(result_to_mesh<OutMesh>(result.get(), g, &boundaries[g]));
  boundaries_ = std::move(boundaries);
  result_ = std::move(result);
  meshes_ = std::move(meshes);
}

template <class InMesh, class OutMesh>
const cm_stats &CompatibleTriangulationT<InMesh, OutMesh>::stats() const
{
  if (!result_) throw Error(CM_ERR_ARGUMENT, "no result: run() has not succeeded");
  return *cm_result_stats(result_.get());
}

namespace detail {
// Geometry g's quality from `get` (cm_result_quality or _before).
inline cm_quality quality_of(const cm_result *result, std::size_t g,
                             cm_status (*get)(const cm_result *, std::size_t, cm_quality *))
{
  if (!result) throw Error(CM_ERR_ARGUMENT, "no result: run() has not succeeded");
  cm_quality quality;
  if (get(result, g, &quality) != CM_OK) throw Error(CM_ERR_ARGUMENT, "no geometry " + std::to_string(g));
  return quality;
}
}  // namespace detail

template <class InMesh, class OutMesh>
cm_quality CompatibleTriangulationT<InMesh, OutMesh>::quality(std::size_t g) const
{
  return detail::quality_of(result_.get(), g, cm_result_quality);
}

template <class InMesh, class OutMesh>
cm_quality CompatibleTriangulationT<InMesh, OutMesh>::quality_before_remesh(std::size_t g) const
{
  return detail::quality_of(result_.get(), g, cm_result_quality_before);
}

template <class OutMesh, class InMesh>
std::vector<OutMesh> compatible_triangulation(const std::vector<InMesh> &meshes,
                                              const cm_options *options)
{
  CompatibleTriangulationT<InMesh, OutMesh> tool;
  if (options) tool.set_options(*options);
  for (const InMesh &mesh : meshes) tool.add_mesh(mesh);
  tool.run();
  return std::move(tool.meshes());
}

}  // namespace compatmesh

#endif
