/* The swept volume's boundary faces in groups: 0 the first section, 1 the
 * last, 2 + l the wall over loop l (the outer loop, then the holes).
 *
 * A boundary edge u -> w of the triangulation, with the material on its
 * left, sweeps to the quad u w w' u' (primes one section up), whose normal
 * points to the right of u -> w: out of the volume. The caps are the
 * triangles, counter-clockwise seen from +z: the top's as they are, the
 * bottom's reversed. */
#include <stdlib.h>

#include "morph/sweep_boundary.h"

/* Does tetrahedron t (4 nodes) hold nodes a and b? */
static int tet_has_edge(const int32_t *t, int32_t a, int32_t b)
{
    int has_a = 0, has_b = 0;
    for (int i = 0; i < 4; i++) has_a |= t[i] == a, has_b |= t[i] == b;
    return has_a && has_b;
}

static void put(cm_sweep_boundary *b, int32_t group, int32_t p, int32_t q, int32_t r, int32_t s)
{
    int32_t *f = b->faces + 4 * b->nf;
    f[0] = p, f[1] = q, f[2] = r, f[3] = s;
    b->groups[b->nf++] = group;
}

cm_status cm_sweep_boundary_build(cm_sweep_boundary *b, const cm_result *r, size_t ns, const int32_t *tets,
                                  cm_error *error)
{
    size_t nv = r->mesh.nv, nt = r->mesh.nt, n = r->n;
    size_t walls = (ns - 1) * n * (tets ? 2 : 1);
    b->nf = 0;
    b->faces = malloc(4 * (2 * nt + walls) * sizeof *b->faces);
    b->groups = malloc((2 * nt + walls) * sizeof *b->groups);
    if (!b->faces || !b->groups) {
        cm_sweep_boundary_free(b);
        return cm_fail_status(error, CM_ERR_NO_MEMORY);
    }
    const int32_t *tri = r->mesh.tri;
    int32_t top = (int32_t)((ns - 1) * nv);
    for (size_t t = 0; t < nt; t++) put(b, 0, tri[3 * t], tri[3 * t + 2], tri[3 * t + 1], -1);
    for (size_t t = 0; t < nt; t++) put(b, 1, top + tri[3 * t], top + tri[3 * t + 1], top + tri[3 * t + 2], -1);
    /* Boundary vertex w ends the boundary edge u -> w whose left side is a
     * triangle: the opposite of w's outgoing boundary half-edge, which
     * runs clockwise. Vertices in order, so the loops come in order. */
    for (size_t w = 0; w < n; w++) {
        int32_t h = r->vertex_he[w], u = r->he_to[h], t = r->he_face[h ^ 1];
        int32_t group = 2 + (int32_t)(r->loop_start ? cm_loop_of(r->loop_start, r->num_loops, w) : 0);
        for (size_t s = 0; s + 1 < ns; s++) {
            int32_t lo = (int32_t)(s * nv), hi = (int32_t)((s + 1) * nv);
            int32_t a = lo + u, c = lo + (int32_t)w, c1 = hi + (int32_t)w, a1 = hi + u;
            if (!tets) {
                put(b, group, a, c, c1, a1);
                continue;
            }
            const int32_t *prism_tets = tets + 12 * (s * nt + (size_t)t);
            int diagonal_a_c1 = 0;
            for (int i = 0; i < 3; i++) diagonal_a_c1 |= tet_has_edge(prism_tets + 4 * i, a, c1);
            if (diagonal_a_c1) {
                put(b, group, a, c, c1, -1);
                put(b, group, a, c1, a1, -1);
            } else {
                put(b, group, a, c, a1, -1);
                put(b, group, c, c1, a1, -1);
            }
        }
    }
    return CM_OK;
}

void cm_sweep_boundary_free(cm_sweep_boundary *b)
{
    free(b->faces), free(b->groups);
    b->faces = b->groups = NULL;
    b->nf = 0;
}
