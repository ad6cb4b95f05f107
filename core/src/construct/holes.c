/* Hole bridges. A hole joined to the rest by two vertex-disjoint paths
 * splits the piece around it in two: the paths and one arc of the hole
 * bound one side, the other arc the other. A path is a straight chord
 * between two loop vertices or, where no chord is valid in every geometry,
 * two segments through a Steiner vertex placed in each geometry on its
 * own. Paths that share no vertex leave every loop vertex at most one
 * path, inside its material corner, and Steiner vertices two segments, so
 * the order of edges around every vertex, and hence every piece's vertex
 * cycle, is the same in every geometry once each path is valid in each. */
#include <stdlib.h>
#include <string.h>
#include <math.h>

#include "construct/holes.h"
#include "geom/predicates.h"

/* Paths tried with Steiner bends when no straight chord is valid: the
 * shortest this many vertex pairs (the search costs O(n^3) per geometry),
 * with at most MAX_BENDS bends each. */
#define BEND_CANDIDATES 12
#define MAX_BENDS 32

typedef struct cut_state {
    const double *const *geoms;
    size_t k, num_loops, n;
    const size_t *start;
    int32_t *link;      /* loop vertex: the next vertex of its path, -1 none;
                           bend n + b: link[n + b] and the path's ends */
    int32_t *seg;       /* 2 vertex ids per path segment */
    size_t num_segs, num_paths, num_bends;
    int32_t *bend_nbr;  /* 2 per bend: its neighbours along its path */
    double **bend_xy;   /* k arrays, 2 per bend */
    size_t bend_cap;
    double *cand_xy;    /* scratch: candidate bend points of one geometry */
    int32_t *parent;    /* scratch: the search's tree */
    int32_t *queue;
    double *path_xy;    /* scratch: k paths of up to max_bends points */
    int32_t *path_len;
} cut_state;

typedef struct { double len; int32_t p, q; } candidate;

static int by_length(const void *a, const void *b)
{
    const candidate *x = a, *y = b;
    if (x->len != y->len) return x->len < y->len ? -1 : 1;
    if (x->p != y->p) return x->p < y->p ? -1 : 1;
    return (x->q > y->q) - (x->q < y->q);
}

static size_t loop_of(const cut_state *cs, int32_t v)
{
    size_t l = 0;
    while ((size_t)v >= cs->start[l + 1]) l++;
    return l;
}

static int32_t succ(const cut_state *cs, int32_t v)
{
    return (int32_t)cm_loops_next(cs->start, cs->n, (size_t)v);
}

static int32_t pred(const cut_state *cs, int32_t v)
{
    return (int32_t)cm_loops_prev(cs->start, cs->n, (size_t)v);
}

/* Where vertex v (loop vertex or bend) is in geometry g. */
static const double *pos(const cut_state *cs, size_t g, int32_t v)
{
    return (size_t)v < cs->n ? cs->geoms[g] + 2 * v : cs->bend_xy[g] + 2 * ((size_t)v - cs->n);
}

/* Point q strictly inside the material's corner at loop vertex v
 * (material left of pred -> v and v -> succ). */
static int in_corner(const cut_state *cs, size_t g, int32_t v, const double q[2])
{
    const double *pa = pos(cs, g, pred(cs, v)), *pv = pos(cs, g, v), *pb = pos(cs, g, succ(cs, v));
    int left_in = cm_orient2d(pa, pv, q) > 0, left_out = cm_orient2d(pv, pb, q) > 0;
    return cm_orient2d(pa, pv, pb) >= 0 ? left_in && left_out : left_in || left_out;
}

/* Segment a-b in geometry g (a, b loop vertices of the new path, or -1 for
 * the point bend): touches no loop edge away from a and b and no segment of
 * a path already chosen. */
static int segment_free(const cut_state *cs, size_t g, int32_t a, const double pa[2], int32_t b,
                        const double pb[2])
{
    for (size_t e = 0; e < cs->n; e++) {
        int32_t u = (int32_t)e, w = succ(cs, u);
        if (u == a || u == b || w == a || w == b) continue;
        if (cm_segments_intersect(pa, pb, pos(cs, g, u), pos(cs, g, w))) return 0;
    }
    for (size_t c = 0; c < cs->num_segs; c++)
        if (cm_segments_intersect(pa, pb, pos(cs, g, cs->seg[2 * c]), pos(cs, g, cs->seg[2 * c + 1])))
            return 0;
    return 1;
}

