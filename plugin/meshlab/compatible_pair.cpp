#include "compatible_pair.h"

#include "float_check.h"
#include "layer_boundary.h"

#include <compatmesh/resample.hh>

#include <algorithm>
#include <cstdio>

namespace compatmesh_plugin {

namespace {

compatmesh::Boundary read_layer(const CMeshO &layer, const std::string &name, bool &is_disk)
{
  try {
    return layer_boundary(layer, is_disk);
  } catch (const compatmesh::Error &e) {
    throw FilterError("layer '" + name + "': " + e.what());
  }
}

// The polygon refitted after its vertices changed: a disk's frame follows
// the (possibly reversed) boundary as the adapter's does, a polyline's
// keeps the canonical normal.
compatmesh::Boundary rebuild(std::vector<double> xyz, std::vector<int> source, bool is_disk,
                             const std::string &name)
{
  try {
    return compatmesh::make_boundary(std::move(xyz), std::move(source),
                                     compatmesh::kDefaultPlanarityTolerance,
                                     is_disk ? compatmesh::NormalSign::FollowWinding
                                             : compatmesh::NormalSign::Canonical);
  } catch (const compatmesh::Error &e) {
    throw FilterError("layer '" + name + "': " + e.what());
  }
}

// Starts the polygon at vertex offset (mod n) and optionally reverses it
// (keeping that start vertex first).
compatmesh::Boundary reorder(const compatmesh::Boundary &b, long offset, bool reverse, bool is_disk,
                             const std::string &name)
{
  const long n = long(b.size());
  std::vector<double> xyz;
  std::vector<int> source;
  for (long i = 0; i < n; i++) {
    long k = reverse ? -i : i;
    long j = (((offset + k) % n) + n) % n;
    xyz.insert(xyz.end(), b.xyz.begin() + 3 * j, b.xyz.begin() + 3 * j + 3);
    source.push_back(b.source_vertex[j]);
  }
  return rebuild(std::move(xyz), std::move(source), is_disk, name);
}

std::string degrees(double value)
{
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", value);
  return buf;
}

}  // namespace

PairOutcome compatible_pair(const CMeshO &first, const CMeshO &second,
                            const std::string &first_name, const std::string &second_name,
                            const PairSettings &settings, ThrottledProgress &progress)
{
  PairOutcome outcome;
  bool disk[2];
  std::vector<compatmesh::Boundary> polygons;
  polygons.push_back(read_layer(first, first_name, disk[0]));
  polygons.push_back(read_layer(second, second_name, disk[1]));
  const std::string names[2] = {first_name, second_name};
  for (int g = 0; g < 2; g++)
    if (polygons[g].size() < 3)
      throw FilterError("layer '" + names[g] + "': its boundary has " +
                      std::to_string(polygons[g].size()) + " vertices; need at least 3");
  if (settings.start_offset != 0 || settings.reverse_second)
    polygons[1] = reorder(polygons[1], settings.start_offset, settings.reverse_second, disk[1],
                          second_name);

  const std::size_t n0 = polygons[0].size(), n1 = polygons[1].size();
  if (n0 != n1) {
    if (!settings.resample)
      throw FilterError("the boundaries have " + std::to_string(n0) + " and " + std::to_string(n1) +
                      " vertices; tick 'Resample to a common count' or give equal counts");
    compatmesh::ResampledLoop a, b;
    compatmesh::resample_common_count(polygons[0].xyz.data(), n0, polygons[1].xyz.data(), n1, a, b);
    for (int &s : a.source) s = s < 0 ? -1 : polygons[0].source_vertex[s];
    for (int &s : b.source) s = s < 0 ? -1 : polygons[1].source_vertex[s];
    polygons[0] = rebuild(std::move(a.xyz), std::move(a.source), disk[0], first_name);
    polygons[1] = rebuild(std::move(b.xyz), std::move(b.source), disk[1], second_name);
    outcome.log.push_back("resampled " + std::to_string(n0) + " and " + std::to_string(n1) +
                          " boundary vertices to " + std::to_string(polygons[0].size()) +
                          " each by arc length (every input vertex kept)");
  }

  cm_options options;
  cm_options_init(&options);
  options.min_angle_deg = settings.min_angle_deg;
  options.max_steiner = settings.max_steiner;
  options.remesh = settings.remesh ? 1 : 0;
  compatmesh::ResultPtr result;
  try {
    result = compatmesh::triangulate(polygons, options, progress.as_function(0, 0.95));
  } catch (const compatmesh::Error &e) {
    std::string message = e.what();
    if (e.status() == CM_ERR_ORIENTATION_MISMATCH)
      message += " (toggle 'Reverse second boundary')";
    throw FilterError(message);
  }

  const cm_result *r = result.get();
  const cm_stats *stats = cm_result_stats(r);
  const std::size_t n = stats->n, nv = cm_result_num_vertices(r), nt = cm_result_num_triangles(r);
  const int32_t *tri = cm_result_triangles(r);
  const std::vector<int32_t> triangles(tri, tri + 3 * nt);
  for (int g = 0; g < 2; g++) {
    const compatmesh::Boundary &b = polygons[g];
    const double *xy = cm_result_vertices(r, g);
    std::vector<double> xyz(b.xyz.begin(), b.xyz.end());  // the input vertices, as read
    for (std::size_t v = n; v < nv; v++) {
      auto p = b.frame.to_space(xy[2 * v], xy[2 * v + 1]);
      xyz.insert(xyz.end(), p.begin(), p.end());
    }
    LayerData layer;
    layer.label = "compatible " + names[g];
    layer.xyz = round_to_float(xyz);
    layer.triangles = triangles;
    layer.quality.assign(nv, 0.0f);
    std::fill(layer.quality.begin() + n, layer.quality.end(), 1.0f);  // 1 marks Steiner vertices
    std::string problem = check_float_geometry(layer.xyz, n, b.frame, triangles);
    if (!problem.empty())
      throw FilterError("the compatible triangulation is valid in double precision but not after "
                      "rounding to MeshLab's float coordinates (layer '" + names[g] + "': " +
                      problem + "); nothing was added");
    outcome.layers.push_back(std::move(layer));
  }
  progress.report(1.0, "done");

  cm_quality q[2];
  cm_result_quality(r, 0, &q[0]);
  cm_result_quality(r, 1, &q[1]);
  outcome.log.push_back("compatible triangulation: " + std::to_string(n) + " boundary vertices, " +
                        std::to_string(stats->steiner) + " Steiner vertices (vertex quality 1), " +
                        std::to_string(nt) + " triangles");
  outcome.log.push_back("smallest angle: " + degrees(q[0].min_angle_deg) + " deg in '" + first_name +
                        "', " + degrees(q[1].min_angle_deg) + " deg in '" + second_name + "'");
  if (stats->fallback_count > 0)
    outcome.log.push_back("overlay fallback used " + std::to_string(stats->fallback_count) + " times");
  std::string ceiling = "no compatible triangulation of this pair can have a smallest angle above " +
                        degrees(stats->ceiling_deg) + " degrees (corner fan " + degrees(stats->corner_fan_cap_deg) +
                        ", correspondence bound " + degrees(stats->correspondence_bound_deg);
  if (stats->correspondence_bound_before_deg > 0)
    ceiling += "; before choosing the starts " + degrees(stats->correspondence_bound_before_deg);
  outcome.log.push_back(ceiling + ")");
  return outcome;
}

}  // namespace compatmesh_plugin
