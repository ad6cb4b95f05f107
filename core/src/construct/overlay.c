/* The Aronov-Seidel-Souvaine construction: map every polygon's triangulation
 * onto one convex polygon C (vertex i to the i-th corner of a regular n-gon;
 * any triangulation of a polygon is a triangulation of a convex polygon
 * with the same vertex order), overlay the images there, triangulate the
 * overlay's convex faces and map everything back. A point of C lies in one
 * triangle of every image, and each image maps back affinely per triangle,
 * so the overlay is compatible with every polygon.
 *
 * The overlay's combinatorics are exact: chords cross iff their endpoints
 * interleave (C is strictly convex, checked), and the order of crossings
 * along a chord, where floating point cannot separate them, is decided with
 * exact rational arithmetic. Only Steiner positions are rounded, and the
 * final mesh is checked exactly by the caller.
 *
 * Rounding can invert a triangle: real outlines give pieces whose
 * triangles are slivers thinner than the spacing of doubles (samples along
 * a straight edge, rotated), and a crossing rounded off its diagonal lands
 * outside them. The faces are cut combinatorially (every triangulation of
 * a face is valid at the exact positions), then the Steiner vertices of
 * inverted triangles are moved, one at a time, to doubles that make their
 * triangles positive, found exactly (repair_geometry); failing that, a
 * polygon star-shaped in every geometry becomes a fan around one vertex
 * placed the same way (star_fan), and a small one a fan around two
 * (two_fan). What stays inverted is reported as such: the construction
 * always ends, valid or with that message. */
#include <gmp.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "construct/overlay.h"
#include "base/buf.h"
#include "geom/angle.h"
#include "geom/polytri.h"
#include "geom/predicates.h"

typedef struct { int32_t a, b; } chord;           /* a < b, a diagonal of C */
typedef struct { long l, m; double tl, tm, x, y; } crossing;

typedef struct {
    size_t n, k;
    double *cxy;                  /* C's corners, 2n doubles */
    chord *chords; long nc;
    unsigned char *owner;         /* nc * k: chord is a diagonal of T_j */
    crossing *cross; long nx;
    long *vertex_of_cross;        /* crossing -> overlay vertex id */
    long nv;                      /* n + number of crossing vertices */
    long *chord_seq_start, *chord_seq; /* per chord: vertex ids from a to b */
    mpq_t q[8];                   /* scratch for exact comparisons */
} overlay;

/* ---- C and its chords ---------------------------------------------------- */

