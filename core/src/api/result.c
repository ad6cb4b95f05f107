/* The result handle: status, message, and the accessors of the public API. */
#include <stdlib.h>

#include "api/result.h"
#include "api/quality.h"

/* Drops all geometry, keeping status and message (a failed result). */
void cm_result_clear_geometry(cm_result *r)
{
    cm_mesh_clear(&r->mesh);
    cm_boundary_map_clear(&r->boundary);
    free(r->loop_start);
    r->loop_start = NULL, r->num_loops = 0;
    free(r->he_next), free(r->he_to), free(r->he_face), free(r->vertex_he), free(r->face_he);
    free(r->quality), free(r->quality_before);
    r->he_next = r->he_to = r->he_face = r->vertex_he = r->face_he = NULL;
    r->quality = r->quality_before = NULL;
    r->nh = 0;
    cm_result_free_resume(r->resume);
    r->resume = NULL;
}

void cm_result_free_resume(cm_remesh_resume *resume)
{
    if (resume) cm_remesh_resume_clear(resume);
    free(resume);
}

cm_status cm_result_measure(cm_result *r, const cm_quality *known)
{
    size_t k = r->mesh.k;
    r->quality = calloc(k, sizeof *r->quality);
    if (!r->quality) return cm_fail_status(&r->error, CM_ERR_NO_MEMORY);
    for (size_t g = 0; g < k; g++) {
        if (known) r->quality[g] = known[g];
        else cm_mesh_quality(&r->mesh, g, &r->quality[g]);
    }
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

const char *cm_correspondence_choice_name(cm_correspondence_choice choice)
{
    static const char *const names[] = {"index", "arclength", "conformal", "similarity", "affine", "corners", "annulus"};
    return (unsigned)choice < sizeof names / sizeof *names ? names[choice] : "unknown";
}

static int ok(const cm_result *r) { return r && r->error.status == CM_OK; }

cm_status cm_result_status(const cm_result *r) { return r ? r->error.status : CM_ERR_ARGUMENT; }
const char *cm_result_message(const cm_result *r) { return r ? r->error.message : "no result"; }

void cm_result_error_location(const cm_result *r, long *polygon, long *vertex, long *other)
{
    if (polygon) *polygon = r ? r->error.polygon : -1;
    if (vertex) *vertex = r ? r->error.vertex : -1;
    if (other) *other = r ? r->error.other : -1;
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

long cm_result_boundary_source(const cm_result *r, size_t g, size_t i, double *t)
{
    if (!ok(r) || g >= r->mesh.k || i >= r->n) return -1;
    if (t) *t = r->boundary.n ? r->boundary.t[g][i] : 0.0;
    return r->boundary.n ? (long)r->boundary.edge[g][i] : (long)i;
}

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
