#include "morph/prism_split.h"

#include <stdlib.h>
#include <string.h>

#include "base/mesh.h"
#include "morph/cell_shape.h"

/* The corner orders: the first three are rotations of the triangle's own
 * (counter-clockwise) order, the last three reflections. */
static const unsigned char orders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};

void cm_prism_split_tets(const int32_t v[6], unsigned char order, int32_t out[12])
{
    const unsigned char *o = orders[order];
    int32_t bp = v[o[0]], bq = v[o[1]], br = v[o[2]], tp = v[o[0] + 3], tq = v[o[1] + 3], tr = v[o[2] + 3];
    const int32_t tets[12] = {bp, bq, br, tr, bp, bq, tr, tq, bp, tp, tq, tr};
    memcpy(out, tets, sizeof tets);
    if (order >= 3) /* a reflection: swapping two corners of each restores the sign */
        for (int j = 0; j < 3; j++) {
            int32_t swap = out[4 * j];
            out[4 * j] = out[4 * j + 1], out[4 * j + 1] = swap;
        }
}

void cm_prism_split_free(cm_prism_split *split)
{
    free(split->tri_edge), free(split->edge_tri), free(split->edge_end);
    free(split->dir), free(split->score), free(split->order), free(split->queue);
    free(split->vertex_start), free(split->vertex_edge), free(split->saved);
    memset(split, 0, sizeof *split);
}

cm_status cm_prism_split_init(cm_prism_split *split, const int32_t *tri, size_t nt, size_t nv,
                              cm_error *error)
{
    memset(split, 0, sizeof *split);
    split->nv = nv, split->nt = nt, split->tri = tri;
    cm_edge_key *keys = cm_mesh_edge_keys(tri, nt);
    split->tri_edge = malloc((3 * nt + 1) * sizeof *split->tri_edge);
    split->edge_tri = malloc((6 * nt + 1) * sizeof *split->edge_tri);
    split->edge_end = malloc((6 * nt + 1) * sizeof *split->edge_end);
    split->dir = malloc(3 * nt + 1);
    split->score = malloc((6 * nt + 1) * sizeof *split->score);
    split->order = malloc((nt + 1) * sizeof *split->order);
    split->queue = malloc((3 * nt + 1) * sizeof *split->queue);
    if (!keys || !split->tri_edge || !split->edge_tri || !split->edge_end || !split->dir || !split->score ||
        !split->order || !split->queue) {
        free(keys);
        cm_prism_split_free(split);
        return cm_fail_status(error, CM_ERR_NO_MEMORY);
    }
    size_t ne = 0;
    for (size_t i = 0; i < 3 * nt; i++) {
        if (i == 0 || keys[i].lo != keys[i - 1].lo || keys[i].hi != keys[i - 1].hi) {
            split->edge_end[2 * ne] = keys[i].lo, split->edge_end[2 * ne + 1] = keys[i].hi;
            split->edge_tri[2 * ne] = keys[i].corner / 3, split->edge_tri[2 * ne + 1] = -1;
            ne++;
        } else {
            split->edge_tri[2 * (ne - 1) + 1] = keys[i].corner / 3;
        }
        split->tri_edge[keys[i].corner] = (int32_t)(ne - 1);
    }
    split->ne = ne;
    free(keys);
    split->vertex_start = calloc(nv + 2, sizeof *split->vertex_start);
    split->vertex_edge = malloc((2 * ne + 1) * sizeof *split->vertex_edge);
    split->saved = malloc(ne + 1);
    if (!split->vertex_start || !split->vertex_edge || !split->saved) {
        cm_prism_split_free(split);
        return cm_fail_status(error, CM_ERR_NO_MEMORY);
    }
    for (size_t e = 0; e < ne; e++) split->vertex_start[split->edge_end[2 * e] + 2]++, split->vertex_start[split->edge_end[2 * e + 1] + 2]++;
    for (size_t v = 0; v < nv; v++) split->vertex_start[v + 2] += split->vertex_start[v + 1];
    for (size_t e = 0; e < ne; e++)
        for (int k = 0; k < 2; k++) split->vertex_edge[split->vertex_start[split->edge_end[2 * e + k] + 1]++] = (int32_t)e;
    return CM_OK;
}

