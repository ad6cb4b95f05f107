/* Boundary edges split where their edge cap binds. A triangle on a
 * boundary edge cannot have a smallest angle above the edge's cap
 * (remesh/criteria.h), and the remesher takes the caps of the boundary it
 * starts from as the limits of its targets (the halves of an edge it
 * splits itself keep the whole edge's cap); so where the points a
 * correspondence added leave an edge long beside a close stretch of
 * boundary, the aim is lowered there unless the edge is split first.
 * Halving such an edge at the same parameter in
 * every polygon keeps the correspondence (the segments stay on their
 * input edges, the map along them linear) and raises the cap: the
 * isosceles triangle of a given base angle on a half lies inside the one
 * on the whole edge, so caps never fall, and the half's is at least twice
 * as tall for the same obstacle. */
#include <math.h>
#include <stdlib.h>

#include "api/capsplit.h"
#include "correspond/split.h"
#include "base/mesh.h"
#include "geom/angle.h"
#include "geom/looptri.h"
#include "geom/polytri.h"
#include "remesh/criteria.h"

/* Rounds of halving: an edge shrinks by at most 2^CAP_SPLIT_ROUNDS. */
#define CAP_SPLIT_ROUNDS 6

void cm_cap_tris_free(int32_t **tris, size_t k)
{
    for (size_t g = 0; tris && g < k; g++) free(tris[g]);
    free(tris);
}

/* The loops' boundaries one after another, each with the material to its
 * left (loop_start: L + 1 offsets): the outer loop as its map runs, a hole's
 * counter-clockwise map backwards from its vertex 0, so that hole vertex j
 * is map vertex cm_loop_reversed(m, j). */
typedef struct merged {
    size_t k, n, num_loops;
    size_t *loop_start;
    double **xy;
} merged;

static void merged_free(merged *b)
{
    for (size_t g = 0; b->xy && g < b->k; g++) free(b->xy[g]);
    free(b->xy), free(b->loop_start);
}

static int merged_make(merged *b, const cm_cap_loop *loops, size_t num_loops)
{
    size_t k = loops[0].map->k, n = 0;
    *b = (merged){k, 0, num_loops, malloc((num_loops + 1) * sizeof(size_t)), calloc(k, sizeof(double *))};
    if (!b->loop_start || !b->xy) return -1;
    for (size_t l = 0; l < num_loops; l++) b->loop_start[l] = n, n += loops[l].map->n;
    b->loop_start[num_loops] = b->n = n;
    for (size_t g = 0; g < k; g++) {
        if (!(b->xy[g] = malloc(2 * n * sizeof(double)))) return -1;
        for (size_t l = 0; l < num_loops; l++) {
            const cm_boundary_map *map = loops[l].map;
            size_t m = map->n;
            for (size_t j = 0; j < m; j++) {
                const double *p = map->xy[g] + 2 * (l ? cm_loop_reversed(m, j) : j);
                double *q = b->xy[g] + 2 * (b->loop_start[l] + j);
                q[0] = p[0], q[1] = p[1];
            }
        }
    }
    return 0;
}

/* The smallest edge and vertex caps over the polygons of b (radians,
 * unscaled), each polygon triangulated on its own (into tris[g], 3 (n - 2
 * + 2 h) each). *simple = 0 when one is not simple (rounding of the points
 * added): the pipeline's check then says where. */
