#include <compatmesh/openmesh.hh>

#include <iostream>

int main()
{
  // Two polygons with corresponding vertices, e.g. single-face OFF files.
  std::vector<compatmesh::PolyMesh> polygons(2);
  if (!OpenMesh::IO::read_mesh(polygons[0], "a.off") ||
      !OpenMesh::IO::read_mesh(polygons[1], "b.off"))
    return 1;

  try {
    // One triangle mesh per polygon, all with the same connectivity.
    std::vector<compatmesh::TriMesh> meshes = compatmesh::compatible_triangulation(polygons);
    std::cout << meshes[0].n_faces() << " triangles\n";
    OpenMesh::IO::write_mesh(meshes[0], "a_tri.off", OpenMesh::IO::Options::Default, 17);
    OpenMesh::IO::write_mesh(meshes[1], "b_tri.off", OpenMesh::IO::Options::Default, 17);
  } catch (const compatmesh::Error &e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
}
