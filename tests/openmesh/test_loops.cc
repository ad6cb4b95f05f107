// Polygons with holes read from OpenMesh meshes: several closed polylines
// (edges only) and planar face meshes with several boundary loops, the
// outer loop chosen by area, and their compatible triangulation.
#include "helpers.hh"

using namespace OpenMesh;
using compatmesh::Boundary;
using compatmesh::read_boundary;

// n points on a square of half-side r about (cx, cy), counter-clockwise (n % 4 == 0).
static Points square(int n, double r, double cx = 0, double cy = 0)
{
  Points p;
  const double corners[5][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
  for (int side = 0; side < 4; side++)
    for (int i = 0; i < n / 4; i++) {
      double t = double(i) / (n / 4);
      p.push_back({{cx + r * (corners[side][0] + t * (corners[side + 1][0] - corners[side][0])),
                    cy + r * (corners[side][1] + t * (corners[side + 1][1] - corners[side][1])), 0.0}});
    }
  return p;
}

// n points on a circle, counter-clockwise.
static Points circle(int n, double r, double cx = 0, double cy = 0)
{
  Points p;
  for (int i = 0; i < n; i++)
    p.push_back({{cx + r * std::cos(2 * M_PI * i / n), cy + r * std::sin(2 * M_PI * i / n), 0.0}});
  return p;
}

// Loops as edges only; with hole_first the hole's vertices come first, so
// the outer loop must be found by its area.
static PolyMesh loops_mesh(const Points &outer, const Points &hole, bool hole_first)
{
  PolyMesh mesh;
  auto add_loop = [&](const Points &points) {
    auto v = add_vertices(mesh, points);
    for (std::size_t i = 0; i < v.size(); i++) mesh.new_edge(v[i], v[(i + 1) % v.size()]);
  };
  if (hole_first) add_loop(hole), add_loop(outer);
  else add_loop(outer), add_loop(hole);
  return mesh;
}

// A planar annulus with faces: quads between outer vertex i and hole vertex i
// (both loops counter-clockwise and of the same size), split into triangles.
static TriMesh annulus_mesh(const Points &outer, const Points &hole)
{
  TriMesh mesh;
  auto o = add_vertices(mesh, outer), h = add_vertices(mesh, hole);
  for (std::size_t i = 0; i < o.size(); i++) {
    std::size_t j = (i + 1) % o.size();
    mesh.add_face(o[i], o[j], h[j]);
    mesh.add_face(o[i], h[j], h[i]);
  }
  return mesh;
}

static double signed_area(const std::vector<double> &xy, std::size_t from, std::size_t n)
{
  double area = 0;
  for (std::size_t i = 0; i < n; i++) {
    const double *a = &xy[2 * (from + i)], *b = &xy[2 * (from + (i + 1) % n)];
    area += a[0] * b[1] - b[0] * a[1];
  }
  return area / 2;
}

// Every face counter-clockwise in the xy plane, Euler characteristic 0
// (one hole), two boundary loops, and the input vertices kept.
static void check_annulus_result(const TriMesh &mesh, const char *what)
{
  bool ccw = true;
  for (auto fh : mesh.faces()) {
    std::vector<TriMesh::Point> p;
    for (auto vh : mesh.fv_range(fh)) p.push_back(mesh.point(vh));
    double cross = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
    ccw &= p.size() == 3 && cross > 0;
  }
  CHECK_MSG(ccw, "%s: a face is not counter-clockwise", what);
  long euler = long(mesh.n_vertices()) - long(mesh.n_edges()) + long(mesh.n_faces());
  CHECK_MSG(euler == 0, "%s: Euler characteristic %ld, expected 0", what, euler);
  Boundary again = read_boundary(mesh);
  CHECK_MSG(again.num_loops() == 2, "%s: %zu boundary loops, expected 2", what, again.num_loops());
}

static void test_reading()
{
  const Points outer = square(8, 2.0), hole = circle(6, 0.5, 0.3, 0.1);
  for (bool hole_first : {false, true}) {
    Boundary b = read_boundary(loops_mesh(outer, hole, hole_first));
    CHECK(b.num_loops() == 2 && b.loop_sizes[0] == 8 && b.loop_sizes[1] == 6);
    // The outer loop starts at its lowest mesh vertex, the hole after it.
    CHECK(b.source_vertex[0] == (hole_first ? 6 : 0) && b.source_vertex[8] == (hole_first ? 0 : 8));
    CHECK(signed_area(b.xy, 0, 8) > 0 && signed_area(b.xy, 8, 6) > 0);
    CHECK(b.next(7) == 0 && b.next(13) == 8 && b.next(8) == 9);
  }

  // Faces: every loop follows the faces (the hole clockwise), the frame the outer loop.
  Boundary faces = read_boundary(annulus_mesh(square(8, 2.0), circle(8, 0.5)));
  CHECK(faces.num_loops() == 2 && faces.loop_sizes[0] == 8 && faces.source_vertex[8] == 8);
  CHECK(signed_area(faces.xy, 0, 8) > 0 && signed_area(faces.xy, 8, 8) < 0);

  // Three holes: ordered by their lowest vertex index.
  PolyMesh three;
  for (const Points &loop : {circle(5, 0.3, 1, 1), square(8, 3.0), circle(5, 0.3, -1, 1), circle(5, 0.3, 0, -1)}) {
    auto v = add_vertices(three, loop);
    for (std::size_t i = 0; i < v.size(); i++) three.new_edge(v[i], v[(i + 1) % v.size()]);
  }
  Boundary b3 = read_boundary(three);
  CHECK(b3.num_loops() == 4 && b3.loop_sizes[0] == 8);
  CHECK(b3.source_vertex[0] == 5 && b3.source_vertex[8] == 0 && b3.source_vertex[13] == 13 &&
        b3.source_vertex[18] == 18);

  // Planarity covers every loop: a hole lifted off the plane is refused.
  Points lifted = circle(6, 0.5);
  for (auto &p : lifted) p[2] = 0.5;
  CHECK_ERROR(read_boundary(loops_mesh(outer, lifted, false)), CM_ERR_ARGUMENT, "not planar");
}

static void test_pairs()
{
  // A square with a square hole against a disc with a round hole, as edges
  // (different sizes: auto correspondence loop by loop) and as faces.
  std::vector<PolyMesh> edges{loops_mesh(square(8, 2.0), square(4, 0.6, 0.4, 0.2), false),
                              loops_mesh(circle(24, 2.0), circle(12, 0.7, -0.3, 0.1), true)};
  compatmesh::CompatibleTriangulationT<PolyMesh> tool;
  run_auto(tool, edges);
  CHECK(tool.stats().holes == 1 && tool.stats().n >= 36);
  CHECK(tool.meshes()[0].n_faces() == tool.meshes()[1].n_faces());
  check_annulus_result(tool.meshes()[0], "edges, square");
  check_annulus_result(tool.meshes()[1], "edges, disc");

  std::vector<TriMesh> faces{annulus_mesh(square(16, 2.0), square(16, 0.6, 0.4, 0.2)),
                             annulus_mesh(circle(16, 2.0), circle(16, 0.7, -0.3, 0.1))};
  std::vector<TriMesh> out = compatmesh::compatible_triangulation(faces);
  CHECK(out.size() == 2);
  check_annulus_result(out[0], "faces, square");
  check_annulus_result(out[1], "faces, disc");
  // The input vertices come back where they were, numbered as the loops.
  OpenMesh::VPropHandleT<int> source;
  CHECK(out[1].get_property_handle(source, compatmesh::kSourceVertexProperty));
  bool kept = true;
  for (auto vh : out[1].vertices()) {
    int s = out[1].property(source, vh);
    if (s >= 0) kept &= out[1].point(vh) == faces[1].point(OpenMesh::VertexHandle(s));
  }
  CHECK(kept);

  // A polygon with a hole against one without: the core names the counts.
  std::vector<PolyMesh> mixed{loops_mesh(square(8, 2.0), square(4, 0.6), false), face_mesh(octagon())};
  CHECK_ERROR(compatmesh::compatible_triangulation(mixed), CM_ERR_COUNT_MISMATCH, "polygon 1 has 0 holes but polygon 0 has 1");
}

int main()
{
  test_reading();
  test_pairs();
  return check_summary("test_loops");
}