/* A fixed pseudo-random offset in [0, 1) per corner. */
static double corner_jitter(size_t i)
{
    uint64_t z = (uint64_t)i * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return (double)((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}

/* C: corners on the unit circle at jittered angles. A regular polygon has
 * many concurrent diagonals; with k >= 3 triangulations they would make
 * crossings nearly coincide, so the jitter breaks that symmetry. */
static int make_convex_polygon(overlay *o)
{
    size_t n = o->n;
    o->cxy = malloc(2 * n * sizeof *o->cxy);
    if (!o->cxy) return -1;
    for (size_t i = 0; i < n; i++) {
        double angle = 2.0 * CM_PI * ((double)i + 0.5 * corner_jitter(i)) / (double)n;
        o->cxy[2 * i] = cos(angle);
        o->cxy[2 * i + 1] = sin(angle);
    }
    for (size_t i = 0; i < n; i++) {
        if (cm_orient2d(o->cxy + 2 * ((i + n - 1) % n), o->cxy + 2 * i,
                        o->cxy + 2 * ((i + 1) % n)) <= 0)
            return 1;
    }
    return 0;
}

static int compare_chords(const void *pa, const void *pb)
{
    const chord *x = pa, *y = pb;
    if (x->a != y->a) return x->a < y->a ? -1 : 1;
    return (x->b > y->b) - (x->b < y->b);
}

static int is_boundary_edge(int32_t a, int32_t b, size_t n)
{
    return b == a + 1 || (a == 0 && (size_t)b == n - 1);
}

/* Collects the diagonals of all triangulations, once each, with owners. */
static int collect_chords(overlay *o, const int32_t *const *tris)
{
    size_t n = o->n, k = o->k, cap = k * (n - 3) + 1;
    chord *all = malloc(cap * sizeof *all);
    if (!all) return -1;
    long count = 0;
    for (size_t j = 0; j < k; j++) {
        for (size_t e = 0; e < 3 * (n - 2); e++) {
            int32_t u = tris[j][e], v = tris[j][e - e % 3 + (e + 1) % 3];
            if (u > v) { int32_t t = u; u = v; v = t; }
            /* Each diagonal appears twice, once per direction: keep one. */
            if (is_boundary_edge(u, v, n) || tris[j][e] != u) continue;
            all[count++] = (chord){u, v};
        }
    }
    qsort(all, (size_t)count, sizeof *all, compare_chords);
    long nc = 0;
    for (long i = 0; i < count; i++)
        if (nc == 0 || compare_chords(&all[nc - 1], &all[i]) != 0) all[nc++] = all[i];
    o->chords = all;
    o->nc = nc;
    o->owner = calloc((size_t)nc * k + 1, 1);
    if (!o->owner) return -1;
    for (size_t j = 0; j < k; j++) {
        for (size_t e = 0; e < 3 * (n - 2); e++) {
            int32_t u = tris[j][e], v = tris[j][e - e % 3 + (e + 1) % 3];
            if (u > v) { int32_t t = u; u = v; v = t; }
            if (is_boundary_edge(u, v, n)) continue;
            chord key = {u, v};
            chord *hit = bsearch(&key, all, (size_t)nc, sizeof *all, compare_chords);
            if (hit) o->owner[(size_t)(hit - all) * k + j] = 1;
        }
    }
    return 0;
}

/* ---- crossings ------------------------------------------------------------ */

static int interleave(chord p, chord q)
{
    if (p.a == q.a || p.a == q.b || p.b == q.a || p.b == q.b) return 0;
    return (p.a < q.a && q.a < p.b) != (p.a < q.b && q.b < p.b);
}

static const double *corner(const overlay *o, int32_t i) { return o->cxy + 2 * (size_t)i; }

static int find_crossings(overlay *o)
{
    size_t cap = 0;
    o->cross = NULL;
    o->nx = 0;
    for (long i = 0; i < o->nc; i++) {
        for (long j = i + 1; j < o->nc && o->chords[j].a < o->chords[i].b; j++) {
            if (!interleave(o->chords[i], o->chords[j])) continue;
            const double *la = corner(o, o->chords[i].a), *lb = corner(o, o->chords[i].b);
            const double *ma = corner(o, o->chords[j].a), *mb = corner(o, o->chords[j].b);
            double dlx = lb[0] - la[0], dly = lb[1] - la[1];
            double dmx = mb[0] - ma[0], dmy = mb[1] - ma[1];
            double ex = ma[0] - la[0], ey = ma[1] - la[1];
            double den = dlx * dmy - dly * dmx;
            double tl = (ex * dmy - ey * dmx) / den, tm = (ex * dly - ey * dlx) / den;
            if (cm_grow((void **)&o->cross, &cap, (size_t)o->nx + 1, sizeof *o->cross)) return -1;
            o->cross[o->nx++] = (crossing){i, j, tl, tm, la[0] + tl * dlx, la[1] + tl * dly};
        }
    }
    return 0;
}

/* Chords j > i with chords[j].a >= chords[i].b cannot interleave with i
 * (sorted by a), which is what bounds the inner loop above. */

static long other_chord(const crossing *x, long c) { return x->l == c ? x->m : x->l; }
static double param_on(const crossing *x, long c) { return x->l == c ? x->tl : x->tm; }

/* Exact parameter where chord m crosses chord c, along c:
 * t = cross(M.a - C.a, dM) / cross(dC, dM), into out (uses q[0..5]). */
static void exact_param(overlay *o, long c, long m, mpq_ptr out)
{
    mpq_t *q = o->q;
    const double *p[4] = {corner(o, o->chords[c].a), corner(o, o->chords[c].b),
                          corner(o, o->chords[m].a), corner(o, o->chords[m].b)};
    for (int axis = 0; axis < 2; axis++) {
        mpq_set_d(q[4], p[0][axis]);
        mpq_set_d(q[0 + axis], p[3][axis]);        /* dM */
        mpq_set_d(q[5], p[2][axis]);
        mpq_sub(q[0 + axis], q[0 + axis], q[5]);
        mpq_sub(q[2 + axis], q[5], q[4]);          /* M.a - C.a */
    }
    mpq_mul(q[4], q[2], q[1]);
    mpq_mul(q[5], q[3], q[0]);
    mpq_sub(out, q[4], q[5]);                      /* cross(M.a - C.a, dM) */
    for (int axis = 0; axis < 2; axis++) {         /* q[2..3] = dC */
        mpq_set_d(q[2 + axis], p[1][axis]);
        mpq_set_d(q[4], p[0][axis]);
        mpq_sub(q[2 + axis], q[2 + axis], q[4]);
    }
    mpq_mul(q[4], q[2], q[1]);
    mpq_mul(q[5], q[3], q[0]);
    mpq_sub(q[4], q[4], q[5]);                     /* cross(dC, dM) */
    mpq_div(out, out, q[4]);
}

static int exact_param_compare(overlay *o, long c, long m1, long m2)
{
    exact_param(o, c, m1, o->q[6]);
    exact_param(o, c, m2, o->q[7]);
    return mpq_cmp(o->q[6], o->q[7]);
}

/* Union-find over crossings: crossings at the same point (three or more
 * chords through it, possible for k >= 3) become one vertex. */
static long find_root(long *parent, long x)
{
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
}

typedef struct { double t; long x; } param_entry;

static int compare_params(const void *pa, const void *pb)
{
    const param_entry *a = pa, *b = pb;
    return (a->t > b->t) - (a->t < b->t);
}

/* Where doubles cannot order two crossings safely, ask exact arithmetic.
 * Parameters differ from the exact ones by far less than this. */
#define PARAM_TOLERANCE 1e-9

static void order_along_chord(overlay *o, long c, param_entry *e, long count, long *parent)
{
    qsort(e, (size_t)count, sizeof *e, compare_params);
    for (long i = 1; i < count; i++) {
        for (long j = i; j > 0 && e[j].t - e[j - 1].t < PARAM_TOLERANCE; j--) {
            long m1 = other_chord(&o->cross[e[j - 1].x], c);
            long m2 = other_chord(&o->cross[e[j].x], c);
            int cmp = exact_param_compare(o, c, m1, m2);
            if (cmp == 0) {
                long r1 = find_root(parent, e[j - 1].x), r2 = find_root(parent, e[j].x);
                if (r1 != r2) parent[r2] = r1;
            }
            if (cmp <= 0) break;
            param_entry t = e[j]; e[j] = e[j - 1]; e[j - 1] = t;
        }
    }
}

/* Builds, for every chord, the sequence of overlay vertices from a to b. */
static int build_chord_sequences(overlay *o)
{
    long nc = o->nc, nx = o->nx, status = -1;
    long *count = calloc((size_t)nc + 1, sizeof *count);
    long *start = malloc(((size_t)nc + 1) * sizeof *start);
    param_entry *entries = malloc((2 * (size_t)nx + 1) * sizeof *entries);
    long *parent = malloc(((size_t)nx + 1) * sizeof *parent);
    long *root_vertex = malloc(((size_t)nx + 1) * sizeof *root_vertex);
    o->vertex_of_cross = malloc(((size_t)nx + 1) * sizeof *o->vertex_of_cross);
    o->chord_seq_start = malloc(((size_t)nc + 1) * sizeof *o->chord_seq_start);
    o->chord_seq = malloc((2 * (size_t)nx + 2 * (size_t)nc + 1) * sizeof *o->chord_seq);
    if (!count || !start || !entries || !parent || !root_vertex || !o->vertex_of_cross ||
        !o->chord_seq_start || !o->chord_seq)
        goto done;
    for (long x = 0; x < nx; x++) {
        count[o->cross[x].l]++, count[o->cross[x].m]++;
        parent[x] = x;
    }
    start[0] = 0;
    for (long c = 0; c < nc; c++) start[c + 1] = start[c] + count[c];
    memset(count, 0, (size_t)nc * sizeof *count);
    for (long x = 0; x < nx; x++) {
        long l = o->cross[x].l, m = o->cross[x].m;
        entries[start[l] + count[l]++] = (param_entry){o->cross[x].tl, x};
        entries[start[m] + count[m]++] = (param_entry){o->cross[x].tm, x};
    }
    for (long c = 0; c < nc; c++)
        order_along_chord(o, c, entries + start[c], start[c + 1] - start[c], parent);

    o->nv = (long)o->n;
    for (long x = 0; x < nx; x++) root_vertex[x] = -1;
    for (long x = 0; x < nx; x++) {
        long r = find_root(parent, x);
        if (root_vertex[r] < 0) root_vertex[r] = o->nv++;
        o->vertex_of_cross[x] = root_vertex[r];
    }
    long len = 0;
    for (long c = 0; c < nc; c++) {
        o->chord_seq_start[c] = len;
        o->chord_seq[len++] = o->chords[c].a;
        for (long i = start[c]; i < start[c + 1]; i++) {
            long v = o->vertex_of_cross[entries[i].x];
            if (o->chord_seq[len - 1] != v) o->chord_seq[len++] = v;
        }
        o->chord_seq[len++] = o->chords[c].b;
    }
    o->chord_seq_start[nc] = len;
    status = 0;
done:
    free(count), free(start), free(entries), free(parent), free(root_vertex);
    return (int)status;
}

/* ---- the planar overlay as half-edges ------------------------------------ */

typedef struct {
    long nh;
    long *from, *to, *chord_of; /* chord_of: -1 on the boundary */
    signed char *forward;       /* +1 along the chord from a to b, -1 back */
    long *out_start, *out;      /* outgoing half-edges per vertex, CCW */
    long *pos;                  /* index of h in its origin's out list */
} graph;

static void graph_free(graph *g)
{
    free(g->from), free(g->to), free(g->chord_of), free(g->forward);
    free(g->out_start), free(g->out), free(g->pos);
}

/* Sign of cross(d1, d2) for directions along chords through one interior
 * point. Such chords cross, so c2.b lies strictly on one side of c1. */
static int direction_cross(const overlay *o, long c1, int s1, long c2, int s2)
{
    if (c1 == c2) return 0;
    return s1 * s2 * cm_orient2d(corner(o, o->chords[c1].a), corner(o, o->chords[c1].b),
                                 corner(o, o->chords[c2].b));
}

/* Angular order around a crossing vertex: the half-plane left of the first
 * direction (including it) comes first, then the rest; within a half-plane
 * counter-clockwise. */
static int angular_half(const overlay *o, const graph *g, long ref, long h)
{
    int c = direction_cross(o, g->chord_of[ref], g->forward[ref], g->chord_of[h], g->forward[h]);
    if (c == 0) return g->forward[ref] == g->forward[h] ? 0 : 1;
    return c > 0 ? 0 : 1;
}

static int angular_less(const overlay *o, const graph *g, long ref, long h1, long h2)
{
    int a = angular_half(o, g, ref, h1), b = angular_half(o, g, ref, h2);
    if (a != b) return a < b;
    return direction_cross(o, g->chord_of[h1], g->forward[h1], g->chord_of[h2], g->forward[h2]) > 0;
}

static long corner_key(const overlay *o, const graph *g, long h)
{
    long n = (long)o->n, i = g->from[h];
    if (g->chord_of[h] < 0) return ((g->to[h] - i) % n + n) % n;
    const chord *c = &o->chords[g->chord_of[h]];
    long other = c->a == i ? c->b : c->a;
    return ((other - i) % n + n) % n;
}

static void sort_outgoing(const overlay *o, graph *g, long v)
{
    long *list = g->out + g->out_start[v], deg = g->out_start[v + 1] - g->out_start[v];
    long ref = list[0]; /* angles are measured from a fixed direction */
    for (long i = 1; i < deg; i++) {
        long h = list[i], j = i;
        if (v < (long)o->n) {
            long key = corner_key(o, g, h);
            while (j > 0 && corner_key(o, g, list[j - 1]) > key) list[j] = list[j - 1], j--;
        } else {
            while (j > 0 && angular_less(o, g, ref, h, list[j - 1]))
                list[j] = list[j - 1], j--;
        }
        list[j] = h;
    }
}

static void add_edge(graph *g, long u, long v, long c)
{
    long h = g->nh;
    g->from[h] = u, g->to[h] = v, g->chord_of[h] = c, g->forward[h] = 1;
    g->from[h + 1] = v, g->to[h + 1] = u, g->chord_of[h + 1] = c, g->forward[h + 1] = -1;
    g->nh += 2;
}

static int build_graph(const overlay *o, graph *g)
{
    long n = (long)o->n, nv = o->nv;
    size_t nh = 2 * ((size_t)n + (size_t)(o->chord_seq_start[o->nc] - o->nc));
    memset(g, 0, sizeof *g);
    g->from = malloc(nh * sizeof *g->from);
    g->to = malloc(nh * sizeof *g->to);
    g->chord_of = malloc(nh * sizeof *g->chord_of);
    g->forward = malloc(nh);
    g->out_start = calloc((size_t)nv + 1, sizeof *g->out_start);
    g->out = malloc(nh * sizeof *g->out);
    g->pos = malloc(nh * sizeof *g->pos);
    long *fill = calloc((size_t)nv + 1, sizeof *fill);
    if (!g->from || !g->to || !g->chord_of || !g->forward || !g->out_start || !g->out ||
        !g->pos || !fill) {
        free(fill);
        return -1;
    }
    for (long i = 0; i < n; i++) add_edge(g, i, (i + 1) % n, -1);
    for (long c = 0; c < o->nc; c++)
        for (long i = o->chord_seq_start[c]; i + 1 < o->chord_seq_start[c + 1]; i++)
            add_edge(g, o->chord_seq[i], o->chord_seq[i + 1], c);

    for (long h = 0; h < g->nh; h++) g->out_start[g->from[h] + 1]++;
    for (long v = 0; v < nv; v++) g->out_start[v + 1] += g->out_start[v];
    for (long h = 0; h < g->nh; h++) g->out[g->out_start[g->from[h]] + fill[g->from[h]]++] = h;
    free(fill);
    for (long v = 0; v < nv; v++) {
        sort_outgoing(o, g, v);
        for (long i = g->out_start[v]; i < g->out_start[v + 1]; i++)
            g->pos[g->out[i]] = i - g->out_start[v];
    }
    return 0;
}

/* The face left of h continues with the clockwise neighbour of h's twin. */
static long next_in_face(const graph *g, long h)
{
    long t = h ^ 1, v = g->from[t];
    long deg = g->out_start[v + 1] - g->out_start[v];
    return g->out[g->out_start[v] + (g->pos[t] + deg - 1) % deg];
}

/* ---- mapping back into every polygon ------------------------------------- */

/* The triangle of T_j (as a triangulation of C) with the largest smallest
 * barycentric coordinate at p, and p's coordinates in it. Only needed for
 * k >= 3, where a crossing may lie on no diagonal of T_j. */
static void locate_in_triangulation(const overlay *o, const int32_t *tri, const double *p,
                                    long *best_t, double bary[3])
{
    double best = -INFINITY;
    for (long t = 0; t < (long)o->n - 2; t++) {
        const double *a = corner(o, tri[3 * t]), *b = corner(o, tri[3 * t + 1]),
                     *c = corner(o, tri[3 * t + 2]);
        double det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        double l1 = ((p[0] - a[0]) * (c[1] - a[1]) - (p[1] - a[1]) * (c[0] - a[0])) / det;
        double l2 = ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])) / det;
        double l0 = 1.0 - l1 - l2, lo = fmin(l0, fmin(l1, l2));
        if (lo > best) best = lo, *best_t = t, bary[0] = l0, bary[1] = l1, bary[2] = l2;
    }
}

