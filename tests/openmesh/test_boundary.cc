// Reading polygons from meshes (disk, single face, polyline, vertices), planes
// in 3D, and every error the adapter reports.
#include "helpers.hh"

#include <OpenMesh/Tools/Utils/MeshCheckerT.hh>

#include <numeric>

using namespace OpenMesh;
using compatmesh::Boundary;
using compatmesh::read_boundary;

static std::vector<int> iota(int n, int first = 0)
{
  std::vector<int> v(n);
  std::iota(v.begin(), v.end(), first);
  return v;
}

static double signed_area(const std::vector<double> &xy)
{
  double area = 0;
  std::size_t n = xy.size() / 2;
  for (std::size_t i = 0; i < n; i++) {
    std::size_t j = (i + 1) % n;
    area += xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
  }
  return area / 2;
}

// Each form gives the polygon with vertex i = mesh vertex i, and the xy plane
// gives exact 2D coordinates.
static void test_forms()
{
  const Points points = star();
  std::vector<double> exact_xy;
  for (const auto &p : points) exact_xy.insert(exact_xy.end(), {p[0], p[1]});

  Boundary from_face = read_boundary(face_mesh(points));
  Boundary from_fan = read_boundary(fan_mesh(points));
  Boundary from_polyline = read_boundary(polyline_mesh(points));
  Boundary from_vertices = read_boundary(vertex_mesh(points));
  for (const Boundary *b : {&from_face, &from_fan, &from_polyline, &from_vertices}) {
    CHECK(b->source_vertex == iota(8));
    CHECK(b->xy == exact_xy);
    CHECK(b->frame.fixed_axis == 2);
  }

  // A disk whose vertices are numbered from the inside out: the polygon
  // starts at the lowest boundary index and follows the faces.
  TriMesh grid;
  std::vector<VertexHandle> v;
  v.push_back(grid.add_vertex(TriMesh::Point(1, 1, 0)));  // the centre, vertex 0
  const int ring[8][2] = {{2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}, {0, 0}, {1, 0}, {2, 0}};
  for (const auto &p : ring) v.push_back(grid.add_vertex(TriMesh::Point(p[0], p[1], 0)));
  for (int i = 1; i <= 8; i++) grid.add_face(v[0], v[i], v[i % 8 + 1]);
  Boundary from_grid = read_boundary(grid);
  CHECK(from_grid.source_vertex == iota(8, 1));
  CHECK(signed_area(from_grid.xy) > 0);

  // Faces turned away from +z: the polygon follows the faces, the normal
  // follows them too, and the polygon is counter-clockwise in its plane.
  Boundary turned = read_boundary(face_mesh(reversed(points)));
  CHECK(turned.source_vertex == iota(8));
  CHECK(turned.frame.normal[2] == -1.0);
  CHECK(signed_area(turned.xy) > 0);

  // Face-less input keeps its winding: clockwise stays clockwise.
  Boundary clockwise = read_boundary(vertex_mesh(reversed(points)));
  CHECK(clockwise.frame.normal[2] == 1.0);
  CHECK(signed_area(clockwise.xy) < 0);

  // A polyline whose edges were added in another order.
  PolyMesh shuffled;
  auto h = add_vertices(shuffled, points);
  for (int i : {3, 0, 6, 1, 7, 2, 5, 4}) shuffled.new_edge(h[i], h[(i + 1) % 8]);
  CHECK(read_boundary(shuffled).source_vertex == iota(8));
}