static void corner_xyz(const double *bottom, const double *top, int32_t node, size_t nv, double p[3])
{
    const double *src = (size_t)node < nv ? bottom + 3 * (size_t)node : top + 3 * ((size_t)node - nv);
    p[0] = src[0], p[1] = src[1], p[2] = src[2];
}

/* Smallest dihedral angle of the 3 tetrahedra of triangle t's prism in
 * corner order o. */
static double order_score(const cm_prism_split *s, size_t t, unsigned char o, const double *bottom,
                          const double *top)
{
    const int32_t *c = s->tri + 3 * t;
    int32_t nv = (int32_t)s->nv, v[6] = {c[0], c[1], c[2], c[0] + nv, c[1] + nv, c[2] + nv}, q[12];
    cm_prism_split_tets(v, o, q);
    double worst = 180;
    for (int j = 0; j < 3; j++) {
        double p[4][3];
        for (int k = 0; k < 4; k++) corner_xyz(bottom, top, q[4 * j + k], s->nv, p[k]);
        double angle = cm_tet_min_dihedral(p);
        if (angle < worst) worst = angle;
    }
    return worst;
}

/* 1 if corner order o of triangle t agrees with the edges already oriented. */
static int order_allowed(const cm_prism_split *s, size_t t, unsigned char o)
{
    const unsigned char *ord = orders[o];
    int rank[3];
    for (int i = 0; i < 3; i++) rank[ord[i]] = i;
    for (int c = 0; c < 3; c++) {
        int32_t e = s->tri_edge[3 * t + c];
        if (s->dir[e] < 0) continue;
        int32_t u = s->tri[3 * t + c];
        int u_first = rank[c] < rank[(c + 1) % 3]; /* u before the edge's other end */
        int lower_first = u == s->edge_end[2 * e] ? u_first : !u_first;
        if (lower_first != s->dir[e]) return 0;
    }
    return 1;
}

/* The edges queue[head .. logged) were just oriented: triangles with two
 * edges forming a path get their third edge forced, transitively. Every
 * edge oriented is appended to the log (queue[0 .. logged)), so a trial
 * can be undone. */
static void propagate(cm_prism_split *s, size_t head)
{
    size_t tail = s->logged;
    while (head < tail) {
        int32_t f = s->queue[head++];
        for (int side = 0; side < 2; side++) {
            int32_t t = s->edge_tri[2 * f + side];
            if (t < 0) continue;
            int open = -1, count = 0;
            for (int c = 0; c < 3; c++)
                if (s->dir[s->tri_edge[3 * t + c]] < 0) open = c, count++;
            if (count != 1) continue;
            /* Corner c's edge runs c -> c+1; the two oriented edges are
             * (c+1, c+2) and (c+2, c): a path when both agree with, or both
             * oppose, the counter-clockwise direction; the open edge then
             * closes it the other way round (acyclic). */
            int along[3];
            for (int c = 0; c < 3; c++) {
                int32_t g = s->tri_edge[3 * t + c];
                if (s->dir[g] < 0) continue;
                int lower_first = s->dir[g];
                along[c] = (s->tri[3 * t + c] == s->edge_end[2 * g]) == lower_first;
            }
            int c1 = (open + 1) % 3, c2 = (open + 2) % 3;
            if (along[c1] != along[c2]) continue;
            /* The open edge goes against that direction. */
            int32_t g = s->tri_edge[3 * t + open];
            int u_lower = s->tri[3 * t + open] == s->edge_end[2 * g];
            s->dir[g] = (signed char)(along[c1] ? !u_lower : u_lower);
            s->queue[tail++] = g;
        }
    }
    s->logged = tail;
}

