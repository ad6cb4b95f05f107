#include "compatmesh/plane.hh"

#include <Eigen/Dense>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace compatmesh {

namespace {

using Vec3 = Eigen::Vector3d;

Vec3 point(const double *xyz, std::size_t i) { return Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]); }

std::array<double, 3> array_of(const Vec3 &p) { return {{p.x(), p.y(), p.z()}}; }

// Newell's vector: twice the vector area of the closed polygon; it points
// to the side from which the polygon turns counter-clockwise.
Vec3 newell_vector(const double *xyz, std::size_t n)
{
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 0; i < n; i++) sum += point(xyz, i).cross(point(xyz, (i + 1) % n));
  return sum;
}

// The coordinate axis on which all points agree exactly, preferring z, or -1.
int shared_axis(const double *xyz, std::size_t n)
{
  for (int axis : {2, 1, 0}) {
    bool same = true;
    for (std::size_t i = 1; i < n && same; i++) same = xyz[3 * i + axis] == xyz[axis];
    if (same) return axis;
  }
  return -1;
}

PlaneFrame coordinate_plane(const double *xyz, std::size_t n, int axis, NormalSign sign,
                            std::size_t winding_points)
{
  // Right-handed order of the two remaining axes: (x, y) for z, (y, z) for x, (z, x) for y.
  int a = (axis + 1) % 3, b = (axis + 2) % 3;
  PlaneFrame frame;
  frame.fixed_axis = axis;
  frame.origin = {{0.0, 0.0, 0.0}};
  frame.origin[axis] = n > 0 ? xyz[axis] : 0.0;
  frame.u = {{0.0, 0.0, 0.0}};
  frame.v = {{0.0, 0.0, 0.0}};
  frame.normal = {{0.0, 0.0, 0.0}};
  frame.u[a] = 1.0;
  frame.v[b] = 1.0;
  frame.normal[axis] = 1.0;
  if (sign == NormalSign::FollowWinding && newell_vector(xyz, winding_points)[axis] < 0) {
    std::swap(frame.u, frame.v);
    frame.normal[axis] = -1.0;
  }
  return frame;
}

}  // namespace

std::array<double, 2> PlaneFrame::to_plane(const double *p) const
{
  if (fixed_axis >= 0) {
    // u and v are unit coordinate axes here: copy, do not compute.
    int a = u[0] != 0.0 ? 0 : u[1] != 0.0 ? 1 : 2;
    int b = v[0] != 0.0 ? 0 : v[1] != 0.0 ? 1 : 2;
    return {{p[a], p[b]}};
  }
  Vec3 d = Vec3(p[0], p[1], p[2]) - Vec3(origin.data());
  return {{d.dot(Vec3(u.data())), d.dot(Vec3(v.data()))}};
}

std::array<double, 3> PlaneFrame::to_space(double x, double y) const
{
  if (fixed_axis >= 0) {
    std::array<double, 3> p = origin;
    int a = u[0] != 0.0 ? 0 : u[1] != 0.0 ? 1 : 2;
    int b = v[0] != 0.0 ? 0 : v[1] != 0.0 ? 1 : 2;
    p[a] = x;
    p[b] = y;
    return p;
  }
  return array_of(Vec3(origin.data()) + x * Vec3(u.data()) + y * Vec3(v.data()));
}

