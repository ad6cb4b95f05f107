/* section_plane.h over compatmesh::PlaneFrame (bindings/common). */
#include "section_plane.h"

#include <compatmesh/plane.hh>

#include <algorithm>
#include <new>
#include <cstdio>
#include <cstring>
#include <vector>

namespace {

compatmesh::PlaneFrame frame_of(const section_frame &f)
{
    compatmesh::PlaneFrame p;
    std::copy(f.origin, f.origin + 3, p.origin.begin());
    std::copy(f.u, f.u + 3, p.u.begin());
    std::copy(f.v, f.v + 3, p.v.begin());
    std::copy(f.normal, f.normal + 3, p.normal.begin());
    p.fixed_axis = f.fixed_axis;
    return p;
}

section_frame section_of(const compatmesh::PlaneFrame &p)
{
    section_frame f;
    std::copy(p.origin.begin(), p.origin.end(), f.origin);
    std::copy(p.u.begin(), p.u.end(), f.u);
    std::copy(p.v.begin(), p.v.end(), f.v);
    std::copy(p.normal.begin(), p.normal.end(), f.normal);
    f.fixed_axis = p.fixed_axis;
    return f;
}

}  // namespace

extern "C" int section_fit(const double *xyz, size_t n, size_t winding_points, section_frame *frame,
                           size_t *vertex, char *message, size_t size)
{
    try {
        *frame = section_of(compatmesh::fit_plane(xyz, n, compatmesh::kDefaultPlanarityTolerance,
                                                  compatmesh::NormalSign::FollowWinding, winding_points));
        return 0;
    } catch (const compatmesh::PlaneError &e) {
        *vertex = e.vertex();
        std::snprintf(message, size, "%s", e.what());
        return -1;
    } catch (const std::bad_alloc &) {
        *vertex = 0;
        std::snprintf(message, size, "out of memory");
        return -2;
    }
}

extern "C" int section_align(section_frame *frames, size_t k)
{
    try {
        std::vector<compatmesh::PlaneFrame> planes;
        for (size_t g = 0; g < k; g++) planes.push_back(frame_of(frames[g]));
        compatmesh::align_frames(planes, true);
        for (size_t g = 0; g < k; g++) frames[g] = section_of(planes[g]);
        return 0;
    } catch (const std::bad_alloc &) {
        return -1;
    }
}

extern "C" void section_to_plane(const section_frame *frame, const double *xyz, size_t n, double *xy)
{
    const compatmesh::PlaneFrame plane = frame_of(*frame);
    for (size_t i = 0; i < n; i++) {
        std::array<double, 2> p = plane.to_plane(xyz + 3 * i);
        xy[2 * i] = p[0], xy[2 * i + 1] = p[1];
    }
}

extern "C" void section_to_space(const section_frame *frame, double x, double y, double p[3])
{
    std::array<double, 3> q = frame_of(*frame).to_space(x, y);
    std::copy(q.begin(), q.end(), p);
}