/* The best score triangle t can still get. */
static float bound(const cm_prism_split *s, size_t t)
{
    float best = -2;
    for (unsigned char o = 0; o < 6; o++)
        if (s->score[6 * t + o] > best && order_allowed(s, t, o)) best = s->score[6 * t + o];
    return best;
}

/* Gives triangle t corner order o (allowed by its oriented edges): its
 * open edges are all oriented before any forcing, so forcing cannot turn
 * one of them against o. */
static void apply_order(cm_prism_split *s, size_t t, unsigned char o)
{
    const unsigned char *ord = orders[o];
    int rank[3];
    for (int k = 0; k < 3; k++) rank[ord[k]] = k;
    size_t first = s->logged;
    for (int c = 0; c < 3; c++) {
        int32_t e = s->tri_edge[3 * t + c];
        if (s->dir[e] >= 0) continue;
        int u_first = rank[c] < rank[(c + 1) % 3];
        s->dir[e] = (signed char)(s->tri[3 * t + c] == s->edge_end[2 * e] ? u_first : !u_first);
        s->queue[s->logged++] = e;
    }
    propagate(s, first);
}

/* Orders by vertex index: conforming whatever the geometry, the fallback
 * when look-ahead ends in a conflict. */
static unsigned char index_order(const int32_t *c)
{
    for (unsigned char o = 0;; o++)
        if (c[orders[o][0]] < c[orders[o][1]] && c[orders[o][1]] < c[orders[o][2]]) return o;
}

/* 1 if triangle t has all three edges oriented around it one way. */
static int cyclic(const cm_prism_split *s, size_t t)
{
    int along = 0;
    for (int c = 0; c < 3; c++) {
        int32_t g = s->tri_edge[3 * t + c];
        if (s->dir[g] < 0) return 0;
        along += (s->tri[3 * t + c] == s->edge_end[2 * g]) == s->dir[g];
    }
    return along == 0 || along == 3;
}

/* What order o of triangle t leaves its neighbours: the smallest best
 * score among the triangles whose edges it orients (forced ones
 * included), t's own for o among them; -3 when forcing runs into a
 * triangle oriented in a cycle (two forced directions for one edge).
 * Leaves the orientation unchanged. */
static float trial(cm_prism_split *s, size_t t, unsigned char o)
{
    size_t start = s->logged;
    apply_order(s, t, o);
    float worst = s->score[6 * t + o];
    for (size_t i = start; i < s->logged && worst > -3; i++) {
        int32_t e = s->queue[i];
        for (int side = 0; side < 2; side++) {
            int32_t u = s->edge_tri[2 * e + side];
            if (u < 0) continue;
            if (cyclic(s, (size_t)u)) {
                worst = -3;
                break;
            }
            if ((size_t)u == t) continue;
            float b = bound(s, (size_t)u);
            if (b < worst) worst = b;
        }
    }
    for (size_t i = start; i < s->logged; i++) s->dir[s->queue[i]] = -1;
    s->logged = start;
    return worst;
}

static int compare_best(const void *x, const void *y)
{
    const cm_split_rank *p = x, *q = y;
    if (p->best != q->best) return p->best < q->best ? -1 : 1;
    return (p->tri > q->tri) - (p->tri < q->tri);
}

/* The corner order the oriented edges give triangle t, or -1 if they run
 * around it in a cycle. */
static int order_of(const cm_prism_split *s, size_t t)
{
    int precedes[3] = {0, 0, 0};
    for (int c = 0; c < 3; c++) {
        int32_t e = s->tri_edge[3 * t + c];
        int along = (s->tri[3 * t + c] == s->edge_end[2 * e]) == s->dir[e];
        precedes[along ? c : (c + 1) % 3]++;
    }
    for (int o = 0; o < 6; o++)
        if (precedes[orders[o][0]] == 2 && precedes[orders[o][1]] == 1) return o;
    return -1;
}

/* Makes vertex v come first (sink 0) or last (sink 1) among its
 * neighbours, which keeps every triangle acyclic, if that raises the
 * smallest score among the triangles whose order it changes. Returns 1 if
 * done. */
