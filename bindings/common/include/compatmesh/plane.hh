// Planar polygons in 3D: the plane they lie in, and the map to 2D and back.
// Shared by the OpenMesh adapter and the Python module so that both read a
// 3D polygon the same way.
#ifndef COMPATMESH_PLANE_HH
#define COMPATMESH_PLANE_HH

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace compatmesh {

// Default for fit_plane's relative_tolerance: loose enough for float
// coordinates, tight enough to reject a visibly bent polygon.
constexpr double kDefaultPlanarityTolerance = 1e-5;

// An orthonormal frame of a plane: the plane point (x, y) is the 3D point
// origin + x * u + y * v, and normal = u x v.
struct PlaneFrame {
  std::array<double, 3> origin{{0.0, 0.0, 0.0}};
  std::array<double, 3> u{{1.0, 0.0, 0.0}};
  std::array<double, 3> v{{0.0, 1.0, 0.0}};
  std::array<double, 3> normal{{0.0, 0.0, 1.0}};
  // 0, 1 or 2 when every point has exactly the same coordinate on that
  // axis: the frame is then that coordinate plane, and the 2D coordinates
  // are copies of the other two coordinates (no rounding). -1 otherwise.
  int fixed_axis = 2;

  std::array<double, 2> to_plane(const double *point) const;
  std::array<double, 3> to_space(double x, double y) const;
};

// How fit_plane picks the side the normal points to.
enum class NormalSign {
  // A fixed rule independent of the vertex order (the normal's largest
  // component is positive; +x, +y or +z for a coordinate plane), so a
  // clockwise polygon stays clockwise in 2D.
  Canonical,
  // The closed polygon through the points, in order, turns
  // counter-clockwise about the normal (right-hand rule), as a face does.
  FollowWinding,
};

// What fit_plane throws; vertex is the offending point's index.
class PlaneError : public std::invalid_argument {
 public:
  PlaneError(const std::string &message, std::size_t vertex, bool not_finite = false)
      : std::invalid_argument(message), vertex_(vertex), not_finite_(not_finite) {}
  std::size_t vertex() const { return vertex_; }
  // A NaN or infinite coordinate (the core's CM_ERR_NOT_FINITE), rather
  // than points off the plane.
  bool not_finite() const { return not_finite_; }

 private:
  std::size_t vertex_;
  bool not_finite_;
};

// Fits the plane through a closed polygon by least squares.
//   xyz:   n * 3 doubles, point i at xyz[3i], xyz[3i+1], xyz[3i+2]
//   relative_tolerance: largest distance allowed between a point and the
//          plane, as a fraction of the bounding-box diagonal
//   sign:  which way the normal points
//   winding_points: FollowWinding takes the turn of the closed polygon
//          through the first winding_points points (0: all n), so that a
//          polygon with holes, stored outer loop first, follows its outer loop
// Returns the frame. Throws PlaneError, naming the farthest point, when the
// points are not planar within the tolerance, or a non-finite point. Fewer than
// three points or collinear points give some plane through them (the
// polygon check reports them later).
PlaneFrame fit_plane(const double *xyz, std::size_t n, double relative_tolerance,
                     NormalSign sign, std::size_t winding_points = 0);

// Frames of sections of one part, in this order: with loft, the first
// frame's normal turned towards the second plane (the direction of a loft
// through them, whose cells are then positive; without, it keeps the side
// it has, as a face's winding gave it); each frame after the first gets its
// normal on the side of the one before (turned over where
// it points away: a polygon listed the other way round then runs
// clockwise in its plane, for the correspondence to settle), and its u
// and v are the previous frame's carried by the least rotation taking the
// previous normal onto its own (about their cross product), and its
// origin the previous one carried along the previous normal into its
// plane, so that a section's plane coordinates turn and move only as much
// as the planes do. A frame that does not change keeps its fixed_axis; the
// others get -1.
void align_frames(std::vector<PlaneFrame> &frames, bool loft);

// Appends the frame as the core's loft takes a geometry's plane
// (cm_sweep_options.frames, cm_loft_section): origin, u, v, 9 doubles.
void append_loft_frame(const PlaneFrame &frame, std::vector<double> &frames);

// The plane coordinates of n points: 2n doubles.
std::vector<double> to_plane(const PlaneFrame &frame, const double *xyz, std::size_t n);

// The sections' frames aligned (align_frames) and each section's plane
// coordinates computed again in its frame. Section has members frame,
// xyz (3n doubles), xy (2n) and size() (n): the front ends' polygons.
template <class Section>
void align_sections(const std::vector<Section *> &sections, bool loft)
{
  std::vector<PlaneFrame> frames;
  for (const Section *s : sections) frames.push_back(s->frame);
  align_frames(frames, loft);
  for (std::size_t g = 0; g < sections.size(); g++) {
    Section &s = *sections[g];
    s.frame = frames[g];
    s.xy = to_plane(s.frame, s.xyz.data(), s.size());
  }
}

}  // namespace compatmesh

#endif
