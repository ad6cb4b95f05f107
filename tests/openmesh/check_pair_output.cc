// check_pair_output IN_A IN_B OUT_A OUT_B: checks what pair_meshes (or the
// README example) wrote: two valid triangle meshes with one connectivity,
// whose first vertices are the input polygons' vertices.
#include "helpers.hh"

#include <OpenMesh/Tools/Utils/MeshCheckerT.hh>

using namespace OpenMesh;

int main(int argc, char **argv)
{
  if (argc != 5) {
    std::fprintf(stderr, "usage: check_pair_output IN_A IN_B OUT_A OUT_B\n");
    return 2;
  }
  PolyMesh inputs[2];
  TriMesh outputs[2];
  for (int i = 0; i < 2; i++) {
    CHECK_MSG(IO::read_mesh(inputs[i], argv[1 + i]), "cannot read %s", argv[1 + i]);
    CHECK_MSG(IO::read_mesh(outputs[i], argv[3 + i]), "cannot read %s", argv[3 + i]);
  }
  if (check_failed) return check_summary("check_pair_output");

  for (int i = 0; i < 2; i++) {
    CHECK(Utils::MeshCheckerT<TriMesh>(outputs[i]).check());
    compatmesh::Boundary polygon = compatmesh::read_boundary(inputs[i]);
    int moved = 0;
    for (std::size_t v = 0; v < polygon.size(); v++) {
      TriMesh::Point p = outputs[i].point(VertexHandle(int(v)));
      for (int c = 0; c < 3; c++) moved += p[c] != polygon.xyz[3 * v + c];
    }
    CHECK_MSG(moved == 0, "%s: %d input coordinates changed", argv[3 + i], moved);
    // The output's boundary is the input polygon.
    compatmesh::Boundary output_polygon = compatmesh::read_boundary(outputs[i]);
    CHECK(output_polygon.xyz == polygon.xyz);
  }

  CHECK(outputs[0].n_vertices() == outputs[1].n_vertices());
  CHECK(outputs[0].n_faces() == outputs[1].n_faces());
  int different = 0;
  for (FaceHandle fh : outputs[0].faces()) {
    std::vector<int> a, b;
    for (VertexHandle vh : outputs[0].fv_range(fh)) a.push_back(vh.idx());
    for (VertexHandle vh : outputs[1].fv_range(FaceHandle(fh.idx()))) b.push_back(vh.idx());
    different += a != b;
  }
  CHECK_MSG(different == 0, "%d faces differ between the two outputs", different);
  std::printf("%zu vertices, %zu faces each\n", outputs[0].n_vertices(), outputs[0].n_faces());
  return check_summary("check_pair_output");
}