// A polygon in a tilted plane: the outputs keep the input vertices
// bit-identical, put the Steiner vertices on the plane, and face the way the
// input faces did.
static void test_tilted_plane()
{
  const Points a = tilted(octagon()), b = tilted(star());
  Boundary boundary = read_boundary(face_mesh(a));
  CHECK(boundary.frame.fixed_axis == -1);
  // The map to 2D is a rigid motion: distances survive.
  for (int i = 0; i < 8; i++) {
    int j = (i + 3) % 8;
    double d3 = std::hypot(a[i][0] - a[j][0], a[i][1] - a[j][1], a[i][2] - a[j][2]);
    double d2 = std::hypot(boundary.xy[2 * i] - boundary.xy[2 * j], boundary.xy[2 * i + 1] - boundary.xy[2 * j + 1]);
    CHECK(std::abs(d3 - d2) < 1e-12);
  }

  std::vector<PolyMesh> inputs{face_mesh(a), face_mesh(b)};
  std::vector<TriMesh> outputs = compatmesh::compatible_triangulation(inputs);
  CHECK(outputs.size() == 2);
  const auto &normal = boundary.frame.normal;
  for (int g = 0; g < 2; g++) {
    const Points &input = g ? b : a;
    const TriMesh &mesh = outputs[g];
    CHECK(Utils::MeshCheckerT<TriMesh>(mesh).check());
    int wrong = 0;
    for (int i = 0; i < 8; i++) wrong += mesh.point(VertexHandle(i)) != TriMesh::Point(input[i][0], input[i][1], input[i][2]);
    double farthest = 0;
    for (VertexHandle vh : mesh.vertices()) {
      TriMesh::Point d = mesh.point(vh) - mesh.point(VertexHandle(0));
      farthest = std::max(farthest, std::abs(d[0] * normal[0] + d[1] * normal[1] + d[2] * normal[2]));
    }
    for (FaceHandle fh : mesh.faces()) {
      TriMesh::Normal n = mesh.calc_face_normal(fh);
      wrong += !(n[0] * normal[0] + n[1] * normal[1] + n[2] * normal[2] > 0.999);
    }
    CHECK_MSG(wrong == 0, "geometry %d: %d wrong vertices or faces", g, wrong);
    CHECK_MSG(farthest < 1e-12, "a vertex is %g off the plane", farthest);
  }

  // A coordinate plane other than xy: the 2D coordinates are copies.
  Points on_x_plane;
  for (const auto &p : octagon()) on_x_plane.push_back({{5.0, p[0], p[1]}});
  Boundary x_plane = read_boundary(vertex_mesh(on_x_plane));
  CHECK(x_plane.frame.fixed_axis == 0 && x_plane.frame.normal[0] == 1.0);
  int copied = 0;
  for (int i = 0; i < 8; i++) copied += x_plane.xy[2 * i] == on_x_plane[i][1] && x_plane.xy[2 * i + 1] == on_x_plane[i][2];
  CHECK(copied == 8);
}