static void lerp(const double *p, const double *q, double t, double *out)
{
    out[0] = p[0] + t * (q[0] - p[0]);
    out[1] = p[1] + t * (q[1] - p[1]);
}

/* Positions of the overlay's vertices in geometry j: polygon vertices as
 * given (bit-identical), crossings on a diagonal of T_j at the same
 * parameter along it as in C (the map C -> P_j is affine along a diagonal). */
static void map_back(const overlay *o, const double *geom, const int32_t *tri, size_t j,
                     double *xy, unsigned char *placed)
{
    memcpy(xy, geom, 2 * o->n * sizeof *xy);
    memset(placed + o->n, 0, (size_t)o->nv - o->n);
    for (long x = 0; x < o->nx; x++) {
        const crossing *c = &o->cross[x];
        long v = o->vertex_of_cross[x];
        if (placed[v]) continue;
        long on = o->owner[(size_t)c->l * o->k + j] ? c->l : o->owner[(size_t)c->m * o->k + j] ? c->m : -1;
        if (on < 0) continue;
        const chord *d = &o->chords[on];
        lerp(geom + 2 * (size_t)d->a, geom + 2 * (size_t)d->b, param_on(c, on), xy + 2 * v);
        placed[v] = 1;
    }
    for (long x = 0; x < o->nx; x++) {
        long v = o->vertex_of_cross[x];
        if (placed[v]) continue;
        long t = 0;
        double bary[3] = {1, 0, 0}, p[2] = {o->cross[x].x, o->cross[x].y};
        locate_in_triangulation(o, tri, p, &t, bary);
        for (int axis = 0; axis < 2; axis++) {
            xy[2 * v + axis] = bary[0] * geom[2 * tri[3 * t] + axis] +
                               bary[1] * geom[2 * tri[3 * t + 1] + axis] +
                               bary[2] * geom[2 * tri[3 * t + 2] + axis];
        }
        placed[v] = 1;
    }
}

/* ---- triangulating the overlay's faces ----------------------------------- */

typedef struct {
    size_t k;
    double **xy;        /* k position arrays */
    int32_t *tri;
    size_t nt, cap_t;
    size_t nv, cap_v;   /* vertices used / allocated per geometry */
    size_t centroids;
} face_output;

static double ear_quality(const face_output *f, long a, long b, long c, const long *face,
                          long m)
{
    double worst = INFINITY;
    for (size_t j = 0; j < f->k; j++) {
        const double *xy = f->xy[j];
        const double *pa = xy + 2 * a, *pb = xy + 2 * b, *pc = xy + 2 * c;
        if (cm_orient2d(pa, pb, pc) <= 0) return -1;
        for (long i = 0; i < m; i++) {
            long v = face[i];
            if (v == a || v == b || v == c) continue;
            const double *p = xy + 2 * v;
            if (cm_orient2d(pa, pb, p) >= 0 && cm_orient2d(pb, pc, p) >= 0 &&
                cm_orient2d(pc, pa, p) >= 0)
                return -1;
        }
        worst = fmin(worst, cm_triangle_min_angle(pa, pb, pc));
    }
    return worst;
}

static int emit_triangle(face_output *f, long a, long b, long c)
{
    if (cm_grow((void **)&f->tri, &f->cap_t, 3 * (f->nt + 1), sizeof *f->tri)) return -1;
    f->tri[3 * f->nt] = (int32_t)a, f->tri[3 * f->nt + 1] = (int32_t)b,
    f->tri[3 * f->nt + 2] = (int32_t)c;
    f->nt++;
    return 0;
}