static int chord_valid_in(const cut_state *cs, size_t g, int32_t p, int32_t q)
{
    const double *a = pos(cs, g, p), *b = pos(cs, g, q);
    return in_corner(cs, g, p, b) && in_corner(cs, g, q, a) && segment_free(cs, g, p, a, q, b);
}

/* Candidate bend points of geometry g, 2 per loop vertex: a step inside
 * its corner along the bisector, and one inward from the middle of the
 * edge leaving it (each a quarter of the shorter edge there). Whether a
 * point is usable is decided by the exact segment tests alone. */
static size_t bend_candidates(const cut_state *cs, size_t g, double *out)
{
    size_t count = 0;
    for (int32_t w = 0; (size_t)w < cs->n; w++) {
        const double *a = pos(cs, g, pred(cs, w)), *v = pos(cs, g, w), *b = pos(cs, g, succ(cs, w));
        double ax = a[0] - v[0], ay = a[1] - v[1], bx = b[0] - v[0], by = b[1] - v[1];
        double la = hypot(ax, ay), lb = hypot(bx, by), step = 0.25 * fmin(la, lb);
        double dx = ax / la + bx / lb, dy = ay / la + by / lb, ld = hypot(dx, dy);
        int convex = cm_orient2d(a, v, b) > 0;
        if (ld < 1e-9 * (la + lb)) dx = -by / lb, dy = bx / lb, ld = 1; /* straight: the left normal */
        else if (!convex) dx = -dx, dy = -dy;
        out[count++] = v[0] + step * dx / ld, out[count++] = v[1] + step * dy / ld;
        out[count++] = v[0] + 0.5 * bx - 0.25 * by, out[count++] = v[1] + 0.5 * by + 0.25 * bx;
    }
    return count / 2;
}

/* One link of a path being searched in geometry g: node 0 is p, node
 * c + 1 candidate c, node m + 1 q (m candidates). */
static const double *node_pos(const cut_state *cs, size_t g, int32_t p, int32_t q, size_t m, size_t node)
{
    return node == 0 ? pos(cs, g, p) : node == m + 1 ? pos(cs, g, q) : cs->cand_xy + 2 * (node - 1);
}

static int link_ok(const cut_state *cs, size_t g, int32_t p, int32_t q, size_t m, size_t u, size_t v)
{
    const double *a = node_pos(cs, g, p, q, m, u), *b = node_pos(cs, g, p, q, m, v);
    if (a[0] == b[0] && a[1] == b[1]) return 0;
    if (u == 0 && !in_corner(cs, g, p, b)) return 0;
    if (v == m + 1 && !in_corner(cs, g, q, a)) return 0;
    return segment_free(cs, g, u == 0 ? p : -1, a, v == m + 1 ? q : -1, b);
}

/* A path from p to q in geometry g with the fewest links through candidate
 * points (breadth-first over their visibility, exact tests), written to
 * cs->path_xy + 2 * MAX_BENDS * g as its bends; the path must not touch
 * itself. Returns the number of bends, -1 when there is none. */
static long search_path(cut_state *cs, size_t g, int32_t p, int32_t q)
{
    size_t m = bend_candidates(cs, g, cs->cand_xy), head = 0, tail = 0;
    for (size_t v = 0; v < m + 2; v++) cs->parent[v] = -1;
    cs->parent[0] = 0, cs->queue[tail++] = 0;
    while (head < tail && cs->parent[m + 1] < 0) {
        size_t u = (size_t)cs->queue[head++];
        for (size_t v = 1; v < m + 2; v++)
            if (cs->parent[v] < 0 && link_ok(cs, g, p, q, m, u, v)) {
                cs->parent[v] = (int32_t)u;
                cs->queue[tail++] = (int32_t)v;
                if (v == m + 1) break;
            }
    }
    if (cs->parent[m + 1] < 0) return -1;
    long bends = 0;
    for (size_t v = (size_t)cs->parent[m + 1]; v != 0; v = (size_t)cs->parent[v]) bends++;
    if (bends > MAX_BENDS) return -1;
    double *out = cs->path_xy + 2 * MAX_BENDS * g;
    long i = bends;
    for (size_t v = (size_t)cs->parent[m + 1]; v != 0; v = (size_t)cs->parent[v]) {
        const double *c = cs->cand_xy + 2 * (v - 1);
        i--, out[2 * i] = c[0], out[2 * i + 1] = c[1];
    }
    /* no two links of the path may touch, but consecutive ones at their
     * shared bend (and then not folding back) */
    for (long a = 0; a <= bends; a++)
        for (long b = a + 1; b <= bends; b++) {
            const double *a0 = a ? out + 2 * (a - 1) : pos(cs, g, p), *a1 = a < bends ? out + 2 * a : pos(cs, g, q);
            const double *b0 = out + 2 * (b - 1), *b1 = b < bends ? out + 2 * b : pos(cs, g, q);
            if (b == a + 1 ? cm_orient2d(a0, a1, b1) == 0 &&
                                 (a1[0] - a0[0]) * (b1[0] - a1[0]) + (a1[1] - a0[1]) * (b1[1] - a1[1]) <= 0
                           : cm_segments_intersect(a0, a1, b0, b1))
                return -1;
        }
    return bends;
}

