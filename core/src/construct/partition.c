/* The partition driver: a stack of sub-polygons ("items"), each cut until
 * it is triangulated.
 *
 * For an item:
 * (1) The Steiner-free dynamic program over its common diagonals
 *     (steinerfree.h) triangulates it when that is possible (always tried
 *     up to CM_DP_MAX_VERTICES, beyond when cheap), else cuts it along
 *     common diagonals into triangles and stuck faces; when two or more
 *     Steiner vertices would be needed, the same program with a fan point
 *     (a kernel point of the item or of a stuck face, in every geometry)
 *     may merge stuck faces into one fan around a single Steiner vertex.
 *     Large items with many common diagonals are first split along the
 *     most balanced one (the paper's tie-break for link distance 1).
 * (2) A stuck face (no common diagonal, so at least one Steiner vertex)
 *     that is star-shaped in every geometry is fanned from one Steiner
 *     vertex: the fewest possible.
 * (3) Otherwise it is cut along minimum-link paths (paper, section 2):
 *     vertex pairs ranked by the largest link distance over the
 *     geometries, then by balance, within the size guard (a piece may keep
 *     its parent's size once); the shorter paths are refined to the same
 *     number of links; the bends become Steiner vertices shared by both
 *     halves. Among the first valid cuts the one whose halves need the
 *     fewest Steiner vertices (estimated with the program) is taken.
 *     Faces above LINK_ALL_PAIRS vertices rank only the pairs with one
 *     end among a bounded number of evenly spread sources.
 * (4) If no cut is valid, the item goes to the overlay construction
 *     (stats fallback_count).
 *
 * Visibility tables: bit sets of common diagonals (diagset.h). The input's
 * serves every item cut from it along diagonals (a diagonal between two
 * vertices of such a sub-polygon is a diagonal of it iff it is one of the
 * input); an item with bends on its boundary gets a set of its own. A set
 * is built only when needed: an item large enough that the steps try the
 * fan first tries it before its set, and an item above the table limit
 * (CM_PARTITION_MAX_VERTICES) gets none: it is cut into pieces that shrink
 * geometrically (a common diagonal leaving at least an eighth on either
 * side, from the ends of its triangulations' most balanced diagonals and
 * spread vertices, else a minimum-link path leaving a quarter) until they
 * are small enough, so that tables and cuts cost O(n log n) in all where
 * one short cut per pass would cost O(n^2 / span). */
#include "construct/partition.h"
#include "base/buf.h"
#include "base/clock.h"
#include "construct/overlay.h"
#include "geom/angle.h"
#include "geom/polytri.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "geom/linkpath.h"
#include "geom/predicates.h"
#include "construct/steinerfree.h"
#include "geom/visibility.h"
#include "base/cycle.h"

/* Beyond this, the dynamic program's O(m (m + c)) work is skipped. */
#define DP_WORK_LIMIT 6e7
/* Stuck faces up to this size compare all vertex pairs by link distance;
 * larger ones only the pairs with one end among LINK_WORK / m sources
 * spread evenly around the face (at least LINK_MIN_SOURCES), which bounds
 * the distance table at k LINK_WORK entries and the window partitions
 * built at that many per geometry. */
#define LINK_ALL_PAIRS 600
#define LINK_WORK 360000L
#define LINK_MIN_SOURCES 48
/* The same for the faces of an input above the table limit: it has many
 * faces of a few hundred vertices (beside the long cuts between its
 * pieces), and all their pairs would cost more than the rest together;
 * their number and size grow faster than n (each long link of a balanced
 * cut runs past vertices that see only it), so a face above
 * LINK_ALL_PAIRS_LARGE gets a fixed number of sources, O(m) window
 * partitions in all. When that finds no cut, the budget of small inputs
 * is tried before the overlay. Such a face is first cut where it leaves a
 * quarter on either side (as a piece above the table limit is): its
 * fewest-link pairs among those sources are short, each peels off a few
 * dozen vertices, and a face of a few hundred peeled that way costs
 * O(m / peel) cuts of O(m) each, one bend apiece. */
#define LINK_ALL_PAIRS_LARGE 64
#define LINK_WORK_LARGE 1024L
#define LINK_MIN_SOURCES_LARGE 16
/* Vertex pairs tried, best first, before giving up on a stuck face; of
 * the valid cuts, this many are compared by what their halves need. */
#define LINK_MAX_TRIES 40
/* Sources of a cut that must leave a given share on either side: every
 * source pairs with a whole opposite arc, so a few spread ones suffice
 * (from a vertex of a random polygon the window partition is a chain of
 * pockets of nearly all its vertices, O(m) per level and source: more
 * sources find a pair a link shorter now and then, at their full cost).
 * Their link distances start at this cap (a piece above the table limit
 * rarely has a balanced pair within two links, and each larger cap builds
 * the partitions again from the source). */
#define BALANCED_SOURCES 4
#define BALANCED_FIRST_CAP 4
/* A piece above this many times the table limit takes half as many: its
 * window partitions are the deepest (its links the longest) and its
 * distances cost the most of all its cuts. */
#define BALANCED_FEWER_ABOVE 2
/* Cuts in a row that keep a face's size, when the overlay is the only
 * other way left (else one). */
#define MAX_REPEATS 4
#define LINK_EVALUATE 12

typedef struct vtable {
    cm_diagset common; /* a diagonal in every geometry */
    long base;         /* stack height under the item it was built for:
                          once the stack is back there, no item reads it */
} vtable;

typedef struct item {
    int32_t *gid;  /* global vertex ids, counter-clockwise */
    int32_t *tix;  /* indices into the table, NULL while table < 0 */
    long m, table; /* table -1: needs a table of its own */
    int repeat;    /* cuts in a row that kept the size of the polygon cut */
    int stuck;     /* known to have no common diagonal */
    int fanless;   /* known not to be star-shaped in some geometry */
} item;

typedef struct part {
    size_t k, n;
    long table_limit; /* items above this size get no table */
    double **xy;
    size_t nv, cap_v;
    int32_t *tri;
    size_t nt, cap_t;
    vtable *tab;
    long ntab, cap_tab;
    item *stack;
    long top, cap_stack;
    cm_partition_stats *st;
    cm_error *err;
    cm_progress *progress;
    const cm_on_edges *on;  /* NULL: every boundary vertex is an input vertex */
    cm_sf_work *sf;         /* the link cuts' small programs' arrays, made
                               on first use */
} part;

/* The input edge before input vertex e of geometry g: e - 1, or the last
 * of e's loop when e is the loop's first. */
static int32_t edge_before(const cm_on_edges *on, size_t g, int32_t e)
{
    const size_t *start = on->loop_start[g];
    size_t l = 0;
    while ((size_t)e >= start[l + 1]) l++;
    return (size_t)e == start[l] ? (int32_t)start[l + 1] - 1 : e - 1;
}

/* Do vertices a and b (global ids) lie on one input edge in some
 * geometry? Then segment ab runs along that edge: the rounding of the
 * points added on it may leave it a diagonal of the polygon, but only a
 * sliver could lie between it and the boundary. */
static int flat_pair(const part *p, int32_t a, int32_t b)
{
    if (!p->on || (size_t)a >= p->n || (size_t)b >= p->n) return 0;
    if (p->on->vertex) a = p->on->vertex[a], b = p->on->vertex[b];
    if (a < 0 || b < 0) return 0;
    for (size_t g = 0; g < p->k; g++) {
        int32_t ea = p->on->edge[g][a], eb = p->on->edge[g][b];
        int va = p->on->t[g][a] == 0, vb = p->on->t[g][b] == 0;
        /* an input vertex lies on the edges before and after it, a point inside an edge on it alone */
        if (ea == eb || (va && eb == edge_before(p->on, g, ea)) || (vb && ea == edge_before(p->on, g, eb))) return 1;
    }
    return 0;
}

static cm_status no_memory(part *p) { return cm_fail_status(p->err, CM_ERR_NO_MEMORY); }

/* ---- the mesh under construction ---------------------------------------- */

/* pos[g] = the new vertex in geometry g. Returns its id or -1. All
 * geometries share the capacity cap_v (in doubles). */
static long add_vertex(part *p, const double *const *pos)
{
    size_t cap = p->cap_v;
    for (size_t g = 0; g < p->k; g++) {
        cap = p->cap_v;
        if (cm_grow((void **)&p->xy[g], &cap, 2 * (p->nv + 1), sizeof(double)) != 0) return -1;
    }
    p->cap_v = cap;
    for (size_t g = 0; g < p->k; g++) p->xy[g][2 * p->nv] = pos[g][0], p->xy[g][2 * p->nv + 1] = pos[g][1];
    return (long)p->nv++;
}

static int mesh_add_triangle(part *p, int32_t a, int32_t b, int32_t c)
{
    if (cm_grow((void **)&p->tri, &p->cap_t, 3 * (p->nt + 1), sizeof *p->tri) != 0) return -1;
    p->tri[3 * p->nt] = a, p->tri[3 * p->nt + 1] = b, p->tri[3 * p->nt + 2] = c;
    p->nt++;
    return 0;
}

static void item_free(item *it)
{
    free(it->gid), free(it->tix);
    it->gid = it->tix = NULL;
}

/* Takes ownership of the item's arrays (freed on failure). */
static int push_item(part *p, item it)
{
    size_t cap = (size_t)p->cap_stack;
    if (cm_grow((void **)&p->stack, &cap, (size_t)p->top + 1, sizeof *p->stack) != 0) {
        item_free(&it);
        return -1;
    }
    p->cap_stack = (long)cap;
    p->stack[p->top++] = it;
    return 0;
}