/* A face no ear can cut in every geometry (rounding made it slightly
 * non-convex somewhere): fan it from a new vertex at its vertex centroid,
 * if that fan is valid everywhere. Nothing is emitted otherwise. */
static int fan_from_centroid(face_output *f, const long *face, long m)
{
    if (f->nv >= f->cap_v) return 1;
    long c = (long)f->nv;
    for (size_t j = 0; j < f->k; j++) {
        double sx = 0, sy = 0;
        for (long i = 0; i < m; i++) sx += f->xy[j][2 * face[i]], sy += f->xy[j][2 * face[i] + 1];
        f->xy[j][2 * c] = sx / (double)m, f->xy[j][2 * c + 1] = sy / (double)m;
    }
    for (long i = 0; i < m; i++) {
        long a = face[i], b = face[(i + 1) % m];
        for (size_t j = 0; j < f->k; j++)
            if (cm_orient2d(f->xy[j] + 2 * a, f->xy[j] + 2 * b, f->xy[j] + 2 * c) <= 0) return 1;
    }
    f->nv++;
    for (long i = 0; i < m; i++)
        if (emit_triangle(f, face[i], face[(i + 1) % m], c)) return -1;
    f->centroids++;
    return 0;
}

/* Geometries in which the ear abc is counter-clockwise as rounded. */
static size_t ear_votes(const face_output *f, long a, long b, long c)
{
    size_t votes = 0;
    for (size_t j = 0; j < f->k; j++)
        votes += cm_orient2d(f->xy[j] + 2 * a, f->xy[j] + 2 * b, f->xy[j] + 2 * c) > 0;
    return votes;
}

/* Cuts the best ear (largest smallest angle over all geometries) until a
 * triangle remains. Every face is strictly convex in C, hence (an affine
 * image inside one triangle of T_j) at the exact crossing positions in
 * every geometry, so every ear is valid there: a face that rounding made
 * non-convex is still cut, by the ear valid in the most geometries, and
 * repair_geometry moves its Steiner vertices afterwards. Returns 0, or -1
 * out of memory. */
static int triangulate_face(face_output *f, long *face, long m)
{
    while (m > 3) {
        long best = -1;
        double best_q = -1;
        for (long i = 0; i < m; i++) {
            double q = ear_quality(f, face[(i + m - 1) % m], face[i], face[(i + 1) % m], face, m);
            if (q > best_q) best_q = q, best = i;
        }
        if (best < 0) {
            int s = fan_from_centroid(f, face, m);
            if (s <= 0) return s;
            size_t best_votes = 0;
            best = 0;
            for (long i = 0; i < m; i++) {
                size_t v = ear_votes(f, face[(i + m - 1) % m], face[i], face[(i + 1) % m]);
                if (v > best_votes) best_votes = v, best = i;
            }
        }
        if (emit_triangle(f, face[(best + m - 1) % m], face[best], face[(best + 1) % m])) return -1;
        memmove(face + best, face + best + 1, (size_t)(m - best - 1) * sizeof *face);
        m--;
    }
    return emit_triangle(f, face[0], face[1], face[2]);
}

/* ---- moving Steiner vertices where rounding inverted a triangle ----------- */

/* Any placement of the Steiner vertices is as good as the exact one as long
 * as every triangle stays strictly counter-clockwise: the boundary is the
 * polygon, so the mesh then covers it once. The exact positions make every
 * triangle positive, but rounding them can invert a thin one (a polygon
 * whose ear-clipped triangles are slivers thinner than the spacing of
 * doubles, say). A vertex of an inverted triangle is moved to the first
 * candidate that makes all its triangles positive, or else to the one that
 * leaves fewest inverted; a move is taken only when that count drops, so
 * the count of inverted triangles falls with every move and the repair
 * ends. Candidates, cheapest first: the centroid of its neighbours, points
 * on the way to each neighbour, the doubles within REPAIR_RINGS units in
 * the last place around it, REPAIR_LINES rows and columns of doubles
 * through it (scan_line), and last the lattice search for a star whose
 * kernel is a sliver thinner than one unit (lattice_search). Every
 * candidate is checked with exact predicates. */
#define REPAIR_RINGS 12
#define REPAIR_PASSES 64
#define REPAIR_LINES 16

typedef struct incidence {
    long *start, *tri; /* triangles around each vertex */
} incidence;

static int incidence_build(const face_output *f, incidence *inc)
{
    inc->start = calloc(f->nv + 2, sizeof *inc->start);
    inc->tri = malloc((3 * f->nt + 1) * sizeof *inc->tri);
    if (!inc->start || !inc->tri) return -1;
    for (size_t e = 0; e < 3 * f->nt; e++) inc->start[f->tri[e] + 2]++;
    for (size_t v = 0; v < f->nv; v++) inc->start[v + 2] += inc->start[v + 1];
    for (size_t e = 0; e < 3 * f->nt; e++) inc->tri[inc->start[f->tri[e] + 1]++] = (long)(e / 3);
    return 0;
}

static int inverted(const face_output *f, const double *xy, long t)
{
    const int32_t *c = f->tri + 3 * t;
    return cm_orient2d(xy + 2 * c[0], xy + 2 * c[1], xy + 2 * c[2]) <= 0;
}

static long inverted_around(const face_output *f, const incidence *inc, const double *xy, long v)
{
    long bad = 0;
    for (long i = inc->start[v]; i < inc->start[v + 1]; i++) bad += inverted(f, xy, inc->tri[i]);
    return bad;
}

static double unit_in_last_place(double x)
{
    x = fabs(x);
    return nextafter(x, INFINITY) - x;
}

/* Tries candidate p for v; keeps it in best when it beats *best_bad. */
static int try_candidate(const face_output *f, const incidence *inc, double *xy, long v,
                         double px, double py, long *best_bad, double *best)
{
    if (!isfinite(px) || !isfinite(py)) return 0;
    double keep[2] = {xy[2 * v], xy[2 * v + 1]};
    xy[2 * v] = px, xy[2 * v + 1] = py;
    long bad = inverted_around(f, inc, xy, v);
    xy[2 * v] = keep[0], xy[2 * v + 1] = keep[1];
    if (bad < *best_bad) *best_bad = bad, best[0] = px, best[1] = py;
    return bad == 0;
}

/* The doubles on one line of the grid: coordinate `w` fixed to `value`,
 * the other (u) free. Every triangle (v, a, b) around v bounds u to an open
 * interval, exactly (GMP rationals): a sliver thinner than a unit in the
 * last place in both axes, but long, still holds doubles on many such
 * lines, at its exact middle there. q: 5 scratch rationals. */
static int scan_line(const face_output *f, const incidence *inc, double *xy, long v, int w,
                     double value, mpq_t *q, long *best_bad, double *best)
{
    int u = 1 - w, have_lo = 0, have_hi = 0;
    mpq_t *lo = &q[0], *hi = &q[1], *c = &q[2], *bound = &q[3];
    for (long i = inc->start[v]; i < inc->start[v + 1]; i++) {
        const int32_t *t = f->tri + 3 * inc->tri[i];
        int at = t[0] == v ? 0 : t[1] == v ? 1 : 2;
        const double *a = xy + 2 * t[(at + 1) % 3], *b = xy + 2 * t[(at + 2) % 3];
        /* orient(a, b, p) = (b_u - a_u)(p_w - a_w) - (b_w - a_w)(p_u - a_u)
         * for u = x, the negative for u = y: c (p_u - a_u) + r. */
        mpq_t *r = bound, *d = &q[4];
        mpq_set_d(*r, value), mpq_set_d(*d, a[w]), mpq_sub(*r, *r, *d);
        mpq_set_d(*c, b[u]), mpq_set_d(*d, a[u]), mpq_sub(*c, *c, *d);
        mpq_mul(*r, *r, *c);
        mpq_set_d(*c, b[w]), mpq_set_d(*d, a[w]), mpq_sub(*c, *c, *d);
        if (u == 1) mpq_neg(*r, *r); else mpq_neg(*c, *c);
        /* orient = c (P_u - a_u) + r > 0 */
        int sign = mpq_sgn(*c);
        if (sign == 0) {
            if (mpq_sgn(*r) <= 0) return 0;
            continue;
        }
        mpq_div(*r, *r, *c);
        mpq_neg(*r, *r);
        mpq_set_d(*c, a[u]);
        mpq_add(*r, *r, *c);                           /* a_u - r / c */
        if (sign > 0 && (!have_lo || mpq_cmp(*r, *lo) > 0)) mpq_set(*lo, *r), have_lo = 1;
        if (sign < 0 && (!have_hi || mpq_cmp(*r, *hi) < 0)) mpq_set(*hi, *r), have_hi = 1;
    }
    if (!have_lo || !have_hi || mpq_cmp(*lo, *hi) >= 0) return 0;
    mpq_add(*lo, *lo, *hi);
    mpq_div_2exp(*lo, *lo, 1);
    double mid = mpq_get_d(*lo), cand[3] = {mid, nextafter(mid, -INFINITY), nextafter(mid, INFINITY)};
    for (int i = 0; i < 3; i++) {
        double p[2];
        p[u] = cand[i], p[w] = value;
        if (try_candidate(f, inc, xy, v, p[0], p[1], best_bad, best)) return 1;
    }
    return 0;
}

