#include "sweep.h"

#include "float_check.h"
#include "layer_boundary.h"

#include "gmsh_volume.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <cerrno>
#include <unistd.h>

namespace compatmesh_plugin {

namespace {

// fit_plane's tolerance is a fraction of the bounding-box diagonal, which
// no point of the box can exceed.
constexpr double kAnyBend = 1.0;

struct Geometry {
  std::vector<double> xyz;
  std::vector<int32_t> triangles;
};

Geometry geometry_of(const compatmesh::PolyMesh &mesh)
{
  Geometry g;
  for (auto vh : mesh.vertices())
    for (int c = 0; c < 3; c++) g.xyz.push_back(mesh.point(vh)[c]);
  for (auto fh : mesh.faces())
    for (auto vh : mesh.fv_range(fh)) g.triangles.push_back(vh.idx());
  return g;
}

// Vertex order with the boundary loops first (what cm_check_geometry_loops wants),
// and the inverse map.
void boundary_first(const std::vector<int> &loop, std::size_t nv, std::vector<int> &order,
                    std::vector<int> &position)
{
  position.assign(nv, -1);
  order = loop;
  for (std::size_t i = 0; i < loop.size(); i++) position[loop[i]] = int(i);
  for (std::size_t v = 0; v < nv; v++)
    if (position[v] < 0) position[v] = int(order.size()), order.push_back(int(v));
}

}  // namespace

SectionMorph::SectionMorph(const std::vector<double> &xyz0, const std::vector<double> &xyz1,
                           const std::vector<int32_t> &triangles, const std::vector<int> &boundary,
                           const std::vector<std::size_t> &loop_sizes, const std::string &first_name,
                           const std::string &second_name)
{
  const std::size_t nv = xyz0.size() / 3, n = boundary.size();
  std::vector<int> position;
  boundary_first(boundary, nv, order_, position);
  std::vector<int32_t> reindexed(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); i++) reindexed[i] = position[triangles[i]];
  // Each layer in 2D in its own plane; the normal follows the boundary loop
  // so both layers' triangles get the same orientation in 2D, and the
  // second plane's axes are the first's carried onto it (align_frames), so
  // the 2D layers turn only as much as their planes do.
  std::vector<double> xy[2], ordered[2];
  std::vector<compatmesh::PlaneFrame> frames(2);
  const std::vector<double> *layers[2] = {&xyz0, &xyz1};
  const std::string *names[2] = {&first_name, &second_name};
  for (int g = 0; g < 2; g++) {
    for (int v : order_) ordered[g].insert(ordered[g].end(), &(*layers[g])[3 * v], &(*layers[g])[3 * v + 3]);
    try {
      frames[g] = compatmesh::fit_plane(ordered[g].data(), n, compatmesh::kDefaultPlanarityTolerance,
                                        compatmesh::NormalSign::FollowWinding, loop_sizes[0]);
    } catch (const compatmesh::PlaneError &e) {
      throw FilterError("layer '" + *names[g] + "': " + e.what());
    }
  }
  compatmesh::align_frames(frames, true);
  for (const compatmesh::PlaneFrame &frame : frames) compatmesh::append_loft_frame(frame, frames_);
  for (int g = 0; g < 2; g++) xy[g] = compatmesh::to_plane(frames[g], ordered[g].data(), nv);
  const double *geometries[2] = {xy[0].data(), xy[1].data()};
  cm_result *result = nullptr;
  cm_status s = cm_result_from_meshes_loops(geometries, 2, loop_sizes.data(), loop_sizes.size(), nv,
                                            reindexed.data(), reindexed.size() / 3, &result);
  result_.reset(result);
  if (s != CM_OK) {
    long g = -1;
    cm_result_error_location(result_.get(), &g, nullptr, nullptr);
    std::string which = g == 0 ? " (layer '" + first_name + "')" : g == 1 ? " (layer '" + second_name + "')" : "";
    std::string message = "layers '" + first_name + "' and '" + second_name +
                          "' are not a compatible pair" + which + ": " + cm_result_message(result_.get()) +
                          " (vertex and triangle numbers count the boundary loops first)";
    throw FilterError(message);
  }
  // Intrinsic weights: still convex combinations (every section valid),
  // but rotation-aware. On the regular 12-gon pair half a turn apart the
  // smallest section angle is 21.4 degrees against 4.7 with interpolated
  // mean value weights, whose stars shrink as they turn.
  cm_morph_options options;
  cm_morph_options_init(&options);
  options.method = CM_MORPH_INTRINSIC;
  cm_morph *morph = nullptr;
  s = cm_morph_create(result_.get(), &options, &morph);
  morph_.reset(morph);
  if (s != CM_OK)
    throw FilterError(std::string("the morph between the layers failed: ") + cm_morph_message(morph));
}