static cm_status caps_of(const merged *b, cm_progress *progress, double *bcap, double *vcap, int32_t **tris,
                         int *simple, cm_error *err)
{
    size_t n = b->n, holes = b->num_loops - 1;
    const size_t *loops = holes ? b->loop_start : NULL;
    int32_t *idx = malloc(n * sizeof *idx);
    double *c = malloc(2 * n * sizeof *c), *v = c ? c + n : NULL;
    cm_status s = idx && c ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    *simple = 1;
    for (size_t i = 0; s == CM_OK && i < n; i++) idx[i] = (int32_t)i, bcap[i] = vcap[i] = INFINITY;
    for (size_t g = 0; s == CM_OK && *simple && g < b->k; g++) {
        int t = holes ? cm_loops_triangulate(b->xy[g], loops, b->num_loops, tris[g])
                      : cm_polygon_triangulate(b->xy[g], idx, (long)n, tris[g], progress);
        cm_mesh one = {1, n, n - 2 + 2 * holes, &b->xy[g], tris[g], loops, holes ? b->num_loops : 0};
        if (t == 0) t = cm_boundary_caps(&one, n, progress, c, v);
        if (t == CM_CANCELLED) s = cm_fail_status(err, CM_ERR_CANCELLED);
        else if (t == CM_NO_MEMORY) s = cm_fail_status(err, CM_ERR_NO_MEMORY);
        else if (t != 0) *simple = 0;
        for (size_t i = 0; s == CM_OK && *simple && i < n; i++)
            bcap[i] = fmin(bcap[i], c[i]), vcap[i] = fmin(vcap[i], v[i]);
    }
    free(idx), free(c);
    return s;
}

/* Edge j -> next(j) caps every triangle on it below the aim: its cap,
 * with the remesher's margin, under the aim and under the vertex caps at
 * its ends (where half a corner is lower, the corner binds first). */
static int binds(const merged *b, const double *bcap, const double *vcap, size_t j, double aim)
{
    size_t next = cm_loops_next(b->num_loops > 1 ? b->loop_start : NULL, b->n, j);
    return CM_EDGE_CAP_MARGIN * bcap[j] < fmin(aim, fmin(vcap[j], vcap[next]));
}

/* Grading. Around a boundary vertex v the triangles at v form one fan in
 * every polygon (the connectivity is shared), from one boundary edge at v
 * to the other. Each takes at least alpha of the corner theta at v, and
 * its two sides at v differ by at most 1 / sin(alpha) (law of sines, its
 * other angles at least alpha), so the two edges at v differ by at most
 * (1 / sin(alpha))^floor(theta / alpha): where an input puts a tiny edge
 * beside a long one (two points a section cut put almost together), no
 * triangle there can reach the aim until the long edge is split near v.
 * The remesher's splits, one at a time, raise nothing until a dozen are
 * made; here the long edge is halved, round after round, until the ratio
 * at v allows the aim (with the edge caps' margin; at a corner sharper
 * than twice the aim, half the corner, the aim there). Halving keeps the
 * correspondence, as for the edge caps. */
#define CM_GRADE_ROUNDS 40
/* ... and no edge shorter than this share of its polygon's extent (its
 * largest coordinate or its bounding box, whichever is larger) in some
 * polygon is halved: the edge at the same parameter in another polygon
 * may be near a rounding step of its coordinates there, and the halves of
 * a piece that short could coincide with its ends. */
#define CM_GRADE_SHORTEST 1e-9

/* The extent of each of b's polygons (CM_GRADE_SHORTEST). */
static void extents(const merged *b, double *extent)
{
    for (size_t g = 0; g < b->k; g++) {
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY}, big = 0;
        for (size_t i = 0; i < b->n; i++)
            for (int d = 0; d < 2; d++) {
                double x = b->xy[g][2 * i + d];
                lo[d] = fmin(lo[d], x), hi[d] = fmax(hi[d], x), big = fmax(big, fabs(x));
            }
        extent[g] = fmax(big, hypot(hi[0] - lo[0], hi[1] - lo[1]));
    }
}

/* Does the fan at v allow alpha (radians) between edges whose lengths
 * differ by the factor ratio >= 1, at the corner theta? */
static int fan_allows(double alpha, double theta, double ratio)
{
    double k = floor(theta / alpha);
    return k >= 1 && k * -log(sin(alpha)) >= log(ratio);
}

