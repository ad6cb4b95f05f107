/* Internal types shared by the core's modules. Not installed. */
#ifndef CM_INTERNAL_H
#define CM_INTERNAL_H

#include "compatmesh/compatmesh.h"

#define CM_PI 3.14159265358979323846

/* A triangle list over one vertex numbering with k geometries: what every
 * construction stage produces and the validator checks. */
typedef struct cm_mesh {
    size_t k;        /* geometries */
    size_t nv, nt;   /* vertices, triangles */
    double **xy;     /* k arrays of 2 * nv doubles */
    int32_t *tri;    /* 3 * nt indices, counter-clockwise */
} cm_mesh;

void cm_mesh_clear(cm_mesh *mesh);

struct cm_result {
    cm_status status;
    char message[512];
    long error_polygon, error_vertex, error_other;

    size_t n;
    cm_mesh mesh;

    size_t nh;
    int32_t *he_next, *he_to, *he_face, *vertex_he, *face_he;

    cm_stats stats;
    cm_quality *quality; /* k entries */
    cm_quality *quality_before; /* k entries: before remeshing */
};

/* Sets status and a printf-style message on the result; returns status. */
cm_status cm_fail(cm_result *r, cm_status status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
void cm_fail_at(cm_result *r, long polygon, long vertex, long other);
void cm_result_clear_geometry(cm_result *r);
/* Fills r->quality and the size stats of a checked result. */
cm_status cm_result_measure(cm_result *r);

/* input.c: checks the k polygons; sets *clockwise when all are clockwise. */
cm_status cm_input_validate(const double *const *polygons, const size_t *counts,
                            size_t k, cm_result *r, int *clockwise);

/* polytri.c: triangulates the simple counter-clockwise polygon whose
 * vertices are xy[idx[0]], ..., xy[idx[m-1]] (xy holds 2 doubles per vertex)
 * into m - 2 triangles written to tri_out (3 * (m - 2) entries, values from
 * idx), by ear clipping followed by Delaunay edge flips (the result is the
 * constrained Delaunay triangulation of the polygon). Exact predicates.
 * Returns 0 on success, -1 out of memory, 1 if no ear was found (the
 * polygon was not simple). */
int cm_polygon_triangulate(const double *xy, const int32_t *idx, long m,
                           int32_t *tri_out);

/* overlay.c: the Aronov-Seidel-Souvaine construction.
 *   geoms: k arrays of 2n doubles, counter-clockwise simple polygons;
 *   tris:  k triangulations, 3 * (n - 2) indices each (vertex indices < n).
 * Writes a compatible triangulation into *out (polygon vertices first).
 * *extra_centroids counts faces that needed a centroid vertex.
 * Returns CM_OK, CM_ERR_NO_MEMORY or CM_ERR_INTERNAL (message on r). */
cm_status cm_overlay(const double *const *geoms, const int32_t *const *tris,
                     size_t k, size_t n, cm_mesh *out, size_t *extra_centroids,
                     cm_result *r);

/* halfedge.c: builds the result's half-edge arrays from r->mesh and checks
 * exactly that the mesh is a valid compatible triangulation of the polygon
 * whose counter-clockwise boundary is the vertex cycle boundary[0..n-1]:
 * the boundary edges are exactly boundary[i] -> boundary[i+1], every
 * triangle is strictly counter-clockwise in every geometry, and the mesh is
 * a manifold disk. (With a simple boundary this makes every geometry a
 * valid triangulation: an orientation-preserving map of a disk that is
 * injective on its boundary is injective.) Returns CM_OK, CM_ERR_NO_MEMORY
 * or CM_ERR_INTERNAL. */
cm_status cm_halfedge_build_and_check(cm_result *r, const int32_t *boundary);

/* quality.c: angle statistics of geometry g. */
void cm_mesh_quality(const cm_mesh *mesh, size_t g, cm_quality *q);
/* Smallest angle (radians) of triangle abc. */
double cm_triangle_min_angle(const double a[2], const double b[2], const double c[2]);

double cm_seconds_now(void);

#endif
