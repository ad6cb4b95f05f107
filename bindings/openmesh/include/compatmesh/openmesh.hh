// OpenMesh adapter for compatmesh: polygons read from OpenMesh meshes, results
// returned as OpenMesh meshes whose handles are the core's indices.
//
// One call:
//
//   std::vector<compatmesh::TriMesh> inputs(2);   // read with OpenMesh::IO
//   std::vector<compatmesh::TriMesh> outputs = compatmesh::compatible_triangulation(inputs);
//
// or the tool object, configured by setters and run by one call:
//
//   compatmesh::CompatibleTriangulationT<compatmesh::TriMesh> tool;
//   tool.add_mesh(a); tool.add_mesh(b);
//   tool.set_progress(...);
//   tool.run();                                   // throws compatmesh::Error
//   tool.meshes()[0] ...
//
// Input meshes (any OpenMesh TriMesh or PolyMesh type; only read, nothing is
// added to them) give one planar polygon each, with holes or without:
// - a mesh with faces must be a connected, manifold planar surface: a disk
//   (one boundary loop, Euler characteristic 1) or a disk with h holes
//   (h + 1 boundary loops, Euler characteristic 1 - h). Every loop runs in
//   the direction of the faces. A single polygonal face (an OFF or OBJ
//   file with one face read into a PolyMesh, or into a TriMesh, which fans
//   it) is a disk.
// - a mesh with edges but no faces must be one or more disjoint closed
//   polylines: each edge's first half-edge (OpenMesh's halfedge_handle(e,
//   0)) points along its polyline.
// - a mesh with vertices only is the closed polygon through its vertices in
//   index order. OpenMesh's OBJ reader drops `l` (polyline) elements and
//   keeps the vertices in file order, so an OBJ polyline whose `l` line
//   lists the vertices in order, or an OFF file with 0 faces, reads as this.
// Several loops are one polygon with holes: the loop of largest area is the
// outer loop, the others its holes, ordered by their lowest mesh vertex
// index; every loop starts at its vertex with the lowest index. The core
// pairs loop l of every polygon with loop l (cm_triangulate_loops).
// Isolated vertices are ignored when the mesh has edges or faces. The
// polygon may lie in any plane; see PlaneFrame and NormalSign in plane.hh:
// meshes with faces keep their face orientation, face-less ones use the
// canonical normal so their winding reaches the core unchanged. The plane
// is fitted to all loops; a face mesh's normal follows its outer loop.
//
// Output meshes: one triangle mesh per input, all with the same
// connectivity. Vertex v, half-edge h and face f of the core's result are
// OpenMesh's VertexHandle(v), HalfedgeHandle(h) and FaceHandle(f), with the
// same next, opposite, to-vertex and face relations. The input vertices come
// first with their original 3D coordinates; Steiner vertices are mapped
// from the plane back to 3D. Two int vertex properties, persistent (kept by
// the OM format), say where each vertex came from:
//   kInputIndexProperty   the boundary vertex index, -1 for a Steiner vertex
//   kSourceVertexProperty the input mesh's vertex index, -1 for a Steiner
//                         vertex or (CM_CORRESPOND_ARCLENGTH) a point added
//                         on an input edge
//
// Files: OpenMesh 9 reads and writes OFF, OBJ, PLY and STL coordinates as
// float, also for double meshes, and writes ASCII with 6 digits unless
// write_mesh is given a precision (17 keeps every digit it has); OM keeps
// doubles and the two vertex properties.
#ifndef COMPATMESH_OPENMESH_HH
#define COMPATMESH_OPENMESH_HH

// OpenMesh wants its IO header before the mesh kernels.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Utils/Noncopyable.hh>

#include <compatmesh/compatmesh.h>
#include <compatmesh/handles.hh>
#include <compatmesh/plane.hh>

#include <cstddef>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace compatmesh {

// Double coordinates, so the input vertices come back bit-identical.
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<OpenMesh::DefaultTraitsDouble>;
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<OpenMesh::DefaultTraitsDouble>;

constexpr const char *kInputIndexProperty = "compatmesh:input_index";
constexpr const char *kSourceVertexProperty = "compatmesh:source_vertex";

// Everything the adapter reports goes through this exception: bad meshes
// (status CM_ERR_ARGUMENT), failures of the core (its status and message).
class Error : public std::runtime_error {
 public:
  // mesh: index of the input mesh concerned, or -1. vertex, other_vertex:
  // polygon vertex indices (the core's error location), or -1.
  Error(cm_status status, const std::string &message, long mesh = -1, long vertex = -1,
        long other_vertex = -1);
  cm_status status() const { return status_; }
  long mesh() const { return mesh_; }
  long vertex() const { return vertex_; }
  long other_vertex() const { return other_vertex_; }

 private:
  cm_status status_;
  long mesh_, vertex_, other_vertex_;
};

// One input polygon, read from a mesh: its loops one after another, the
// outer loop first (a polygon without holes has one loop).
struct Boundary {
  std::vector<double> xyz;         // 3n: the original coordinates, in polygon order
  std::vector<int> source_vertex;  // n: the mesh's vertex index of each polygon vertex
  PlaneFrame frame;                // the polygon's plane
  std::vector<double> xy;          // 2n: the coordinates in that plane
  std::vector<std::size_t> loop_sizes;  // vertices per loop, outer first; they sum to n

  std::size_t size() const { return source_vertex.size(); }
  std::size_t num_loops() const { return loop_sizes.size(); }
  // The vertex after vertex i in i's loop.
  std::size_t next(std::size_t i) const;
};

