// The core's half-edge h, vertex v and face f are OpenMesh's HalfedgeHandle(h),
// VertexHandle(v) and FaceHandle(f), with the same relations, and OpenMesh's
// own traversal and checker accept the mesh.
#include "helpers.hh"

#include <OpenMesh/Tools/Utils/MeshCheckerT.hh>

#include <sstream>

using namespace OpenMesh;

static compatmesh::ResultPtr run_core(const Points &a, const Points &b)
{
  std::vector<double> xy;
  for (const Points *polygon : {&a, &b})
    for (const auto &p : *polygon) xy.insert(xy.end(), {p[0], p[1]});
  cm_result *result = nullptr;
  cm_status status = cm_triangulate(xy.data(), 2, a.size(), nullptr, &result);
  CHECK_MSG(status == CM_OK, "%s", cm_result_message(result));
  return compatmesh::ResultPtr(result);
}

static void check_geometry(const cm_result *r, std::size_t g)
{
  const std::size_t n = cm_result_stats(r)->n, nv = cm_result_num_vertices(r),
                    nh = cm_result_num_halfedges(r), nt = cm_result_num_triangles(r);
  const int32_t *next = cm_result_halfedge_next(r), *to = cm_result_halfedge_to_vertex(r),
                *face = cm_result_halfedge_face(r), *vertex_he = cm_result_vertex_halfedge(r),
                *face_he = cm_result_face_halfedge(r), *tri = cm_result_triangles(r);
  const double *xy = cm_result_vertices(r, g);
  TriMesh mesh = compatmesh::result_to_mesh<TriMesh>(r, g);

  CHECK(mesh.n_vertices() == nv && mesh.n_halfedges() == nh && mesh.n_edges() == nh / 2 &&
        mesh.n_faces() == nt);
  int wrong = 0;
  for (std::size_t h = 0; h < nh; h++) {
    HalfedgeHandle heh{int(h)};
    wrong += mesh.next_halfedge_handle(heh).idx() != next[h];
    wrong += mesh.opposite_halfedge_handle(heh).idx() != int(h ^ 1);
    wrong += mesh.to_vertex_handle(heh).idx() != to[h];
    wrong += mesh.from_vertex_handle(heh).idx() != to[h ^ 1];
    wrong += mesh.face_handle(heh).idx() != face[h];
    wrong += mesh.edge_handle(heh).idx() != int(h / 2);
    wrong += mesh.prev_halfedge_handle(HalfedgeHandle(next[h])) != heh;
  }
  for (std::size_t v = 0; v < nv; v++) {
    VertexHandle vh{int(v)};
    wrong += mesh.halfedge_handle(vh).idx() != vertex_he[v];
    wrong += mesh.point(vh) != TriMesh::Point(xy[2 * v], xy[2 * v + 1], 0.0);  // bit-identical
    wrong += mesh.is_boundary(vh) != (v < n);
  }
  for (std::size_t f = 0; f < nt; f++) {
    FaceHandle fh{int(f)};
    wrong += mesh.halfedge_handle(fh).idx() != face_he[f];
    HalfedgeHandle heh = mesh.halfedge_handle(fh);
    for (int corner = 0; corner < 3; corner++, heh = mesh.next_halfedge_handle(heh))
      wrong += mesh.from_vertex_handle(heh).idx() != tri[3 * f + corner];
    wrong += !(mesh.calc_face_normal(fh)[2] > 0);  // counter-clockwise in the xy plane
  }
  CHECK_MSG(wrong == 0, "geometry %zu: %d differences", g, wrong);

  // OpenMesh's traversal: the boundary loop runs clockwise 0, n-1, ..., 1.
  HalfedgeHandle start = mesh.halfedge_handle(VertexHandle(0));
  CHECK(mesh.is_boundary(start));
  std::vector<int> loop;
  HalfedgeHandle heh = start;
  do {
    loop.push_back(mesh.from_vertex_handle(heh).idx());
    heh = mesh.next_halfedge_handle(heh);
  } while (heh != start && loop.size() <= nh);
  std::vector<int> expected{0};
  for (std::size_t i = n - 1; i > 0; i--) expected.push_back(int(i));
  CHECK(loop == expected);
  std::size_t fan_sizes = 0;
  for (VertexHandle vh : mesh.vertices()) fan_sizes += mesh.valence(vh);
  CHECK(fan_sizes == nh);
  std::size_t face_corners = 0;
  for (FaceHandle fh : mesh.faces()) face_corners += mesh.valence(fh);
  CHECK(face_corners == 3 * nt);
  CHECK(Utils::MeshCheckerT<TriMesh>(mesh).check());

  // Where each vertex came from.
  VPropHandleT<int> input_index, source_vertex;
  CHECK(mesh.get_property_handle(input_index, compatmesh::kInputIndexProperty));
  CHECK(mesh.get_property_handle(source_vertex, compatmesh::kSourceVertexProperty));
  wrong = 0;
  for (VertexHandle vh : mesh.vertices()) {
    int expect = vh.idx() < int(n) ? vh.idx() : -1;
    wrong += mesh.property(input_index, vh) != expect || mesh.property(source_vertex, vh) != expect;
  }
  CHECK(wrong == 0);

  // The mesh is an ordinary OpenMesh mesh: editing it keeps it consistent.
  mesh.request_vertex_status();
  mesh.request_edge_status();
  mesh.request_face_status();
  int flips = 0;
  for (EdgeHandle eh : mesh.edges())
    if (!mesh.is_boundary(eh) && mesh.is_flip_ok(eh) && flips < 3) mesh.flip(eh), flips++;
  CHECK(Utils::MeshCheckerT<TriMesh>(mesh).check());
}