/* Splits the longest link of geometry g's path (bends in path_xy) at its
 * midpoint, a bend strictly inside a free segment, until it has `want`. */
static void pad_path(cut_state *cs, size_t g, int32_t p, int32_t q, long have, long want)
{
    double *out = cs->path_xy + 2 * MAX_BENDS * g;
    for (; have < want; have++) {
        long best = 0;
        double best_len = -1;
        for (long a = 0; a <= have; a++) {
            const double *a0 = a ? out + 2 * (a - 1) : pos(cs, g, p), *a1 = a < have ? out + 2 * a : pos(cs, g, q);
            double len = hypot(a1[0] - a0[0], a1[1] - a0[1]);
            if (len > best_len) best_len = len, best = a;
        }
        const double *a0 = best ? out + 2 * (best - 1) : pos(cs, g, p), *a1 = best < have ? out + 2 * best : pos(cs, g, q);
        double mx = 0.5 * (a0[0] + a1[0]), my = 0.5 * (a0[1] + a1[1]);
        memmove(out + 2 * (best + 1), out + 2 * best, 2 * (size_t)(have - best) * sizeof *out);
        out[2 * best] = mx, out[2 * best + 1] = my;
    }
}

static void add_segment(cut_state *cs, int32_t a, int32_t b)
{
    cs->seg[2 * cs->num_segs] = a, cs->seg[2 * cs->num_segs + 1] = b;
    cs->num_segs++;
}

/* The loop vertices a path from hole h may reach: the outer loop and the
 * holes joined before it (joined[l]), free of paths. Candidates from hole
 * h to those, shortest first (summed over the geometries, so the path is
 * short in all); the first valid straight chord is taken, else the first
 * of the shortest BEND_CANDIDATES that has a bend in every geometry.
 * Returns 1, 0 when none is valid. */
static int join_hole(cut_state *cs, size_t h, const unsigned char *joined, candidate *cand)
{
    size_t nc = 0;
    for (int32_t p = (int32_t)cs->start[h]; (size_t)p < cs->start[h + 1]; p++) {
        if (cs->link[p] >= 0) continue;
        for (int32_t q = 0; (size_t)q < cs->n; q++) {
            if (cs->link[q] >= 0 || !joined[loop_of(cs, q)]) continue;
            double len = 0;
            for (size_t g = 0; g < cs->k; g++) {
                const double *a = pos(cs, g, p), *b = pos(cs, g, q);
                len += hypot(a[0] - b[0], a[1] - b[1]);
            }
            cand[nc++] = (candidate){len, p, q};
        }
    }
    qsort(cand, nc, sizeof *cand, by_length);
    for (size_t i = 0; i < nc; i++) {
        int32_t p = cand[i].p, q = cand[i].q;
        size_t g = 0;
        while (g < cs->k && chord_valid_in(cs, g, p, q)) g++;
        if (g < cs->k) continue;
        cs->link[p] = q, cs->link[q] = p;
        add_segment(cs, p, q);
        cs->num_paths++;
        return 1;
    }
    for (size_t i = 0; i < nc && i < BEND_CANDIDATES; i++) {
        int32_t p = cand[i].p, q = cand[i].q;
        long most = 0, g = 0;
        for (; g < (long)cs->k; g++) {
            long bends = search_path(cs, (size_t)g, p, q);
            if (bends < 0) break;
            cs->path_len[g] = (int32_t)bends;
            if (bends > most) most = bends;
        }
        if (g < (long)cs->k) continue;
        if (most == 0) most = 1; /* straight everywhere yet no common chord: cannot be */
        if (cs->num_bends + (size_t)most > cs->bend_cap) return 0;
        for (size_t h2 = 0; h2 < cs->k; h2++) {
            pad_path(cs, h2, p, q, cs->path_len[h2], most);
            memcpy(cs->bend_xy[h2] + 2 * cs->num_bends, cs->path_xy + 2 * MAX_BENDS * h2,
                   2 * (size_t)most * sizeof(double));
        }
        int32_t first = (int32_t)(cs->n + cs->num_bends), prev = p;
        for (long b = 0; b < most; b++) {
            int32_t id = first + (int32_t)b, next = b + 1 < most ? id + 1 : q;
            cs->bend_nbr[2 * (size_t)(id - (int32_t)cs->n)] = prev;
            cs->bend_nbr[2 * (size_t)(id - (int32_t)cs->n) + 1] = next;
            add_segment(cs, prev, id);
            prev = id;
        }
        add_segment(cs, prev, q);
        cs->link[p] = first, cs->link[q] = prev;
        cs->num_bends += (size_t)most;
        cs->num_paths++;
        return 1;
    }
    return 0;
}

