#include "compatmesh/resample.hh"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace compatmesh {

namespace {

double edge_length(const double *xyz, std::size_t n, std::size_t i)
{
  const double *p = xyz + 3 * i, *q = xyz + 3 * ((i + 1) % n);
  return std::sqrt((q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) +
                   (q[2] - p[2]) * (q[2] - p[2]));
}

// For each vertex, the shorter of its two edges, in parameter units.
std::vector<double> local_edge(const std::vector<double> &params)
{
  const std::size_t n = params.size();
  std::vector<double> local(n);
  for (std::size_t i = 0; i < n; i++) {
    double after = (i + 1 < n ? params[i + 1] : 1.0) - params[i];
    double before = params[i] - (i > 0 ? params[i - 1] : params[n - 1] - 1.0);
    local[i] = std::min(before, after);
  }
  return local;
}

// The point at parameter t of the loop, on the edge starting at vertex i
// (whose parameter is params[i]).
void point_at(const double *xyz, std::size_t n, const std::vector<double> &params, std::size_t i,
              double t, ResampledLoop &out)
{
  double t0 = params[i], t1 = i + 1 < n ? params[i + 1] : 1.0;
  double s = (t - t0) / (t1 - t0);
  const double *p = xyz + 3 * i, *q = xyz + 3 * ((i + 1) % n);
  for (int c = 0; c < 3; c++) out.xyz.push_back(p[c] + s * (q[c] - p[c]));
  out.source.push_back(-1);
}

void take_vertex(const double *xyz, std::size_t i, ResampledLoop &out)
{
  out.xyz.insert(out.xyz.end(), xyz + 3 * i, xyz + 3 * i + 3);
  out.source.push_back(int(i));
}

}  // namespace

std::vector<double> arc_length_parameters(const double *xyz, std::size_t n)
{
  if (n < 3) throw std::invalid_argument("a closed polyline needs at least 3 points");
  std::vector<double> params(n);
  double total = 0;
  for (std::size_t i = 0; i < n; i++) {
    params[i] = total;
    total += edge_length(xyz, n, i);
  }
  if (!(total > 0) || !std::isfinite(total))
    throw std::invalid_argument("a closed polyline of zero or non-finite length");
  for (double &t : params) t /= total;
  return params;
}

void resample_common_count(const double *a, std::size_t na, const double *b, std::size_t nb,
                           ResampledLoop &out_a, ResampledLoop &out_b)
{
  const std::vector<double> ta = arc_length_parameters(a, na), tb = arc_length_parameters(b, nb);
  const std::vector<double> la = local_edge(ta), lb = local_edge(tb);
  out_a = ResampledLoop();
  out_b = ResampledLoop();

  // Walk both parameter lists in order; i and j are the next unused
  // vertices of a and b, so the edge holding a parameter of the other
  // loop is the one starting at i - 1 (resp. j - 1).
  std::size_t i = 0, j = 0;
  while (i < na || j < nb) {
    double next_a = i < na ? ta[i] : 2.0, next_b = j < nb ? tb[j] : 2.0;
    double merge = i < na && j < nb ? 0.5 * std::min(la[i], lb[j]) : 0.0;
    if (std::fabs(next_a - next_b) <= merge) {
      take_vertex(a, i++, out_a);
      take_vertex(b, j++, out_b);
    } else if (next_a < next_b) {
      take_vertex(a, i, out_a);
      point_at(b, nb, tb, j - 1, next_a, out_b);
      i++;
    } else {
      point_at(a, na, ta, i - 1, next_b, out_a);
      take_vertex(b, j, out_b);
      j++;
    }
  }
}

}  // namespace compatmesh