static int move_vertex(cm_prism_split *s, int32_t v, int sink, unsigned char *order)
{
    float before = 180, after = 180;
    size_t lo = s->vertex_start[v], hi = s->vertex_start[v + 1];
    for (size_t i = lo; i < hi; i++) {
        int32_t e = s->vertex_edge[i];
        s->saved[e] = s->dir[e];
        int v_lower = s->edge_end[2 * e] == v;
        s->dir[e] = (signed char)(sink ? !v_lower : v_lower);
    }
    for (size_t i = lo; i < hi; i++) {
        int32_t e = s->vertex_edge[i];
        for (int side = 0; side < 2; side++) {
            int32_t t = s->edge_tri[2 * e + side];
            if (t < 0) continue;
            int o = order_of(s, (size_t)t);
            if (o == order[t]) continue; /* unchanged: not part of the comparison */
            float value = o < 0 ? -3 : s->score[6 * (size_t)t + (size_t)o];
            after = value < after ? value : after;
            before = s->score[6 * (size_t)t + order[t]] < before ? s->score[6 * (size_t)t + order[t]] : before;
        }
    }
    if (after > before) {
        for (size_t i = lo; i < hi; i++)
            for (int side = 0; side < 2; side++) {
                int32_t t = s->edge_tri[2 * s->vertex_edge[i] + side];
                if (t >= 0) order[t] = (unsigned char)order_of(s, (size_t)t);
            }
        return 1;
    }
    for (size_t i = lo; i < hi; i++) s->dir[s->vertex_edge[i]] = s->saved[s->vertex_edge[i]];
    return 0;
}

/* Gives triangle t corner order o if its neighbours stay acyclic and the
 * smallest score among t and the neighbours whose order changes rises.
 * Returns 1 if done. */
static int move_triangle(cm_prism_split *s, size_t t, unsigned char o, unsigned char *order)
{
    if (o == order[t]) return 0;
    const unsigned char *ord = orders[o];
    int rank[3];
    for (int k = 0; k < 3; k++) rank[ord[k]] = k;
    float before = s->score[6 * t + order[t]], after = s->score[6 * t + o];
    int32_t other[3];
    for (int c = 0; c < 3; c++) {
        int32_t e = s->tri_edge[3 * t + c];
        other[c] = s->edge_tri[2 * e] == (int32_t)t ? s->edge_tri[2 * e + 1] : s->edge_tri[2 * e];
        s->saved[e] = s->dir[e];
        int u_first = rank[c] < rank[(c + 1) % 3];
        s->dir[e] = (signed char)(s->tri[3 * t + c] == s->edge_end[2 * e] ? u_first : !u_first);
    }
    int next[3] = {0, 0, 0};
    for (int c = 0; c < 3; c++) {
        if (other[c] < 0) continue;
        size_t u = (size_t)other[c];
        next[c] = order_of(s, u);
        if (next[c] == order[u]) continue; /* unchanged: not part of the comparison */
        float value = next[c] < 0 ? -3 : s->score[6 * u + (size_t)next[c]];
        after = value < after ? value : after;
        before = s->score[6 * u + order[u]] < before ? s->score[6 * u + order[u]] : before;
    }
    if (after > before) {
        order[t] = o;
        for (int c = 0; c < 3; c++)
            if (other[c] >= 0) order[other[c]] = (unsigned char)next[c];
        return 1;
    }
    for (int c = 0; c < 3; c++) s->dir[s->tri_edge[3 * t + c]] = s->saved[s->tri_edge[3 * t + c]];
    return 0;
}

/* Local search after the greedy choice: a prism whose split came out poor
 * (its edges forced by neighbours chosen earlier) flips one of its
 * diagonals when both prisms sharing it stay acyclic and the worse of the
 * two improves, takes another order on the same terms with its three
 * neighbours, or moves one of its corners to the front or the back of
 * the order around it (always acyclic) when the prisms around improve. A
 * few passes, worst prisms first. */