// check_same_connectivity notices a mesh that differs from the result.
static void check_detects_differences(const cm_result *r)
{
  TriMesh mesh = compatmesh::result_to_mesh<TriMesh>(r, 0);
  compatmesh::check_same_connectivity(r, mesh);  // must not throw
  check_passed++;

  TriMesh moved_halfedge = mesh;
  moved_halfedge.set_halfedge_handle(FaceHandle(0),
                                     moved_halfedge.next_halfedge_handle(mesh.halfedge_handle(FaceHandle(0))));
  CHECK_ERROR(compatmesh::check_same_connectivity(r, moved_halfedge), CM_ERR_INTERNAL, "face 0");

  // The same triangles added face by face get OpenMesh's own edge order.
  TriMesh added;
  for (VertexHandle vh : mesh.vertices()) added.add_vertex(mesh.point(vh));
  const int32_t *tri = cm_result_triangles(r);
  for (std::size_t f = 0; f < cm_result_num_triangles(r); f++)
    added.add_face(VertexHandle(tri[3 * f]), VertexHandle(tri[3 * f + 1]), VertexHandle(tri[3 * f + 2]));
  CHECK(added.n_faces() == mesh.n_faces());
  bool same = true;
  try {
    compatmesh::check_same_connectivity(r, added);
  } catch (const compatmesh::Error &) {
    same = false;
  }
  std::printf("add_face numbering %s the core's\n", same ? "happens to match" : "differs from");
}

int main()
{
  compatmesh::ResultPtr result = run_core(octagon(), star());
  if (!result || cm_result_status(result.get()) != CM_OK) return check_summary("test_mapping");
  std::printf("octagon/star: %zu vertices, %zu Steiner, %zu triangles\n",
              cm_result_num_vertices(result.get()), cm_result_stats(result.get())->steiner,
              cm_result_num_triangles(result.get()));
  CHECK(cm_result_stats(result.get())->steiner > 0);  // Steiner vertices are mapped too
  for (std::size_t g = 0; g < 2; g++) check_geometry(result.get(), g);
  check_detects_differences(result.get());

  // Clockwise input: the core renumbers internally; the mapping still holds.
  compatmesh::ResultPtr clockwise = run_core(reversed(octagon()), reversed(star()));
  if (clockwise && cm_result_status(clockwise.get()) == CM_OK) {
    CHECK(cm_result_stats(clockwise.get())->reversed_input == 1);
    for (std::size_t g = 0; g < 2; g++) {
      TriMesh mesh = compatmesh::result_to_mesh<TriMesh>(clockwise.get(), g);
      CHECK(Utils::MeshCheckerT<TriMesh>(mesh).check());
    }
  }

  CHECK_ERROR(compatmesh::result_to_mesh<TriMesh>(result.get(), 2), CM_ERR_ARGUMENT, "no geometry 2");

  // Any OpenMesh mesh type on either side: OpenMesh's float meshes, and a
  // PolyMesh as output (built the same way, checked the same way).
  using FloatTriMesh = OpenMesh::TriMesh_ArrayKernelT<>;
  std::vector<FloatTriMesh> float_inputs(2);
  for (int g = 0; g < 2; g++)
    for (const auto &p : g ? star() : octagon())
      float_inputs[g].add_vertex(FloatTriMesh::Point(float(p[0]), float(p[1]), float(p[2])));
  std::vector<PolyMesh> poly_outputs = compatmesh::compatible_triangulation<PolyMesh>(float_inputs);
  CHECK(poly_outputs.size() == 2 && Utils::MeshCheckerT<PolyMesh>(poly_outputs[1]).check());
  FloatTriMesh float_output = compatmesh::result_to_mesh<FloatTriMesh>(result.get(), 1);
  CHECK(float_output.n_faces() == cm_result_num_triangles(result.get()));
  return check_summary("test_mapping");
}