/* The corner of polygon g's boundary b at vertex v. */
static double corner_at(const merged *b, size_t g, size_t v)
{
    const size_t *loops = b->num_loops > 1 ? b->loop_start : NULL;
    const double *xy = b->xy[g];
    return cm_corner_angle(xy + 2 * cm_loops_prev(loops, b->n, v), xy + 2 * v,
                           xy + 2 * cm_loops_next(loops, b->n, v));
}

static double edge_length(const merged *b, size_t g, size_t j)
{
    size_t next = cm_loops_next(b->num_loops > 1 ? b->loop_start : NULL, b->n, j);
    const double *p = b->xy[g] + 2 * j, *q = b->xy[g] + 2 * next;
    return hypot(q[0] - p[0], q[1] - p[1]);
}

/* Is edge j -> next(j) too long, in some polygon, beside the other edge at
 * either end for the fan there to reach the aim, and long enough in every
 * polygon to be halved (extent: the polygons' extents)? */
static int grading_binds(const merged *b, const double *extent, size_t j, double aim)
{
    const size_t *loops = b->num_loops > 1 ? b->loop_start : NULL;
    size_t ends[2] = {j, cm_loops_next(loops, b->n, j)};
    size_t beside[2] = {cm_loops_prev(loops, b->n, j), ends[1]};
    for (size_t g = 0; g < b->k; g++)
        if (!(edge_length(b, g, j) >= CM_GRADE_SHORTEST * extent[g])) return 0;
    for (size_t g = 0; g < b->k; g++) {
        double len = edge_length(b, g, j);
        for (int e = 0; e < 2; e++) {
            double other = edge_length(b, g, beside[e]), theta = corner_at(b, g, ends[e]);
            double alpha = fmin(aim, 0.5 * theta) / CM_EDGE_CAP_MARGIN;
            if (len > other && other > 0 && !fan_allows(fmin(alpha, 0.5 * CM_PI), theta, len / other)) return 1;
        }
    }
    return 0;
}

/* k arrays of 3 nt indices, or NULL. */
static int32_t **tris_new(size_t k, size_t nt)
{
    int32_t **tris = calloc(k, sizeof *tris);
    for (size_t g = 0; tris && g < k; g++)
        if (!(tris[g] = malloc(3 * nt * sizeof **tris))) {
            cm_cap_tris_free(tris, k);
            return NULL;
        }
    return tris;
}

/* Splits the edges pieces[] says (material-left numbering of b) in each
 * loop's map: hole edge j -> j + 1 is the map's segment from its vertex
 * cm_loop_reversed(m, j + 1). */
static cm_status split_loops(cm_cap_loop *loops, const merged *b, const size_t *pieces, size_t *scratch, cm_error *err)
{
    cm_status s = CM_OK;
    for (size_t l = 0; s == CM_OK && l < b->num_loops; l++) {
        size_t m = loops[l].map->n, at = b->loop_start[l], more = 0;
        for (size_t j = 0; j < m; j++) more += (scratch[l ? cm_loop_reversed(m, (j + 1) % m) : j] = pieces[at + j]) - 1;
        if (more)
            s = cm_boundary_map_split_edges(loops[l].map, loops[l].polygons, loops[l].counts, loops[l].orientation,
                                            scratch, err);
    }
    return s;
}

/* The ceiling, asked once (cm_cap_ceiling): *aim lowered to it; none set
 * where none could be had (the boundary is then left as it is). */
typedef struct ceiling_ask {
    cm_cap_ceiling fn;
    void *ctx;
    int asked, none;
} ceiling_ask;

static cm_status lower_aim(ceiling_ask *c, const merged *b, double *aim)
{
    cm_status s = CM_OK;
    if (c->asked || !c->fn) return s;
    double deg = c->fn(c->ctx, (const double *const *)b->xy, b->loop_start, b->num_loops, &s);
    c->asked = 1, c->none = s == CM_OK && deg < 0;
    if (s == CM_OK && deg >= 0) *aim = fmin(*aim, deg);
    return s;
}

/* One round of grading: the edges grading_binds marks halved, within the
 * budget (at most start + max_added boundary vertices); *more receives
 * how many points were added. */