static void test_errors()
{
  // Not planar: one vertex lifted by 1% of the size.
  Points bent = tilted(star());
  bent[5][2] += 0.04;
  CHECK_ERROR(read_boundary(face_mesh(bent)), CM_ERR_ARGUMENT, "not planar: vertex 5");
  CHECK_ERROR(read_boundary(vertex_mesh(bent)), CM_ERR_ARGUMENT, "mesh vertex 5");
  read_boundary(face_mesh(bent), 0.05);  // within a looser tolerance
  check_passed++;

  // Holes: an annulus has two boundary loops.
  TriMesh annulus;
  std::vector<VertexHandle> outer = add_vertices(annulus, octagon()), inner;
  for (const auto &p : octagon()) inner.push_back(annulus.add_vertex(TriMesh::Point(p[0] / 4, p[1] / 4, 0)));
  for (int i = 0; i < 8; i++) {
    int j = (i + 1) % 8;
    annulus.add_face(outer[i], outer[j], inner[j]);
    annulus.add_face(outer[i], inner[j], inner[i]);
  }
  // Two boundary loops: a polygon with a hole (tests/openmesh/test_loops.cc).
  CHECK(read_boundary(annulus).num_loops() == 2);

  // Two pieces.
  PolyMesh pieces = face_mesh(octagon());
  Points shifted = star();
  for (auto &p : shifted) p[0] += 10;
  pieces.add_face(add_vertices(pieces, shifted));
  CHECK_ERROR(read_boundary(pieces), CM_ERR_ARGUMENT, "2 connected parts");

  // Closed: a tetrahedron.
  TriMesh tetrahedron;
  auto t = add_vertices(tetrahedron, {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}});
  tetrahedron.add_face(t[0], t[2], t[1]);
  tetrahedron.add_face(t[0], t[1], t[3]);
  tetrahedron.add_face(t[1], t[2], t[3]);
  tetrahedron.add_face(t[2], t[0], t[3]);
  CHECK_ERROR(read_boundary(tetrahedron), CM_ERR_ARGUMENT, "closed");

  // A handle: a torus of 4 x 4 quads with one quad removed has one boundary
  // loop but Euler characteristic -1.
  PolyMesh torus;
  VertexHandle grid[4][4];
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++) {
      double u = M_PI / 2 * i, w = M_PI / 2 * j;
      grid[i][j] = torus.add_vertex(PolyMesh::Point((2 + std::cos(w)) * std::cos(u),
                                                    (2 + std::cos(w)) * std::sin(u), std::sin(w)));
    }
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++)
      if (i + j > 0)
        torus.add_face(grid[i][j], grid[(i + 1) % 4][j], grid[(i + 1) % 4][(j + 1) % 4], grid[i][(j + 1) % 4]);
  CHECK_ERROR(read_boundary(torus), CM_ERR_ARGUMENT, "Euler characteristic is -1");

  // A non-manifold vertex: two triangles meeting at one vertex.
  TriMesh bowtie;
  auto w = add_vertices(bowtie, {{{0, 0, 0}}, {{1, -1, 0}}, {{1, 1, 0}}, {{-1, 1, 0}}, {{-1, -1, 0}}});
  bowtie.add_face(w[0], w[1], w[2]);
  bowtie.add_face(w[0], w[3], w[4]);
  CHECK_ERROR(read_boundary(bowtie), CM_ERR_ARGUMENT, "vertex 0 is not manifold");

  // Polylines that are not one closed loop.
  PolyMesh open_polyline = polyline_mesh(star());
  open_polyline.new_edge(VertexHandle(0), VertexHandle(4));
  CHECK_ERROR(read_boundary(open_polyline), CM_ERR_ARGUMENT, "vertex 0 has 1 incoming and 2 outgoing");
  PolyMesh two_loops;
  auto q = add_vertices(two_loops, octagon());
  for (int i = 0; i < 4; i++) two_loops.new_edge(q[i], q[(i + 1) % 4]);
  for (int i = 4; i < 8; i++) two_loops.new_edge(q[i], q[i == 7 ? 4 : i + 1]);
  // Two loops side by side read as a polygon with a hole; the core refuses
  // the hole outside the outer loop.
  CHECK(read_boundary(two_loops).num_loops() == 2);
  std::vector<PolyMesh> side_by_side{two_loops, two_loops};
  CHECK_ERROR(compatmesh::compatible_triangulation(side_by_side), CM_ERR_SELF_INTERSECTION, "");

  // The core's own errors come through with its status, located in the mesh.
  Points crossing = octagon();
  std::swap(crossing[1], crossing[2]);  // chords 0-2 and 1-3 of a convex polygon cross
  std::vector<PolyMesh> bad{face_mesh(octagon()), vertex_mesh(crossing)};
  CHECK_ERROR(compatmesh::compatible_triangulation(bad), CM_ERR_SELF_INTERSECTION, "mesh 1, mesh vertex");
  // Different counts: without a correspondence given the counts decide,
  // as on the command line and in Python (auto); the index one, given,
  // refuses them.
  std::vector<PolyMesh> mismatched{face_mesh(octagon()), face_mesh({{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}})};
  std::vector<TriMesh> paired = compatmesh::compatible_triangulation(mismatched);
  CHECK(paired.size() == 2 && paired[0].n_faces() > 0 && paired[0].n_faces() == paired[1].n_faces());
  cm_options index;
  cm_options_init(&index);
  CHECK_ERROR(compatmesh::compatible_triangulation(mismatched, &index), CM_ERR_COUNT_MISMATCH, "");
  std::vector<PolyMesh> one{face_mesh(octagon())};
  CHECK_ERROR(compatmesh::compatible_triangulation(one), CM_ERR_ARGUMENT, "");
  // Errors of the tool name the mesh.
  std::vector<PolyMesh> second_bent{face_mesh(octagon()), face_mesh(bent)};
  CHECK_ERROR(compatmesh::compatible_triangulation(second_bent), CM_ERR_ARGUMENT, "mesh 1: ");
}