/* A sub-item of it on the local vertices loc[0..m-1]. */
static int push_sub(part *p, const item *it, const long *loc, long m, int stuck)
{
    item c = {malloc((size_t)m * sizeof(int32_t)), it->tix ? malloc((size_t)m * sizeof(int32_t)) : NULL, m,
              it->table, m == it->m ? it->repeat : 0, stuck, 0};
    if (!c.gid || (it->tix && !c.tix)) {
        item_free(&c);
        return -1;
    }
    for (long i = 0; i < m; i++) c.gid[i] = it->gid[loc[i]];
    for (long i = 0; it->tix && i < m; i++) c.tix[i] = it->tix[loc[i]];
    return push_item(p, c);
}

/* k arrays of the item's 2m local coordinates. */
static double **local_xy(const part *p, const item *it)
{
    double **l = calloc(p->k, sizeof *l);
    if (!l) return NULL;
    for (size_t g = 0; g < p->k; g++) {
        l[g] = malloc(2 * (size_t)it->m * sizeof **l);
        if (!l[g]) {
            for (size_t h = 0; h < g; h++) free(l[h]);
            free(l);
            return NULL;
        }
        for (long i = 0; i < it->m; i++) {
            l[g][2 * i] = p->xy[g][2 * (size_t)it->gid[i]];
            l[g][2 * i + 1] = p->xy[g][2 * (size_t)it->gid[i] + 1];
        }
    }
    return l;
}

static void free_xy(double **l, size_t k)
{
    if (!l) return;
    for (size_t g = 0; g < k; g++) free(l[g]);
    free(l);
}

/* ---- common-diagonal tables ---------------------------------------------- */

/* Takes the set (cleared on failure). */
static long add_table(part *p, cm_diagset *common)
{
    size_t cap = (size_t)p->cap_tab;
    if (cm_grow((void **)&p->tab, &cap, (size_t)p->ntab + 1, sizeof *p->tab) != 0) {
        cm_diagset_clear(common);
        return -1;
    }
    p->cap_tab = (long)cap;
    p->tab[p->ntab] = (vtable){*common, p->top};
    return p->ntab++;
}

/* Visibility rows of each geometry of a polygon (the rows read the
 * triangulations, kept here when made here). */
typedef struct rowset {
    cm_visrows **rows;
    int32_t *tri;
    size_t k;
} rowset;

static void close_rows(rowset *r)
{
    for (size_t g = 0; r->rows && g < r->k; g++) cm_visrows_free(r->rows[g]);
    free(r->rows), free(r->tri);
    r->rows = NULL, r->tri = NULL;
}

/* The rows of a polygon of m vertices. tris[g] may be NULL: then geometry
 * g is triangulated here. 0, -1 memory, 1 failed (not simple); *r is
 * closed on failure. */
static int open_rows(const double *const *xy, const int32_t *const *tris, size_t k, long m, rowset *r)
{
    r->k = k, r->rows = calloc(k, sizeof *r->rows);
    r->tri = tris ? NULL : malloc(3 * (size_t)m * k * sizeof *r->tri);
    int32_t *idx = malloc((size_t)m * sizeof *idx);
    int status = r->rows && (tris || r->tri) && idx ? 0 : -1;
    for (long i = 0; status == 0 && i < m; i++) idx[i] = (int32_t)i;
    for (size_t g = 0; status == 0 && g < k; g++) {
        const int32_t *t = tris ? tris[g] : r->tri + 3 * (size_t)m * g;
        if (!tris) status = cm_polygon_ear_clip(xy[g], idx, m, r->tri + 3 * (size_t)m * g, NULL);
        if (status == 0 && !(r->rows[g] = cm_visrows_create(xy[g], m, t))) status = -1;
    }
    free(idx);
    if (status != 0) close_rows(r);
    return status;
}

/* all[j] &= (vertex j sees vertex i in every geometry of r), j = 0..m-1:
 * the caller sets all[] to the candidates, none below lo (every one from
 * lo on with from_lo: the first walk then needs no counts). Each geometry's
 * cones look only for the candidates still in. row: m bytes of scratch;
 * want: m + 1 counts of scratch. The geometries go in turn, *lead's
 * first: the result is the same in any order, but a walk after the first
 * enters only the pockets holding a vertex seen so far, so the geometry
 * that sees least is best first. With learn, *lead passes to a later
 * geometry that kept under half of what the lead saw. */
static void seen_by_all(const rowset *r, long i, long m, long lo, int from_lo, unsigned char *row,
                        unsigned char *all, int32_t *want, size_t *lead, int learn)
{
    memset(want, 0, ((size_t)lo + 1) * sizeof *want);
    long lead_seen = 0, least = LONG_MAX;
    size_t next = *lead;
    for (size_t t = 0; t < r->k; t++) {
        size_t g = t == 0 ? *lead : t <= *lead ? t - 1 : t; /* the lead, then the others in order */
        if (t == 0 && from_lo) {
            if (lo >= m) return;
            cm_visrows_row_from(r->rows[g], i, lo, row);
            memcpy(all + lo, row + lo, (size_t)(m - lo));
            continue;
        }
        for (long j = lo; j < m; j++) want[j + 1] = want[j] + all[j];
        if (want[m] == 0) return;
        if (t == 1) lead_seen = want[m];
        cm_visrows_row_wanted(r->rows[g], i, want, row);
        long seen = 0;
        if (learn && t > 0)
            for (long j = lo; j < m; j++) all[j] &= row[j], seen += all[j];
        else
            for (long j = lo; j < m; j++) all[j] &= row[j];
        if (learn && t > 0 && seen < least) least = seen, next = g;
    }
    if (learn && least < lead_seen && 2 * least < lead_seen) *lead = next; /* least: LONG_MAX when none followed */
}

/* The table's rows that decide which geometry's walk comes first. */
#define LEAD_EVERY 4

/* The common diagonals: pairs that see each other in every geometry, one
 * row of each geometry's visibility at a time (O(k m) memory beside the
 * set). tris as for open_rows. 0, -1 memory, 1 failed (not simple);
 * *common is set up here, cleared on failure. */
static int common_table(const double *const *xy, const int32_t *const *tris, size_t k, long m,
                        const part *p, const int32_t *gid, cm_diagset *common)
{
    rowset r = {NULL, NULL, k};
    unsigned char *row = malloc(2 * (size_t)m);
    int32_t *want = malloc(((size_t)m + 1) * sizeof *want);
    int status = open_rows(xy, tris, k, m, &r);
    if (status != 0) goto done;
    status = -1;
    if (!row || !want || cm_diagset_init(common, m) != 0) goto done;
    unsigned char *all = row + m;
    size_t lead = 0;
    const part *flats = p && p->on ? p : NULL; /* only points on edges make flat pairs */
    for (long i = 0; i < m; i++) {
        memset(all, 0, (size_t)i + 1);
        memset(all + i + 1, 1, (size_t)(m - i - 1));
        seen_by_all(&r, i, m, i + 1, 1, row, all, want, &lead, i % LEAD_EVERY == 0);
        for (long j = i + 1; j < m; j++)
            if (all[j] && !(flats && flat_pair(flats, gid[i], gid[j]))) cm_diagset_add(common, i, j);
    }
    status = 0;
done:
    if (status != 0) cm_diagset_clear(common);
    close_rows(&r);
    free(row), free(want);
    return status;
}

static cm_status table_for_item(part *p, item *it)
{
    double t0 = cm_seconds_now();
    long m = it->m;
    double **l = local_xy(p, it);
    cm_diagset common = {0, 0, NULL};
    it->tix = malloc((size_t)m * sizeof *it->tix);
    int s = l && it->tix ? common_table((const double *const *)l, NULL, p->k, m, p, it->gid, &common) : -1;
    free_xy(l, p->k);
    if (s == 0) it->table = add_table(p, &common);
    if (s != 0 || it->table < 0) {
        if (s > 0) return cm_fail(p->err, CM_ERR_INTERNAL, "partition: a sub-polygon is not simple");
        return no_memory(p);
    }
    for (long i = 0; i < m; i++) it->tix[i] = (int32_t)i;
    p->st->seconds_visibility += cm_seconds_now() - t0;
    return CM_OK;
}

/* The item's common diagonals in local indices: a view of its table. */
static cm_diagview local_common(const part *p, const item *it)
{
    return (cm_diagview){&p->tab[it->table].common, it->tix};
}

/* ---- steps ---------------------------------------------------------------- */

static int add_item_triangle(part *p, const item *it, long a, long b, long c)
{
    return mesh_add_triangle(p, it->gid[a], it->gid[b], it->gid[c]);
}

/* A Steiner vertex at pos[g] and the fan from it over the item's local
 * face f[0..n-1] (counter-clockwise). Returns 0 or -1. */
static int emit_fan(part *p, const item *it, const int32_t *f, long n, const double *const *pos)
{
    long x = add_vertex(p, pos);
    if (x < 0) return -1;
    for (long s = 0; s < n; s++)
        if (mesh_add_triangle(p, it->gid[f[s]], it->gid[f[(s + 1) % n]], (int32_t)x) != 0) return -1;
    p->st->fans++;
    return 0;
}

/* A point inside the kernel of the sub-polygon f[0..n-1] of l, in every
 * geometry (pos: k rows of 2 doubles). Returns 1, 0 (not star-shaped in
 * some geometry) or -1. */
static int kernel_points(size_t k, double **l, const int32_t *f, long n, double *pos)
{
    double *xy = malloc(2 * (size_t)n * sizeof *xy);
    if (!xy) return -1;
    int found = 1;
    for (size_t g = 0; g < k && found == 1; g++) {
        for (long i = 0; i < n; i++) xy[2 * i] = l[g][2 * f[i]], xy[2 * i + 1] = l[g][2 * f[i] + 1];
        found = cm_kernel_point(xy, n, pos + 2 * g);
    }
    free(xy);
    return found;
}

/* Fan points worth a try: the kernel of the whole item (enough alone: one
 * Steiner vertex for everything), else those of its largest stuck faces.
 * cand gets up to max candidates of 2k doubles; returns their number or
 * -1. */
