#include "compatible_pair.h"

#include "float_check.h"
#include "layer_boundary.h"


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

// The pins text "I,J; I,J ..." as pairs of boundary positions (the
// polygons' indices), from the layers' vertex numbers.
std::vector<std::size_t> parse_pins(const std::string &text, const compatmesh::Boundary *polygons,
                                    const std::string *names)
{
  std::vector<std::size_t> pins;
  std::size_t at = 0;
  while (true) {
    at = text.find_first_not_of(" \t;", at);
    if (at == std::string::npos) break;
    std::size_t end = text.find(';', at);
    std::string item = text.substr(at, end == std::string::npos ? std::string::npos : end - at);
    while (!item.empty() && (item.back() == ' ' || item.back() == '\t')) item.pop_back();
    long v[2];
    char tail = 0;
    if (std::sscanf(item.c_str(), " %ld , %ld %c", &v[0], &v[1], &tail) != 2 || v[0] < 0 || v[1] < 0)
      throw FilterError("Pins: '" + item + "' is not a pair 'I,J' of vertex numbers (pairs separated by ';')");
    for (int g = 0; g < 2; g++) {
      const std::vector<int> &source = polygons[g].source_vertex;
      auto it = std::find(source.begin(), source.end(), int(v[g]));
      if (it == source.end())
        throw FilterError("Pins: '" + item + "': vertex " + std::to_string(v[g]) + " of layer '" +
                          names[g] + "' is not on its boundary");
      pins.push_back(std::size_t(it - source.begin()));
    }
    at = end;
  }
  return pins;
}

const char *correspondence_name(cm_correspondence c)
{
  return c == CM_CORRESPOND_INDEX ? "index" : c == CM_CORRESPOND_ARCLENGTH ? "arc length"
         : c == CM_CORRESPOND_AUTO ? "auto" : "similarity";
}

