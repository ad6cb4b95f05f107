/* Hole bridges. A hole joined to the rest by two vertex-disjoint chords
 * splits the piece around it in two: the chords and one arc of the hole
 * bound one side, the other arc the other. Chords that share no vertex
 * leave every vertex at most one chord, so the order of edges around each
 * vertex, and hence every piece's vertex cycle, is the same in every
 * geometry once each chord is valid in each. */
#include <stdlib.h>
#include <string.h>
#include <math.h>

#include "construct/holes.h"
#include "geom/predicates.h"

typedef struct cut_state {
    const double *const *geoms;
    size_t k, num_loops, n;
    const size_t *start;
    int32_t *chord_of;  /* the other end of the chord at a vertex, -1 none */
    int32_t *chords;    /* 2 per chord */
    size_t num_chords;
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

/* Point q strictly inside the material's corner at v (material left of
 * a -> v and v -> b). */
static int in_corner(const double *xy, int32_t a, int32_t v, int32_t b, const double q[2])
{
    const double *pa = xy + 2 * a, *pv = xy + 2 * v, *pb = xy + 2 * b;
    int left_in = cm_orient2d(pa, pv, q) > 0, left_out = cm_orient2d(pv, pb, q) > 0;
    return cm_orient2d(pa, pv, pb) >= 0 ? left_in && left_out : left_in || left_out;
}

/* Chord p-q valid in geometry g: inside both corners, touching no loop
 * edge away from p and q, and no chord already chosen. */
static int chord_valid_in(const cut_state *cs, size_t g, int32_t p, int32_t q)
{
    const double *xy = cs->geoms[g], *a = xy + 2 * p, *b = xy + 2 * q;
    if (!in_corner(xy, pred(cs, p), p, succ(cs, p), b) || !in_corner(xy, pred(cs, q), q, succ(cs, q), a))
        return 0;
    for (size_t e = 0; e < cs->n; e++) {
        int32_t u = (int32_t)e, w = succ(cs, u);
        if (u == p || u == q || w == p || w == q) continue;
        if (cm_segments_intersect(a, b, xy + 2 * u, xy + 2 * w)) return 0;
    }
    for (size_t c = 0; c < cs->num_chords; c++)
        if (cm_segments_intersect(a, b, xy + 2 * cs->chords[2 * c], xy + 2 * cs->chords[2 * c + 1]))
            return 0;
    return 1;
}

static int chord_valid(const cut_state *cs, int32_t p, int32_t q)
{
    for (size_t g = 0; g < cs->k; g++)
        if (!chord_valid_in(cs, g, p, q)) return 0;
    return 1;
}

/* The loop vertices a chord from hole h may reach: the outer loop and the
 * holes joined before it (joined[l]), free of chords. Candidates from
 * hole h to those, shortest first (summed over the geometries, so the
 * chord is short in all); the first valid one is taken. */
static int join_hole(cut_state *cs, size_t h, const unsigned char *joined, candidate *cand,
                     int32_t *taken_p, int32_t *taken_q)
{
    size_t nc = 0;
    for (int32_t p = (int32_t)cs->start[h]; (size_t)p < cs->start[h + 1]; p++) {
        if (cs->chord_of[p] >= 0) continue;
        for (int32_t q = 0; (size_t)q < cs->n; q++) {
            if (cs->chord_of[q] >= 0 || !joined[loop_of(cs, q)]) continue;
            double len = 0;
            for (size_t g = 0; g < cs->k; g++) {
                const double *xy = cs->geoms[g];
                len += hypot(xy[2 * p] - xy[2 * q], xy[2 * p + 1] - xy[2 * q + 1]);
            }
            cand[nc++] = (candidate){len, p, q};
        }
    }
    qsort(cand, nc, sizeof *cand, by_length);
    for (size_t i = 0; i < nc; i++)
        if (chord_valid(cs, cand[i].p, cand[i].q)) {
            *taken_p = cand[i].p, *taken_q = cand[i].q;
            cs->chord_of[cand[i].p] = cand[i].q, cs->chord_of[cand[i].q] = cand[i].p;
            cs->chords[2 * cs->num_chords] = cand[i].p;
            cs->chords[2 * cs->num_chords + 1] = cand[i].q;
            cs->num_chords++;
            return 1;
        }
    return 0;
}

/* Walks the pieces: along a loop edge into a vertex with a chord, the
 * chord comes next (it lies inside the material corner, first clockwise
 * from the edge back); along a chord, the loop edge leaving its end. */
static cm_status trace_pieces(const cut_state *cs, cm_pieces *out, cm_error *err)
{
    size_t n = cs->n, cap = n + 2 * cs->num_chords;
    out->start = malloc((cs->num_loops + 2) * sizeof *out->start);
    out->vertex = malloc(cap * sizeof *out->vertex);
    unsigned char *done = calloc(n, 1), *seen = calloc(n, 1);
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
        int32_t v = v0;
        do { /* v -> succ(v) is a loop edge of this piece */
            done[v] = 1;
            int32_t w = succ(cs, v);
            if (seen[v] || used + 2 > cap) {
                s = cm_fail(err, CM_ERR_INTERNAL, "hole bridges: piece %zu visits vertex %d twice", out->count, v);
                break;
            }
            seen[v] = 1, out->vertex[used++] = v;
            if (cs->chord_of[w] >= 0) {
                if (seen[w]) {
                    s = cm_fail(err, CM_ERR_INTERNAL, "hole bridges: piece %zu visits vertex %d twice", out->count, w);
                    break;
                }
                seen[w] = 1, out->vertex[used++] = w;
                v = cs->chord_of[w]; /* then the loop edge leaving the chord's far end */
            } else {
                v = w;
            }
        } while (v != v0);
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
    size_t n = loop_start[num_loops], longest = 0;
    for (size_t l = 1; l < num_loops; l++)
        if (loop_start[l + 1] - loop_start[l] > longest) longest = loop_start[l + 1] - loop_start[l];
    cut_state cs = {geoms, k, num_loops, n, loop_start, malloc(n * sizeof(int32_t)),
                    malloc(4 * num_loops * sizeof(int32_t)), 0};
    unsigned char *joined = calloc(num_loops, 1);
    candidate *cand = malloc((longest * n + 1) * sizeof *cand);
    cm_status s = CM_OK;
    if (!cs.chord_of || !cs.chords || !joined || !cand) {
        s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        goto end;
    }
    for (size_t v = 0; v < n; v++) cs.chord_of[v] = -1;
    joined[0] = 1;
    for (size_t h = 1; h < num_loops && s == CM_OK; h++) {
        int32_t p1, q1, p2, q2;
        if (!join_hole(&cs, h, joined, cand, &p1, &q1) || !join_hole(&cs, h, joined, cand, &p2, &q2))
            s = cm_fail(err, CM_ERR_INTERNAL,
                        "hole %zu: no two disjoint straight chords to the outer loop or an earlier hole "
                        "are inside the material in every polygon", h);
        joined[h] = 1;
    }
    out->chords = cs.num_chords;
    if (s == CM_OK) s = trace_pieces(&cs, out, err);
end:
    free(cs.chord_of), free(cs.chords), free(joined), free(cand);
    if (s != CM_OK) cm_pieces_free(out);
    return s;
}

void cm_pieces_free(cm_pieces *p)
{
    free(p->start), free(p->vertex);
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
