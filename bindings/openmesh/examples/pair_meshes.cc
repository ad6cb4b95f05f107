// pair_meshes: compatible triangulations of two polygons read from mesh files.
//
//   pair_meshes [options] IN_A IN_B OUT_A OUT_B
//
//   --method partition|overlay   how the first triangulation is built
//   --no-remesh                  return the construction as built
//   --min-angle DEGREES          the remesher's target smallest angle
//   --max-steiner N              most Steiner vertices refinement may add
//   --tolerance T                planarity tolerance (fraction of the size)
//
// IN_A and IN_B hold one polygon each, in any format OpenMesh reads (OFF,
// OBJ, PLY, STL, OM): a disk-shaped mesh (its boundary), a single polygonal
// face, or face-less vertices in polygon order. OpenMesh's readers drop OBJ
// `l` lines and PLY edges, so a section saved as edges is read as its
// vertices in file order; where that is not a polygon the error says so.
// Their vertices correspond by polygon index. OUT_A and OUT_B receive the
// two triangle meshes, which share one connectivity; the format follows the
// file extension. OpenMesh 9 writes OFF, OBJ, PLY and STL coordinates as
// float; OM keeps doubles.
#include <compatmesh/openmesh.hh>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace {

// Does the file hold edges that OpenMesh's readers drop: OBJ `l` lines,
// a PLY `element edge` with edges in it? Read only where a face-less mesh
// did not make a polygon, to say why.
bool has_dropped_edges(const std::string &path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  bool ply = false;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line == "ply") ply = true;
    if (ply) {
      if (line.rfind("element edge ", 0) == 0) return std::atol(line.c_str() + 13) > 0;
      if (line == "end_header") return false;
    } else if (line.rfind("l ", 0) == 0) {
      return true;
    }
  }
  return false;
}

int usage()
{
  std::fprintf(stderr,
               "usage: pair_meshes [--method partition|overlay] [--no-remesh] [--min-angle DEGREES]\n"
               "                   [--max-steiner N] [--tolerance T] IN_A IN_B OUT_A OUT_B\n");
  return 2;
}

}  // namespace

int main(int argc, char **argv)
{
  compatmesh::CompatibleTriangulationT<compatmesh::PolyMesh> tool;
  std::vector<std::string> files;
  for (int i = 1; i < argc; i++) {
    std::string arg = argv[i];
    bool has_value = i + 1 < argc;
    if (arg == "--method" && has_value) {
      std::string method = argv[++i];
      if (method != "partition" && method != "overlay") return usage();
      tool.set_method(method == "partition" ? CM_METHOD_PARTITION : CM_METHOD_OVERLAY);
    } else if (arg == "--no-remesh") {
      tool.set_remesh(false);
    } else if (arg == "--min-angle" && has_value) {
      tool.set_min_angle_deg(std::atof(argv[++i]));
    } else if (arg == "--max-steiner" && has_value) {
      tool.set_max_steiner(std::atol(argv[++i]));
    } else if (arg == "--tolerance" && has_value) {
      tool.set_planarity_tolerance(std::atof(argv[++i]));
    } else if (!arg.empty() && arg[0] == '-') {
      return usage();
    } else {
      files.push_back(arg);
    }
  }
  if (files.size() != 4) return usage();

  // PolyMesh keeps a single polygonal face as it is; TriMesh would fan it.
  std::vector<compatmesh::PolyMesh> inputs(2);
  for (int i = 0; i < 2; i++) {
    if (!OpenMesh::IO::read_mesh(inputs[i], files[i])) {
      std::fprintf(stderr, "pair_meshes: cannot read %s\n", files[i].c_str());
      return 1;
    }
  }

  tool.add_mesh(inputs[0]);
  tool.add_mesh(inputs[1]);
  try {
    tool.run();
  } catch (const compatmesh::Error &e) {
    std::string why = e.what();
    for (int i = 0; i < 2; i++)
      if (inputs[i].n_faces() == 0 && has_dropped_edges(files[i]))
        why += "; " + files[i] + ": OpenMesh's reader drops its edges (OBJ l lines, PLY edges) and takes "
               "its vertices in file order, which need not be the polygon's (compatmesh triangulate reads the edges)";
    std::fprintf(stderr, "pair_meshes: %s\n", why.c_str());
    return 1;
  }

  for (int i = 0; i < 2; i++) {
    // 17 digits: OpenMesh's default, 6, would round the coordinates.
    if (!OpenMesh::IO::write_mesh(tool.meshes()[i], files[2 + i], OpenMesh::IO::Options::Default, 17)) {
      std::fprintf(stderr, "pair_meshes: cannot write %s\n", files[2 + i].c_str());
      return 1;
    }
  }
  const cm_stats &stats = tool.stats();
  std::printf("%zu vertices (%zu Steiner; %zu before remeshing), %zu triangles\n", stats.vertices,
              stats.steiner, stats.steiner_before_remesh, stats.triangles);
  for (int i = 0; i < 2; i++)
    std::printf("%s: minimum angle %.2f degrees\n", files[2 + i].c_str(),
                tool.quality(i).min_angle_deg);
  return 0;
}