static int fan_candidates(size_t k, double **l, long m, const cm_sf_plan *plan, double *cand, int max)
{
    long *order = malloc((size_t)(plan->nf + 1) * sizeof *order);
    int32_t *all = malloc((size_t)m * sizeof *all);
    int count = 0, r = order && all ? 0 : -1;
    for (long i = 0; r == 0 && i < m; i++) all[i] = (int32_t)i;
    if (r == 0) r = kernel_points(k, l, all, m, cand);
    if (r > 0) max = count = 1;
    for (long f = 0; r >= 0 && f < plan->nf; f++) order[f] = f;
    for (long a = 0; r >= 0 && a < plan->nf; a++) /* largest faces first */
        for (long b = a + 1; b < plan->nf; b++) {
            long na = plan->face_start[order[a] + 1] - plan->face_start[order[a]];
            long nb = plan->face_start[order[b] + 1] - plan->face_start[order[b]];
            if (nb > na) {
                long t = order[a];
                order[a] = order[b], order[b] = t;
            }
        }
    for (long i = 0; r >= 0 && i < plan->nf && count < max; i++) {
        long f = order[i], n = plan->face_start[f + 1] - plan->face_start[f];
        r = kernel_points(k, l, plan->face + plan->face_start[f], n, cand + 2 * k * (size_t)count);
        if (r > 0) count++;
    }
    free(order), free(all);
    return r < 0 ? -1 : count;
}

/* Applies a plan: triangles out, fan faces fanned from their points
 * (fans: 2k doubles per point), stuck faces back on the stack. */
static int apply_plan(part *p, item *it, const cm_sf_plan *plan, const double *fans)
{
    int bad = 0;
    for (long t = 0; t < plan->nt && !bad; t++)
        bad = add_item_triangle(p, it, plan->tri[3 * t], plan->tri[3 * t + 1], plan->tri[3 * t + 2]);
    long *loc = malloc((size_t)it->m * sizeof *loc);
    const double **pos = calloc(p->k, sizeof *pos);
    bad |= !loc || !pos;
    for (long f = 0; f < plan->nf && !bad; f++) {
        long m = plan->face_start[f + 1] - plan->face_start[f];
        const int32_t *face = plan->face + plan->face_start[f];
        if (plan->face_fan[f] >= 0) {
            for (size_t g = 0; g < p->k; g++) pos[g] = fans + 2 * (p->k * (size_t)plan->face_fan[f] + g);
            bad = emit_fan(p, it, face, m, pos);
            continue;
        }
        for (long i = 0; i < m; i++) loc[i] = face[i];
        bad = push_sub(p, it, loc, m, 1);
    }
    free(loc), free(pos);
    return bad ? -1 : 0;
}

/* The Steiner-free program; when the item needs two or more Steiner
 * vertices, the same program with fan points (kernel points of the item
 * and of its stuck faces) may merge stuck faces into fans, one Steiner
 * vertex each. */
static cm_status plan_item(part *p, item *it, const cm_diagview *common)
{
    enum { MAX_FANS = 8 };
    double t0 = cm_seconds_now();
    size_t k = p->k;
    double **l = local_xy(p, it), *cand = malloc(MAX_FANS * 2 * k * sizeof *cand);
    cm_sf_plan plan = {0}, other;
    cm_sf_memo *memo = NULL;
    int fanned = 0, bad = !l || !cand;
    if (!bad) bad = cm_steinerfree_plan_memo(it->m, common, (const double *const *)l, k, &plan, &memo) != 0;
    int count = bad || plan.cost < 2 ? 0 : fan_candidates(k, l, it->m, &plan, cand, MAX_FANS);
    bad |= count < 0;
    if (!bad && count > 0) {
        bad = cm_steinerfree_plan_fans(memo, cand, (size_t)count, &other) != 0;
        if (!bad && other.cost < plan.cost) {
            cm_sf_plan_clear(&plan);
            plan = other, fanned = 1;
        } else if (!bad) {
            cm_sf_plan_clear(&other);
        }
    }
    if (!bad) {
        p->st->dp_runs++;
        p->st->steinerfree += plan.cost == 0;
        bad = apply_plan(p, it, &plan, fanned ? cand : NULL) != 0;
    }
    cm_sf_plan_clear(&plan); /* also when a later step ran out of memory */
    cm_sf_memo_free(memo);
    free_xy(l, k);
    free(cand);
    p->st->seconds_dp += cm_seconds_now() - t0;
    return bad ? no_memory(p) : CM_OK;
}

/* A stuck face that is star-shaped in every geometry: one Steiner vertex,
 * the fewest possible. Returns 1 done, 0 not star-shaped, -1 memory. */
static int fan_face(part *p, item *it)
{
    size_t k = p->k;
    double **l = local_xy(p, it), *pos = malloc(2 * k * sizeof *pos);
    const double **rows = calloc(k, sizeof *rows);
    int32_t *f = malloc((size_t)it->m * sizeof *f);
    int r = l && pos && rows && f ? 0 : -1;
    for (long i = 0; r == 0 && i < it->m; i++) f[i] = (int32_t)i;
    if (r == 0) r = kernel_points(k, l, f, it->m, pos);
    for (size_t g = 0; r == 1 && g < k; g++) rows[g] = pos + 2 * g;
    if (r == 1 && emit_fan(p, it, f, it->m, rows) != 0) r = -1;
    free_xy(l, k);
    free(pos), free(rows), free(f);
    return r;
}

/* fan_face once per item. */
static int try_fan(part *p, item *it)
{
    int r = it->fanless ? 0 : fan_face(p, it);
    it->fanless = r == 0;
    return r;
}

/* Cuts the item along its diagonal (i, j): both halves onto the stack,
 * reading the item's table (or, without one, needing their own). 0 or
 * -1. */
static int split_diagonal(part *p, const item *it, long i, long j)
{
    long m = it->m, *loc = malloc((size_t)(m + 1) * sizeof *loc), c = 0;
    if (!loc) return -1;
    for (long x = i;; x = (x + 1) % m) { loc[c++] = x; if (x == j) break; }
    int bad = push_sub(p, it, loc, c, 0);
    c = 0;
    for (long x = j;; x = (x + 1) % m) { loc[c++] = x; if (x == i) break; }
    bad = bad || push_sub(p, it, loc, c, 0);
    free(loc);
    return bad ? -1 : 0;
}

/* Cuts along the most balanced common diagonal (the paper's tie-break).
 * Returns 1 if cut, 0 if there is none, -1 out of memory. */
static int greedy_split(part *p, item *it, const cm_diagview *common)
{
    long m = it->m;
    cm_diagrows rows;
    int32_t *row = m >= CM_DIAGROWS_FROM ? malloc((size_t)m * sizeof *row) : NULL;
    if (row && cm_diagrows_open(&rows, common, m) == 0) {
        /* the pair the scan below meets first: the largest span (the
         * shorter way round, at least 2), then the smallest start i */
        long best_span = 1, best_i = -1;
        for (long a = 0; a < m; a++) {
            long c = cm_diagrows_row(&rows, a, row);
            for (long t = 0; t < c; t++) {
                long b = row[t], d = (b - a + m) % m, span = d < m - d ? d : m - d;
                long i = d < m - d ? a : d > m - d ? b : (a < b ? a : b);
                if (span > best_span || (span == best_span && span >= 2 && i < best_i))
                    best_span = span, best_i = i;
            }
        }
        cm_diagrows_close(&rows);
        free(row);
        if (best_i < 0) return 0;
        p->st->greedy_splits++;
        return split_diagonal(p, it, best_i, (best_i + best_span) % m) == 0 ? 1 : -1;
    }
    free(row); /* out of memory: pair by pair */
    for (long span = m / 2; span >= 2; span--) {
        for (long i = 0; i < m; i++) {
            long j = (i + span) % m;
            if (2 * span == m && i >= span) break;
            if (!cm_diagview_has(common, i, j)) continue;
            p->st->greedy_splits++;
            return split_diagonal(p, it, i, j) == 0 ? 1 : -1;
        }
    }
    return 0;
}

/* ---- items too large for a table ------------------------------------------ */

/* Sources of a sampled split; when none of them has a common diagonal,
 * up to SAMPLE_MORE further ones are looked at (a piece with common
 * diagonals that few is often stuck, for the overlay, anyway). */
#define SAMPLE_SOURCES 64
#define SAMPLE_MORE 1024

/* The most balanced common diagonal at vertex i better than *best (its
 * balance, the shorter side's span): updates *best and *bj. row, all: m
 * bytes each; want: m + 1 counts. */
static void best_at(const part *p, const item *it, const rowset *r, long i, unsigned char *row, unsigned char *all,
                    int32_t *want, long *best, long *bj)
{
    long m = it->m;
    for (long j = 0; j < m; j++) {
        long span = (j - i + m) % m;
        all[j] = (span < m - span ? span : m - span) > *best;
    }
    size_t lead = 0;
    seen_by_all(r, i, m, 0, 0, row, all, want, &lead, 0);
    *bj = -1;
    for (long j = 0; j < m; j++) {
        long span = (j - i + m) % m, balance = span < m - span ? span : m - span;
        if (all[j] && balance > *best && !flat_pair(p, it->gid[i], it->gid[j])) *best = balance, *bj = j;
    }
}

/* Ends of the most balanced diagonals of the geometries' triangulations
 * tried first: some diagonal of a triangulation leaves at least a third
 * of the vertices on either side, and when it is common (a polygon against
 * a convex one) it is found here, where spread sources rarely meet it. */
#define TRI_CANDIDATES 16

/* Up to max distinct local vertices that end the most balanced diagonals
 * of r's triangulations, most balanced first, into out; their number. */