std::vector<double> section_at(SectionMorph &morph, double t, double *min_angle_deg)
{
  const std::size_t nv = morph.order_.size();
  std::vector<double> xy(2 * nv);
  if (cm_morph_section(morph.morph_.get(), t, xy.data(), nullptr, min_angle_deg) != CM_OK)
    throw FilterError("the morph's section at t = " + std::to_string(t) +
                      " is invalid: " + cm_morph_message(morph.morph_.get()));
  std::vector<double> placed(3 * nv), xyz(3 * nv);
  cm_loft_section(morph.frames_.data(), 2, t, xy.data(), nv, placed.data());
  for (std::size_t j = 0; j < nv; j++)
    for (int c = 0; c < 3; c++) xyz[3 * morph.order_[j] + c] = placed[3 * j + c];
  return xyz;
}

SweptVolume swept_volume(SectionMorph &morph, int sections)
{
  cm_sweep_options options;
  cm_sweep_options_init(&options);
  // A loft between the layers' planes: the core places the nodes there and
  // checks every tetrahedron in space, exactly.
  options.sections = std::size_t(sections);
  options.frames = morph.frames_.data();
  options.tets = 1;
  cm_sweep *sweep = nullptr;
  cm_status s = cm_sweep_create(morph.morph_.get(), &options, &sweep);
  compatmesh::SweepPtr owned(sweep);
  if (s != CM_OK)
    throw FilterError(std::string("the swept volume between the layers: ") + cm_sweep_message(sweep) +
                      "; nothing was added or written");
  SweptVolume volume;
  const std::size_t count = cm_sweep_num_nodes(sweep);
  volume.nodes.assign(cm_sweep_nodes(sweep), cm_sweep_nodes(sweep) + 3 * count);
  volume.tets.assign(cm_sweep_tets(sweep), cm_sweep_tets(sweep) + 4 * cm_sweep_num_tets(sweep));
  const std::size_t faces = cm_sweep_num_boundary_faces(sweep, 1);
  volume.faces.assign(cm_sweep_boundary_faces(sweep, 1), cm_sweep_boundary_faces(sweep, 1) + 4 * faces);
  for (std::size_t g = 0; g < cm_sweep_num_boundary_groups(sweep); g++)
    volume.group_names.push_back(cm_sweep_boundary_group_name(sweep, g));
  volume.group_offsets.assign(cm_sweep_boundary_group_offsets(sweep, 1),
                              cm_sweep_boundary_group_offsets(sweep, 1) + volume.group_names.size() + 1);
  volume.sections = cm_sweep_num_sections(sweep);
  cm_sweep_quality quality;
  cm_sweep_get_quality(sweep, &quality);
  volume.min_dihedral_deg = quality.min_dihedral_deg;
  return volume;
}

void write_msh(const SweptVolume &volume, const std::string &path)
{
  const std::size_t dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  for (char &c : ext) c = char(std::tolower((unsigned char)c));
  if (ext != "msh") throw FilterError("VolumeFile '" + path + "': expected a .msh file");
  const std::size_t slash = path.find_last_of('/');
  std::string temporary = path.substr(0, slash == std::string::npos ? 0 : slash + 1) + ".compatmesh-XXXXXX.msh";
  int fd = mkstemps(&temporary[0], 4);
  if (fd < 0) throw FilterError("cannot write '" + path + "': " + std::strerror(errno));
  close(fd);
  // Gmsh with its own symbols first (deep_bind): Gmsh and MeshLab's
  // libmeshlab-common both define a class PluginManager, and bound to
  // MeshLab's, Gmsh crashes in gmshFinalize.
  std::vector<const char *> names;
  for (const std::string &name : volume.group_names) names.push_back(name.c_str());
  const volume_mesh mesh = {volume.nodes.data(), volume.nodes.size() / 3, volume.tets.data(), volume.tets.size() / 4,
                            1, volume.faces.data(), volume.faces.size() / 4,
                            names.size(), names.data(), volume.group_offsets.data(), nullptr};
  const gmsh_write_options options = {4.1, 1, nullptr, 1, nullptr};
  char message[512] = "";
  const int ierr = gmsh_write_volume(temporary.c_str(), &mesh, &options, message, sizeof message);
  if (ierr || std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw FilterError("cannot write '" + path + "': " + (ierr ? std::string(message) : std::strerror(errno)));
  }
}

