// resample_common_count (bindings/common): two closed polylines with
// different counts brought to one count by arc length, every input vertex
// kept in order, new points on the input edges at the other loop's
// parameters.
#include "check.h"  // tests/core: CHECK, CHECK_MSG, check_summary

#include <compatmesh/resample.hh>

#include <cmath>
#include <stdexcept>
#include <vector>

using compatmesh::ResampledLoop;

static std::vector<double> regular(int n, double radius, double z)
{
  std::vector<double> xyz;
  for (int i = 0; i < n; i++) {
    double t = 2 * M_PI * i / n;
    xyz.insert(xyz.end(), {radius * std::cos(t), radius * std::sin(t), z});
  }
  return xyz;
}

// Every input vertex appears, in order, bit for bit; every other point lies
// on the input edge it was put on (collinear within rounding).
static void check_keeps_input(const std::vector<double> &in, const ResampledLoop &out)
{
  const std::size_t n = in.size() / 3, m = out.source.size();
  CHECK(out.xyz.size() == 3 * m);
  long expected = 0;
  for (std::size_t k = 0; k < m; k++) {
    int s = out.source[k];
    if (s >= 0) {
      CHECK_MSG(s == expected, "vertex %d out of order (expected %ld)", s, expected);
      for (int c = 0; c < 3; c++) CHECK(out.xyz[3 * k + c] == in[3 * s + c]);
      expected = s + 1;
    } else {
      // On the edge from input vertex expected - 1 to expected.
      const double *p = &in[3 * ((expected - 1 + n) % n)], *q = &in[3 * (expected % n)];
      const double *x = &out.xyz[3 * k];
      double cross[3] = {(q[1] - p[1]) * (x[2] - p[2]) - (q[2] - p[2]) * (x[1] - p[1]),
                         (q[2] - p[2]) * (x[0] - p[0]) - (q[0] - p[0]) * (x[2] - p[2]),
                         (q[0] - p[0]) * (x[1] - p[1]) - (q[1] - p[1]) * (x[0] - p[0])};
      double dot = (x[0] - p[0]) * (q[0] - p[0]) + (x[1] - p[1]) * (q[1] - p[1]) + (x[2] - p[2]) * (q[2] - p[2]);
      double len2 = (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) + (q[2] - p[2]) * (q[2] - p[2]);
      CHECK(std::fabs(cross[0]) + std::fabs(cross[1]) + std::fabs(cross[2]) < 1e-12);
      CHECK_MSG(dot > 0 && dot < len2, "point %zu is not inside its edge", k);
    }
  }
  CHECK_MSG(expected == long(n), "only %ld of %zu input vertices kept", expected, n);
}

int main()
{
  // 8 and 12 vertices on circles: parameters k/8 and k/12 share 0, 1/4,
  // 1/2 and 3/4 exactly, and 1/8 vs 1/12 etc. are close enough to pair
  // (within half an edge), so the union has fewer than 8 + 12 - 4 points.
  {
    std::vector<double> a = regular(8, 1.0, 0.0), b = regular(12, 2.0, 1.0);
    ResampledLoop ra, rb;
    compatmesh::resample_common_count(a.data(), 8, b.data(), 12, ra, rb);
    CHECK(ra.source.size() == rb.source.size());
    CHECK(ra.source.size() >= 12 && ra.source.size() <= 16);
    check_keeps_input(a, ra);
    check_keeps_input(b, rb);
    // Paired points have close parameters: |t_a - t_b| within half an edge.
    std::vector<double> ta = compatmesh::arc_length_parameters(ra.xyz.data(), ra.source.size());
    std::vector<double> tb = compatmesh::arc_length_parameters(rb.xyz.data(), rb.source.size());
    for (std::size_t k = 0; k < ta.size(); k++)
      CHECK_MSG(std::fabs(ta[k] - tb[k]) <= 0.5 / 12 + 1e-12, "slot %zu: %g vs %g", k, ta[k], tb[k]);
  }
  // Equal counts and equal parametrisation: nothing changes.
  {
    std::vector<double> a = regular(10, 1.0, 0.0), b = regular(10, 3.0, 5.0);
    ResampledLoop ra, rb;
    compatmesh::resample_common_count(a.data(), 10, b.data(), 10, ra, rb);
    CHECK(ra.xyz == a && rb.xyz == b);
  }
  // A triangle against a 40-gon: the triangle gets points on its edges.
  {
    std::vector<double> a = regular(3, 1.0, 0.0), b = regular(40, 1.0, 0.0);
    ResampledLoop ra, rb;
    compatmesh::resample_common_count(a.data(), 3, b.data(), 40, ra, rb);
    CHECK(ra.source.size() == 40 && rb.source.size() == 40);
    check_keeps_input(a, ra);
    check_keeps_input(b, rb);
  }
  // Bad input.
  {
    std::vector<double> two = {0, 0, 0, 1, 0, 0}, point = regular(3, 0.0, 0.0), ok = regular(5, 1, 0);
    ResampledLoop ra, rb;
    bool thrown = false;
    try { compatmesh::resample_common_count(two.data(), 2, ok.data(), 5, ra, rb); }
    catch (const std::invalid_argument &) { thrown = true; }
    CHECK(thrown);
    thrown = false;
    try { compatmesh::resample_common_count(ok.data(), 5, point.data(), 3, ra, rb); }
    catch (const std::invalid_argument &) { thrown = true; }
    CHECK(thrown);
  }
  return check_summary("test_resample");
}
