/* The swept volume's boundary faces in groups: 0 the first section, 1 the
 * last, then the walls (sweep_boundary.h).
 *
 * A boundary edge u -> w of the triangulation, with the material on its
 * left, sweeps to the quad u w w' u' (primes one section up), whose normal
 * points to the right of u -> w: out of the volume. The caps are the
 * triangles, counter-clockwise seen from +z: the top's as they are, the
 * bottom's reversed. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom/angle.h"
#include "morph/sweep_boundary.h"

/* Does some geometry's boundary turn by more than corner_deg at boundary
 * vertex v, between its neighbours along the loop? The turn is how far
 * the corner angle deviates from 180, as --pin-corners measures it
 * (correspond/corners.c). */
static int is_corner(const cm_result *r, size_t v, double corner_deg)
{
    size_t prev = cm_loops_prev(r->loop_start, r->n, v), next = cm_loops_next(r->loop_start, r->n, v);
    for (size_t g = 0; g < r->mesh.k; g++) {
        const double *xy = r->mesh.xy[g];
        if (180.0 - cm_angle_at(xy + 2 * v, xy + 2 * prev, xy + 2 * next) * (180.0 / CM_PI) > corner_deg) return 1;
    }
    return 0;
}

cm_status cm_sweep_walls_build(cm_sweep_walls *walls, const cm_result *r, double corner_deg, cm_error *error)
{
    size_t n = r->n, loops = r->loop_start ? r->num_loops : 1;
    walls->groups = 2;
    walls->edge_group = malloc((n + 1) * sizeof *walls->edge_group);
    walls->names = malloc((n + 2) * sizeof *walls->names); /* at most a group per edge */
    if (!walls->edge_group || !walls->names) {
        cm_sweep_walls_free(walls);
        return cm_fail_status(error, CM_ERR_NO_MEMORY);
    }
    snprintf(walls->names[0], sizeof walls->names[0], "bottom");
    snprintf(walls->names[1], sizeof walls->names[1], "top");
    for (size_t l = 0; l < loops; l++) {
        size_t start = r->loop_start ? r->loop_start[l] : 0, end = r->loop_start ? r->loop_start[l + 1] : n;
        size_t first = walls->groups, corners = 0;
        int32_t group = (int32_t)first - 1; /* edges before the first corner close the last stretch */
        for (size_t i = start; i < end; i++) {
            if (corner_deg > 0 && is_corner(r, i, corner_deg)) group = (int32_t)(first + corners++);
            walls->edge_group[i] = group;
        }
        size_t stretches = corners ? corners : 1;
        for (size_t i = start; i < end && walls->edge_group[i] == (int32_t)first - 1; i++)
            walls->edge_group[i] = (int32_t)(first + stretches - 1);
        for (size_t j = 0; j < stretches; j++) { /* counts below 2^31, as the int32 vertex indices */
            char *name = walls->names[first + j];
            unsigned loop = (unsigned)l, stretch = (unsigned)(j + 1);
            if (l == 0) snprintf(name, 32, corners ? "side_%u" : "side", stretch);
            else if (corners) snprintf(name, 32, "hole_%u_%u", loop, stretch);
            else snprintf(name, 32, "hole_%u", loop);
        }
        walls->groups += stretches;
    }
    return CM_OK;
}

void cm_sweep_walls_free(cm_sweep_walls *walls)
{
    free(walls->edge_group), free(walls->names);
    walls->edge_group = NULL, walls->names = NULL;
    walls->groups = 0;
}

/* Does tetrahedron t (4 nodes) hold nodes a and b? */
static int tet_has_edge(const int32_t *t, int32_t a, int32_t b)
{
    int has_a = 0, has_b = 0;
    for (int i = 0; i < 4; i++) has_a |= t[i] == a, has_b |= t[i] == b;
    return has_a && has_b;
}

/* Face `at`: group, nodes p q r (s, -1 for a triangle), and the cell
 * face it is (cm_sweep_boundary.cells). */
static void put(cm_sweep_boundary *b, size_t at, int32_t group, const int32_t nodes[4], int64_t cell, int64_t side)
{
    memcpy(b->faces + 4 * at, nodes, 4 * sizeof *nodes);
    b->groups[at] = group;
    b->cells[2 * at] = cell, b->cells[2 * at + 1] = side;
}

/* The face p q r of one of a prism's three tetrahedra (prism_tets, the
 * first numbered first_tet): that tetrahedron and the face's number,
 * from the corner it leaves out (Abaqus C3D4: S1 1-2-3, S2 1-4-2,
 * S3 2-4-3, S4 3-4-1, from 0 here). */
static void put_tet_face(cm_sweep_boundary *b, size_t at, int32_t group, const int32_t *prism_tets, int64_t first_tet,
                         int32_t p, int32_t q, int32_t r)
{
    static const int64_t side_without[4] = {2, 3, 1, 0};
    const int32_t nodes[4] = {p, q, r, -1};
    for (int i = 0; i < 3; i++) {
        const int32_t *t = prism_tets + 4 * i;
        int held = 0, without = 0;
        for (int c = 0; c < 4; c++) {
            if (t[c] == p || t[c] == q || t[c] == r) held++;
            else without = c;
        }
        if (held == 3) {
            put(b, at, group, nodes, first_tet + i, side_without[without]);
            return;
        }
    }
    put(b, at, group, nodes, -1, -1); /* not a face of the prism's tetrahedra: the checks fail */
}

