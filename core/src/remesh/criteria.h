/* What the remesher aims for, kept apart from the operations that get
 * there (as CGAL keeps Delaunay_mesh_criteria_2 apart from its mesher):
 * the angle target, the caps the boundary puts on it, and the smallest
 * gain that counts. */
#ifndef CM_REMESH_CRITERIA_H
#define CM_REMESH_CRITERIA_H

#include "base/mesh.h"
#include "base/progress.h"

/* Improvements smaller than this (radians) do not count: they would let
 * rounding noise drive endless flips and moves. */
#define CM_ANGLE_EPS 1e-9

/* Boundary edge caps carry a margin: the isosceles estimate is what an
 * ideal apex gets, the mesh around it rarely quite does. */
#define CM_EDGE_CAP_MARGIN 0.9

/* Caps from the boundary, per geometry the smallest (radians, n entries):
 * bcap[i], the best smallest angle of an isosceles triangle on boundary
 * edge i -> i+1 that fits inside the polygon (a boundary edge is never
 * split, so its triangle can do no better, near enough); vcap[i], half the
 * corner angle at vertex i (a corner split in two). Each edge examines
 * only the boundary segments near its triangle, found by a walk through
 * mesh's triangles (the construction, valid in every geometry), so about
 * linear time when the triangles near the boundary are few per edge:
 * 0, CM_NO_MEMORY, CM_CANCELLED or CM_CAPS_NOT_TRIANGULATED (a boundary
 * edge in no triangle). */
#define CM_CAPS_NOT_TRIANGULATED (-2)
int cm_boundary_caps(const cm_mesh *mesh, size_t n, cm_progress *progress, double *bcap,
                     double *vcap);

/* Where no boundary edge is split (index mode): lowers each bcap[i] (the
 * unscaled caps of cm_boundary_caps, the least over the geometries) to
 * what a boundary vertex near edge i allows one triangle further (the
 * edge's triangle and the one across its side must both keep it out;
 * criteria.c has the proof), in every geometry; the vertices looked at
 * are found by a walk as in cm_boundary_caps. 0, CM_NO_MEMORY,
 * CM_CANCELLED or CM_CAPS_NOT_TRIANGULATED. */
int cm_near_vertex_caps(const cm_mesh *mesh, size_t n, cm_progress *progress, double *bcap);

/* The edge cap of boundary edge i (unscaled, radians) in geometry xy
 * (the n boundary vertices of mesh's loops) by examining every boundary
 * segment, O(n), triangles not needed: the reference cm_boundary_caps
 * equals bit for bit. */
double cm_edge_cap_scan(const cm_mesh *mesh, const double *xy, size_t n, size_t i);

#endif