/* ---- a double inside a star thinner than the spacing of doubles ------- */

/* In grid units around an origin O on the grid of doubles at spacing
 * (ux, uy) (powers of two no finer than any coordinate of the star needs,
 * so every grid point there is a double), v = O + (i ux, j uy) makes the
 * triangle (v, a, b) counter-clockwise iff A i + B j + C > 0, exactly. */
typedef struct { mpq_t a, b, c; } grid_constraint;

typedef struct { mpq_t i, j; } grid_point;

#define LATTICE_MAX_VERTICES 64
#define LATTICE_CONVERGENTS 96
#define LATTICE_ROWS 24
#define LATTICE_BOX_POINTS 65536

/* Sutherland-Hodgman on exact points: keeps a i + b j + c >= 0. */
static int clip_polygon(grid_point *p, int count, grid_point *out, const grid_constraint *h, mpq_t *t)
{
    int m = 0;
    for (int k = 0; k < count && m + 2 <= LATTICE_MAX_VERTICES; k++) {
        const grid_point *u = &p[k], *w = &p[(k + 1) % count];
        mpq_mul(t[0], h->a, u->i), mpq_mul(t[1], h->b, u->j), mpq_add(t[0], t[0], t[1]), mpq_add(t[0], t[0], h->c);
        mpq_mul(t[1], h->a, w->i), mpq_mul(t[2], h->b, w->j), mpq_add(t[1], t[1], t[2]), mpq_add(t[1], t[1], h->c);
        int su = mpq_sgn(t[0]), sw = mpq_sgn(t[1]);
        if (su >= 0) mpq_set(out[m].i, u->i), mpq_set(out[m].j, u->j), m++;
        if (su * sw < 0) { /* u + (w - u) su / (su - sw) */
            mpq_sub(t[2], t[0], t[1]);
            mpq_div(t[2], t[0], t[2]);
            mpq_sub(t[3], w->i, u->i), mpq_mul(t[3], t[3], t[2]), mpq_add(out[m].i, u->i, t[3]);
            mpq_sub(t[3], w->j, u->j), mpq_mul(t[3], t[3], t[2]), mpq_add(out[m].j, u->j, t[3]);
            m++;
        }
    }
    return m;
}

/* Lattice points of one row: (i, j) = s e1 + t e2 for integer s at a fixed
 * integer t. Tries the first integer s inside the open interval the
 * constraints allow. */
static int lattice_row(const face_output *f, const incidence *inc, double *xy, long v,
                       const grid_constraint *h, int nh, const mpq_t *e, const mpq_t row,
                       const double *origin, const double *unit, mpq_t *t, long *best_bad, double *best)
{
    int have_lo = 0, have_hi = 0;
    mpq_t *lo = &t[0], *hi = &t[1], *cs = &t[2], *r = &t[3], *tmp = &t[4];
    for (int k = 0; k < nh; k++) {
        mpq_mul(*cs, h[k].a, e[0]), mpq_mul(*tmp, h[k].b, e[1]), mpq_add(*cs, *cs, *tmp);
        mpq_mul(*r, h[k].a, e[2]), mpq_mul(*tmp, h[k].b, e[3]), mpq_add(*r, *r, *tmp);
        mpq_mul(*r, *r, row), mpq_add(*r, *r, h[k].c);             /* cs s + r > 0 */
        int sign = mpq_sgn(*cs);
        if (sign == 0) {
            if (mpq_sgn(*r) <= 0) return 0;
            continue;
        }
        mpq_div(*r, *r, *cs), mpq_neg(*r, *r);
        if (sign > 0 && (!have_lo || mpq_cmp(*r, *lo) > 0)) mpq_set(*lo, *r), have_lo = 1;
        if (sign < 0 && (!have_hi || mpq_cmp(*r, *hi) < 0)) mpq_set(*hi, *r), have_hi = 1;
    }
    if (!have_lo || !have_hi || mpq_cmp(*lo, *hi) >= 0) return 0;
    mpz_fdiv_q(mpq_numref(*tmp), mpq_numref(*lo), mpq_denref(*lo));
    mpz_add_ui(mpq_numref(*tmp), mpq_numref(*tmp), 1);
    mpz_set_ui(mpq_denref(*tmp), 1);                                 /* floor(lo) + 1 */
    if (mpq_cmp(*tmp, *hi) >= 0) return 0;
    double p[2];
    for (int axis = 0; axis < 2; axis++) {
        mpq_mul(*r, *tmp, e[axis]), mpq_mul(*cs, row, e[2 + axis]), mpq_add(*r, *r, *cs);
        mpq_set_d(*cs, unit[axis]), mpq_mul(*r, *r, *cs);
        mpq_set_d(*cs, origin[axis]), mpq_add(*r, *r, *cs);
        p[axis] = mpq_get_d(*r);
    }
    return try_candidate(f, inc, xy, v, p[0], p[1], best_bad, best);
}

/* Finds a double strictly inside the star's kernel when that kernel is a
 * sliver thinner than the spacing of doubles in every axis direction but
 * long enough to hold some: its exact shape R (in grid units), its long
 * direction D, and the continued fraction of D's slope give integer
 * vectors e1 nearly parallel to D with a partner e2 (det = +-1); the rows
 * t e2 + s e1 then run along the sliver, and a row through its middle holds
 * an integer s wherever R is longer than e1. A few convergents and rows
 * are tried; every candidate is checked exactly. */
