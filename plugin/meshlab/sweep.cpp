#include "sweep.h"

#include "float_check.h"
#include "layer_boundary.h"

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

// Vertex order with the boundary loop first (what cm_check_geometry wants),
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

std::vector<double> section_at(const std::vector<double> &start, const std::vector<double> &end,
                               double t)
{
  std::vector<double> xyz(start.size());
  for (std::size_t i = 0; i < start.size(); i++) xyz[i] = (1 - t) * start[i] + t * end[i];
  return xyz;
}

SweepOutcome compatible_sweep(const CMeshO &first, const CMeshO &second,
                              const std::string &first_name, const std::string &second_name,
                              int sections, ThrottledProgress &progress)
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

  // Sections keep the first layer's vertex quality (the Steiner flags).
  std::vector<float> quality;
  if (vcg::tri::HasPerVertexQuality(first))
    for (int v : index0) quality.push_back(float(first.vert[v].cQ()));

  SweepOutcome outcome;
  std::vector<std::vector<float>> levels;  // boundary loops of every level, for the lateral surface
  auto add_level = [&](const std::vector<float> &xyz) {
    std::vector<float> ring;
    for (int v : loop.source_vertex) ring.insert(ring.end(), &xyz[3 * v], &xyz[3 * v + 3]);
    levels.push_back(std::move(ring));
  };
  add_level(std::vector<float>(g0.xyz.begin(), g0.xyz.end()));
  for (int s = 1; s <= sections; s++) {
    const double t = double(s) / (sections + 1);
    const std::vector<float> xyz = round_to_float(section_at(g0.xyz, g1.xyz, t));
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
          compatmesh::fit_plane(ring.data(), n, kAnyBend, compatmesh::NormalSign::FollowWinding);
      problem = check_float_geometry(ordered, n, frame, reindexed);
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
    progress.report(double(s) / sections, "sections", 0, 0.9);
  }
  add_level(std::vector<float>(g1.xyz.begin(), g1.xyz.end()));

  // Lateral surface: one quad per boundary edge between consecutive levels,
  // split into two triangles.
  LayerData lateral;
  lateral.label = "lateral surface";
  for (const std::vector<float> &ring : levels) lateral.xyz.insert(lateral.xyz.end(), ring.begin(), ring.end());
  for (std::size_t s = 0; s + 1 < levels.size(); s++)
    for (std::size_t i = 0; i < n; i++) {
      int32_t a = int32_t(s * n + i), b = int32_t(s * n + (i + 1) % n);
      int32_t c = b + int32_t(n), d = a + int32_t(n);
      lateral.triangles.insert(lateral.triangles.end(), {a, b, c, a, c, d});
    }
  outcome.layers.push_back(std::move(lateral));
  progress.report(1.0, "done");
  outcome.log.push_back(std::to_string(sections) + " intermediate sections, each checked valid after "
                        "float rounding; lateral surface of " +
                        std::to_string(2 * n * (levels.size() - 1)) + " triangles");
  return outcome;
}

}  // namespace compatmesh_plugin
