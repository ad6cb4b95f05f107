// cm_cgal_single: the price of compatibility. Meshes one polygon on its own
// with CGAL's 2D Delaunay mesher (Shewchuk-style refinement of a constrained
// Delaunay triangulation) at a smallest-angle bound, and prints one line:
//
//   cm_cgal_single POLYGON.xy ANGLE_DEG [MIN_CPU_SECONDS]
//   -> "steiner S boundary_steiner B triangles T min_angle_deg A
//       mesh_cpu_s C repeats R"
//
// S counts every vertex CGAL added, B those of them on the boundary (CGAL
// splits boundary edges; compatmesh never does, so its Steiner vertices
// are all interior). C is the process CPU time of one meshing (building
// the constrained triangulation and refining it; reading the file and
// starting the process excluded), the mean over R runs: one, or as many
// as it takes to spend MIN_CPU_SECONDS when given, so that short runs are
// measurable. A bench-only tool: CGAL (libcgal-dev) is not a dependency
// of the library.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <ctime>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_2<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<CDT>;
using Point = K::Point_2;

// The .xy format of the CLI: "x y" per line, '#' comments, commas allowed.
static bool read_xy(const char *path, std::vector<Point> &out)
{
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find('#'));
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream words(line);
    double x, y;
    if (words >> x >> y) out.emplace_back(x, y);
  }
  return in.eof() && out.size() >= 3;
}

static double smallest_angle_deg(const CDT::Face_handle &f)
{
  double lo = 180;
  for (int i = 0; i < 3; i++) {
    const Point &a = f->vertex(i)->point(), &b = f->vertex((i + 1) % 3)->point(),
                &c = f->vertex((i + 2) % 3)->point();
    double ux = b.x() - a.x(), uy = b.y() - a.y(), vx = c.x() - a.x(), vy = c.y() - a.y();
    lo = std::min(lo, std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / M_PI);
  }
  return lo;
}

static double cpu_now()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

// The polygon meshed at the angle bound into cdt (empty on entry); returns
// the number of vertices before refinement.
static size_t mesh(const std::vector<Point> &polygon, double angle, CDT &cdt)
{
  std::vector<CDT::Vertex_handle> corners;
  for (const Point &p : polygon) corners.push_back(cdt.insert(p));
  for (size_t i = 0; i < corners.size(); i++)
    cdt.insert_constraint(corners[i], corners[(i + 1) % corners.size()]);
  size_t before = cdt.number_of_vertices();
  // CGAL's shape bound is the squared sine of the smallest angle.
  CGAL::refine_Delaunay_mesh_2(cdt, Criteria(std::sin(angle) * std::sin(angle)));
  return before;
}

int main(int argc, char **argv)
{
  std::vector<Point> polygon;
  double min_cpu = argc == 4 ? std::atof(argv[3]) : 0;
  if ((argc != 3 && argc != 4) || !read_xy(argv[1], polygon) || !(min_cpu >= 0)) {
    std::cerr << "usage: cm_cgal_single POLYGON.xy ANGLE_DEG [MIN_CPU_SECONDS]\n";
    return 2;
  }
  double angle = std::atof(argv[2]) * M_PI / 180;
  CDT cdt;
  double start = cpu_now();
  size_t before = mesh(polygon, angle, cdt);
  long repeats = 1;
  for (; cpu_now() - start < min_cpu; repeats++) {
    CDT again;
    mesh(polygon, angle, again);
  }
  double per_mesh = (cpu_now() - start) / repeats;
  size_t triangles = 0;
  double lo = 180;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_in_domain()) triangles++, lo = std::min(lo, smallest_angle_deg(f));
  // Each vertex CGAL put on the boundary splits a constrained edge in two.
  size_t constrained = 0;
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
    constrained += cdt.is_constrained(*e);
  size_t boundary_steiner = constrained - polygon.size();
  std::printf("steiner %zu boundary_steiner %zu triangles %zu min_angle_deg %.3f mesh_cpu_s %.9f repeats %ld\n",
              cdt.number_of_vertices() - before, boundary_steiner, triangles, lo, per_mesh, repeats);
  return 0;
}