static int lattice_search(const face_output *f, const incidence *inc, double *xy, long v,
                          const double *home, long *best_bad, double *best)
{
    long deg = inc->start[v + 1] - inc->start[v];
    if (deg + 4 > LATTICE_MAX_VERTICES) return 0;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (long k = inc->start[v]; k < inc->start[v + 1]; k++)
        for (int e = 0; e < 3; e++) {
            const double *u = xy + 2 * f->tri[3 * inc->tri[k] + e];
            for (int axis = 0; axis < 2; axis++) lo[axis] = fmin(lo[axis], u[axis]), hi[axis] = fmax(hi[axis], u[axis]);
        }
    double unit[2], origin[2];
    for (int axis = 0; axis < 2; axis++) {
        unit[axis] = unit_in_last_place(fmax(fabs(lo[axis]), fabs(hi[axis])));
        origin[axis] = unit[axis] * nearbyint(home[axis] / unit[axis]);
        if (!(unit[axis] > 0) || !isfinite(origin[axis])) return 0;
    }
    int found = 0, nh = (int)deg, count = 4;
    grid_constraint h[LATTICE_MAX_VERTICES];
    grid_point poly[2][LATTICE_MAX_VERTICES];
    mpq_t t[8], e[4], conv[LATTICE_CONVERGENTS + 2][2], row, tlo, thi;
    for (int k = 0; k < 8; k++) mpq_init(t[k]);
    for (int k = 0; k < 4; k++) mpq_init(e[k]);
    for (int k = 0; k < LATTICE_CONVERGENTS + 2; k++) mpq_init(conv[k][0]), mpq_init(conv[k][1]);
    mpq_init(row), mpq_init(tlo), mpq_init(thi);
    for (int k = 0; k < nh; k++) mpq_init(h[k].a), mpq_init(h[k].b), mpq_init(h[k].c);
    for (int b = 0; b < 2; b++)
        for (int k = 0; k < LATTICE_MAX_VERTICES; k++) mpq_init(poly[b][k].i), mpq_init(poly[b][k].j);

    for (int k = 0; k < nh; k++) {
        const int32_t *c = f->tri + 3 * inc->tri[inc->start[v] + k];
        int at = c[0] == v ? 0 : c[1] == v ? 1 : 2;
        const double *a = xy + 2 * c[(at + 1) % 3], *b = xy + 2 * c[(at + 2) % 3];
        /* orient(a, b, O + (i ux, j uy)) = (bx - ax)(Oy + j uy - ay) - (by - ay)(Ox + i ux - ax) */
        mpq_set_d(t[0], b[0]), mpq_set_d(t[1], a[0]), mpq_sub(t[0], t[0], t[1]);   /* dx */
        mpq_set_d(t[1], b[1]), mpq_set_d(t[2], a[1]), mpq_sub(t[1], t[1], t[2]);   /* dy */
        mpq_set_d(t[2], unit[1]), mpq_mul(h[k].b, t[0], t[2]);
        mpq_set_d(t[2], unit[0]), mpq_mul(h[k].a, t[1], t[2]), mpq_neg(h[k].a, h[k].a);
        mpq_set_d(t[2], origin[1]), mpq_set_d(t[3], a[1]), mpq_sub(t[2], t[2], t[3]), mpq_mul(t[2], t[2], t[0]);
        mpq_set_d(t[3], origin[0]), mpq_set_d(t[4], a[0]), mpq_sub(t[3], t[3], t[4]), mpq_mul(t[3], t[3], t[1]);
        mpq_sub(h[k].c, t[2], t[3]);
    }
    /* R: the star's bounding box clipped by every constraint. */
    for (int k = 0; k < 4; k++) {
        double gx = (k == 1 || k == 2) ? hi[0] : lo[0], gy = k >= 2 ? hi[1] : lo[1];
        mpq_set_d(t[0], gx), mpq_set_d(t[1], origin[0]), mpq_sub(t[0], t[0], t[1]);
        mpq_set_d(t[1], unit[0]), mpq_div(poly[0][k].i, t[0], t[1]);
        mpq_set_d(t[0], gy), mpq_set_d(t[1], origin[1]), mpq_sub(t[0], t[0], t[1]);
        mpq_set_d(t[1], unit[1]), mpq_div(poly[0][k].j, t[0], t[1]);
    }
    int cur = 0;
    for (int k = 0; k < nh && count >= 3; k++) {
        count = clip_polygon(poly[cur], count, poly[1 - cur], &h[k], t);
        cur = 1 - cur;
    }
    if (count < 3) goto done;
    /* A small R: every grid point of its bounding box, so a double in the
     * kernel is found whenever there is one. */
    double box[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (int a = 0; a < count; a++) {
        double gi = mpq_get_d(poly[cur][a].i), gj = mpq_get_d(poly[cur][a].j);
        box[0] = fmin(box[0], gi), box[1] = fmin(box[1], gj);
        box[2] = fmax(box[2], gi), box[3] = fmax(box[3], gj);
    }
    box[0] = floor(box[0]) - 1, box[1] = floor(box[1]) - 1, box[2] = ceil(box[2]) + 1, box[3] = ceil(box[3]) + 1;
    if ((box[2] - box[0] + 1) * (box[3] - box[1] + 1) <= LATTICE_BOX_POINTS) {
        for (double gi = box[0]; gi <= box[2] && !found; gi++)
            for (double gj = box[1]; gj <= box[3] && !found; gj++)
                found = try_candidate(f, inc, xy, v, origin[0] + gi * unit[0], origin[1] + gj * unit[1],
                                      best_bad, best);
        goto done;
    }
    /* Its long direction: the farthest pair of corners. */
    int fa = 0, fb = 0;
    double far = -1;
    for (int a = 0; a < count; a++)
        for (int b = a + 1; b < count; b++) {
            mpq_sub(t[0], poly[cur][a].i, poly[cur][b].i), mpq_sub(t[1], poly[cur][a].j, poly[cur][b].j);
            double d = hypot(mpq_get_d(t[0]), mpq_get_d(t[1]));
            if (d > far) far = d, fa = a, fb = b;
        }
    mpq_sub(t[6], poly[cur][fb].i, poly[cur][fa].i), mpq_sub(t[7], poly[cur][fb].j, poly[cur][fa].j);
    mpq_abs(t[0], t[6]), mpq_abs(t[1], t[7]);
    int primary = mpq_cmp(t[0], t[1]) >= 0 ? 0 : 1;                      /* the longer axis */
    if (mpq_sgn(primary ? t[7] : t[6]) == 0) goto done;
    /* Convergents h/k of the slope r = D_other / D_primary, as vectors
     * (primary, other) = (k, h), from h_-1/k_-1 = 1/0 and h_-2/k_-2 = 0/1. */
    mpq_div(t[2], primary ? t[6] : t[7], primary ? t[7] : t[6]);     /* r */
    mpz_t num, den, a_k, rem;
    mpz_inits(num, den, a_k, rem, NULL);
    mpz_set(num, mpq_numref(t[2])), mpz_set(den, mpq_denref(t[2]));
    mpq_set_ui(conv[0][0], 1, 1), mpq_set_ui(conv[0][1], 0, 1);      /* (k, h) of index -2: k=1, h=0 */
    mpq_set_ui(conv[1][0], 0, 1), mpq_set_ui(conv[1][1], 1, 1);      /* index -1: k=0, h=1 */
    int nconv = 2;
    while (nconv < LATTICE_CONVERGENTS + 2 && mpz_sgn(den) != 0) {
        mpz_fdiv_qr(a_k, rem, num, den);
        mpz_set(num, den), mpz_set(den, rem);
        mpq_set_z(t[3], a_k);
        for (int c = 0; c < 2; c++) {
            mpq_mul(conv[nconv][c], conv[nconv - 1][c], t[3]);
            mpq_add(conv[nconv][c], conv[nconv][c], conv[nconv - 2][c]);
        }
        if (hypot(mpq_get_d(conv[nconv][0]), mpq_get_d(conv[nconv][1])) > far) break;
        nconv++;
    }
    mpz_clears(num, den, a_k, rem, NULL);
    /* From the longest e1 that fits in R down. */
    for (int c = nconv - 1; c >= 2 && !found; c--) {
        for (int which = 0; which < 2; which++) {
            const mpq_t *src = which == 0 ? conv[c] : conv[c - 1];
            mpq_set(e[2 * which + primary], src[0]);                  /* k along the primary axis */
            mpq_set(e[2 * which + 1 - primary], src[1]);
        }
        /* Rows t = cross(e1, P) / cross(e1, e2) over R's corners. */
        mpq_mul(t[0], e[0], e[3]), mpq_mul(t[1], e[1], e[2]), mpq_sub(t[5], t[0], t[1]); /* det */
        for (int k = 0; k < count; k++) {
            mpq_mul(t[0], e[0], poly[cur][k].j), mpq_mul(t[1], e[1], poly[cur][k].i);
            mpq_sub(t[0], t[0], t[1]), mpq_div(t[0], t[0], t[5]);
            if (k == 0 || mpq_cmp(t[0], tlo) < 0) mpq_set(tlo, t[0]);
            if (k == 0 || mpq_cmp(t[0], thi) > 0) mpq_set(thi, t[0]);
        }
        mpq_add(row, tlo, thi), mpq_div_2exp(row, row, 1);
        mpz_fdiv_q(mpq_numref(t[6]), mpq_numref(row), mpq_denref(row));
        mpz_set_ui(mpq_denref(t[6]), 1);                             /* the middle row */
        for (int r = 0; r < LATTICE_ROWS && !found; r++) {
            mpq_set_si(t[7], (r + 1) / 2 * (r % 2 ? 1 : -1), 1);
            mpq_add(row, t[6], t[7]);
            if (mpq_cmp(row, tlo) < 0 || mpq_cmp(row, thi) > 0) continue;
            found = lattice_row(f, inc, xy, v, h, nh, e, row, origin, unit, t, best_bad, best);
        }
    }
done:
    for (int k = 0; k < 8; k++) mpq_clear(t[k]);
    for (int k = 0; k < 4; k++) mpq_clear(e[k]);
    for (int k = 0; k < LATTICE_CONVERGENTS + 2; k++) mpq_clear(conv[k][0]), mpq_clear(conv[k][1]);
    mpq_clear(row), mpq_clear(tlo), mpq_clear(thi);
    for (int k = 0; k < nh; k++) mpq_clear(h[k].a), mpq_clear(h[k].b), mpq_clear(h[k].c);
    for (int b = 0; b < 2; b++)
        for (int k = 0; k < LATTICE_MAX_VERTICES; k++) mpq_clear(poly[b][k].i), mpq_clear(poly[b][k].j);
    return found;
}

/* Moves v to a better place if there is one among the candidates; home is
 * where the construction put it, next to its exact position. */
static int move_vertex(const face_output *f, const incidence *inc, double *xy, long v,
                       const double *home)
{
    long bad = inverted_around(f, inc, xy, v), deg = inc->start[v + 1] - inc->start[v];
    if (bad == 0 || deg == 0) return 0;
    double best[2], x = xy[2 * v], y = xy[2 * v + 1], cx = 0, cy = 0, reach = fmax(fabs(x), fabs(y));
    long best_bad = bad;
    for (long i = inc->start[v]; i < inc->start[v + 1]; i++) {
        const int32_t *c = f->tri + 3 * inc->tri[i];
        for (int e = 0; e < 3; e++) {
            if (c[e] == v) continue;
            const double *u = xy + 2 * c[e];
            cx += u[0] / (double)(2 * deg), cy += u[1] / (double)(2 * deg);
            reach = fmax(reach, fmax(fabs(u[0]), fabs(u[1])));
        }
    }
    int done = try_candidate(f, inc, xy, v, cx, cy, &best_bad, best);
    for (double s = 0.5; !done && s > 0x1p-60; s *= 0.5)
        done = try_candidate(f, inc, xy, v, x + s * (cx - x), y + s * (cy - y), &best_bad, best);
    for (long i = inc->start[v]; !done && i < inc->start[v + 1]; i++) {
        const int32_t *c = f->tri + 3 * inc->tri[i];
        for (int e = 0; e < 3 && !done; e++) {
            if (c[e] == v) continue;
            const double *u = xy + 2 * c[e];
            for (double s = 0.25; !done && s > 0x1p-60; s *= 0.5)
                done = try_candidate(f, inc, xy, v, x + s * (u[0] - x), y + s * (u[1] - y), &best_bad, best);
        }
    }
    double ux = unit_in_last_place(reach), uy = ux;
    for (int r = 1; !done && r <= REPAIR_RINGS; r++)
        for (int i = -r; i <= r && !done; i++)
            for (int k = -r; k <= r && !done; k += (abs(i) == r ? 1 : 2 * r))
                done = try_candidate(f, inc, xy, v, x + i * ux, y + k * uy, &best_bad, best);
    if (!done) {
        mpq_t q[5];
        for (int i = 0; i < 5; i++) mpq_init(q[i]);
        const double base[3][2] = {{home[0], home[1]}, {x, y}, {cx, cy}};
        for (int i = 0; i <= REPAIR_LINES && !done; i++)
            for (int b = 0; b < 3 && !done; b++)
                for (int w = 0; w < 2 && !done; w++) {
                    double at = base[b][w], step = unit_in_last_place(at);
                    done = scan_line(f, inc, xy, v, w, at + i * step, q, &best_bad, best) ||
                           (i > 0 && scan_line(f, inc, xy, v, w, at - i * step, q, &best_bad, best));
                }
        for (int i = 0; i < 5; i++) mpq_clear(q[i]);
    }
    if (!done) done = lattice_search(f, inc, xy, v, home, &best_bad, best);
    if (best_bad >= bad) return 0;
    xy[2 * v] = best[0], xy[2 * v + 1] = best[1];
    return 1;
}

/* Returns the number of triangles still inverted in geometry j, or -1 out
 * of memory. Vertices below `fixed` (the polygon's) never move. */
static long repair_geometry(const face_output *f, const incidence *inc, size_t j, size_t fixed)
{
    double *xy = f->xy[j], *home = malloc(2 * f->nv * sizeof *home);
    long bad = 0;
    if (!home) return -1;
    memcpy(home, xy, 2 * f->nv * sizeof *home);
    for (int pass = 0; pass < REPAIR_PASSES; pass++) {
        int moved = 0;
        for (long t = 0; t < (long)f->nt; t++)
            for (int e = 0; e < 3 && inverted(f, xy, t); e++) {
                long v = f->tri[3 * t + e];
                if ((size_t)v >= fixed) moved |= move_vertex(f, inc, xy, v, home + 2 * v);
            }
        /* Counted afresh: a move may invert a triangle passed earlier, as
         * long as it rights more than that around its vertex. */
        bad = 0;
        for (long t = 0; t < (long)f->nt; t++) bad += inverted(f, xy, t);
        if (bad == 0 || !moved) break;
    }
    free(home);
    return bad;
}

static int triangulate_faces(const graph *g, size_t n, face_output *f)
{
    char *seen = calloc((size_t)g->nh, 1);
    long *face = malloc((size_t)g->nh * sizeof *face);
    int status = -1;
    if (!seen || !face) goto done;
    /* The outer face is the one left of the boundary's reversed half-edges
     * (odd ids below 2n); it must consist of exactly those. */
    long outer_len = 0;
    int outer_ok = 1;
    for (long h = 1; !seen[h]; h = next_in_face(g, h)) {
        seen[h] = 1;
        outer_ok &= (h & 1) && h < 2 * (long)n;
        outer_len++;
    }
    status = 1;
    if (!outer_ok || outer_len != (long)n) goto done;
    for (long h0 = 0; h0 < g->nh; h0++) {
        if (seen[h0]) continue;
        long m = 0;
        for (long h = h0; !seen[h]; h = next_in_face(g, h)) {
            seen[h] = 1;
            face[m++] = g->from[h];
        }
        int s = triangulate_face(f, face, m);
        if (s != 0) { status = s; goto done; }
    }
    status = 0;
done:
    free(seen), free(face);
    return status;
}

/* Repairs every geometry; 0 when all are valid, 1 (with the count and
 * the geometry left inverted) when not, -1 out of memory. */
static int repair_all(face_output *f, size_t fixed, long *bad, size_t *where)
{
    incidence inc = {NULL, NULL};
    int status = -1;
    if (incidence_build(f, &inc)) goto done;
    status = 0;
    for (size_t j = 0; j < f->k && status == 0; j++) {
        *bad = repair_geometry(f, &inc, j, fixed);
        if (*bad < 0) status = -1;
        else if (*bad > 0) status = 1, *where = j;
    }
done:
    free(inc.start), free(inc.tri);
    return status;
}

/* A fan mesh of the n polygon vertices and `extra` Steiner vertices (their
 * positions left to the caller): 0, or -1 out of memory (*fan empty). */
static int fan_begin(const double *const *geoms, size_t k, size_t n, size_t extra, face_output *fan)
{
    memset(fan, 0, sizeof *fan);
    fan->k = k;
    fan->nv = fan->cap_v = n + extra;
    fan->xy = calloc(k, sizeof *fan->xy);
    for (size_t j = 0; fan->xy && j < k; j++) {
        fan->xy[j] = malloc(2 * (n + extra) * sizeof *fan->xy[j]);
        if (!fan->xy[j]) break;
        memcpy(fan->xy[j], geoms[j], 2 * n * sizeof *fan->xy[j]);
        if (j + 1 == k) return 0;
    }
    if (fan->xy)
        for (size_t j = 0; j < k; j++) free(fan->xy[j]);
    free(fan->xy);
    memset(fan, 0, sizeof *fan);
    return -1;
}

/* Places the fan's Steiner vertices by the repair; on any failure frees it.
 * Returns as repair_all. */
static int fan_finish(face_output *fan, size_t n, int emitted)
{
    long bad = 0;
    size_t where = 0;
    int status = emitted ? repair_all(fan, n, &bad, &where) : -1;
    if (status != 0) {
        for (size_t j = 0; j < fan->k; j++) free(fan->xy[j]);
        free(fan->xy), free(fan->tri);
        memset(fan, 0, sizeof *fan);
    }
    return status;
}

/* The last resort when the overlay's Steiner vertices cannot all be placed
 * (several of them crowded into one sliver thinner than the spacing of
 * doubles): a polygon star-shaped in every geometry is a fan around one
 * vertex placed in each kernel, and the repair's search (down to the
 * lattice search in a sliver kernel) is what places it. Returns 0 with
 * *fan filled, 1 when some geometry has no such vertex, -1 out of memory. */
static int star_fan(const double *const *geoms, size_t k, size_t n, face_output *fan)
{
    if (fan_begin(geoms, k, n, 1, fan)) return -1;
    for (size_t j = 0; j < k; j++) {
        double sx = 0, sy = 0;
        for (size_t i = 0; i < n; i++) sx += geoms[j][2 * i] / (double)n, sy += geoms[j][2 * i + 1] / (double)n;
        fan->xy[j][2 * n] = sx, fan->xy[j][2 * n + 1] = sy;
    }
    int emitted = 1;
    for (size_t i = 0; i < n && emitted; i++) emitted = !emit_triangle(fan, (long)i, (long)((i + 1) % n), (long)n);
    fan->centroids = 1;
    return fan_finish(fan, n, emitted);
}

/* The next resort for a small polygon that is not star-shaped in some
 * geometry, or whose kernel holds no double: two Steiner vertices, s1
 * fanning the boundary chain a..b and s2 the chain b..a, with the edge
 * s1 s2 between them (triangles (b, s2, s1) and (a, s1, s2)). Each needs
 * only to see its own chain, so a sliver whose kernel is empty of doubles
 * can still take them. Every split a < b is tried. Returns as star_fan. */
#define TWO_FAN_MAX_N 12

static int two_fan(const double *const *geoms, size_t k, size_t n, size_t a, size_t b,
                   face_output *fan)
{
    if (fan_begin(geoms, k, n, 2, fan)) return -1;
    long s1 = (long)n, s2 = (long)n + 1;
    for (size_t j = 0; j < k; j++)
        for (int side = 0; side < 2; side++) {
            size_t from = side ? b : a, to = side ? a + n : b, count = to - from + 1;
            double sx = 0, sy = 0;
            for (size_t i = from; i <= to; i++)
                sx += geoms[j][2 * (i % n)] / (double)count, sy += geoms[j][2 * (i % n) + 1] / (double)count;
            fan->xy[j][2 * (n + (size_t)side)] = sx, fan->xy[j][2 * (n + (size_t)side) + 1] = sy;
        }
    int emitted = 1;
    for (size_t i = a; i < b && emitted; i++) emitted = !emit_triangle(fan, (long)i, (long)(i + 1), s1);
    for (size_t i = b; i < a + n && emitted; i++)
        emitted = !emit_triangle(fan, (long)(i % n), (long)((i + 1) % n), s2);
    emitted = emitted && !emit_triangle(fan, (long)b, s2, s1) && !emit_triangle(fan, (long)a, s1, s2);
    fan->centroids = 2;
    return fan_finish(fan, n, emitted);
}

/* ---- the whole construction ---------------------------------------------- */

static void overlay_free(overlay *o)
{
    free(o->cxy), free(o->chords), free(o->owner), free(o->cross);
    free(o->vertex_of_cross), free(o->chord_seq_start), free(o->chord_seq);
    for (int i = 0; i < 8; i++) mpq_clear(o->q[i]);
}

cm_status cm_overlay(const double *const *geoms, const int32_t *const *tris, size_t k,
                     size_t n, cm_mesh *out, size_t *extra_centroids, cm_error *err)
{
    overlay o;
    graph g;
    face_output f;
    memset(&o, 0, sizeof o);
    memset(&g, 0, sizeof g);
    memset(&f, 0, sizeof f);
    for (int i = 0; i < 8; i++) mpq_init(o.q[i]);
    o.n = n, o.k = k;
    cm_status status = CM_ERR_NO_MEMORY;
    int s = make_convex_polygon(&o);
    if (s > 0) {
        status = cm_fail(err, CM_ERR_INTERNAL, "overlay: the convex %zu-gon is not strictly convex in double precision", n);
        goto done;
    }
    if (s < 0 || collect_chords(&o, tris) || find_crossings(&o) || build_chord_sequences(&o) ||
        build_graph(&o, &g))
        goto done;

    /* Each face of m vertices needs at most one centroid. */
    f.k = k;
    f.nv = (size_t)o.nv;
    f.cap_v = (size_t)o.nv + (size_t)g.nh / 3 + 1;
    f.xy = calloc(k, sizeof *f.xy);
    unsigned char *placed = malloc(f.cap_v);
    if (!f.xy || !placed) { free(placed); goto done; }
    for (size_t j = 0; j < k; j++) {
        f.xy[j] = malloc(2 * f.cap_v * sizeof *f.xy[j]);
        if (!f.xy[j]) { free(placed); goto done; }
        map_back(&o, geoms[j], tris[j], j, f.xy[j], placed);
    }
    free(placed);
    s = triangulate_faces(&g, n, &f);
    if (s < 0) goto done;
    if (s > 0) {
        status = cm_fail(err, CM_ERR_INTERNAL, "overlay: the overlay's outer face is not the boundary");
        goto done;
    }
    long bad = 0;
    size_t where = 0;
    s = repair_all(&f, n, &bad, &where);
    if (s < 0) goto done;
    if (s > 0) {
        face_output fan;
        s = star_fan(geoms, k, n, &fan);
        for (size_t a = 0; s > 0 && n <= TWO_FAN_MAX_N && a < n; a++)
            for (size_t b = a + 2; s > 0 && b + 2 <= a + n && b < n; b++)
                s = two_fan(geoms, k, n, a, b, &fan);
        if (s < 0) goto done;
        if (s > 0) {
            status = cm_fail(err, CM_ERR_PRECISION,
                             "overlay: %ld triangles of geometry %zu stay inverted: no double "
                             "position found for their Steiner vertices (polygon %zu's vertices are "
                             "too close together for their magnitude; nearer the origin it has room)",
                             bad, where, where);
            cm_fail_at(err, (long)where, -1, -1);
            goto done;
        }
        for (size_t j = 0; j < k; j++) free(f.xy[j]);
        free(f.xy), free(f.tri);
        f = fan;
    }
    out->k = k;
    out->nv = f.nv;
    out->nt = f.nt;
    out->xy = f.xy;
    out->tri = f.tri;
    f.xy = NULL, f.tri = NULL;
    *extra_centroids = f.centroids;
    status = CM_OK;
done:
    if (f.xy)
        for (size_t j = 0; j < k; j++) free(f.xy[j]);
    free(f.xy), free(f.tri);
    graph_free(&g);
    overlay_free(&o);
    return status;
}
