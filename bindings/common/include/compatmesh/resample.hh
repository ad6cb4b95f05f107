// Closed polylines with different vertex counts brought to one count, so
// that two planar sections of a solid (which never have equal counts) can
// be paired vertex by vertex.
#ifndef COMPATMESH_RESAMPLE_HH
#define COMPATMESH_RESAMPLE_HH

#include <cstddef>
#include <vector>

namespace compatmesh {

// One closed polyline after resampling: points in order, and for each the
// index of the input vertex it is, or -1 for a point inserted on an edge.
struct ResampledLoop {
  std::vector<double> xyz;  // 3m
  std::vector<int> source;  // m
};

// Resamples two closed 3D polylines a (na points) and b (nb points) to a
// common count by arc length. Each loop is parametrised by normalised arc
// length from its first vertex; both get one point per parameter in the
// union of the two parameter sets, so every input vertex is kept (its shape
// is unchanged) and the other loop's vertices appear as points inserted on
// its edges. A vertex of a and one of b closer in parameter than half the
// shorter edge at either of them are paired instead (both kept, no point
// inserted), which keeps inserted points away from the vertices next to
// them.
//   a, b: 3 * na and 3 * nb doubles, point i at [3i, 3i+2]
// Returns the two loops, with equal sizes (at most na + nb). Throws
// std::invalid_argument for fewer than 3 points or a loop of zero length.
void resample_common_count(const double *a, std::size_t na, const double *b, std::size_t nb,
                           ResampledLoop &out_a, ResampledLoop &out_b);

// Normalised arc-length parameter of each vertex of a closed 3D polyline:
// n values in [0, 1), the first 0.
std::vector<double> arc_length_parameters(const double *xyz, std::size_t n);

}  // namespace compatmesh

#endif