static long balanced_ends(const rowset *r, long m, long *out, long max)
{
    long count = 0, *bal = malloc((size_t)max * sizeof *bal);
    if (!bal) return 0;
    for (size_t g = 0; g < r->k; g++)
        for (long e = 0; e < 3 * (m - 2); e++) {
            long a = r->tri[3 * (size_t)m * g + (size_t)e];
            long b = r->tri[3 * (size_t)m * g + (size_t)(e % 3 == 2 ? e - 2 : e + 1)];
            long d = (b - a + m) % m, balance = d < m - d ? d : m - d;
            if (balance < 2) continue;
            long end = d < m - d ? a : b, at = count; /* one end per diagonal: the start of its shorter side */
            for (long q = 0; q < count && at == count; q++)
                if (out[q] == end) at = bal[q] >= balance ? -1 : q;
            if (at < 0) continue;
            if (at == count) {
                if (count == max && bal[count - 1] >= balance) continue;
                at = count < max ? count++ : count - 1;
            }
            for (; at > 0 && bal[at - 1] < balance; at--) out[at] = out[at - 1], bal[at] = bal[at - 1];
            out[at] = end, bal[at] = balance;
        }
    free(bal);
    return count;
}

/* The most balanced common diagonal of an item without a table, at the
 * ends of its triangulations' most balanced diagonals and at
 * SAMPLE_SOURCES evenly spread vertices (one visibility row per vertex
 * and geometry, O(k m) each), or when none of them has one, the first one
 * from SAMPLE_MORE others: (*bi, *bj), *balance the span of its shorter
 * side. Returns 1 found, 0 none seen, -1 out of memory, 2 not simple. */
static int sampled_diagonal(part *p, item *it, long *bi, long *bj, long *balance)
{
    double t0 = cm_seconds_now();
    long m = it->m, best = 1, ends[TRI_CANDIDATES];
    size_t k = p->k;
    double **l = local_xy(p, it);
    unsigned char *row = malloc(2 * (size_t)m);
    int32_t *want = malloc(((size_t)m + 1) * sizeof *want);
    rowset r = {NULL, NULL, k};
    int s = l && row && want ? open_rows((const double *const *)l, NULL, k, m, &r) : -1;
    long nends = s == 0 ? balanced_ends(&r, m, ends, TRI_CANDIDATES) : 0;
    *bi = *bj = -1;
    for (long q = 0; s == 0 && q < nends && 2 * best < m; q++) {
        long j;
        best_at(p, it, &r, ends[q], row, row + m, want, &best, &j);
        if (j >= 0) *bi = ends[q], *bj = j;
    }
    for (long q = 0; s == 0 && q < SAMPLE_SOURCES && 2 * best < m; q++) {
        long i = (long)((double)q * (double)m / SAMPLE_SOURCES), j;
        best_at(p, it, &r, i, row, row + m, want, &best, &j);
        if (j >= 0) *bi = i, *bj = j;
    }
    long more = m < SAMPLE_MORE ? m : SAMPLE_MORE;
    for (long q = 0; s == 0 && *bi < 0 && q < more; q++) {
        long i = (long)((double)q * (double)m / (double)more + 0.5) % m, j;
        best_at(p, it, &r, i, row, row + m, want, &best, &j);
        if (j >= 0) *bi = i, *bj = j;
    }
    close_rows(&r);
    free_xy(l, k);
    free(row), free(want);
    p->st->seconds_visibility += cm_seconds_now() - t0;
    *balance = best;
    if (s != 0) return s > 0 ? 2 : -1;
    return *bi >= 0;
}

/* ---- cutting a stuck face along minimum-link paths ------------------------ */

typedef struct { long u, v, row; int links, balance, sum; } pair; /* row: of dist */

static int compare_pairs(const void *pa, const void *pb)
{
    const pair *a = pa, *b = pb;
    if (a->links != b->links) return a->links < b->links ? -1 : 1;
    if (a->balance != b->balance) return a->balance > b->balance ? -1 : 1;
    if (a->sum != b->sum) return a->sum < b->sum ? -1 : 1;
    if (a->u != b->u) return a->u < b->u ? -1 : 1;
    return (a->v > b->v) - (a->v < b->v);
}

typedef struct {
    part *p;
    item *it;
    double **l;          /* local coordinates per geometry */
    cm_linkpart **lp;    /* per geometry */
    long *src, nsrc;     /* the sources: local vertices, ascending */
    long *row_of;        /* per vertex: its source row, -1 if not one */
    int *dist;           /* k * nsrc * m: from each source to every vertex */
    cm_diagset *own;     /* k: the face's diagonals in each geometry, for
                            the halves of its cuts; NULL until needed */
    int own_state;       /* 0 not yet, 1 done, -1 not available */
    long min_balance;    /* pairs whose shorter side spans less are not cut */
    int repeats;         /* a half may keep the face's size if the face's
                            repeat count is at most this */
} face_ctx;

static int *dist_row(const face_ctx *f, size_t g, long row)
{
    return f->dist + ((size_t)g * (size_t)f->nsrc + (size_t)row) * (size_t)f->it->m;
}

/* The pairs (u, v), u < v, with a source among them that the size guard
 * allows, best first; *count of them. */
static pair *rank_pairs(const face_ctx *f, long *count)
{
    long m = f->it->m;
    size_t k = f->p->k;
    pair *pairs = malloc((size_t)f->nsrc * (size_t)m * sizeof *pairs + sizeof *pairs);
    if (!pairs) return NULL;
    *count = 0;
    for (long r = 0; r < f->nsrc; r++)
        for (long w = 0; w < m; w++) {
            long s = f->src[r], u = s < w ? s : w, v = s < w ? w : s;
            if (v - u < 2 || (u == 0 && v == m - 1)) continue;
            if (f->row_of[w] >= 0 && f->row_of[w] < r) continue; /* counted from w */
            int links = 0, sum = 0;
            for (size_t g = 0; g < k && links >= 0; g++) {
                int d = dist_row(f, g, r)[w];
                if (d < 1) links = -1;
                else links = d > links ? d : links, sum += d;
            }
            if (links < 0 || (links == 1 && flat_pair(f->p, f->it->gid[u], f->it->gid[v]))) continue;
            long s1 = (v - u + 1) + links - 1, s2 = (m - (v - u) + 1) + links - 1;
            if (s1 > m || s2 > m || ((s1 == m || s2 == m) && f->it->repeat > f->repeats)) continue;
            long span = v - u < m - (v - u) ? v - u : m - (v - u);
            if (span < f->min_balance) continue;
            pairs[(*count)++] = (pair){u, v, r, links, (int)span, sum};
        }
    qsort(pairs, (size_t)*count, sizeof *pairs, compare_pairs);
    return pairs;
}

/* Inserts bends into the path u, b[0..nb-1], v (polygon xy, m vertices)
 * until it has `want` bends: a point near the middle of the longest link
 * that accepts one, pushed sideways by `offset` times the link's length
 * (less if that is not valid), checked exactly. NULL if none fits. */
static double *refine_path(const double *xy, long m, long u, long v, const double *b, long nb,
                           long want, double offset)
{
    static const double at[] = {0.5, 0.35, 0.65};
    const double side[] = {offset, 0.5 * offset, 0.2 * offset, 0.0};
    double *pts = malloc(2 * (size_t)(want + 1) * sizeof *pts);
    double *cand = malloc(2 * (size_t)(want + 1) * sizeof *cand);
    long *order = malloc((size_t)(want + 2) * sizeof *order);
    int tame = cm_coords_tame(xy, 2 * m); /* once for all the candidates */
    if (!pts || !cand || !order) goto fail;
    if (nb > 0) memcpy(pts, b, 2 * (size_t)nb * sizeof *pts);
    while (nb < want) {
        /* links by decreasing length */
        for (long i = 0; i <= nb; i++) order[i] = i;
        for (long i = 0; i <= nb; i++)
            for (long j = i + 1; j <= nb; j++) {
                const double *a1 = order[i] == 0 ? xy + 2 * u : pts + 2 * (order[i] - 1);
                const double *c1 = order[i] == nb ? xy + 2 * v : pts + 2 * order[i];
                const double *a2 = order[j] == 0 ? xy + 2 * u : pts + 2 * (order[j] - 1);
                const double *c2 = order[j] == nb ? xy + 2 * v : pts + 2 * order[j];
                double l1 = hypot(c1[0] - a1[0], c1[1] - a1[1]), l2 = hypot(c2[0] - a2[0], c2[1] - a2[1]);
                if (l2 > l1) {
                    long t = order[i];
                    order[i] = order[j], order[j] = t;
                }
            }
        int done = 0;
        for (long oi = 0; oi <= nb && !done; oi++) {
            long best = order[oi];
            const double *a = best == 0 ? xy + 2 * u : pts + 2 * (best - 1);
            const double *c = best == nb ? xy + 2 * v : pts + 2 * best;
            double dx = c[0] - a[0], dy = c[1] - a[1];
            for (size_t si = 0; si < 4 && !done; si++)
                for (size_t fi = 0; fi < 3 && !done; fi++) {
                    double q[2] = {a[0] + at[fi] * dx - side[si] * dy, a[1] + at[fi] * dy + side[si] * dx};
                    memcpy(cand, pts, 2 * (size_t)best * sizeof *cand);
                    cand[2 * best] = q[0], cand[2 * best + 1] = q[1];
                    memcpy(cand + 2 * (best + 1), pts + 2 * best, 2 * (size_t)(nb - best) * sizeof *cand);
                    if (cm_path_valid_in(xy, m, tame, u, v, cand, nb + 1)) {
                        double *t = pts;
                        pts = cand, cand = t;
                        done = 1;
                    }
                }
        }
        if (!done) goto fail;
        nb++;
    }
    free(cand), free(order);
    return pts;
fail:
    free(pts), free(cand), free(order);
    return NULL;
}

/* ---- choosing the refinement: what the halves' Steiner-free program says */

/* Faces up to this size try several refinements of the shorter paths. */
#define REFINE_SEARCH_MAX 48
static const double offsets[] = {0.0, 0.12, -0.12, 0.3, -0.3};
#define NOFFSETS (sizeof offsets / sizeof offsets[0])

