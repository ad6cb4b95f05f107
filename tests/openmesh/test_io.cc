// Polygons and results through OpenMesh's readers and writers (OFF, OBJ,
// PLY, STL, OM), and what the OBJ reader makes of polylines.
#include "helpers.hh"

#include <OpenMesh/Tools/Utils/MeshCheckerT.hh>

#include <fstream>
#include <map>
#include <set>

using namespace OpenMesh;

// A face as the positions of its corners, rotated to start at the smallest,
// so two meshes can be compared whatever their numbering.
template <class Mesh>
std::set<std::vector<double>> faces_by_position(const Mesh &mesh)
{
  std::set<std::vector<double>> faces;
  for (FaceHandle fh : mesh.faces()) {
    std::vector<std::vector<double>> corners;
    for (VertexHandle vh : mesh.fv_range(fh)) {
      auto p = mesh.point(vh);
      corners.push_back({double(p[0]), double(p[1]), double(p[2])});
    }
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    std::vector<double> flat;
    for (const auto &c : corners) flat.insert(flat.end(), c.begin(), c.end());
    faces.insert(flat);
  }
  return faces;
}

// Rounds to float, as the file formats other than OM do.
static std::set<std::vector<double>> as_float(std::set<std::vector<double>> faces)
{
  std::set<std::vector<double>> out;
  for (auto f : faces) {
    for (double &x : f) x = float(x);
    out.insert(f);
  }
  return out;
}

static bool write(const TriMesh &mesh, const std::string &file)
{
  return IO::write_mesh(mesh, file, IO::Options::Default, 17);  // the default, 6 digits, would round
}

// The points rounded to float, as OFF, OBJ, PLY and STL store them.
static Points rounded(Points points)
{
  for (auto &p : points)
    for (double &x : p) x = float(x);
  return points;
}

int main()
{
  // OpenMesh 9's readers and writers for OFF, OBJ, PLY and STL go through
  // float coordinates, also for double meshes; only OM keeps doubles.
  const std::map<std::string, bool> keeps_doubles{{"off", false}, {"obj", false}, {"om", true},
                                                  {"ply", false}, {"stl", false}};
  std::vector<TriMesh> inputs{fan_mesh(tilted(octagon())), fan_mesh(tilted(star()))};
  std::vector<TriMesh> inputs_as_float{fan_mesh(rounded(tilted(octagon()))), fan_mesh(rounded(tilted(star())))};
  std::vector<TriMesh> expected = compatmesh::compatible_triangulation(inputs);
  std::vector<TriMesh> expected_from_float = compatmesh::compatible_triangulation(inputs_as_float);

  // Inputs written and read back by OpenMesh give the same result as the
  // same coordinates in memory.
  for (const auto &[extension, exact] : keeps_doubles) {
    std::vector<PolyMesh> read(2);
    bool io = true;
    for (int g = 0; g < 2; g++) {
      std::string file = "io_input_" + std::to_string(g) + "." + extension;
      io = io && write(inputs[g], file) && IO::read_mesh(read[g], file);
    }
    CHECK_MSG(io, "%s: write or read failed", extension.c_str());
    if (!io) continue;
    std::vector<TriMesh> outputs;
    try {
      outputs = compatmesh::compatible_triangulation(read);
    } catch (const compatmesh::Error &e) {
      CHECK_MSG(false, "%s: %s", extension.c_str(), e.what());
      continue;
    }
    for (int g = 0; g < 2; g++)
      CHECK_MSG(faces_by_position(outputs[g]) == faces_by_position((exact ? expected : expected_from_float)[g]),
                "%s: geometry %d: different triangles", extension.c_str(), g);
  }

  // Results written by OpenMesh read back as the same triangles.
  const auto expected_faces = faces_by_position(expected[1]);
  for (const auto &[extension, exact] : keeps_doubles) {
    std::string file = "io_result." + extension;
    TriMesh read;
    CHECK_MSG(write(expected[1], file) && IO::read_mesh(read, file), "%s: write or read failed", extension.c_str());
    CHECK(Utils::MeshCheckerT<TriMesh>(read).check());
    CHECK_MSG(faces_by_position(read) == (exact ? expected_faces : as_float(expected_faces)),
              "%s: the triangles read back differ", extension.c_str());
  }

  // OM keeps the persistent vertex properties.
  {
    TriMesh read;
    VPropHandleT<int> input_index;
    read.add_property(input_index, compatmesh::kInputIndexProperty);
    IO::read_mesh(read, "io_result.om");
    int wrong = 0;
    for (VertexHandle vh : read.vertices()) wrong += read.property(input_index, vh) != (vh.idx() < 8 ? vh.idx() : -1);
    CHECK_MSG(wrong == 0, "om: %d vertices lost their input index", wrong);
  }

  // OpenMesh's OBJ reader drops `l` elements and keeps the vertices in file
  // order: the polygon is the vertices in that order.
  {
    std::ofstream obj("io_polyline.obj");
    obj.precision(17);
    for (const auto &p : star()) obj << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
    obj << "l 1 2 3 4 5 6 7 8 1\n";
  }
  PolyMesh polyline;
  CHECK(IO::read_mesh(polyline, "io_polyline.obj"));
  CHECK(polyline.n_vertices() == 8 && polyline.n_edges() == 0 && polyline.n_faces() == 0);
  compatmesh::Boundary boundary = compatmesh::read_boundary(polyline);
  CHECK(boundary.size() == 8 && boundary.source_vertex[7] == 7);
  CHECK(boundary.xy[2] == float(star()[1][0]) && boundary.xy[3] == float(star()[1][1]));

  // So does an OFF file without faces.
  CHECK(IO::write_mesh(vertex_mesh(octagon()), "io_vertices.off", IO::Options::Default, 17));
  PolyMesh vertices_only;
  CHECK(IO::read_mesh(vertices_only, "io_vertices.off") && vertices_only.n_faces() == 0);
  std::vector<PolyMesh> pair{vertices_only, polyline};
  CHECK(compatmesh::compatible_triangulation(pair).size() == 2);

  return check_summary("test_io");
}
