/* The result handle: status, message, and the accessors of the public API. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "internal.h"

const char *cm_status_string(cm_status status)
{
    switch (status) {
    case CM_OK: return "ok";
    case CM_ERR_ARGUMENT: return "invalid argument";
    case CM_ERR_TOO_FEW_VERTICES: return "too few vertices";
    case CM_ERR_COUNT_MISMATCH: return "vertex count mismatch";
    case CM_ERR_NOT_FINITE: return "non-finite coordinate";
    case CM_ERR_REPEATED_VERTEX: return "repeated vertex";
    case CM_ERR_SELF_INTERSECTION: return "self-intersection";
    case CM_ERR_ZERO_AREA: return "zero area";
    case CM_ERR_ORIENTATION_MISMATCH: return "orientation mismatch";
    case CM_ERR_NO_MEMORY: return "out of memory";
    case CM_ERR_CANCELLED: return "cancelled";
    case CM_ERR_INTERNAL: return "internal error";
    }
    return "unknown status";
}

cm_status cm_fail(cm_result *r, cm_status status, const char *fmt, ...)
{
    r->status = status;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->message, sizeof r->message, fmt, ap);
    va_end(ap);
    return status;
}

void cm_fail_at(cm_result *r, long polygon, long vertex, long other)
{
    r->error_polygon = polygon;
    r->error_vertex = vertex;
    r->error_other = other;
}

void cm_mesh_clear(cm_mesh *mesh)
{
    if (mesh->xy)
        for (size_t g = 0; g < mesh->k; g++) free(mesh->xy[g]);
    free(mesh->xy);
    free(mesh->tri);
    mesh->xy = NULL;
    mesh->tri = NULL;
    mesh->nv = mesh->nt = 0;
}

/* Drops all geometry, keeping status and message (a failed result). */
void cm_result_clear_geometry(cm_result *r)
{
    cm_mesh_clear(&r->mesh);
    free(r->he_next), free(r->he_to), free(r->he_face), free(r->vertex_he), free(r->face_he);
    free(r->quality), free(r->quality_before);
    r->he_next = r->he_to = r->he_face = r->vertex_he = r->face_he = NULL;
    r->quality = r->quality_before = NULL;
    r->nh = 0;
}

cm_status cm_result_measure(cm_result *r)
{
    size_t k = r->mesh.k;
    r->quality = calloc(k, sizeof *r->quality);
    if (!r->quality) return cm_fail(r, CM_ERR_NO_MEMORY, "out of memory");
    for (size_t g = 0; g < k; g++) cm_mesh_quality(&r->mesh, g, &r->quality[g]);
    r->stats.vertices = r->mesh.nv;
    r->stats.steiner = r->mesh.nv - r->n;
    r->stats.triangles = r->mesh.nt;
    return CM_OK;
}

void cm_result_free(cm_result *r)
{
    if (!r) return;
    cm_result_clear_geometry(r);
    free(r);
}

static int ok(const cm_result *r) { return r && r->status == CM_OK; }

cm_status cm_result_status(const cm_result *r) { return r ? r->status : CM_ERR_ARGUMENT; }
const char *cm_result_message(const cm_result *r) { return r ? r->message : "no result"; }

void cm_result_error_location(const cm_result *r, long *polygon, long *vertex, long *other)
{
    if (polygon) *polygon = r ? r->error_polygon : -1;
    if (vertex) *vertex = r ? r->error_vertex : -1;
    if (other) *other = r ? r->error_other : -1;
}

size_t cm_result_num_geometries(const cm_result *r) { return ok(r) ? r->mesh.k : 0; }
size_t cm_result_num_vertices(const cm_result *r) { return ok(r) ? r->mesh.nv : 0; }
const double *cm_result_vertices(const cm_result *r, size_t g)
{
    return ok(r) && g < r->mesh.k ? r->mesh.xy[g] : NULL;
}
size_t cm_result_num_triangles(const cm_result *r) { return ok(r) ? r->mesh.nt : 0; }
const int32_t *cm_result_triangles(const cm_result *r) { return ok(r) ? r->mesh.tri : NULL; }
size_t cm_result_num_halfedges(const cm_result *r) { return ok(r) ? r->nh : 0; }
const int32_t *cm_result_halfedge_next(const cm_result *r) { return ok(r) ? r->he_next : NULL; }
const int32_t *cm_result_halfedge_to_vertex(const cm_result *r) { return ok(r) ? r->he_to : NULL; }
const int32_t *cm_result_halfedge_face(const cm_result *r) { return ok(r) ? r->he_face : NULL; }
const int32_t *cm_result_vertex_halfedge(const cm_result *r) { return ok(r) ? r->vertex_he : NULL; }
const int32_t *cm_result_face_halfedge(const cm_result *r) { return ok(r) ? r->face_he : NULL; }
const cm_stats *cm_result_stats(const cm_result *r) { return r ? &r->stats : NULL; }

cm_status cm_result_quality(const cm_result *r, size_t g, cm_quality *quality)
{
    if (!ok(r) || !quality || g >= r->mesh.k) return CM_ERR_ARGUMENT;
    *quality = r->quality[g];
    return CM_OK;
}

cm_status cm_result_quality_before(const cm_result *r, size_t g, cm_quality *quality)
{
    if (!ok(r) || !quality || g >= r->mesh.k || !r->quality_before) return CM_ERR_ARGUMENT;
    *quality = r->quality_before[g];
    return CM_OK;
}