/* Estimated Steiner vertices of a polygon given by k coordinate arrays
 * and its common diagonals: its Steiner-free plan, each stuck face counted
 * 1 if it is star-shaped in every geometry (a fan) and (vertices - 3)
 * otherwise, or 1 if the whole polygon is star-shaped. Exact below limit;
 * a result of limit or more only says the estimate is at least that (the
 * faces left are not looked at). -1 out of memory. */
/* Does some polygon edge lack a triangle on common diagonals and edges?
 * Then no triangulation without Steiner vertices exists (each edge lies in
 * one triangle of any triangulation). */
static int edge_without_triangle(long m, const cm_diagset *common)
{
    for (long a = 0; a < m; a++) {
        long b = (a + 1) % m, before = (a + m - 1) % m, after = (b + 1) % m;
        if (cm_diagset_has(common, b, before) || cm_diagset_has(common, a, after)) continue;
        const uint64_t *ra = common->bits + (size_t)a * common->stride, *rb = common->bits + (size_t)b * common->stride;
        uint64_t any = 0;
        for (size_t w = 0; w < common->stride && !any; w++) any = ra[w] & rb[w];
        if (!any) return 1;
    }
    return 0;
}

static long polygon_cost(part *p, long m, double **xy, const cm_diagset *common, long limit, double *pos,
                         int32_t *all)
{
    size_t k = p->k;
    if (limit <= 1 && m > 3 && edge_without_triangle(m, common)) return 1; /* at least 1 */
    cm_diagview view = {common, NULL};
    long cost = -1;
    cm_sf_plan plan;
    if (!p->sf) p->sf = cm_sf_work_new();
    if (p->sf && cm_steinerfree_plan_in(p->sf, m, &view, (const double *const *)xy, k, &plan) == 0) {
        cost = 0;
        int whole = 0; /* the one face is the polygon, in its order: its test is the polygon's */
        for (long f = 0; f < plan.nf && cost >= 0 && cost < limit; f++) {
            long n = plan.face_start[f + 1] - plan.face_start[f];
            const int32_t *face = plan.face + plan.face_start[f];
            int star = kernel_points(k, xy, face, n, pos);
            cost = star < 0 ? -1 : cost + (star ? 1 : n - 3);
            whole = plan.nf == 1 && n == m;
            for (long i = 0; whole && i < m; i++) whole = face[i] == i;
        }
        for (long i = 0; i < m; i++) all[i] = (int32_t)i;
        if (cost > 1 && !whole) { /* the faces left only add: the whole polygon's fan decides */
            int star = kernel_points(k, xy, all, m, pos);
            cost = star < 0 ? -1 : star ? 1 : cost;
        }
    }
    return cost;
}

/* What the search over a cut's choices has computed: each half's
 * diagonals in each geometry for each choice of that geometry's bends
 * (they depend on nothing else), and the cost of each combination. */
typedef struct {
    long per_g;           /* choices per geometry slot (the most of any) */
    cm_diagset *diag;     /* [(half * k + g) * per_g + choice] */
    signed char *state;   /* same index: 0 not yet, 1 done, 2 not simple */
    long *cost;           /* [choice_0 + per_g * (choice_1 + ...)], -2 unknown */
    /* for each combination's halves (at most `most` vertices each), one
     * block for all: their coordinates in every geometry, their common
     * diagonals' bits, and polygon_cost's kernel point and whole face */
    long most;
    double **xy;
    uint64_t *common_bits;
    double *pos;
    int32_t *all;
} cut_memo;

/* The face's own diagonals in every geometry (once per face). 1, 0 not
 * available (then the halves get tables of their own), -1 memory. */
static int face_diagonals(face_ctx *f)
{
    size_t k = f->p->k;
    if (f->own_state == 0) {
        f->own = calloc(k, sizeof *f->own);
        if (!f->own) return -1;
        f->own_state = 1;
        for (size_t g = 0; g < k && f->own_state == 1; g++) {
            int s = common_table((const double *const *)&f->l[g], NULL, 1, f->it->m, NULL, NULL, &f->own[g]);
            if (s < 0) return -1;
            if (s > 0) f->own_state = -1;
        }
    }
    return f->own_state == 1;
}

/* The diagonals of a half h[0..size-1] of the face in geometry g: the
 * face's chain from vertex `from` (h[0]) to h[nc - 1], then the bends
 * back to h[0] (the path P). The half lies inside the face, so two chain
 * vertices other than the path's ends span a diagonal of the half iff
 * they span one of the face and their segment misses P (both ends lie off
 * P, so only the open segment can touch it). Every other pair is tested
 * on the half directly. Exact, as the tables are. 0 or -1 memory. */
static int half_diagonals(const face_ctx *f, size_t g, long from, long nc, const double *h, long size,
                          cm_diagset *set)
{
    long m = f->it->m;
    signed char *turn = malloc((size_t)size);
    if (!turn || cm_diagset_init(set, size) != 0) {
        free(turn);
        return -1;
    }
    int tame = cm_vertex_turns(h, size, turn); /* each corner's turn once, not per pair */
    for (long i = 0; i < size; i++)
        for (long j = i + 2; j < size; j++) {
            if (i == 0 && j == size - 1) continue; /* an edge */
            int inner = i >= 1 && j <= nc - 2, chain = j <= nc - 1, seen;
            /* chain vertices that do not see each other in the face do
             * not in the half either */
            /* chain vertices are from + i < from + nc <= from + m */
            seen = !chain || cm_diagset_has(&f->own[g], from + i < m ? from + i : from + i - m,
                                            from + j < m ? from + j : from + j - m);
            if (seen && inner) {
                for (long e = nc - 1; seen && e < size; e++) /* the path's links */
                    seen = (tame ? cm_segments_intersect_tame : cm_segments_intersect)(
                               h + 2 * i, h + 2 * j, h + 2 * e, h + 2 * cm_cycle_next(e, size)) == 0;
            } else if (seen && chain && !(i == 0 && j == nc - 1)) {
                /* one end is an end of P: a diagonal of the face, so only
                 * P's links (edges nc - 1 .. size - 1) and that end's new
                 * corner need a test */
                seen = cm_segment_inside_edges(h, size, turn, tame, i, j, nc - 1, size - nc + 1);
            } else if (seen) {
                seen = cm_segment_inside_edges(h, size, turn, tame, i, j, 0, size);
            }
            if (seen) cm_diagset_add(set, i, j);
        }
    free(turn);
    return 0;
}

/* The half's common diagonals (AND over the geometries of the memo's
 * sets, computed when missing from xy: derived from the face's when the
 * cut has bends, else a table of its own). 0, -1 memory, 1 not simple. */
static int half_common(face_ctx *f, cut_memo *memo, const pair *pr, int half, const long *pick, long m,
                       double **xy, cm_diagset *common)
{
    size_t k = f->p->k;
    long from = half == 0 ? pr->u : pr->v, nc = m - (pr->links - 1);
    int derive = pr->links >= 2 ? face_diagonals(f) : 0;
    if (derive < 0) return -1;
    for (size_t g = 0; g < k; g++) {
        size_t at = ((size_t)half * k + g) * (size_t)memo->per_g + (size_t)pick[g];
        if (memo->state[at] == 0) {
            int s = derive ? half_diagonals(f, g, from, nc, xy[g], m, &memo->diag[at])
                           : common_table((const double *const *)&xy[g], NULL, 1, m, NULL, NULL, &memo->diag[at]);
            if (s < 0) return -1;
            memo->state[at] = s == 0 ? 1 : 2;
        }
        if (memo->state[at] == 2) return 1;
    }
    /* every word is written below: the memo's block needs no zeroing */
    common->n = m, common->stride = ((size_t)m + 63) / 64, common->bits = memo->common_bits;
    size_t words = common->stride * (size_t)m;
    for (size_t w = 0; w < words; w++) {
        uint64_t bits = ~(uint64_t)0;
        for (size_t g = 0; g < k; g++) bits &= memo->diag[((size_t)half * k + g) * (size_t)memo->per_g + (size_t)pick[g]].bits[w];
        common->bits[w] = bits;
    }
    return 0;
}

/* Sum of the halves' stuck costs for the cut u -> bends -> v, bends[g]
 * being choice pick[g] of geometry g: exact below limit, else a bound
 * from below of at least limit (what the search needs: it only takes a
 * cost below its best so far, and that best only falls, so a bound kept
 * in the memo stays at or above every later limit). */
static long cut_cost(face_ctx *f, const pair *pr, double **bends, const long *pick, cut_memo *memo, long limit)
{
    size_t k = f->p->k;
    long m = f->it->m, nb = pr->links - 1, total = 0, key = 0;
    for (size_t g = k; g-- > 0;) key = key * memo->per_g + pick[g];
    if (memo->cost[key] != -2) return memo->cost[key];
    double **xy = memo->xy;
    for (int half = 0; half < 2 && total >= 0 && total < limit; half++) {
        long from = half == 0 ? pr->u : pr->v, to = half == 0 ? pr->v : pr->u;
        long size = (to - from + m) % m + 1 + nb;
        for (size_t g = 0; g < k; g++) {
            long n = 0;
            for (long x = from;; x = cm_cycle_next(x, m)) {
                xy[g][2 * n] = f->l[g][2 * x], xy[g][2 * n + 1] = f->l[g][2 * x + 1], n++;
                if (x == to) break;
            }
            for (long j = 0; j < nb; j++) {
                long b = half == 0 ? nb - 1 - j : j;
                xy[g][2 * n] = bends[g][2 * b], xy[g][2 * n + 1] = bends[g][2 * b + 1], n++;
            }
        }
        long c = 0;
        if (size > 3) {
            cm_diagset common = {0, 0, NULL};
            int s = half_common(f, memo, pr, half, pick, size, xy, &common);
            c = s < 0 ? -1 : s > 0 ? LONG_MAX : polygon_cost(f->p, size, xy, &common, limit - total, memo->pos, memo->all);
        }
        total = c < 0 ? -1 : c == LONG_MAX ? LONG_MAX : total + c;
    }
    if (total >= 0) memo->cost[key] = total;
    return total;
}