// Builds a Boundary from 3D points in polygon order (fits the plane; throws
// Error when they are not planar within relative_tolerance).
Boundary make_boundary(std::vector<double> xyz, std::vector<int> source_vertex,
                       double relative_tolerance, NormalSign sign);
// The same for a polygon with holes: loop_sizes (outer first) split the
// points into loops; the plane is fitted to all of them, FollowWinding
// follows the outer loop.
Boundary make_boundary(std::vector<double> xyz, std::vector<int> source_vertex,
                       std::vector<std::size_t> loop_sizes, double relative_tolerance,
                       NormalSign sign);

// Sections of one part in planes that are not the same: each frame after
// the first turned within its plane so that its axes are the previous
// frame's carried onto it (align_frames), and the plane coordinates mapped
// again. Fitted frames take their axes from each polygon's own spread, so
// two sections of a pipe may get axes a quarter turn apart, and a
// correspondence chosen in the plane (auto's least turn) would twist them.
void align_boundaries(std::vector<Boundary> &polygons);

// Reads the polygon of a mesh (the three forms listed at the top). Throws
// Error with a message saying what is wrong: a closed mesh, several parts,
// a non-manifold vertex, handles, a polyline that branches or is not
// closed, non-planar points.
template <class Mesh>
Boundary read_boundary(const Mesh &mesh, double relative_tolerance = kDefaultPlanarityTolerance);

// Runs the core on the polygons (cm_triangulate_loops when one has holes;
// all need the same number of loops). Throws Error with the core's status and
// message (the location translated to the input mesh's vertex) on failure;
// rethrows what the progress function threw.
ResultPtr triangulate(const std::vector<Boundary> &polygons, const cm_options &options,
                      const ProgressFn &progress = ProgressFn());

// The correspondence for polygons that were given none, as on the command
// line and in Python (cm_correspondence_by_counts): arc length where
// pinned, auto where some loop's vertex count differs, else index.
cm_correspondence correspondence_by_counts(const std::vector<Boundary> &polygons, bool pinned);

// Geometry g of a result as an OpenMesh mesh with the core's numbering.
//   boundary: where the polygon came from (3D coordinates, plane, source
//             vertices); NULL for a polygon given in the xy plane.
// Throws Error(CM_ERR_INTERNAL) if OpenMesh's traversal disagrees with the
// core's half-edge structure.
template <class Mesh>
Mesh result_to_mesh(const cm_result *result, std::size_t g, const Boundary *boundary = nullptr);

// Checks, with OpenMesh's own traversal, that mesh has exactly the core's
// connectivity and numbering. Throws Error(CM_ERR_INTERNAL) naming the
// first difference.
template <class Mesh>
void check_same_connectivity(const cm_result *result, const Mesh &mesh);

// The tool: compatible triangulation of k >= 2 meshes' polygons.
template <class InMesh, class OutMesh = TriMesh>
class CompatibleTriangulationT : private OpenMesh::Utils::Noncopyable {
 public:
  CompatibleTriangulationT() { cm_options_init(&options_); }

  // The mesh is only read, during run(); it must live until then.
  void add_mesh(const InMesh &mesh) { inputs_.push_back(&mesh); }
  void clear_meshes() { inputs_.clear(); }

  // The core's options, as filled by cm_options_init and then changed. Its
  // progress fields are replaced by set_progress when that is given. Its
  // correspondence is taken as given; without set_options or
  // set_correspondence the counts decide (correspondence_by_counts: auto
  // where they differ, index where they agree, arc length with pins).
  void set_options(const cm_options &options) { options_ = options, correspondence_given_ = true; }
  void set_correspondence(cm_correspondence correspondence)
  {
    options_.correspondence = correspondence, correspondence_given_ = true;
  }
  const cm_options &options() const { return options_; }
  void set_method(cm_method method) { options_.method = method; }
  void set_remesh(bool remesh) { options_.remesh = remesh ? 1 : 0; }
  void set_min_angle_deg(double degrees) { options_.min_angle_deg = degrees; }
  void set_max_steiner(long count) { options_.max_steiner = count; }
  void set_smoothing(cm_smoothing smoothing) { options_.smoothing = smoothing; }
  // The certified caps on the smallest angle (stats().ceiling_deg and the
  // fields after it); on by default, off for the fastest run.
  void set_ceiling(bool ceiling) { options_.ceiling = ceiling ? 1 : 0; }
  void set_planarity_tolerance(double relative) { planarity_tolerance_ = relative; }
  void set_progress(ProgressFn progress) { progress_ = std::move(progress); }

  // Reads the polygons, triangulates them, builds the output meshes.
  // Throws Error; on failure the previous results are cleared.
  void run();

  // One mesh per input, in input order (empty before run()).
  std::vector<OutMesh> &meshes() { return meshes_; }
  const std::vector<OutMesh> &meshes() const { return meshes_; }
  const std::vector<Boundary> &boundaries() const { return boundaries_; }
  const cm_stats &stats() const;
  cm_quality quality(std::size_t g) const;
  cm_quality quality_before_remesh(std::size_t g) const;

 private:
  std::vector<const InMesh *> inputs_;
  cm_options options_;
  bool correspondence_given_ = false;
  double planarity_tolerance_ = kDefaultPlanarityTolerance;
  ProgressFn progress_;
  std::vector<Boundary> boundaries_;
  ResultPtr result_;
  std::vector<OutMesh> meshes_;
};

// One call: the compatible triangulation of the meshes' polygons, one
// output mesh per input. options: NULL for the defaults.
template <class OutMesh = TriMesh, class InMesh>
std::vector<OutMesh> compatible_triangulation(const std::vector<InMesh> &meshes,
                                              const cm_options *options = nullptr);

}  // namespace compatmesh

#include <compatmesh/openmesh_impl.hh>

#endif