/* Appends vertex v to the piece being walked; 0, or -1 when the piece
 * already has it (not a simple polygon). */
static int record(cm_pieces *out, size_t *used, unsigned char *seen, int32_t v)
{
    if (seen[v]) return -1;
    seen[v] = 1, out->vertex[(*used)++] = v;
    return 0;
}

/* Walks the pieces: along a loop edge into a vertex with a path, the path
 * comes next (it lies inside the material corner, first clockwise from the
 * edge back); at the path's far end, the loop edge leaving it. */
static cm_status trace_pieces(const cut_state *cs, cm_pieces *out, cm_error *err)
{
    size_t n = cs->n, cap = n + 2 * cs->num_paths + 2 * cs->num_bends;
    out->start = malloc((cs->num_loops + 2) * sizeof *out->start);
    out->vertex = malloc(cap * sizeof *out->vertex);
    unsigned char *done = calloc(n, 1), *seen = calloc(n + cs->num_bends, 1);
    cm_status s = CM_OK;
    if (!out->start || !out->vertex || !done || !seen) {
        s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        goto end;
    }
    size_t used = 0;
    out->count = 0;
    out->start[0] = 0;
    for (int32_t v0 = 0; (size_t)v0 < n && s == CM_OK; v0++) {
        if (done[v0]) continue;
        if (out->count == cs->num_loops) {
            s = cm_fail(err, CM_ERR_INTERNAL, "hole bridges: more pieces than loops");
            break;
        }
        size_t first = used;
        int32_t v = v0, bad = -1;
        do { /* v -> succ(v) is a loop edge of this piece */
            done[v] = 1;
            if (record(out, &used, seen, v)) { bad = v; break; }
            int32_t w = succ(cs, v);
            if (cs->link[w] < 0) {
                v = w;
                continue;
            }
            if (record(out, &used, seen, w)) { bad = w; break; }
            int32_t prev = w, at = cs->link[w];
            while ((size_t)at >= n) { /* bends, on to the end not entered from */
                if (record(out, &used, seen, at)) { bad = at; break; }
                const int32_t *nbr = cs->bend_nbr + 2 * ((size_t)at - n);
                int32_t next = nbr[0] == prev ? nbr[1] : nbr[0];
                prev = at, at = next;
            }
            if (bad >= 0) break;
            v = at; /* the path's far end: its loop edge comes next */
        } while (v != v0);
        if (bad >= 0) {
            s = cm_fail(err, CM_ERR_INTERNAL, "hole bridges: piece %zu visits vertex %d twice", out->count, bad);
            break;
        }
        for (size_t i = first; i < used; i++) seen[out->vertex[i]] = 0;
        out->start[++out->count] = used;
    }
    if (s == CM_OK && out->count != cs->num_loops)
        s = cm_fail(err, CM_ERR_INTERNAL, "hole bridges: %zu pieces for %zu loops", out->count, cs->num_loops);
end:
    free(done), free(seen);
    return s;
}