/* Distance from p along the unit direction dir to the polygon boundary
 * (doubles: it only places candidates). */
static double free_run(const double *xy, long m, const double p[2], const double dir[2])
{
    double best = INFINITY;
    for (long i = 0; i < m; i++) {
        const double *a = xy + 2 * i, *b = xy + 2 * cm_cycle_next(i, m);
        double ex = b[0] - a[0], ey = b[1] - a[1], den = dir[0] * ey - dir[1] * ex;
        if (den == 0) continue;
        double t = ((a[0] - p[0]) * ey - (a[1] - p[1]) * ex) / den;
        double s = ((a[0] - p[0]) * dir[1] - (a[1] - p[1]) * dir[0]) / den;
        if (t > 1e-12 && s >= 0 && s <= 1 && t < best) best = t;
    }
    return best;
}

/* Single bends for u -> v other than the link path's: points seen from
 * both, spread over u's corner. out: up to max points (2 doubles each). */
static long sample_bends(const double *xy, long m, long u, long v, double *out, long max)
{
    const double *pu = xy + 2 * u, *pn = xy + 2 * ((u + 1) % m), *pp = xy + 2 * ((u + m - 1) % m);
    double a0 = atan2(pn[1] - pu[1], pn[0] - pu[0]), span = atan2(pp[1] - pu[1], pp[0] - pu[0]) - a0;
    while (span <= 0) span += 2 * CM_PI;
    long count = 0;
    int tame = cm_coords_tame(xy, 2 * m); /* once for all the candidates */
    for (int fi = 1; fi < 8 && count < max; fi++) {
        double angle = a0 + span * fi / 8.0, dir[2] = {cos(angle), sin(angle)};
        double run = free_run(xy, m, pu, dir);
        for (int di = 1; di < 4 && isfinite(run) && count < max; di++) {
            double y[2] = {pu[0] + run * di / 4.0 * dir[0], pu[1] + run * di / 4.0 * dir[1]};
            if (cm_path_valid_in(xy, m, tame, u, v, y, 1)) out[2 * count] = y[0], out[2 * count + 1] = y[1], count++;
        }
    }
    return count;
}

/* Candidate bend arrays for one geometry (want bends each): the link
 * path, refined with several sideways offsets when it is short, and for a
 * single bend a spread of other points seen from both ends. */
typedef struct {
    double *bends; /* count * 2 * want doubles */
    long count;
} choices;

#define MAX_SAMPLES 10

static int cut_choices(const face_ctx *f, const pair *pr, size_t g, const double *path, long nb,
                       int search, choices *c)
{
    long m = f->it->m, want = pr->links - 1, per = 2 * want;
    size_t offsets_tried = search && nb < want ? NOFFSETS : 1;
    c->count = 0;
    c->bends = malloc(sizeof(double) * (size_t)(per > 0 ? per : 1) * (NOFFSETS + MAX_SAMPLES));
    if (!c->bends) return -1;
    for (size_t o = 0; o < offsets_tried; o++) {
        /* A long cut across a large face may need many more bends in one
         * geometry than its own path has: on its links they would make
         * flat chains, slivers to the cuts after; pushed sideways they
         * zigzag (refine_path falls back to less, down to none). */
        double side = f->min_balance > 0 && o == 0 ? offsets[1] : offsets[o];
        double *b = refine_path(f->l[g], m, pr->u, pr->v, path, nb, want, side);
        if (!b) continue;
        memcpy(c->bends + per * c->count++, b, sizeof(double) * (size_t)per);
        free(b);
    }
    if (search && want == 1) c->count += sample_bends(f->l[g], m, pr->u, pr->v, c->bends + per * c->count, MAX_SAMPLES);
    return 0;
}

/* Builds the cut for pair pr in every geometry: bends[g] gets links - 1
 * bends. In a small face the choices of every geometry are searched
 * (coordinate descent) for the cut whose halves need the fewest Steiner
 * vertices, their estimate in *cost (0 when not estimated). Returns 1, 0
 * (no valid cut), -1 out of memory. */
static int build_cut(face_ctx *f, const pair *pr, double **bends, long *cost)
{
    size_t k = f->p->k;
    long m = f->it->m, want = pr->links - 1, per = 2 * want;
    int search = m <= REFINE_SEARCH_MAX;
    choices *c = calloc(k, sizeof *c);
    long *pick = calloc(k, sizeof *pick), *cur = calloc(k, sizeof *cur), best = LONG_MAX;
    cut_memo memo = {0, NULL, NULL, NULL, m + 1 + want, NULL, NULL, NULL, NULL};
    int result = c && pick && cur ? 1 : -1;
    for (size_t g = 0; g < k && result == 1; g++) {
        double *path = NULL;
        long nb = 0;
        long end = f->src[pr->row] == pr->u ? pr->v : pr->u;
        int expect = dist_row(f, g, pr->row)[end];
        int links = cm_link_path_within(f->lp[g], pr->u, pr->v, expect, &path, &nb);
        if (links < 0) result = -1;
        else if (links == 0 || links != expect) result = 0;
        else if (cut_choices(f, pr, g, path, nb, search, &c[g]) != 0) result = -1;
        else if (c[g].count == 0) result = 0;
        free(path);
    }
    for (size_t g = 0; g < k && result == 1; g++) bends[g] = c[g].bends; /* views while searching */
    if (result == 1 && search) {
        size_t combos = 1;
        for (size_t g = 0; g < k; g++) memo.per_g = c[g].count > memo.per_g ? c[g].count : memo.per_g;
        for (size_t g = 0; g < k; g++) combos *= (size_t)memo.per_g;
        memo.diag = calloc(2 * k * (size_t)memo.per_g, sizeof *memo.diag);
        memo.state = calloc(2 * k * (size_t)memo.per_g, sizeof *memo.state);
        memo.cost = malloc(combos * sizeof *memo.cost);
        for (size_t i = 0; memo.cost && i < combos; i++) memo.cost[i] = -2;
        size_t coords = 2 * (size_t)memo.most, words = ((size_t)memo.most + 63) / 64 * (size_t)memo.most;
        memo.xy = malloc(k * sizeof *memo.xy + (k * coords + 2 * k) * sizeof **memo.xy +
                         words * sizeof *memo.common_bits + (size_t)memo.most * sizeof *memo.all);
        for (size_t g = 0; memo.xy && g < k; g++) memo.xy[g] = (double *)(memo.xy + k) + g * coords;
        if (memo.xy) {
            memo.pos = (double *)(memo.xy + k) + k * coords;
            memo.common_bits = (uint64_t *)(memo.pos + 2 * k);
            memo.all = (int32_t *)(memo.common_bits + words);
        }
        if (!memo.diag || !memo.state || !memo.cost || !memo.xy) result = -1;
    }
    if (result == 1 && search) best = cut_cost(f, pr, bends, cur, &memo, LONG_MAX);
    for (int pass = 0; pass < 2 && result == 1 && search && best > 0; pass++)
        for (size_t g = 0; g < k && best > 0; g++)
            for (long i = 0; i < c[g].count && best > 0; i++) {
                if (i == pick[g]) continue;
                bends[g] = c[g].bends + per * i, cur[g] = i;
                long cost_i = cut_cost(f, pr, bends, cur, &memo, best);
                if (cost_i < 0) result = -1;
                if (cost_i >= 0 && cost_i < best) best = cost_i, pick[g] = i;
                bends[g] = c[g].bends + per * pick[g], cur[g] = pick[g];
            }
    for (size_t i = 0; memo.diag && i < 2 * k * (size_t)memo.per_g; i++) cm_diagset_clear(&memo.diag[i]);
    free(memo.diag), free(memo.state), free(memo.cost), free(memo.xy), free(cur);
    /* hand over copies of the picked choices */
    for (size_t g = 0; g < k; g++) {
        double *b = result == 1 ? malloc(sizeof(double) * (size_t)(per > 0 ? per : 1)) : NULL;
        if (b) memcpy(b, c[g].bends + per * pick[g], sizeof(double) * (size_t)per);
        if (result == 1 && !b) result = -1;
        bends[g] = b;
        if (c) free(c[g].bends);
    }
    *cost = search ? best : 0;
    free(c), free(pick);
    return result;
}

/* The two halves of the face cut by the path u -> bends -> v. */
static int split_along(part *p, const item *it, const pair *pr, const long *steiner)
{
    long m = it->m, nb = pr->links - 1;
    for (int half = 0; half < 2; half++) {
        long from = half == 0 ? pr->u : pr->v, to = half == 0 ? pr->v : pr->u;
        long size = (to - from + m) % m + 1 + nb;
        item c = {malloc((size_t)size * sizeof(int32_t)), NULL, size, -1, size == m ? it->repeat + 1 : 0, 0, 0};
        if (!c.gid) return -1;
        long n = 0;
        for (long x = from;; x = (x + 1) % m) {
            c.gid[n++] = it->gid[x];
            if (x == to) break;
        }
        for (long j = 0; j < nb; j++) c.gid[n++] = (int32_t)steiner[half == 0 ? nb - 1 - j : j];
        if (push_item(p, c) != 0) return -1;
    }
    return 0;
}

/* Do the nb bends of each geometry keep clear of the face's vertices and
 * of each other, by more than BEND_GAP of the face's extent? A bend a few
 * units in the last place from a vertex is valid, but the pieces beside
 * it are slivers that later cuts, and even the overlay, cannot place
 * points in. */