static void improve(cm_prism_split *s, unsigned char *order)
{
    for (int pass = 0; pass < 8; pass++) {
        int changed = 0;
        for (size_t t = 0; t < s->nt; t++) s->order[t] = (cm_split_rank){s->score[6 * t + order[t]], (int32_t)t};
        qsort(s->order, s->nt, sizeof *s->order, compare_best);
        for (size_t i = 0; i < s->nt; i++) {
            size_t t = (size_t)s->order[i].tri;
            for (int c = 0; c < 3; c++) {
                int32_t e = s->tri_edge[3 * t + c];
                int32_t u = s->edge_tri[2 * e] == (int32_t)t ? s->edge_tri[2 * e + 1] : s->edge_tri[2 * e];
                float before = s->score[6 * t + order[t]];
                if (u >= 0 && s->score[6 * (size_t)u + order[u]] < before) before = s->score[6 * (size_t)u + order[u]];
                s->dir[e] = (signed char)!s->dir[e];
                int ot = order_of(s, t), ou = u >= 0 ? order_of(s, (size_t)u) : 0;
                if (ot >= 0 && ou >= 0) {
                    float after = s->score[6 * t + (size_t)ot];
                    if (u >= 0 && s->score[6 * (size_t)u + (size_t)ou] < after) after = s->score[6 * (size_t)u + (size_t)ou];
                    if (after > before) {
                        order[t] = (unsigned char)ot;
                        if (u >= 0) order[u] = (unsigned char)ou;
                        changed = 1;
                        continue;
                    }
                }
                s->dir[e] = (signed char)!s->dir[e];
            }
            for (int c = 0; c < 3; c++)
                for (int sink = 0; sink < 2; sink++) changed |= move_vertex(s, s->tri[3 * t + c], sink, order);
            for (unsigned char o = 0; o < 6; o++) changed |= move_triangle(s, t, o, order);
        }
        if (!changed) break;
    }
}

double cm_prism_split_choose(cm_prism_split *s, const double *bottom, const double *top, unsigned char *order)
{
    size_t nt = s->nt;
    memset(s->dir, -1, s->ne);
    for (size_t t = 0; t < nt; t++) {
        float top_score = -2;
        for (unsigned char o = 0; o < 6; o++) {
            float value = (float)order_score(s, t, o, bottom, top);
            s->score[6 * t + o] = value;
            if (value > top_score) top_score = value;
        }
        s->order[t] = (cm_split_rank){top_score, (int32_t)t};
    }
    qsort(s->order, nt, sizeof *s->order, compare_best);
    /* Each triangle, worst first, takes the allowed order that leaves the
     * triangles it constrains the best (one step of look-ahead: a forced
     * edge can leave a neighbour with only a sliver), then its own best. */
    double worst = 180;
    s->logged = 0;
    for (size_t i = 0; i < nt; i++) {
        size_t t = (size_t)s->order[i].tri;
        int chosen = -1;
        float chosen_trial = 0;
        for (unsigned char o = 0; o < 6; o++) {
            if (!order_allowed(s, t, o)) continue;
            float value = trial(s, t, o);
            if (value <= -3) continue;
            if (chosen < 0 || value > chosen_trial ||
                (value == chosen_trial && s->score[6 * t + o] > s->score[6 * t + chosen]))
                chosen = o, chosen_trial = value;
        }
        if (chosen < 0) { /* every order conflicts: split by vertex index */
            memset(s->dir, 1, s->ne);
            for (size_t u = 0; u < nt; u++) order[u] = index_order(s->tri + 3 * u);
            break;
        }
        order[t] = (unsigned char)chosen;
        apply_order(s, t, (unsigned char)chosen);
        s->logged = 0; /* kept: the log is for trials only */
    }
    improve(s, order);
    for (size_t t = 0; t < nt; t++)
        if (s->score[6 * t + order[t]] < worst) worst = s->score[6 * t + order[t]];
    return worst;
}