SweepOutcome compatible_sweep(const CMeshO &first, const CMeshO &second,
                              const std::string &first_name, const std::string &second_name,
                              int sections, const std::string &volume_file, ThrottledProgress &progress)
{
  if (sections < 1) throw FilterError("Sections must be at least 1");
  std::vector<int> index0, index1;
  compatmesh::PolyMesh mesh0, mesh1;
  try {
    mesh0 = layer_to_openmesh(first, index0);
    mesh1 = layer_to_openmesh(second, index1);
  } catch (const compatmesh::Error &e) {
    throw FilterError(std::string("reading the layers: ") + e.what());
  }
  if (mesh0.n_faces() == 0 || mesh1.n_faces() == 0)
    throw FilterError("both layers need faces: run 'Compatible Triangulation of Two Boundaries' first");
  Geometry g0 = geometry_of(mesh0), g1 = geometry_of(mesh1);
  if (g0.xyz.size() != g1.xyz.size() || g0.triangles != g1.triangles)
    throw FilterError("layers '" + first_name + "' and '" + second_name +
                    "' do not have the same vertices and faces (not a compatible pair)");

  compatmesh::Boundary loop;
  try {
    loop = compatmesh::read_boundary(mesh0);
  } catch (const compatmesh::Error &e) {
    throw FilterError("layer '" + first_name + "': " + e.what());
  }
  const std::size_t n = loop.size(), nv = g0.xyz.size() / 3;
  std::vector<int> order, position;
  boundary_first(loop.source_vertex, nv, order, position);
  std::vector<int32_t> reindexed(g0.triangles.size());
  for (std::size_t i = 0; i < reindexed.size(); i++) reindexed[i] = position[g0.triangles[i]];
  SectionMorph morph(g0.xyz, g1.xyz, g0.triangles, loop.source_vertex, loop.loop_sizes, first_name, second_name);
  const std::size_t outer = loop.loop_sizes[0];
  progress.report(0.05, "morph");
  // The volume's exact check (every tetrahedron positive in space) runs
  // whether or not the volume is written: where the layers' planes cross
  // inside the polygons the lateral surface alone folded inside out, and
  // only the volume saw it. Its sections at the same times as the layers'
  // (more where a cell needs them): the layers' sections are its faces.
  const SweptVolume volume = swept_volume(morph, sections + 2);
  progress.report(0.1, "volume");

  // Sections keep the first layer's vertex quality (the Steiner flags).
  std::vector<float> quality;
  if (vcg::tri::HasPerVertexQuality(first))
    for (int v : index0) quality.push_back(float(first.vert[v].cQ()));

  SweepOutcome outcome;
  std::vector<std::vector<float>> levels;  // the boundary loops of every level, for the lateral surface
  auto add_level = [&](const std::vector<float> &xyz) {
    std::vector<float> ring;
    for (int v : loop.source_vertex) ring.insert(ring.end(), &xyz[3 * v], &xyz[3 * v + 3]);
    levels.push_back(std::move(ring));
  };
  add_level(std::vector<float>(g0.xyz.begin(), g0.xyz.end()));
  double smallest_angle = 180;
  for (int s = 1; s <= sections; s++) {
    const double t = double(s) / (sections + 1);
    double angle = 0;
    const std::vector<float> xyz = round_to_float(section_at(morph, t, &angle));
    smallest_angle = std::min(smallest_angle, angle);
    std::vector<double> ring;  // the boundary, for the plane of the section
    std::vector<float> ordered;
    for (int v : order) ordered.insert(ordered.end(), &xyz[3 * v], &xyz[3 * v + 3]);
    for (std::size_t i = 0; i < 3 * n; i++) ring.push_back(ordered[i]);
    // Between non-parallel planes a section is slightly bent: it is valid
    // when it is a graph over its best-fitting plane, so any bend is
    // accepted by the fit and the exact check decides.
    std::string problem;
    try {
      compatmesh::PlaneFrame frame =
          compatmesh::fit_plane(ring.data(), n, kAnyBend, compatmesh::NormalSign::FollowWinding, outer);
      problem = check_float_geometry(ordered, loop.loop_sizes, frame, reindexed);
    } catch (const compatmesh::PlaneError &e) {
      problem = e.what();
    }
    if (!problem.empty())
      throw FilterError("section " + std::to_string(s) + " of " + std::to_string(sections) +
                      " (t = " + std::to_string(t) + ") is invalid: " + problem + "; nothing was added");
    LayerData layer;
    layer.label = "section " + std::to_string(s);
    layer.xyz = xyz;
    layer.triangles = g0.triangles;
    layer.quality = quality;
    outcome.layers.push_back(std::move(layer));
    add_level(xyz);
    progress.report(0.1 + 0.8 * double(s) / sections, "sections");
  }
  add_level(std::vector<float>(g1.xyz.begin(), g1.xyz.end()));

  // Lateral surface: one ring per loop (the outer loop and every hole), one
  // quad per boundary edge between consecutive levels, split into two
  // triangles.
  LayerData lateral;
  lateral.label = "lateral surface";
  for (const std::vector<float> &ring : levels) lateral.xyz.insert(lateral.xyz.end(), ring.begin(), ring.end());
  // Outward whatever the layers' order and the loops' direction: over a
  // closed surface the flux of x - centre (taken per level, in the level's
  // own plane) is twice the enclosed volume, so its sign over the outer
  // loop's quads says which way they face. Every loop follows the faces
  // (a hole runs against the outer loop), so the same rule turns each
  // hole's ring away from the material, into the hole.
  double flux = 0;
  for (std::size_t s = 0; s + 1 < levels.size(); s++) {
    const std::vector<float> &ring = levels[s];
    double centre[3] = {0, 0, 0};
    for (std::size_t i = 0; i < outer; i++)
      for (int c = 0; c < 3; c++) centre[c] += ring[3 * i + c] / double(outer);
    for (std::size_t i = 0; i < outer; i++) {
      const float *a = &ring[3 * i], *b = &ring[3 * loop.next(i)], *d = &levels[s + 1][3 * i];
      double u[3], v[3];
      for (int c = 0; c < 3; c++) u[c] = double(b[c]) - a[c], v[c] = double(d[c]) - a[c];
      const double normal[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      for (int c = 0; c < 3; c++) flux += normal[c] * (0.5 * (double(a[c]) + b[c]) - centre[c]);
    }
  }
  const bool outward = flux >= 0;
  for (std::size_t s = 0; s + 1 < levels.size(); s++)
    for (std::size_t i = 0; i < n; i++) {
      int32_t a = int32_t(s * n + i), b = int32_t(s * n + loop.next(i));
      int32_t c = b + int32_t(n), d = a + int32_t(n);
      if (outward) lateral.triangles.insert(lateral.triangles.end(), {a, b, c, a, c, d});
      else lateral.triangles.insert(lateral.triangles.end(), {a, c, b, a, d, c});
    }
  outcome.layers.push_back(std::move(lateral));
  if (!volume_file.empty()) {
    progress.report(0.95, "writing the volume");
    write_msh(volume, volume_file);
    char dihedral[32];
    std::snprintf(dihedral, sizeof dihedral, "%.2f", volume.min_dihedral_deg);
    outcome.log.push_back("volume: " + std::to_string(volume.tets.size() / 4) + " tetrahedra, " +
                          std::to_string(volume.nodes.size() / 3) + " nodes in " + std::to_string(volume.sections) +
                          " sections, each positive (exact), smallest dihedral angle " + dihedral +
                          " degrees, written to " + volume_file);
  }
  progress.report(1.0, "done");
  char angle_text[32];
  std::snprintf(angle_text, sizeof angle_text, "%.2f", smallest_angle);
  outcome.log.push_back(std::to_string(sections) + " intermediate sections by convex-combination morph "
                        "(smallest angle " + angle_text + " degrees in the plane), each checked valid after "
                        "float rounding; lateral surface of " +
                        std::to_string(2 * n * (levels.size() - 1)) + " triangles in " +
                        std::to_string(loop.num_loops()) + (loop.num_loops() == 1 ? " ring" : " rings"));
  return outcome;
}

}  // namespace compatmesh_plugin