static void test_tool()
{
  PolyMesh a = face_mesh(octagon()), b = face_mesh(star());
  compatmesh::CompatibleTriangulationT<PolyMesh> tool;
  tool.add_mesh(a);
  tool.add_mesh(b);
  CHECK_ERROR(tool.stats(), CM_ERR_ARGUMENT, "run()");

  std::vector<std::string> stages;
  tool.set_progress([&](double, const char *stage) {
    stages.push_back(stage);
    return false;
  });
  tool.run();
  CHECK(!stages.empty());
  CHECK(tool.meshes().size() == 2 && tool.boundaries().size() == 2);
  CHECK(tool.stats().k == 2 && tool.stats().n == 8);
  CHECK(tool.meshes()[0].n_faces() == tool.stats().triangles);
  CHECK(tool.quality(1).min_angle_deg > 0);
  CHECK_ERROR(tool.quality(2), CM_ERR_ARGUMENT, "no geometry 2");

  // Nothing is left on the caller's meshes.
  CHECK(a.n_vertices() == 8 && a.n_faces() == 1);
  std::size_t properties = 0;
  for (auto it = a.vprops_begin(); it != a.vprops_end(); ++it) properties += *it != nullptr;
  PolyMesh fresh = face_mesh(octagon());
  std::size_t fresh_properties = 0;
  for (auto it = fresh.vprops_begin(); it != fresh.vprops_end(); ++it) fresh_properties += *it != nullptr;
  CHECK(properties == fresh_properties);

  // Cancelling, and a callback that throws.
  tool.set_progress([](double fraction, const char *) { return fraction > 0.5; });
  CHECK_ERROR(tool.run(), CM_ERR_CANCELLED, "cancelled");
  CHECK(tool.meshes().empty());
  tool.set_progress([](double, const char *) -> bool { throw std::logic_error("from the callback"); });
  bool rethrown = false;
  try {
    tool.run();
  } catch (const std::logic_error &e) {
    rethrown = std::string(e.what()) == "from the callback";
  }
  CHECK(rethrown);

  // Options reach the core.
  tool.set_progress(nullptr);
  cm_options options;
  cm_options_init(&options);
  options.method = cm_method(99);
  tool.set_options(options);
  CHECK_ERROR(tool.run(), CM_ERR_ARGUMENT, "method");
  tool.set_method(CM_METHOD_OVERLAY);
  tool.run();
  CHECK(tool.meshes().size() == 2);
  tool.set_method(CM_METHOD_PARTITION);
  tool.set_remesh(false);
  tool.run();
  CHECK(tool.stats().remesh_iterations == 0 && tool.stats().steiner == tool.stats().steiner_before_remesh);
  CHECK(tool.quality(0).min_angle_deg == tool.quality_before_remesh(0).min_angle_deg);
  tool.set_remesh(true);
  tool.set_min_angle_deg(75);
  CHECK_ERROR(tool.run(), CM_ERR_ARGUMENT, "min_angle_deg");
}

// Two sections of a pipe cut askew in different directions: their fitted
// frames take axes from each polygon's spread, a quarter turn apart; the
// tool carries the second plane's axes from the first's, so auto pairs
// vertex 0 with vertex 0 (a quarter-turn twist before).
static Points pipe_section(double z, double radius, double tilt_x, double tilt_y)
{
  Points points;
  for (int i = 0; i < 40; i++) {
    double t = 2 * M_PI * i / 40, x = radius * std::cos(t), y = radius * std::sin(t);
    points.push_back({x, y, z + tilt_x * x + tilt_y * y});
  }
  return points;
}

static void test_pipe_sections()
{
  const Points a = pipe_section(0, 1.0, 0.03, 0), b = pipe_section(3, 1.05, 0, 0.03);
  std::vector<PolyMesh> inputs{polyline_mesh(a), polyline_mesh(b)};
  compatmesh::CompatibleTriangulationT<PolyMesh> tool;
  run_auto(tool, inputs);
  const TriMesh &first = tool.meshes()[0], &second = tool.meshes()[1];
  int at = -1;
  for (auto vh : first.vertices())
    if (first.point(vh) == TriMesh::Point(a[0][0], a[0][1], a[0][2])) at = vh.idx();
  CHECK_MSG(at >= 0 && second.point(OpenMesh::VertexHandle(at)) == TriMesh::Point(b[0][0], b[0][1], b[0][2]),
            "vertex 0 of the first section met (%g, %g) of the second", at >= 0 ? second.point(OpenMesh::VertexHandle(at))[0] : 0.0,
            at >= 0 ? second.point(OpenMesh::VertexHandle(at))[1] : 0.0);
}

int main()
{
  test_forms();
  test_tilted_plane();
  test_errors();
  test_tool();
  test_pipe_sections();
  return check_summary("test_boundary");
}