static cm_status grade_round(cm_cap_loop *loops, size_t num_loops, double *aim, ceiling_ask *ask, size_t start,
                             size_t max_added, size_t *more, cm_error *err)
{
    merged b;
    int made = merged_make(&b, loops, num_loops);
    size_t n = b.n, binding = 0;
    size_t *pieces = made == 0 ? malloc(2 * n * sizeof *pieces) : NULL;
    double *extent = made == 0 ? malloc(b.k * sizeof *extent) : NULL;
    cm_status s = pieces && extent ? CM_OK : cm_fail_status(err, CM_ERR_NO_MEMORY);
    *more = 0;
    if (s == CM_OK) extents(&b, extent);
    for (size_t j = 0; s == CM_OK && j < n; j++) binding += grading_binds(&b, extent, j, *aim);
    if (s == CM_OK && binding) s = lower_aim(ask, &b, aim);
    for (size_t j = 0; s == CM_OK && binding && !ask->none && j < n; j++) {
        pieces[j] = grading_binds(&b, extent, j, *aim) && n + *more < start + max_added ? 2 : 1;
        *more += pieces[j] - 1;
    }
    if (s == CM_OK && *more) s = split_loops(loops, &b, pieces, pieces + n, err);
    free(pieces), free(extent);
    merged_free(&b);
    return s;
}

cm_status cm_boundary_maps_split_caps(cm_cap_loop *loops, size_t num_loops, double aim, cm_cap_ceiling ceiling,
                                      void *ctx, size_t max_added, cm_progress *progress, int32_t ***tris_out,
                                      cm_error *err)
{
    size_t start = 0, more = 1;
    for (size_t l = 0; l < num_loops; l++) start += loops[l].map->n;
    size_t k = loops[0].map->k;
    cm_status s = CM_OK;
    int32_t **tris = NULL;
    ceiling_ask ask = {ceiling, ctx, 0, 0};
    if (tris_out) *tris_out = NULL;
    for (int round = 0; s == CM_OK && more && round < CM_GRADE_ROUNDS; round++)
        s = grade_round(loops, num_loops, &aim, &ask, start, max_added, &more, err);
    for (int round = 0; s == CM_OK && round < CAP_SPLIT_ROUNDS; round++) {
        merged b;
        int made = merged_make(&b, loops, num_loops);
        size_t n = b.n, binding = 0;
        double *bcap = made == 0 ? malloc(2 * n * sizeof *bcap) : NULL, *vcap = bcap ? bcap + n : NULL;
        size_t *pieces = made == 0 ? malloc(2 * n * sizeof *pieces) : NULL;
        int simple = 0;
        more = 0;
        cm_cap_tris_free(tris, k);
        tris = made == 0 ? tris_new(k, n - 2 + 2 * (num_loops - 1)) : NULL;
        s = bcap && pieces && tris ? caps_of(&b, progress, bcap, vcap, tris, &simple, err)
                                   : cm_fail_status(err, CM_ERR_NO_MEMORY);
        for (size_t j = 0; s == CM_OK && simple && j < n; j++) binding += binds(&b, bcap, vcap, j, aim);
        if (s == CM_OK && simple && binding) s = lower_aim(&ask, &b, &aim);
        if (ask.none) simple = 0; /* no ceiling: leave the boundary to the pipeline's check */
        for (size_t j = 0; s == CM_OK && simple && binding && j < n; j++) {
            pieces[j] = binds(&b, bcap, vcap, j, aim) && n + more < start + max_added ? 2 : 1;
            more += pieces[j] - 1;
        }
        if (s == CM_OK && more) s = split_loops(loops, &b, pieces, pieces + n, err);
        free(bcap), free(pieces);
        merged_free(&b);
        if (s == CM_OK && more == 0) { /* the triangulations are the final boundary's */
            if (simple && tris_out && num_loops == 1) *tris_out = tris, tris = NULL;
            break;
        }
    }
    cm_cap_tris_free(tris, k);
    return s;
}
