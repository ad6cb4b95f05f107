/* The plane of a section given in 3D (bindings/common's plane fit, for the
 * command line's C): sections in planes other than z = constant are meshed
 * in their plane's coordinates and written back in space. */
#ifndef CM_CLI_SECTION_PLANE_H
#define CM_CLI_SECTION_PLANE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* compatmesh::PlaneFrame: the plane point (x, y) is origin + x u + y v;
 * fixed_axis 0, 1 or 2 where every point had that coordinate exactly (the
 * plane coordinates are then copies), else -1. */
typedef struct section_frame {
    double origin[3], u[3], v[3], normal[3];
    int fixed_axis;
} section_frame;

/* Fits the plane of n points (xyz, 3 each) by least squares, its normal
 * turning with the first winding_points of them (the outer loop)
 * counter-clockwise. 0, or -1 where a point lies farther from the plane
 * than 1e-5 of the points' bounding-box diagonal (or is not finite):
 * *vertex is that point and message says how far; -2 out of memory. */
int section_fit(const double *xyz, size_t n, size_t winding_points, section_frame *frame, size_t *vertex,
                char *message, size_t size);

/* The frames of a loft's sections (compatmesh::align_frames): the first
 * normal towards the second plane, each next one on the side of the one
 * before, each frame after the first turned and moved in its plane so
 * that its axes and origin are the one before's carried into it: the
 * sections then turn only as much as their planes, and the loft's cells
 * are positive. 0, or -1 out of memory. */
int section_align(section_frame *frames, size_t k);

/* The plane coordinates of n points (xy: 2 n doubles). */
void section_to_plane(const section_frame *frame, const double *xyz, size_t n, double *xy);

/* The point (x, y) of the plane in space. */
void section_to_space(const section_frame *frame, double x, double y, double p[3]);

#ifdef __cplusplus
}
#endif

#endif