#define BEND_GAP 1e-9
static int bends_apart(const face_ctx *f, long nb, double **bends)
{
    long m = f->it->m;
    for (size_t g = 0; g < f->p->k; g++) {
        const double *xy = f->l[g];
        double lo[2] = {xy[0], xy[1]}, hi[2] = {xy[0], xy[1]};
        for (long i = 1; i < m; i++)
            for (int d = 0; d < 2; d++) lo[d] = fmin(lo[d], xy[2 * i + d]), hi[d] = fmax(hi[d], xy[2 * i + d]);
        double gap = BEND_GAP * fmax(hi[0] - lo[0], hi[1] - lo[1]);
        for (long j = 0; j < nb; j++) {
            const double *b = bends[g] + 2 * j;
            for (long i = 0; i < m; i++)
                if (fabs(b[0] - xy[2 * i]) <= gap && fabs(b[1] - xy[2 * i + 1]) <= gap) return 0;
            for (long i = 0; i < j; i++)
                if (fabs(b[0] - bends[g][2 * i]) <= gap && fabs(b[1] - bends[g][2 * i + 1]) <= gap) return 0;
        }
    }
    return 1;
}

/* Cuts the face along the best valid pair: ranked by the paper's rule,
 * the first LINK_EVALUATE valid cuts compared by bends plus the estimated
 * Steiner vertices of their halves. 1 cut, 0 none worked, -1 memory. */
static int cut_face(face_ctx *f)
{
    part *p = f->p;
    size_t k = p->k;
    long npairs = 0;
    pair *pairs = rank_pairs(f, &npairs);
    if (!pairs) return -1;
    double **bends = calloc(k, sizeof *bends), **best = calloc(k, sizeof *best);
    double **pos = calloc(k, sizeof *pos);
    long best_pair = -1, best_total = LONG_MAX, valid = 0;
    int result = bends && best && pos ? 0 : -1;
    for (long c = 0; c < npairs && c < LINK_MAX_TRIES && valid < LINK_EVALUATE && result == 0; c++) {
        if (best_pair >= 0 && pairs[c].links - 1 >= best_total) break; /* cannot win */
        long cost = 0;
        int s = build_cut(f, &pairs[c], bends, &cost);
        if (s == 1 && !bends_apart(f, pairs[c].links - 1, bends)) s = 0;
        if (s < 0) result = -1;
        if (s == 1) {
            valid++;
            long total = pairs[c].links - 1 + cost;
            if (total < best_total) {
                best_total = total, best_pair = c;
                for (size_t g = 0; g < k; g++) {
                    free(best[g]);
                    best[g] = bends[g], bends[g] = NULL;
                }
            }
            if (cost == 0) break; /* halves Steiner-free: the ranking decides */
        }
        for (size_t g = 0; g < k; g++) free(bends[g]), bends[g] = NULL;
    }
    long *steiner = NULL;
    if (result == 0 && best_pair >= 0) {
        long nb = pairs[best_pair].links - 1;
        steiner = malloc((size_t)(nb + 1) * sizeof *steiner);
        result = steiner ? 1 : -1;
        for (long j = 0; j < nb && result == 1; j++) {
            for (size_t g = 0; g < k; g++) pos[g] = best[g] + 2 * j;
            steiner[j] = add_vertex(p, (const double *const *)pos);
            if (steiner[j] < 0) result = -1;
        }
        if (result == 1 && split_along(p, f->it, &pairs[best_pair], steiner) != 0) result = -1;
        p->st->link_splits += result == 1;
    }
    for (size_t g = 0; bends && g < k; g++) free(bends[g]);
    for (size_t g = 0; best && g < k; g++) free(best[g]);
    free(steiner), free(pairs), free(bends), free(best), free(pos);
    return result;
}

/* Does the item get the sources of a face of an input above the table
 * limit (fewer than a small input's)? */
static int large_budget(const part *p, const item *it)
{
    return (long)p->n > p->table_limit && it->m > LINK_ALL_PAIRS_LARGE;
}

/* Cuts the item along a minimum-link path between two of its vertices
 * whose shorter side spans at least min_balance vertices; a half keeps
 * the item's size only if the item's repeat count is at most repeats;
 * wide: the sources of a small input's faces whatever the input's size.
 * 1 cut, 0 none, -1 memory. */
static int link_split(part *p, item *it, long min_balance, int repeats, int wide)
{
    long m = it->m;
    long all = LINK_ALL_PAIRS, work = LINK_WORK, least = LINK_MIN_SOURCES;
    if ((long)p->n > p->table_limit && !wide)
        all = LINK_ALL_PAIRS_LARGE, work = LINK_WORK_LARGE, least = LINK_MIN_SOURCES_LARGE;
    long nsrc = m <= all ? m : work / m > least ? work / m : least;
    if (min_balance > 0) /* any pair across will do */
        nsrc = m > BALANCED_FEWER_ABOVE * p->table_limit ? BALANCED_SOURCES / 2 : BALANCED_SOURCES;
    if (nsrc > m) nsrc = m;
    double t0 = cm_seconds_now();
    face_ctx f = {p, it, local_xy(p, it), calloc(p->k, sizeof(cm_linkpart *)), malloc((size_t)nsrc * sizeof(long)),
                  nsrc, malloc((size_t)m * sizeof(long)), malloc(p->k * (size_t)nsrc * (size_t)m * sizeof(int)), NULL, 0,
                  min_balance, repeats};
    unsigned char *open = malloc(p->k * (size_t)nsrc), *need = malloc((size_t)m);
    int result = f.l && f.lp && f.src && f.row_of && f.dist && open && need ? 0 : -1;
    for (long v = 0; result == 0 && v < m; v++) f.row_of[v] = -1;
    for (long r = 0; result == 0 && r < nsrc; r++) f.src[r] = r * m / nsrc, f.row_of[f.src[r]] = r;
    for (size_t g = 0; g < p->k && result == 0; g++) {
        f.lp[g] = cm_linkpart_create(f.l[g], m);
        if (!f.lp[g]) result = -1;
    }
    /* Only the smallest largest link distance matters: deeper levels of
     * the window partitions only when no pair is within the cap, and only
     * for the sources whose partition went deeper than the cap. */
    if (open) memset(open, 1, p->k * (size_t)nsrc);
    int first = min_balance > 0 ? BALANCED_FIRST_CAP : 2;
    for (int cap = first; result == 0; cap = cap < 8 ? 2 * cap : INT_MAX) {
        long deeper = 0;
        for (size_t g = 0; g < p->k && result == 0; g++)
            for (long r = 0; r < nsrc && result == 0; r++) {
                if (!open[g * (size_t)nsrc + (size_t)r]) continue;
                /* rank_pairs reads a row only at the vertices that are
                 * not sources of earlier rows, at least min_balance away
                 * either way round, and within the cap in the geometries
                 * before (the others it does not rank) */
                int *row = dist_row(&f, g, r), before_open = 0;
                long needed = 0;
                for (size_t h = 0; h < g; h++) before_open |= open[h * (size_t)nsrc + (size_t)r];
                for (long w = 0; w < m; w++) {
                    long d = (w - f.src[r] + m) % m, span = d < m - d ? d : m - d;
                    need[w] = w != f.src[r] && !(f.row_of[w] >= 0 && f.row_of[w] < r) && span >= min_balance;
                    for (size_t h = 0; need[w] && h < g; h++) need[w] = dist_row(&f, h, r)[w] >= 1;
                    needed += need[w];
                }
                int s = 0;
                if (needed > 0) s = cm_link_distances_needed(f.lp[g], f.src[r], cap, need, row);
                else for (long w = 0; w < m; w++) row[w] = -1;
                if (s < 0) result = -1;
                /* a row that read fewer vertices than a deeper row before
                 * it will reach goes again with it */
                open[g * (size_t)nsrc + (size_t)r] = (unsigned char)(s == 1 || before_open);
                deeper += s == 1;
            }
        if (result == 0) result = cut_face(&f);
        if (result != 0 || cap == INT_MAX || deeper == 0) break;
    }
    free(open), free(need);
    for (size_t g = 0; f.lp && g < p->k; g++) cm_linkpart_free(f.lp[g]);
    for (size_t g = 0; f.own && g < p->k; g++) cm_diagset_clear(&f.own[g]);
    free(f.own);
    free(f.lp), free(f.dist), free(f.src), free(f.row_of);
    free_xy(f.l, p->k);
    p->st->seconds_link += cm_seconds_now() - t0;
    return result;
}

/* A link cut with the sources of the input's size, then, for a face of an
 * input above the table limit, with a small input's. 1, 0 or -1 as
 * link_split. */
static int link_split_widening(part *p, item *it)
{
    int cut = link_split(p, it, 0, 0, 0);
    if (cut == 0 && large_budget(p, it)) cut = link_split(p, it, 0, 0, 1);
    return cut;
}

/* ---- the guaranteed fallback ---------------------------------------------- */

static cm_status fallback(part *p, item *it)
{
    double t0 = cm_seconds_now();
    long m = it->m;
    size_t k = p->k;
    double **l = local_xy(p, it);
    int32_t **tris = calloc(k, sizeof *tris), *idx = malloc((size_t)m * sizeof *idx);
    cm_mesh sub;
    memset(&sub, 0, sizeof sub);
    long *map = NULL;
    double **pos = calloc(k, sizeof *pos);
    cm_status s = CM_ERR_NO_MEMORY;
    if (!l || !tris || !idx || !pos) goto done;
    for (long i = 0; i < m; i++) idx[i] = (int32_t)i;
    for (size_t g = 0; g < k; g++) {
        tris[g] = malloc(3 * (size_t)(m - 2) * sizeof **tris);
        if (!tris[g]) goto done;
        int t = cm_polygon_triangulate(l[g], idx, m, tris[g], p->progress);
        if (t == CM_CANCELLED) s = cm_fail_status(p->err, CM_ERR_CANCELLED);
        if (t < 0) goto done;
        if (t > 0) {
            s = cm_fail(p->err, CM_ERR_INTERNAL, "partition: a sub-polygon is not simple");
            goto done;
        }
    }
    size_t centroids = 0;
    s = cm_overlay((const double *const *)l, (const int32_t *const *)tris, k, (size_t)m, &sub,
                   &centroids, p->err);
    if (s != CM_OK) goto done;
    s = CM_ERR_NO_MEMORY;
    map = malloc(sub.nv * sizeof *map);
    if (!map) goto done;
    for (size_t v = 0; v < sub.nv; v++) {
        if ((long)v < m) {
            map[v] = it->gid[v];
            continue;
        }
        for (size_t g = 0; g < k; g++) pos[g] = sub.xy[g] + 2 * v;
        map[v] = add_vertex(p, (const double *const *)pos);
        if (map[v] < 0) goto done;
    }
    for (size_t t = 0; t < sub.nt; t++)
        if (mesh_add_triangle(p, (int32_t)map[sub.tri[3 * t]], (int32_t)map[sub.tri[3 * t + 1]],
                         (int32_t)map[sub.tri[3 * t + 2]]) != 0)
            goto done;
    p->st->fallback_count++;
    s = CM_OK;
done:
    if (s == CM_ERR_NO_MEMORY) no_memory(p);
    free_xy(l, k);
    for (size_t g = 0; tris && g < k; g++) free(tris[g]);
    free(tris), free(idx), free(map), free(pos);
    cm_mesh_clear(&sub);
    p->st->seconds_fallback += cm_seconds_now() - t0;
    return s;
}

