/* The sweep's boundary faces checked against the cells: the group count,
 * sizes and offsets, each cap on its section and each wall face on two
 * consecutive sections over its own loop, the faces closing around the
 * volume outward (the flux of x / 3 through them is the cells' volume:
 * the bilinear quads integrated exactly by 2 x 2 Gauss points), and with
 * tets the boundary triangles exactly the tetrahedra's unshared faces. */
#ifndef CM_TEST_SWEEP_BOUNDARY_CHECK_H
#define CM_TEST_SWEEP_BOUNDARY_CHECK_H
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "compatmesh/compatmesh.h"

static void sb_cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1], out[1] = a[2] * b[0] - a[0] * b[2], out[2] = a[0] * b[1] - a[1] * b[0];
}

static double sb_dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* The flux of (x - o) / 3 through the face (triangle or bilinear quad);
 * o off every face's plane, so that no face's share is zero. */
static double sb_flux(const double *nodes, const int32_t *f, const double o[3])
{
    double corner[4][3];
    for (int i = 0; i < 4 && (i < 3 || f[3] >= 0); i++)
        for (int k = 0; k < 3; k++) corner[i][k] = nodes[3 * (size_t)f[i] + (size_t)k] - o[k];
    const double *a = corner[0], *b = corner[1], *c = corner[2];
    double n[3];
    if (f[3] < 0) {
        sb_cross(b, c, n);
        return sb_dot(a, n) / 6.0;
    }
    const double *d = corner[3];
    static const double g[2] = {0.21132486540518711775, 0.78867513459481288225};
    double sum = 0;
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            double u = g[i], v = g[j], p[3], pu[3], pv[3];
            for (int k = 0; k < 3; k++) {
                p[k] = (1 - u) * (1 - v) * a[k] + u * (1 - v) * b[k] + u * v * c[k] + (1 - u) * v * d[k];
                pu[k] = (1 - v) * (b[k] - a[k]) + v * (c[k] - d[k]);
                pv[k] = (1 - u) * (d[k] - a[k]) + u * (c[k] - b[k]);
            }
            sb_cross(pu, pv, n);
            sum += 0.25 * sb_dot(p, n);
        }
    return sum / 3.0;
}

static int sb_int_less(const void *pa, const void *pb)
{
    int32_t a = *(const int32_t *)pa, b = *(const int32_t *)pb;
    return (a > b) - (a < b);
}

static int sb_key_less(const void *pa, const void *pb)
{
    const int32_t *a = pa, *b = pb;
    for (int i = 0; i < 3; i++)
        if (a[i] != b[i]) return (a[i] > b[i]) - (a[i] < b[i]);
    return 0;
}

/* With tets: the boundary triangles, sorted, against the tetrahedra's
 * faces that no other tetrahedron shares. */
static void sb_check_tet_faces(const char *name, const cm_sweep *w)
{
    size_t nt4 = 4 * cm_sweep_num_tets(w), nb = cm_sweep_num_boundary_faces(w, 1), open = 0;
    int32_t *faces = malloc(3 * nt4 * sizeof *faces), *mine = malloc(3 * nb * sizeof *mine);
    const int32_t *tet = cm_sweep_tets(w), *bf = cm_sweep_boundary_faces(w, 1);
    for (size_t i = 0; i < nt4; i++) {
        for (int c = 0, j = 0; c < 4; c++)
            if (c != (int)(i % 4)) faces[3 * i + (size_t)j++] = tet[4 * (i / 4) + (size_t)c];
        qsort(faces + 3 * i, 3, sizeof *faces, sb_int_less);
    }
    qsort(faces, nt4, 3 * sizeof *faces, sb_key_less);
    for (size_t i = 0; i < nt4;) {
        size_t j = i + 1;
        while (j < nt4 && sb_key_less(faces + 3 * i, faces + 3 * j) == 0) j++;
        if (j - i == 1) memmove(faces + 3 * open++, faces + 3 * i, 3 * sizeof *faces);
        i = j;
    }
    for (size_t i = 0; i < nb; i++) {
        memcpy(mine + 3 * i, bf + 4 * i, 3 * sizeof *mine);
        qsort(mine + 3 * i, 3, sizeof *mine, sb_int_less);
    }
    qsort(mine, nb, 3 * sizeof *mine, sb_key_less);
    CHECK_MSG(open == nb && memcmp(faces, mine, 3 * nb * sizeof *mine) == 0,
              "%s: %zu boundary triangles against %zu unshared tetrahedron faces", name, nb, open);
    free(faces), free(mine);
}

/* Each face is the face of its cell that cm_sweep_boundary_cells names
 * (Abaqus' numbering from 0: the same corners, in any order). */