cm_status cm_holes_cut(const double *const *geoms, size_t k, const size_t *loop_start,
                       size_t num_loops, cm_pieces *out, cm_error *err)
{
    memset(out, 0, sizeof *out);
    size_t n = loop_start[num_loops], longest = 0, max_paths = 2 * num_loops;
    size_t bend_cap = MAX_BENDS * max_paths;
    for (size_t l = 1; l < num_loops; l++)
        if (loop_start[l + 1] - loop_start[l] > longest) longest = loop_start[l + 1] - loop_start[l];
    cut_state cs = {0};
    cs.geoms = geoms, cs.k = k, cs.num_loops = num_loops, cs.n = n, cs.start = loop_start;
    cs.bend_cap = bend_cap;
    cs.link = malloc((n + bend_cap) * sizeof *cs.link);
    cs.seg = malloc(2 * (max_paths + bend_cap) * sizeof *cs.seg);
    cs.bend_nbr = malloc(2 * bend_cap * sizeof *cs.bend_nbr);
    cs.bend_xy = calloc(k, sizeof *cs.bend_xy);
    cs.cand_xy = malloc(4 * n * sizeof *cs.cand_xy);
    cs.parent = malloc((2 * n + 2) * sizeof *cs.parent);
    cs.queue = malloc((2 * n + 2) * sizeof *cs.queue);
    cs.path_xy = malloc(2 * MAX_BENDS * k * sizeof *cs.path_xy);
    cs.path_len = malloc(k * sizeof *cs.path_len);
    unsigned char *joined = calloc(num_loops, 1);
    candidate *cand = malloc((longest * n + 1) * sizeof *cand);
    cm_status s = CM_OK;
    int ok = cs.link && cs.seg && cs.bend_nbr && cs.bend_xy && cs.cand_xy && cs.parent && cs.queue &&
             cs.path_xy && cs.path_len && joined && cand;
    for (size_t g = 0; ok && g < k; g++) ok = (cs.bend_xy[g] = malloc(2 * bend_cap * sizeof(double))) != NULL;
    if (!ok) {
        s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        goto end;
    }
    for (size_t v = 0; v < n + bend_cap; v++) cs.link[v] = -1;
    joined[0] = 1;
    for (size_t h = 1; h < num_loops && s == CM_OK; h++) {
        if (!join_hole(&cs, h, joined, cand) || !join_hole(&cs, h, joined, cand))
            s = cm_fail(err, CM_ERR_INTERNAL,
                        "hole %zu: no two disjoint paths (straight, or with up to %d bends) to the outer "
                        "loop or an earlier hole are inside the material in every polygon", h, MAX_BENDS);
        joined[h] = 1;
    }
    out->chords = cs.num_paths;
    out->bends = cs.num_bends;
    if (s == CM_OK) s = trace_pieces(&cs, out, err);
    if (s == CM_OK) { /* the bends' coordinates move to out */
        out->bend_xy = cs.bend_xy;
        cs.bend_xy = NULL;
    }
end:
    if (cs.bend_xy)
        for (size_t g = 0; g < k; g++) free(cs.bend_xy[g]);
    free(cs.link), free(cs.seg), free(cs.bend_nbr), free(cs.bend_xy), free(joined), free(cand);
    free(cs.cand_xy), free(cs.parent), free(cs.queue), free(cs.path_xy), free(cs.path_len);
    if (s != CM_OK) cm_pieces_free(out);
    out->k = k;
    return s;
}

void cm_pieces_free(cm_pieces *p)
{
    if (p->bend_xy)
        for (size_t g = 0; g < p->k; g++) free(p->bend_xy[g]);
    free(p->start), free(p->vertex), free(p->bend_xy);
    memset(p, 0, sizeof *p);
}

cm_status cm_holes_glue(cm_mesh *whole, const int32_t *ids, size_t m, const cm_mesh *piece)
{
    size_t extra = piece->nv - m, nv = whole->nv + extra, nt = whole->nt + piece->nt;
    for (size_t g = 0; g < whole->k; g++) {
        double *xy = realloc(whole->xy[g], 2 * nv * sizeof *xy);
        if (!xy) return CM_ERR_NO_MEMORY;
        whole->xy[g] = xy;
        memcpy(xy + 2 * whole->nv, piece->xy[g] + 2 * m, 2 * extra * sizeof *xy);
    }
    int32_t *tri = realloc(whole->tri, 3 * nt * sizeof *tri);
    if (!tri) return CM_ERR_NO_MEMORY;
    whole->tri = tri;
    for (size_t i = 0; i < 3 * piece->nt; i++) {
        int32_t v = piece->tri[i];
        tri[3 * whole->nt + i] = (size_t)v < m ? ids[v] : (int32_t)(whole->nv + (size_t)v - m);
    }
    whole->nv = nv, whole->nt = nt;
    return CM_OK;
}