cm_status cm_sweep_boundary_build(cm_sweep_boundary *b, const cm_result *r, const cm_sweep_walls *walls, size_t ns,
                                  const int32_t *tets, cm_error *error)
{
    size_t nv = r->mesh.nv, nt = r->mesh.nt, n = r->n, per_edge = (ns - 1) * (tets ? 2 : 1);
    b->nf = 2 * nt + n * per_edge;
    b->faces = malloc(4 * b->nf * sizeof *b->faces);
    b->groups = malloc(b->nf * sizeof *b->groups);
    b->cells = malloc(2 * b->nf * sizeof *b->cells);
    b->offsets = calloc(walls->groups + 1, sizeof *b->offsets);
    size_t *at = malloc((walls->groups + 1) * sizeof *at); /* where each group's next face goes */
    if (!b->faces || !b->groups || !b->cells || !b->offsets || !at) {
        free(at);
        cm_sweep_boundary_free(b);
        return cm_fail_status(error, CM_ERR_NO_MEMORY);
    }
    const int32_t *tri = r->mesh.tri;
    int32_t top = (int32_t)((ns - 1) * nv);
    /* Prism p = s * nt + t (a b c over a' b' c', Abaqus C3D6: S1 the
     * bottom, S2 the top, S3 + j the quad over edge j); tetrahedra 3 p to
     * 3 p + 2. */
    size_t last = (ns - 2) * nt;
    for (size_t t = 0; t < nt; t++) {
        const int32_t *v = tri + 3 * t, bottom[4] = {v[0], v[2], v[1], -1};
        const int32_t upper[4] = {top + v[0], top + v[1], top + v[2], -1};
        if (!tets) {
            put(b, t, 0, bottom, (int64_t)t, 0);
            put(b, nt + t, 1, upper, (int64_t)(last + t), 1);
            continue;
        }
        put_tet_face(b, t, 0, tets + 12 * t, 3 * (int64_t)t, bottom[0], bottom[1], bottom[2]);
        put_tet_face(b, nt + t, 1, tets + 12 * (last + t), 3 * (int64_t)(last + t), upper[0], upper[1], upper[2]);
    }
    /* The faces sorted by group, the caps first, then a counting sort of
     * the walls; its offsets are kept, so that callers take a group's faces
     * without a scan. */
    size_t *offsets = b->offsets;
    for (size_t i = 0; i < n; i++) offsets[walls->edge_group[i] + 1] += per_edge;
    offsets[1] = nt, offsets[2] = 2 * nt;
    for (size_t g = 2; g < walls->groups; g++) offsets[g + 1] += offsets[g];
    memcpy(at, offsets, (walls->groups + 1) * sizeof *at);
    /* Boundary vertex w ends the boundary edge u -> w whose left side is a
     * triangle: the opposite of w's outgoing boundary half-edge, which
     * runs clockwise. The edge is u's in the loop's order if w follows u
     * there, else w's. */
    for (size_t w = 0; w < n; w++) {
        int32_t h = r->vertex_he[w], u = r->he_to[h], t = r->he_face[h ^ 1];
        size_t edge = cm_loops_next(r->loop_start, n, (size_t)u) == w ? (size_t)u : w;
        int32_t group = walls->edge_group[edge];
        int64_t j = tri[3 * t] == u ? 0 : tri[3 * t + 1] == u ? 1 : 2; /* u -> w is the triangle's edge j */
        for (size_t s = 0; s + 1 < ns; s++) {
            int32_t lo = (int32_t)(s * nv), hi = (int32_t)((s + 1) * nv);
            int32_t a = lo + u, c = lo + (int32_t)w, c1 = hi + (int32_t)w, a1 = hi + u;
            int64_t prism = (int64_t)(s * nt + (size_t)t);
            if (!tets) {
                const int32_t quad[4] = {a, c, c1, a1};
                put(b, at[group]++, group, quad, prism, 2 + j);
                continue;
            }
            const int32_t *prism_tets = tets + 12 * prism;
            int diagonal_a_c1 = 0;
            for (int i = 0; i < 3; i++) diagonal_a_c1 |= tet_has_edge(prism_tets + 4 * i, a, c1);
            if (diagonal_a_c1) {
                put_tet_face(b, at[group]++, group, prism_tets, 3 * prism, a, c, c1);
                put_tet_face(b, at[group]++, group, prism_tets, 3 * prism, a, c1, a1);
            } else {
                put_tet_face(b, at[group]++, group, prism_tets, 3 * prism, a, c, a1);
                put_tet_face(b, at[group]++, group, prism_tets, 3 * prism, c, c1, a1);
            }
        }
    }
    free(at);
    return CM_OK;
}

void cm_sweep_boundary_free(cm_sweep_boundary *b)
{
    free(b->faces), free(b->groups), free(b->cells), free(b->offsets);
    b->faces = b->groups = NULL;
    b->cells = NULL;
    b->offsets = NULL;
    b->nf = 0;
}