PlaneFrame fit_plane(const double *xyz, std::size_t n, double relative_tolerance, NormalSign sign,
                     std::size_t winding_points)
{
  if (n == 0) return PlaneFrame();
  if (winding_points == 0 || winding_points > n) winding_points = n;
  for (std::size_t i = 0; i < 3 * n; i++)
    if (!std::isfinite(xyz[i]))
      throw PlaneError("vertex " + std::to_string(i / 3) + " has a coordinate that is not finite", i / 3, true);
  int axis = shared_axis(xyz, n);
  if (axis >= 0) return coordinate_plane(xyz, n, axis, sign, winding_points);

  Vec3 centroid = Vec3::Zero(), low = point(xyz, 0), high = low;
  for (std::size_t i = 0; i < n; i++) {
    centroid += point(xyz, i);
    low = low.cwiseMin(point(xyz, i));
    high = high.cwiseMax(point(xyz, i));
  }
  centroid /= double(n);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < n; i++) {
    Vec3 d = point(xyz, i) - centroid;
    covariance += d * d.transpose();
  }
  // Eigenvalues come in increasing order: the least-squares normal is the
  // direction of least spread, u the direction of most.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  Vec3 normal = solver.eigenvectors().col(0).normalized();
  Vec3 u = solver.eigenvectors().col(2).normalized();

  bool flip;
  if (sign == NormalSign::FollowWinding) {
    flip = normal.dot(newell_vector(xyz, winding_points)) < 0;
  } else {
    Eigen::Index largest;
    normal.cwiseAbs().maxCoeff(&largest);
    flip = normal[largest] < 0;
  }
  if (flip) normal = -normal;
  Vec3 v = normal.cross(u);

  double size = (high - low).norm(), worst = 0.0;
  std::size_t worst_index = 0;
  for (std::size_t i = 0; i < n; i++) {
    double distance = std::abs((point(xyz, i) - centroid).dot(normal));
    if (distance > worst) worst = distance, worst_index = i;
  }
  if (!(worst <= relative_tolerance * size)) {
    std::ostringstream message;
    message << "the polygon is not planar: vertex " << worst_index << " is " << worst
            << " away from the best-fitting plane, more than " << relative_tolerance
            << " of the polygon's size " << size;
    throw PlaneError(message.str(), worst_index);
  }

  PlaneFrame frame;
  frame.fixed_axis = -1;
  frame.origin = array_of(centroid);
  frame.u = array_of(u);
  frame.v = array_of(v);
  frame.normal = array_of(normal);
  return frame;
}

void align_frames(std::vector<PlaneFrame> &frames, bool loft)
{
  if (loft && frames.size() >= 2) {  // the first normal towards the second plane
    PlaneFrame &first = frames[0];
    Vec3 n(first.normal.data()), v(first.v.data()), d = Vec3(frames[1].origin.data()) - Vec3(first.origin.data());
    if (d.dot(n) < -1e-9 * d.norm())
      first.normal = array_of(-n), first.v = array_of(-v), first.fixed_axis = -1;
  }
  for (std::size_t g = 1; g < frames.size(); g++) {
    const PlaneFrame &before = frames[g - 1];
    PlaneFrame &frame = frames[g];
    Vec3 n0(before.normal.data()), n1(frame.normal.data());
    if (n0.dot(n1) < 0) n1 = -n1;  // to the side of the one before
    Vec3 axis = n0.cross(n1);
    double c = n0.dot(n1), s = axis.norm();
    Vec3 u(before.u.data());
    if (s > 0) {  // Rodrigues: u turned about the axis by the angle between the normals
      Vec3 k = axis / s;
      u = u * c + k.cross(u) * s + k * (k.dot(u)) * (1 - c);
    }
    u = (u - n1 * n1.dot(u)).normalized();
    Vec3 v = n1.cross(u);
    // The origin: the one before carried along its normal into this plane,
    // so that a point on the previous plane's normal keeps its coordinates
    // (an extrusion's sections need no translation in the plane).
    Vec3 o0(before.origin.data()), o1(frame.origin.data());
    Vec3 o = c > 1e-3 ? Vec3(o0 + n0 * ((o1 - o0).dot(n1) / c)) : o1;
    std::array<double, 3> nu = array_of(u), nv = array_of(v), no = array_of(o);
    if (nu == frame.u && nv == frame.v && no == frame.origin) continue;
    frame.u = nu, frame.v = nv, frame.origin = no, frame.normal = array_of(n1), frame.fixed_axis = -1;
  }
}

void append_loft_frame(const PlaneFrame &frame, std::vector<double> &frames)
{
  for (const std::array<double, 3> *a : {&frame.origin, &frame.u, &frame.v}) frames.insert(frames.end(), a->begin(), a->end());
}

std::vector<double> to_plane(const PlaneFrame &frame, const double *xyz, std::size_t n)
{
  std::vector<double> xy(2 * n);
  for (std::size_t i = 0; i < n; i++) {
    std::array<double, 2> p = frame.to_plane(xyz + 3 * i);
    xy[2 * i] = p[0];
    xy[2 * i + 1] = p[1];
  }
  return xy;
}

}  // namespace compatmesh