// A number for the log: angles with two decimals.
std::string text_of(double value, const char *format = "%.2f")
{
  char buf[32];
  std::snprintf(buf, sizeof buf, format, value);
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
  compatmesh::align_boundaries(polygons);  // the second plane's axes carried from the first's
  const std::string names[2] = {first_name, second_name};
  // Loop l of one layer is paired with loop l of the other.
  auto loops = [](std::size_t count) { return std::to_string(count) + (count == 1 ? " boundary loop" : " boundary loops"); };
  if (polygons[0].num_loops() != polygons[1].num_loops())
    throw FilterError("layer '" + second_name + "' has " + loops(polygons[1].num_loops()) + " but layer '" +
                      first_name + "' has " + std::to_string(polygons[0].num_loops()) +
                      "; need the same number (one outer loop and its holes)");
  for (int g = 0; g < 2; g++)
    if (polygons[g].size() < 3)
      throw FilterError("layer '" + names[g] + "': its boundary has " +
                      std::to_string(polygons[g].size()) + " vertices; need at least 3");
  const std::vector<std::size_t> pins = parse_pins(settings.pins, polygons.data(), names);
  if (!pins.empty() && settings.correspondence == CM_CORRESPOND_INDEX)
    throw FilterError("Pins need the correspondence 'arc length' or 'auto' (with 'index', vertex i is vertex i)");

  cm_options options;
  cm_options_init(&options);
  options.min_angle_deg = settings.min_angle_deg;
  options.max_steiner = settings.max_steiner;
  options.remesh = settings.remesh ? 1 : 0;
  options.correspondence = settings.correspondence;
  options.pins = pins.empty() ? nullptr : pins.data();
  options.num_pins = pins.size() / 2;
  options.max_edge = settings.max_edge;
  options.time_limit = settings.time_limit;
  compatmesh::ResultPtr result;
  try {
    result = compatmesh::triangulate(polygons, options, progress.as_function(0, 0.95));
  } catch (const compatmesh::Error &e) {
    std::string message = e.what();
    if (e.status() == CM_ERR_ORIENTATION_MISMATCH || e.status() == CM_ERR_COUNT_MISMATCH)
      message += " (with Correspondence 'auto' the boundaries need not agree)";
    throw FilterError(message);
  }

  const cm_result *r = result.get();
  const cm_stats *stats = cm_result_stats(r);
  const std::size_t n = stats->n, nv = cm_result_num_vertices(r), nt = cm_result_num_triangles(r);
  const int32_t *tri = cm_result_triangles(r);
  const std::vector<int32_t> triangles(tri, tri + 3 * nt);
  // The result's loops: its boundary vertices run loop by loop, each on the
  // input loop it came from.
  std::vector<std::size_t> loop_of(polygons[0].size()), loop_sizes(polygons[0].num_loops(), 0);
  for (std::size_t l = 0, v = 0; l < polygons[0].num_loops(); l++)
    for (std::size_t j = 0; j < polygons[0].loop_sizes[l]; j++) loop_of[v++] = l;
  for (std::size_t v = 0; v < n; v++) loop_sizes[loop_of[std::size_t(cm_result_boundary_source(r, 0, v, nullptr))]]++;
  for (int g = 0; g < 2; g++) {
    const compatmesh::Boundary &b = polygons[g];
    const double *xy = cm_result_vertices(r, g);
    // Boundary vertices: the input vertices as read, and points on the
    // input edges (in 3D, at the core's parameter) where the other
    // boundary has a vertex.
    std::vector<double> xyz;
    for (std::size_t v = 0; v < n; v++) {
      double t = 0;
      const std::size_t e = std::size_t(cm_result_boundary_source(r, g, v, &t)), f = b.next(e);
      for (int c = 0; c < 3; c++)
        xyz.push_back(t == 0 ? b.xyz[3 * e + c] : b.xyz[3 * e + c] + t * (b.xyz[3 * f + c] - b.xyz[3 * e + c]));
    }
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
    std::string problem = check_float_geometry(layer.xyz, loop_sizes, b.frame, triangles);
    if (!problem.empty())
      throw FilterError("the compatible triangulation is valid in double precision but not after "
                      "rounding to MeshLab's float coordinates (layer '" + names[g] + "': " +
                      problem + "); nothing was added");
    outcome.layers.push_back(std::move(layer));
  }
  progress.report(1.0, "done");

  outcome.log.push_back(std::string("correspondence: ") + correspondence_name(settings.correspondence) +
                        ", made: " + cm_correspondence_choice_name(stats->correspondence_choice) + " (" +
                        std::to_string(polygons[0].size()) + " and " +
                        std::to_string(polygons[1].size()) + " input vertices, " + std::to_string(n) +
                        " on the common boundary, every input vertex kept" +
                        (stats->holes ? ", loop by loop: the outer loop and " + std::to_string(stats->holes) +
                                            (stats->holes == 1 ? " hole" : " holes")
                                      : std::string()) +
                        ")");
  outcome.log.push_back("compatible triangulation: " + std::to_string(n) + " boundary vertices, " +
                        std::to_string(stats->steiner) + " Steiner vertices (vertex quality 1), " +
                        std::to_string(nt) + " triangles" +
                        (stats->holes ? ", " + std::to_string(stats->holes) + (stats->holes == 1 ? " hole" : " holes") : std::string()));
  // The layers' own (their float points), which the user measures.
  outcome.log.push_back("smallest angle: " + text_of(float_min_angle_deg(outcome.layers[0].xyz, triangles)) +
                        " deg in '" + first_name + "', " +
                        text_of(float_min_angle_deg(outcome.layers[1].xyz, triangles)) + " deg in '" + second_name +
                        "'");
  if (stats->holes_moved > 0)
    outcome.log.push_back("holes paired by position: " + std::to_string(stats->holes_moved) + " of '" + second_name +
                          "' pair with a hole listed at another place in '" + first_name + "'");
  if (stats->time_limit_reached)
    outcome.log.push_back("time limit of " + text_of(settings.time_limit, "%g") +
                          " s reached: remeshing stopped early, the result reached kept");
  if (stats->fallback_count > 0)
    outcome.log.push_back("overlay fallback used " + std::to_string(stats->fallback_count) + " times");
  std::string ceiling = "no compatible triangulation of this pair can have a smallest angle above " +
                        text_of(stats->ceiling_deg) + " degrees (corner fan " + text_of(stats->corner_fan_cap_deg) +
                        ", correspondence bound " + text_of(stats->correspondence_bound_deg);
  if (stats->correspondence_bound_before_deg > 0)
    ceiling += "; before choosing the starts " + text_of(stats->correspondence_bound_before_deg);
  outcome.log.push_back(ceiling + ")");
  return outcome;
}

}  // namespace compatmesh_plugin