static void sb_check_cells(const char *name, const cm_sweep *w, int tets)
{
    static const int prism_face[5][4] = {{0, 1, 2, -1}, {3, 4, 5, -1}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
    static const int tet_face[4][4] = {{0, 1, 2, -1}, {0, 3, 1, -1}, {1, 3, 2, -1}, {2, 3, 0, -1}};
    size_t nf = cm_sweep_num_boundary_faces(w, tets), wrong = 0;
    size_t cells = tets ? cm_sweep_num_tets(w) : cm_sweep_num_prisms(w), per_cell = tets ? 4 : 6;
    const int32_t *f = cm_sweep_boundary_faces(w, tets), *corners = tets ? cm_sweep_tets(w) : cm_sweep_prisms(w);
    const int64_t *c = cm_sweep_boundary_cells(w, tets);
    for (size_t i = 0; c && i < nf; i++) {
        int64_t cell = c[2 * i], side = c[2 * i + 1];
        if (cell < 0 || (size_t)cell >= cells || side < 0 || side >= (tets ? 4 : 5)) {
            wrong++;
            continue;
        }
        const int *local = tets ? tet_face[side] : prism_face[side];
        int32_t mine[4] = {-1, -1, -1, -1}, theirs[4] = {-1, -1, -1, -1};
        for (int k = 0; k < 4; k++) {
            mine[k] = f[4 * i + (size_t)k];
            if (local[k] >= 0) theirs[k] = corners[per_cell * (size_t)cell + (size_t)local[k]];
        }
        qsort(mine, 4, sizeof *mine, sb_int_less), qsort(theirs, 4, sizeof *theirs, sb_int_less);
        wrong += memcmp(mine, theirs, sizeof mine) != 0;
    }
    CHECK_MSG(c && wrong == 0, "%s: %zu of %zu boundary faces not the cell face named (%s)", name, wrong, nf,
              tets ? "tets" : "prisms");
}

static void check_sweep_boundary(const char *name, const cm_sweep *w, const cm_result *r, int tets)
{
    size_t nv = cm_result_num_vertices(r), nt = cm_result_num_triangles(r), ns = cm_sweep_num_sections(w);
    size_t n = cm_result_stats(r)->n, holes = cm_result_stats(r)->holes;
    /* Each boundary vertex's loop, by walking the boundary half-edges; a
     * loop's number is the order of its smallest vertex (the loops come
     * one after another). */
    const int32_t *vh = cm_result_vertex_halfedge(r), *next = cm_result_halfedge_next(r),
                  *to = cm_result_halfedge_to_vertex(r);
    long *loop = malloc(n * sizeof *loop);
    for (size_t v = 0; v < n; v++) loop[v] = -1;
    long loops = 0;
    for (size_t v = 0; v < n; v++) {
        if (loop[v] >= 0) continue;
        int32_t h = vh[v];
        do loop[to[h ^ 1]] = loops, h = next[h];
        while (to[h ^ 1] != (int32_t)v);
        loops++;
    }
    size_t groups = cm_sweep_num_boundary_groups(w);
    CHECK_MSG((size_t)loops == holes + 1 && groups >= 3 + holes, "%s: %ld loops, %zu holes, %zu groups", name, loops,
              holes, groups);
    size_t nf = cm_sweep_num_boundary_faces(w, tets), per_edge = tets ? 2 : 1;
    const int32_t *f = cm_sweep_boundary_faces(w, tets), *g = cm_sweep_boundary_groups(w, tets);
    CHECK_MSG(nf == 2 * nt + (ns - 1) * n * per_edge, "%s: %zu boundary faces", name, nf);
    /* The group offsets: from 0 to the face count, each group's run of
     * faces exactly its own. */
    const size_t *offsets = cm_sweep_boundary_group_offsets(w, tets);
    size_t off_wrong = 0;
    for (size_t k = 0; offsets && k < groups; k++) {
        off_wrong += offsets[k] > offsets[k + 1] || offsets[k + 1] > nf;
        for (size_t i = offsets[k]; i < offsets[k + 1] && i < nf; i++) off_wrong += g[i] != (int32_t)k;
    }
    CHECK_MSG(offsets && offsets[0] == 0 && offsets[groups] == nf && off_wrong == 0,
              "%s: group offsets %s, %zu out of place", name, offsets ? "given" : "missing", off_wrong);
    sb_check_cells(name, w, tets);
    const double *nodes = cm_sweep_nodes(w);
    /* Each wall group over one loop (the first face's), the loops in
     * order, and each loop's faces all there. */
    size_t misplaced = 0, unsorted = 0, *count = calloc(groups, sizeof *count), *loop_size = calloc(holes + 1, sizeof *count);
    long *group_loop = malloc(groups * sizeof *group_loop);
    for (size_t k = 0; k < groups; k++) group_loop[k] = -1;
    for (size_t v = 0; v < n; v++) loop_size[loop[v]]++;
    double flux = 0, height = cm_sweep_height(w);
    const double o[3] = {nodes[0] - 0.37 * height, nodes[1] - 0.61 * height, nodes[2] - 0.83 * height};
    for (size_t i = 0; i < nf; i++) {
        const int32_t *q = f + 4 * i;
        int corners = q[3] < 0 ? 3 : 4;
        unsorted += g[i] < 0 || (size_t)g[i] >= groups || (i && g[i] < g[i - 1]);
        if (g[i] < 0 || (size_t)g[i] >= groups) continue;
        count[g[i]]++;
        size_t lo = (size_t)q[0] / nv, hi = lo;
        for (int c = 0; c < corners; c++) {
            size_t s = (size_t)q[c] / nv, v = (size_t)q[c] % nv;
            lo = s < lo ? s : lo, hi = s > hi ? s : hi;
            if (g[i] < 2) continue;
            if (v >= n) {
                misplaced++;
                continue;
            }
            if (group_loop[g[i]] < 0) group_loop[g[i]] = loop[v];
            misplaced += loop[v] != group_loop[g[i]];
        }
        if (g[i] == 0) misplaced += corners != 3 || hi != 0;
        else if (g[i] == 1) misplaced += corners != 3 || lo != ns - 1;
        else misplaced += corners != (tets ? 3 : 4) || hi != lo + 1;
        flux += sb_flux(nodes, q, o);
    }
    int sizes_ok = count[0] == nt && count[1] == nt, names_ok = 1;
    size_t *per_loop = calloc(holes + 1, sizeof *per_loop);
    for (size_t k = 2; k < groups; k++) {
        sizes_ok &= group_loop[k] >= 0 && count[k] > 0 && (k == 2 || group_loop[k] >= group_loop[k - 1]);
        if (group_loop[k] < 0) continue;
        per_loop[group_loop[k]] += count[k];
        /* "side..." over the outer loop, "hole_<j>..." over hole j */
        const char *label = cm_sweep_boundary_group_name(w, k);
        char prefix[32];
        snprintf(prefix, sizeof prefix, group_loop[k] ? "hole_%ld" : "side", group_loop[k]);
        size_t length = strlen(prefix);
        names_ok &= label && strncmp(label, prefix, length) == 0 && (label[length] == '\0' || label[length] == '_');
    }
    for (size_t l = 0; l <= holes; l++) sizes_ok &= per_loop[l] == (ns - 1) * loop_size[l] * per_edge;
    names_ok &= strcmp(cm_sweep_boundary_group_name(w, 0), "bottom") == 0 &&
                strcmp(cm_sweep_boundary_group_name(w, 1), "top") == 0 && !cm_sweep_boundary_group_name(w, groups);
    CHECK_MSG(misplaced == 0 && unsorted == 0 && sizes_ok && names_ok,
              "%s: %zu faces misplaced, %zu out of group order%s%s", name, misplaced, unsorted,
              sizes_ok ? "" : ", group sizes wrong", names_ok ? "" : ", names wrong");
    free(per_loop), free(group_loop);
    double volume = cm_sweep_volume(w);
    if (tets) {
        const int32_t *t = cm_sweep_tets(w);
        volume = 0;
        for (size_t i = 0; i < cm_sweep_num_tets(w); i++) {
            const double *a = nodes + 3 * (size_t)t[4 * i], *b = nodes + 3 * (size_t)t[4 * i + 1],
                         *c = nodes + 3 * (size_t)t[4 * i + 2], *d = nodes + 3 * (size_t)t[4 * i + 3];
            double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, x[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]},
                   y[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]}, n3[3];
            sb_cross(x, y, n3);
            volume += sb_dot(u, n3) / 6.0;
        }
        sb_check_tet_faces(name, w);
    }
    CHECK_MSG(fabs(flux - volume) <= 1e-9 * fabs(volume), "%s: the boundary encloses %.15g, the cells %.15g", name,
              flux, volume);
    CHECK(cm_sweep_num_boundary_faces(w, !tets) == (tets ? 2 * nt + (ns - 1) * n : 0) || !tets);
    CHECK(!cm_sweep_boundary_group_offsets(w, !tets) == !cm_sweep_num_boundary_faces(w, !tets));
    free(loop), free(count), free(loop_size);
}
#endif