/* ---- one item ------------------------------------------------------------- */

/* Steiner-free program, or a balanced common diagonal. 1 done, 0 stuck. */
static int common_step(part *p, item *it, cm_status *s)
{
    long m = it->m;
    cm_diagview view = local_common(p, it), *common = &view;
    /* up to CM_DP_MAX_VERTICES only whether there is one matters */
    long chords = cm_steinerfree_count_to(m, common, m <= CM_DP_MAX_VERTICES ? 1 : LONG_MAX);
    int done = 1;
    if (chords == 0) {
        done = 0;
    } else if (m <= CM_DP_MAX_VERTICES || (double)m * (double)(chords + m) <= DP_WORK_LIMIT) {
        *s = plan_item(p, it, common);
    } else {
        /* Too large for the program: one Steiner vertex when the item is
         * star-shaped in every geometry (what the program's fan would
         * give), else a balanced split. */
        int g = try_fan(p, it);
        if (g == 0) g = greedy_split(p, it, common);
        if (g < 0) *s = no_memory(p);
        done = g != 0;
    }
    return done;
}

/* An item above the table limit: one fan when it is star-shaped in every
 * geometry; else a common diagonal that leaves at least m / DIAGONAL_PART
 * vertices on either side; else a minimum-link path with at least m /
 * LINK_PART on either side (bends are Steiner vertices, but the pieces
 * shrink geometrically: a short diagonal, all an unrelated pair may have,
 * peels off a small piece per O(k m) split and leaves large stuck faces);
 * else any common diagonal seen, any link cut, the overlay. */
#define DIAGONAL_PART 8
#define LINK_PART 4
static cm_status large_step(part *p, item *it)
{
    long bi = -1, bj = -1, balance = 0;
    int cut = try_fan(p, it), found = 0;
    if (cut == 0) found = sampled_diagonal(p, it, &bi, &bj, &balance);
    if (found == 2) return cm_fail(p->err, CM_ERR_INTERNAL, "partition: a sub-polygon is not simple");
    if (found == 1 && balance >= it->m / DIAGONAL_PART) cut = 2;
    if (cut == 0 && found >= 0) cut = link_split(p, it, it->m / LINK_PART, 0, 0);
    if (cut == 0 && found == 1) cut = 2;
    if (cut == 0 && found >= 0) cut = link_split_widening(p, it);
    if (cut == 2) {
        p->st->sampled_splits++;
        cut = split_diagonal(p, it, bi, bj) == 0 ? 1 : -1;
    }
    if (cut < 0 || found < 0) return no_memory(p);
    return cut ? CM_OK : fallback(p, it);
}

static cm_status process_item(part *p, item *it)
{
    if (it->m == 3)
        return add_item_triangle(p, it, 0, 1, 2) == 0 ? CM_OK : no_memory(p);
    if (it->table < 0 && (double)it->m * (double)it->m > DP_WORK_LIMIT) {
        /* At this size the steps below try the fan first whatever the
         * table holds: before the table, the same result without it. */
        int fan = try_fan(p, it);
        if (fan != 0) return fan > 0 ? CM_OK : no_memory(p);
    }
    if (it->table < 0 && it->m > p->table_limit) return large_step(p, it);
    cm_status s = CM_OK;
    if (it->table < 0 && (s = table_for_item(p, it)) != CM_OK) return s;
    if (!it->stuck && common_step(p, it, &s)) return s;
    int cut = try_fan(p, it);
    if (cut == 0 && large_budget(p, it)) cut = link_split(p, it, it->m / LINK_PART, 0, 0); /* LINK_ALL_PAIRS_LARGE */
    if (cut == 0) cut = link_split_widening(p, it);
    /* Before the overlay: a piece of a sliver may still be cut if a
     * half may keep its size a few times more (the overlay itself may
     * find no room in doubles for its points there). */
    if (cut == 0 && it->repeat > 0 && it->repeat < MAX_REPEATS) cut = link_split(p, it, 0, it->repeat, 0);
    if (cut < 0) return no_memory(p);
    return cut ? CM_OK : fallback(p, it);
}

static cm_status start(part *p, const double *const *geoms, const int32_t *const *tris)
{
    size_t k = p->k, n = p->n;
    p->xy = calloc(k, sizeof *p->xy);
    if (!p->xy) return no_memory(p);
    p->cap_v = 4 * n; /* doubles: room for n Steiner vertices */
    for (size_t g = 0; g < k; g++) {
        p->xy[g] = malloc(p->cap_v * sizeof(double));
        if (!p->xy[g]) return no_memory(p);
        memcpy(p->xy[g], geoms[g], 2 * n * sizeof(double));
    }
    p->nv = n;
    if ((long)n > p->table_limit || (double)n * (double)n > DP_WORK_LIMIT) { /* the table later, if needed */
        item root = {malloc(n * sizeof(int32_t)), NULL, (long)n, -1, 0, 0, 0};
        if (!root.gid) return no_memory(p);
        for (size_t i = 0; i < n; i++) root.gid[i] = (int32_t)i;
        return push_item(p, root) == 0 ? CM_OK : no_memory(p);
    }
    double t0 = cm_seconds_now();
    item root = {malloc(n * sizeof(int32_t)), malloc(n * sizeof(int32_t)), (long)n, 0, 0, 0, 0};
    if (!root.gid || !root.tix) {
        item_free(&root);
        return no_memory(p);
    }
    for (size_t i = 0; i < n; i++) root.gid[i] = root.tix[i] = (int32_t)i;
    cm_diagset common = {0, 0, NULL};
    int t = common_table(geoms, tris, k, (long)n, p, root.gid, &common);
    if (t != 0) item_free(&root);
    if (t > 0) return cm_fail(p->err, CM_ERR_INTERNAL, "partition: the input is not simple");
    if (t < 0 || add_table(p, &common) < 0) {
        item_free(&root);
        return no_memory(p);
    }
    p->st->seconds_visibility += cm_seconds_now() - t0;
    return push_item(p, root) == 0 ? CM_OK : no_memory(p);
}

static void part_free(part *p)
{
    if (p->xy)
        for (size_t g = 0; g < p->k; g++) free(p->xy[g]);
    free(p->xy), free(p->tri);
    for (long t = 0; t < p->ntab; t++) cm_diagset_clear(&p->tab[t].common);
    free(p->tab);
    for (long i = 0; i < p->top; i++) item_free(&p->stack[i]);
    free(p->stack);
    cm_sf_work_free(p->sf);
}

static cm_status partition_run(const double *const *geoms, const int32_t *const *tris, size_t k, size_t n,
                               long table_limit, const cm_on_edges *on, cm_progress *progress, cm_mesh *out,
                               cm_partition_stats *stats, cm_error *err)
{
    part p;
    memset(&p, 0, sizeof p);
    memset(stats, 0, sizeof *stats);
    p.k = k, p.n = n, p.table_limit = table_limit, p.st = stats, p.err = err, p.progress = progress, p.on = on;
    cm_status s = start(&p, geoms, tris);
    while (s == CM_OK && p.top > 0) {
        item it = p.stack[--p.top];
        s = process_item(&p, &it);
        item_free(&it);
        /* Tables no item on the stack reads any more (an item's table
         * serves only the items cut from it, all above its base). */
        while (p.ntab > 0 && p.tab[p.ntab - 1].base >= p.top) cm_diagset_clear(&p.tab[--p.ntab].common);
        if (s == CM_OK && cm_progress_poll(progress, CM_STAGE_PARTITION, 0.0))
            s = cm_fail_status(err, CM_ERR_CANCELLED);
    }
    if (s == CM_OK) {
        out->k = k, out->nv = p.nv, out->nt = p.nt, out->xy = p.xy, out->tri = p.tri;
        stats->steiner = p.nv - n;
        p.xy = NULL, p.tri = NULL;
    }
    part_free(&p);
    return s;
}

cm_status cm_partition_limited(const double *const *geoms, const int32_t *const *tris, size_t k, size_t n,
                               long table_limit, cm_progress *progress, cm_mesh *out,
                               cm_partition_stats *stats, cm_error *err)
{
    return partition_run(geoms, tris, k, n, table_limit, NULL, progress, out, stats, err);
}

cm_status cm_partition(const double *const *geoms, const int32_t *const *tris, size_t k, size_t n,
                       cm_progress *progress, cm_mesh *out, cm_partition_stats *stats,
                       cm_error *err)
{
    return partition_run(geoms, tris, k, n, CM_PARTITION_MAX_VERTICES, NULL, progress, out, stats, err);
}

cm_status cm_partition_on_edges(const double *const *geoms, const int32_t *const *tris, size_t k, size_t n,
                                const cm_on_edges *on, cm_progress *progress, cm_mesh *out,
                                cm_partition_stats *stats, cm_error *err)
{
    return partition_run(geoms, tris, k, n, CM_PARTITION_MAX_VERTICES, on, progress, out, stats, err);
}
