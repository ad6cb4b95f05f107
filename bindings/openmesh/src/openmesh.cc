#include "compatmesh/openmesh.hh"

#include <exception>

namespace compatmesh {

Error::Error(cm_status status, const std::string &message, long mesh, long vertex, long other_vertex)
    : std::runtime_error(message), status_(status), mesh_(mesh), vertex_(vertex),
      other_vertex_(other_vertex)
{
}

std::size_t Boundary::next(std::size_t i) const
{
  std::size_t start = 0;
  for (std::size_t size : loop_sizes) {
    if (i < start + size) return i + 1 < start + size ? i + 1 : start;
    start += size;
  }
  return size() ? (i + 1) % size() : 0;
}

Boundary make_boundary(std::vector<double> xyz, std::vector<int> source_vertex,
                       double relative_tolerance, NormalSign sign)
{
  const std::size_t n = source_vertex.size();
  return make_boundary(std::move(xyz), std::move(source_vertex), std::vector<std::size_t>{n},
                       relative_tolerance, sign);
}

Boundary make_boundary(std::vector<double> xyz, std::vector<int> source_vertex,
                       std::vector<std::size_t> loop_sizes, double relative_tolerance,
                       NormalSign sign)
{
  const std::size_t n = source_vertex.size();
  if (xyz.size() != 3 * n)
    throw Error(CM_ERR_ARGUMENT, "make_boundary: " + std::to_string(xyz.size()) +
                                     " coordinates for " + std::to_string(n) + " vertices");
  std::size_t total = 0;
  for (std::size_t size : loop_sizes) total += size;
  if (loop_sizes.empty() || total != n)
    throw Error(CM_ERR_ARGUMENT, "make_boundary: loops of " + std::to_string(total) + " vertices for " +
                                     std::to_string(n) + " vertices");
  Boundary boundary;
  try {
    boundary.frame = fit_plane(xyz.data(), n, relative_tolerance, sign, loop_sizes[0]);
  } catch (const PlaneError &e) {
    long vertex = long(e.vertex());
    throw Error(e.not_finite() ? CM_ERR_NOT_FINITE : CM_ERR_ARGUMENT,
                std::string(e.what()) + " (mesh vertex " + std::to_string(source_vertex[vertex]) + ")",
                -1, vertex);
  }
  boundary.xy = to_plane(boundary.frame, xyz.data(), n);
  boundary.xyz = std::move(xyz);
  boundary.source_vertex = std::move(source_vertex);
  boundary.loop_sizes = std::move(loop_sizes);
  return boundary;
}

void align_boundaries(std::vector<Boundary> &polygons)
{
  std::vector<Boundary *> sections;
  for (Boundary &b : polygons) sections.push_back(&b);
  align_sections(sections, false);
}

namespace {
// The polygons as the core takes them with holes; counts (one per polygon,
// kept alive by the caller) stand for the loop sizes of a Boundary filled
// by hand that leaves loop_sizes empty: one loop.
std::vector<cm_loops> loops_of(const std::vector<Boundary> &polygons, std::vector<std::size_t> &counts)
{
  std::vector<cm_loops> loops;
  counts.clear();
  counts.reserve(polygons.size());  // pointed into below
  for (const Boundary &polygon : polygons) {
    counts.push_back(polygon.size());
    const bool one = polygon.loop_sizes.empty();
    loops.push_back(cm_loops{polygon.xy.data(), one ? &counts.back() : polygon.loop_sizes.data(),
                             one ? 1 : polygon.loop_sizes.size()});
  }
  return loops;
}
}  // namespace

cm_correspondence correspondence_by_counts(const std::vector<Boundary> &polygons, bool pinned)
{
  std::vector<std::size_t> counts;
  const std::vector<cm_loops> loops = loops_of(polygons, counts);
  return cm_correspondence_by_counts(loops.data(), loops.size(), pinned ? 1 : 0);
}

ResultPtr triangulate(const std::vector<Boundary> &polygons, const cm_options &options,
                      const ProgressFn &progress)
{
  std::vector<const double *> coordinates;
  std::vector<std::size_t> counts;
  const std::vector<cm_loops> loops = loops_of(polygons, counts);
  bool holes = false;
  for (const Boundary &polygon : polygons) {
    coordinates.push_back(polygon.xy.data());
    holes |= polygon.num_loops() > 1;
  }
  cm_options core_options = options;
  ProgressRelay relay(progress);
  relay.attach(core_options);
  cm_result *raw = nullptr;
  cm_status status = holes ? cm_triangulate_loops(loops.data(), loops.size(), &core_options, &raw)
                           : cm_triangulate_polygons(coordinates.data(), counts.data(), polygons.size(),
                                                     &core_options, &raw);
  ResultPtr result(raw);
  relay.rethrow();
  if (!result) throw Error(CM_ERR_NO_MEMORY, "out of memory");
  if (status == CM_OK) return result;

  long polygon = -1, vertex = -1, other = -1;
  cm_result_error_location(raw, &polygon, &vertex, &other);
  std::string message = cm_result_message(raw);
  // Name the vertices as the input meshes number them.
  if (polygon >= 0 && std::size_t(polygon) < polygons.size()) {
    const std::vector<int> &source = polygons[polygon].source_vertex;
    auto in_range = [&](long v) { return v >= 0 && std::size_t(v) < source.size(); };
    if (in_range(vertex)) {
      message += " (mesh " + std::to_string(polygon) + ", mesh vertex " + std::to_string(source[vertex]);
      if (in_range(other)) message += " and " + std::to_string(source[other]);
      message += ")";
    }
  }
  throw Error(status, message, polygon, vertex, other);
}

}  // namespace compatmesh
