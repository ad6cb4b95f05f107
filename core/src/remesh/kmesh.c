/* The k-geometry corner-table mesh: construction, write-back, the local
 * operations (flip, split, collapse, move) and the triangle quality index. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "remesh/kmesh.h"
#include "remesh/kmesh_log.h"
#include "geom/predicates.h"

/* ---- storage ------------------------------------------------------------ */

/* Free lists hold at most one entry per slot: sized with the slots, pushes
 * onto them never allocate. */
static int reserve_list(cm_ibuf *b, int32_t cap)
{
    if ((size_t)cap <= b->cap) return 0;
    int32_t *a = realloc(b->a, (size_t)cap * sizeof *a);
    if (!a) return -1;
    b->a = a, b->cap = (size_t)cap;
    return 0;
}

/* *array = realloc(*array, count * size); 0, or -1 (*array unchanged). */
static int resize(void *array, size_t count, size_t size)
{
    void **p = array, *q = realloc(*p, count * size);
    if (!q) return -1;
    *p = q;
    return 0;
}

/* Slots for at least need, growing by half (amortised appends). */
static int32_t grown(int32_t cap, int32_t need)
{
    if (!cap) cap = 16;
    while (cap < need) cap = cap + cap / 2 + 16;
    return cap;
}

static int reserve_vertices(cm_kmesh *km, int32_t need)
{
    if (need <= km->cap_v) return 0;
    int32_t cap = grown(km->cap_v, need);
    size_t c = (size_t)cap;
    for (size_t g = 0; g < km->k; g++)
        if (resize(&km->xy[g], 2 * c, sizeof **km->xy)) return -1;
    if (resize(&km->vc, c, sizeof *km->vc) || resize(&km->mark, c, sizeof *km->mark) ||
        resize(&km->vcap, c, sizeof *km->vcap) || resize(&km->vdirty, c, sizeof *km->vdirty) ||
        resize(&km->bnext, c, sizeof *km->bnext) || resize(&km->bcap, c, sizeof *km->bcap) ||
        (km->bedge && (resize(&km->bedge, c * km->k, sizeof *km->bedge) || resize(&km->bt, c * km->k, sizeof *km->bt))) ||
        reserve_list(&km->free_v, cap))
        return -1;
    for (int32_t v = km->cap_v; v < cap; v++)
        km->vc[v] = -1, km->mark[v] = 0, km->vcap[v] = CM_PI, km->vdirty[v] = CM_DIRTY_ALL, km->bnext[v] = -1;
    km->cap_v = cap;
    return 0;
}

static int reserve_triangles(cm_kmesh *km, int32_t need)
{
    if (need <= km->cap_t) return 0;
    int32_t cap = grown(km->cap_t, need);
    size_t c = (size_t)cap;
    if (resize(&km->tri, 3 * c, sizeof *km->tri) || resize(&km->opp, 3 * c, sizeof *km->opp) ||
        resize(&km->tkey, c, sizeof *km->tkey) || resize(&km->slack, c, sizeof *km->slack) ||
        resize(&km->tang, c * km->k, sizeof *km->tang) || resize(&km->eq_stale, 3 * c, sizeof *km->eq_stale) ||
        resize(&km->eq_pending, 3 * c, sizeof *km->eq_pending) ||
        cm_heap_reserve(&km->tq, cap) || cm_heap_reserve(&km->eq, 3 * cap) || reserve_list(&km->free_t, cap))
        return -1;
    for (int32_t i = 3 * km->cap_t; i < 3 * cap; i++) km->tri[i] = -1, km->opp[i] = -1, km->eq_stale[i] = 0;
    for (int32_t t = km->cap_t; t < cap; t++) km->tkey[t] = CM_PI, km->slack[t] = 0, km->tang[(size_t)t * km->k] = NAN;
    km->cap_t = cap;
    return 0;
}

/* ---- slots (through the undo log) ------------------------------------------ */

static void push_free_vertex(cm_kmesh *km, int32_t v)
{
    cm_ibuf_push(&km->free_v, v); /* never allocates: see reserve_list */
    cm_log_free_list(km, v, CM_LOG_PUSH_V);
}

static void push_free_triangle(cm_kmesh *km, int32_t t)
{
    cm_ibuf_push(&km->free_t, t);
    cm_log_free_list(km, t, CM_LOG_PUSH_T);
}

static int32_t new_vertex(cm_kmesh *km)
{
    if (km->free_v.n) {
        int32_t v = km->free_v.a[--km->free_v.n];
        cm_log_free_list(km, v, CM_LOG_POP_V);
        km->vcap[v] = CM_PI;
        return v;
    }
    if (reserve_vertices(km, km->nv + 1)) return -1;
    km->vcap[km->nv] = CM_PI;
    return km->nv++;
}

static int32_t new_triangle(cm_kmesh *km)
{
    if (km->free_t.n) {
        int32_t t = km->free_t.a[--km->free_t.n];
        cm_log_free_list(km, t, CM_LOG_POP_T);
        return t;
    }
    if (reserve_triangles(km, km->nt + 1)) return -1;
    return km->nt++;
}

void cm_kmesh_free(cm_kmesh *km)
{
    cm_kmesh_log_free(km->log);
    if (km->xy)
        for (size_t g = 0; g < km->k; g++) free(km->xy[g]);
    free(km->xy), free(km->tri), free(km->opp), free(km->vc), free(km->scale);
    free(km->tkey), free(km->tang), free(km->slack), free(km->mark), free(km->bcap), free(km->bnext), free(km->vcap), free(km->vdirty);
    free(km->bedge), free(km->bt), free(km->eq_stale), free(km->eq_pending);
    cm_ibuf_free(&km->free_v), cm_ibuf_free(&km->free_t);
    cm_heap_free(&km->tq), cm_heap_free(&km->eq);
    memset(km, 0, sizeof *km);
}

/* ---- geometry ----------------------------------------------------------- */

/* The smallest angle is opposite the shortest side: one atan2. */
double cm_kmesh_tri_angle(const cm_kmesh *km, size_t g, int32_t t)
{
    const int32_t *v = km->tri + 3 * (size_t)t;
    return cm_triangle_min_angle(cm_kmesh_pos(km, g, v[0]), cm_kmesh_pos(km, g, v[1]),
                        cm_kmesh_pos(km, g, v[2]));
}

int cm_kmesh_tri_ok(const cm_kmesh *km, size_t g, int32_t a, int32_t b, int32_t c)
{
    return cm_orient2d(cm_kmesh_pos(km, g, a), cm_kmesh_pos(km, g, b), cm_kmesh_pos(km, g, c)) > 0;
}

/* The angle triangle t should reach. */
static double triangle_target(const cm_kmesh *km, int32_t t)
{
    double target = km->target;
    for (int32_t c = 3 * t; c < 3 * t + 3; c++) {
        target = fmin(target, km->vcap[km->tri[c]]);
        if (km->opp[c] < 0) target = fmin(target, km->bcap[km->tri[cm_next(c)]]);
    }
    return target;
}

double cm_kmesh_split_score(const cm_kmesh *km, int32_t c)
{
    int32_t o = km->opp[c], a = km->tri[cm_next(c)], b = km->tri[cm_prev(c)];
    double alpha = fmax(o < 0 ? km->tkey[c / 3] : fmin(km->tkey[c / 3], km->tkey[o / 3]), 1e-9), len = 0;
    for (size_t g = 0; g < km->k; g++) len = fmax(len, cm_kmesh_rel_length(km, g, a, b));
    return len / (alpha * alpha);
}

/* Files the edge opposite c under its smaller corner, if a triangle
 * beside it still falls short of its target (a boundary edge only with
 * boundary splits). */
static void file_edge(cm_kmesh *km, int32_t c)
{
    int32_t o = km->opp[c];
    if (o < 0) {
        if (km->between && km->slack[c / 3] < 0)
            cm_heap_set(&km->eq, c, -cm_kmesh_split_score(km, c));
        else
            cm_heap_remove(&km->eq, c);
        return;
    }
    int32_t lo = c < o ? c : o, hi = c < o ? o : c;
    cm_heap_remove(&km->eq, hi);
    if (km->slack[c / 3] < 0 || km->slack[o / 3] < 0)
        cm_heap_set(&km->eq, lo, -cm_kmesh_split_score(km, c));
    else
        cm_heap_remove(&km->eq, lo);
}

/* The edge opposite c changed: filed again when the candidates are next
 * read. Its score then comes from the keys and positions of that time,
 * which are those the last change left, so the heap holds what filing at
 * every change would have left. */
static void update_edge(cm_kmesh *km, int32_t c)
{
    if (km->eq_dropped || km->eq_stale[c]) return;
    km->eq_stale[c] = 1;
    km->eq_pending[km->eq_npending++] = c; /* each corner once: room for all */
}

const cm_heap *cm_kmesh_candidates(cm_kmesh *km)
{
    for (int32_t i = 0; i < km->eq_npending; i++) {
        int32_t c = km->eq_pending[i], o = km->opp[c];
        if (!km->eq_stale[c]) continue; /* filed with its twin */
        km->eq_stale[c] = 0;
        if (km->tri[c] < 0) continue; /* died: out of the heap already */
        if (o >= 0) km->eq_stale[o] = 0;
        file_edge(km, c);
    }
    km->eq_npending = 0;
    return &km->eq;
}

void cm_kmesh_forget_candidate(cm_kmesh *km, int32_t c)
{
    cm_kmesh_candidates(km);
    cm_heap_remove(&km->eq, km->opp[c] < 0 || c < km->opp[c] ? c : km->opp[c]);
}

/* Sets t's key, its slack and the heap entries that depend on them. */
static void set_key(cm_kmesh *km, int32_t t, double key)
{
    km->tkey[t] = key;
    km->slack[t] = key - triangle_target(km, t);
    cm_heap_set(&km->tq, t, km->slack[t]);
    for (int32_t c = 3 * t; c < 3 * t + 3; c++) update_edge(km, c);
}

void cm_kmesh_set_dirty(cm_kmesh *km, int32_t v, unsigned dirty)
{
    if (km->vdirty[v] == (uint16_t)dirty) return;
    cm_log_dirty(km, v);
    km->vdirty[v] = (uint16_t)dirty;
}

/* Recomputes t's key (its angle in geometry `only`, the others as known,
 * when only < k and they are; else all) and sets the vdirty bits `mask`
 * of its vertices. */
static double fresh_key(cm_kmesh *km, int32_t t, size_t only, unsigned mask)
{
    double key = CM_PI, *tang = km->tang + (size_t)t * km->k;
    int known = only < km->k && !isnan(tang[0]);
    for (size_t g = 0; g < km->k; g++) {
        if (!known || g == only) tang[g] = cm_kmesh_tri_angle(km, g, t);
        if (tang[g] < key) key = tang[g];
    }
    for (int i = 0; i < 3; i++) {
        int32_t v = km->tri[3 * t + i];
        cm_kmesh_set_dirty(km, v, km->vdirty[v] | mask);
    }
    return key;
}

void cm_kmesh_touch(cm_kmesh *km, int32_t t)
{
    set_key(km, t, fresh_key(km, t, km->k, CM_DIRTY_ALL));
}

/* The restored triangles get their saved keys back (the geometry is the
 * one they were computed on) and the dirty bits their old values: where
 * the smoothing formulas left a vertex in place they would again. The
 * position search runs again around the undone change, as it always
 * has: which searches run changes the results, the fixtures' angles
 * moving either way. */
int cm_kmesh_tx_rollback(cm_kmesh *km)
{
    long nt = cm_log_undo(km);
    if (nt < 0) return -1;
    for (long i = 0; i < nt; i++) {
        int32_t t = cm_log_saved_triangle(km->log, (size_t)i);
        if (km->tri[3 * t] >= 0) {
            set_key(km, t, cm_log_saved_key(km->log, (size_t)i));
            km->tang[(size_t)t * km->k] = NAN; /* its geometry may be restored */
            for (int j = 0; j < 3; j++) km->vdirty[km->tri[3 * t + j]] |= CM_DIRTY_OPTIMIZE;
            continue;
        }
        cm_heap_remove(&km->tq, t);
        for (int j = 0; j < 3; j++) cm_heap_remove(&km->eq, 3 * t + j);
    }
    return 0;
}

int cm_kmesh_tx_vertices(const cm_kmesh *km, cm_ibuf *out)
{
    long nt = cm_log_saved_count(km->log);
    if (nt < 0) return -1;
    for (long i = 0; i < nt; i++) {
        int32_t t = cm_log_saved_triangle(km->log, (size_t)i);
        if (km->tri[3 * t] >= 0)
            for (int j = 0; j < 3; j++)
                if (cm_ibuf_push(out, km->tri[3 * t + j])) return -1;
    }
    return 0;
}

void cm_kmesh_set_caps(cm_kmesh *km, double target, const double *bcap, const double *vcap)
{
    km->target = target;
    for (int32_t i = 0; i < km->n; i++) {
        km->bcap[i] = bcap ? bcap[i] : CM_PI;
        km->vcap[i] = vcap ? vcap[i] : CM_PI;
    }
    for (int32_t v = km->n; v < km->nv; v++) km->vcap[v] = CM_PI;
    for (int32_t t = 0; t < km->nt; t++)
        if (cm_kmesh_tri_live(km, t)) cm_kmesh_touch(km, t);
    for (int32_t t = 0; t < km->nt; t++) /* neighbours' slack is final now */
        if (cm_kmesh_tri_live(km, t))
            for (int32_t c = 3 * t; c < 3 * t + 3; c++) update_edge(km, c);
}

int cm_kmesh_allow_boundary_splits(cm_kmesh *km, cm_kmesh_between between, void *ctx, const int32_t *const *edge,
                                   const double *const *t)
{
    size_t c = (size_t)km->cap_v * km->k;
    if (!(km->bedge = malloc(c * sizeof *km->bedge)) || !(km->bt = malloc(c * sizeof *km->bt))) return -1;
    for (int32_t i = 0; i < km->n; i++)
        for (size_t g = 0; g < km->k; g++)
            km->bedge[km->k * (size_t)i + g] = edge[g][i], km->bt[km->k * (size_t)i + g] = t[g][i];
    km->between = between, km->between_ctx = ctx;
    for (int32_t tr = 0; tr < km->nt; tr++) /* the boundary edges become candidates */
        if (cm_kmesh_tri_live(km, tr))
            for (int32_t e = 3 * tr; e < 3 * tr + 3; e++) update_edge(km, e);
    return 0;
}

int cm_kmesh_corners_near(const cm_kmesh *km, int32_t t, int32_t out[12])
{
    int m = 0;
    for (int32_t c = 3 * t; c < 3 * t + 3; c++) out[m++] = c;
    for (int32_t c = 3 * t; c < 3 * t + 3; c++) {
        int32_t o = km->opp[c];
        if (o < 0) continue;
        for (int32_t d = 3 * (o / 3); d < 3 * (o / 3) + 3; d++) out[m++] = d;
    }
    return m;
}

void cm_kmesh_drop_candidates(cm_kmesh *km)
{
    while (cm_heap_pop(&km->eq) >= 0) {}
    for (int32_t i = 0; i < km->eq_npending; i++) km->eq_stale[km->eq_pending[i]] = 0;
    km->eq_npending = 0;
    km->eq_dropped = 1;
}

double cm_kmesh_min_angle(const cm_kmesh *km)
{
    double lo = CM_PI;
    for (int32_t t = 0; t < km->nt; t++)
        if (cm_kmesh_tri_live(km, t)) lo = fmin(lo, km->tkey[t]);
    return lo;
}

double cm_kmesh_rel_length(const cm_kmesh *km, size_t g, int32_t a, int32_t b)
{
    const double *p = cm_kmesh_pos(km, g, a), *q = cm_kmesh_pos(km, g, b);
    return hypot(q[0] - p[0], q[1] - p[1]) / km->scale[g];
}

double cm_kmesh_min_slack(const cm_kmesh *km)
{
    int32_t t = cm_heap_top(&km->tq);
    return t < 0 ? CM_PI : km->slack[t];
}

double cm_kmesh_min_share(const cm_kmesh *km)
{
    double least = HUGE_VAL;
    for (int32_t t = 0; t < km->nt; t++)
        if (cm_kmesh_tri_live(km, t)) least = fmin(least, km->tkey[t] / triangle_target(km, t));
    return least;
}

/* ---- construction ------------------------------------------------------- */

/* Pairs opposite corners. 0, -1 out of memory, -2 not a surface bounded
 * by the loops i -> bnext[i]. */
static int pair_corners(cm_kmesh *km)
{
    size_t nc = 3 * (size_t)km->nt;
    cm_edge_key *e = cm_mesh_edge_keys(km->tri, (size_t)km->nt);
    if (!e) return -1;
    int32_t boundary = 0;
    int status = 0;
    for (size_t i = 0; i < nc && status == 0;) {
        size_t j = i + 1;
        while (j < nc && e[j].lo == e[i].lo && e[j].hi == e[i].hi) j++;
        int32_t c = cm_prev(e[i].corner); /* the corner opposite the edge */
        if (j - i == 2) {
            int32_t d = cm_prev(e[i + 1].corner);
            if (km->tri[cm_next(c)] != km->tri[cm_prev(d)]) status = -2;
            km->opp[c] = d, km->opp[d] = c;
        } else if (j - i == 1) {
            int32_t a = km->tri[cm_next(c)], b = km->tri[cm_prev(c)];
            if (b != km->bnext[a]) status = -2;
            boundary++;
        } else {
            status = -2;
        }
        i = j;
    }
    free(e);
    return status == 0 && boundary != km->n ? -2 : status;
}

/* Every vertex must be one fan: closed inside, open on the boundary. */
static int check_fans(const cm_kmesh *km)
{
    int32_t *count = calloc((size_t)km->nv + 1, sizeof *count);
    cm_ibuf star = {0};
    if (!count) return -1;
    int status = 0;
    for (int32_t c = 0; c < 3 * km->nt; c++) count[km->tri[c]]++;
    for (int32_t v = 0; v < km->nv && status == 0; v++) {
        long m = km->vc[v] < 0 ? -2 : cm_kmesh_star(km, v, &star);
        if (m == -1) status = -1;
        else if (m < 0 || m != count[v]) status = -2;
    }
    free(count);
    cm_ibuf_free(&star);
    return status;
}

/* The area inside the boundary loops (the holes' clockwise loops count
 * negative). */
static double polygon_area(const double *xy, const int32_t *bnext, int32_t n)
{
    double sum = 0;
    for (int32_t i = 0; i < n; i++) {
        int32_t j = bnext[i];
        sum += xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
    }
    return 0.5 * sum;
}

cm_status cm_kmesh_build(cm_kmesh *km, const cm_mesh *m, size_t n)
{
    memset(km, 0, sizeof *km);
    if (m->nv > (size_t)INT32_MAX / 8 || m->nt > (size_t)INT32_MAX / 8 || n < 3 || m->nv < n)
        return CM_ERR_INTERNAL;
    km->k = m->k;
    km->n = (int32_t)n;
    km->xy = calloc(m->k, sizeof *km->xy);
    km->scale = malloc(m->k * sizeof *km->scale);
    if (!km->xy || !km->scale || cm_heap_init(&km->tq, 0) || cm_heap_init(&km->eq, 0) ||
        reserve_vertices(km, (int32_t)(m->nv + m->nv / 4 + 16)) ||
        reserve_triangles(km, (int32_t)(m->nt + m->nt / 4 + 16))) {
        cm_kmesh_free(km);
        return CM_ERR_NO_MEMORY;
    }
    for (size_t i = 0; i < n; i++) km->bnext[i] = (int32_t)cm_loops_next(m->loop_start, n, i);
    km->nb = (int32_t)n;
    km->nv = km->live_v = (int32_t)m->nv;
    km->nt = km->live_t = (int32_t)m->nt;
    for (size_t g = 0; g < m->k; g++) {
        memcpy(km->xy[g], m->xy[g], 2 * m->nv * sizeof *m->xy[g]);
        km->scale[g] = sqrt(fabs(polygon_area(m->xy[g], km->bnext, km->n)));
        if (!(km->scale[g] > 0)) km->scale[g] = 1;
    }
    for (size_t c = 0; c < 3 * m->nt; c++) {
        int32_t v = m->tri[c];
        if (v < 0 || (size_t)v >= m->nv) {
            cm_kmesh_free(km);
            return CM_ERR_INTERNAL;
        }
        km->tri[c] = v;
        km->vc[v] = (int32_t)c;
    }
    int s = pair_corners(km);
    if (s == 0) s = check_fans(km);
    if (s != 0) {
        cm_kmesh_free(km);
        return s == -1 ? CM_ERR_NO_MEMORY : CM_ERR_INTERNAL;
    }
    cm_kmesh_set_caps(km, 0.0, NULL, NULL);
    return CM_OK;
}

/* The written index of every slot (-1 dead): each loop of the boundary in
 * its order, a vertex added on an edge after the edge's start, then the
 * Steiner vertices in slot order. 0 or -1 out of memory. */
static int32_t *write_order(const cm_kmesh *km)
{
    int32_t *index = malloc(((size_t)km->nv + 1) * sizeof *index), next = 0;
    if (!index) return NULL;
    for (int32_t v = 0; v < km->nv; v++) index[v] = -1;
    for (int32_t i = 0; i < km->n; i++) {
        index[i] = next++;
        for (int32_t v = km->bnext[i]; v >= km->n; v = km->bnext[v]) index[v] = next++;
    }
    for (int32_t v = km->n; v < km->nv; v++)
        if (km->vc[v] >= 0 && !cm_kmesh_is_boundary(km, v)) index[v] = next++;
    return index;
}

void cm_kmesh_written_loops(const cm_kmesh *km, const size_t *loop_start, size_t num_loops, size_t *out)
{
    size_t written = 0, l = 0;
    for (int32_t i = 0; i < km->n; i++) { /* as write_order numbers them */
        while (l < num_loops && loop_start[l] == (size_t)i) out[l++] = written;
        written++;
        for (int32_t v = km->bnext[i]; v >= km->n; v = km->bnext[v]) written++;
    }
    while (l <= num_loops) out[l++] = written;
}

cm_status cm_kmesh_read_back(cm_kmesh *km, const cm_mesh *m, const int32_t *const *edge, const double *const *t)
{
    int32_t *index = write_order(km);
    if (!index) return CM_ERR_NO_MEMORY;
    for (int32_t v = 0; v < km->nv; v++) {
        int32_t i = index[v];
        if (i < 0) continue;
        for (size_t g = 0; g < km->k; g++) {
            memcpy(km->xy[g] + 2 * (size_t)v, m->xy[g] + 2 * (size_t)i, 2 * sizeof(double));
            if (edge && km->bedge && cm_kmesh_is_boundary(km, v))
                km->bedge[km->k * (size_t)v + g] = edge[g][i], km->bt[km->k * (size_t)v + g] = t[g][i];
        }
    }
    for (int32_t tr = 0; tr < km->nt; tr++)
        if (cm_kmesh_tri_live(km, tr)) cm_kmesh_touch(km, tr);
    free(index);
    return CM_OK;
}

cm_status cm_kmesh_write_labels(const cm_kmesh *km, int32_t **edge, double **t)
{
    int32_t *index = write_order(km);
    int ok = index != NULL;
    for (size_t g = 0; ok && g < km->k; g++) {
        int32_t *e = realloc(edge[g], (size_t)km->nb * sizeof *e);
        if (e) edge[g] = e;
        double *u = e ? realloc(t[g], (size_t)km->nb * sizeof *u) : NULL;
        if (u) t[g] = u;
        ok = e && u;
    }
    for (int32_t v = 0; ok && v < km->nv; v++) {
        int32_t i = index[v];
        if (i < 0 || !cm_kmesh_is_boundary(km, v)) continue;
        for (size_t g = 0; g < km->k; g++)
            edge[g][i] = km->bedge[km->k * (size_t)v + g], t[g][i] = km->bt[km->k * (size_t)v + g];
    }
    free(index);
    return ok ? CM_OK : CM_ERR_NO_MEMORY;
}

cm_status cm_kmesh_write(const cm_kmesh *km, cm_mesh *m)
{
    size_t nv = (size_t)km->live_v, nt = (size_t)km->live_t;
    int32_t *index = write_order(km);
    int32_t *tri = malloc((3 * nt + 1) * sizeof *tri);
    double **xy = calloc(km->k, sizeof *xy);
    int ok = index && tri && xy;
    for (size_t g = 0; ok && g < km->k; g++) ok = (xy[g] = malloc(2 * nv * sizeof *xy[g])) != NULL;
    if (!ok) {
        if (xy)
            for (size_t g = 0; g < km->k; g++) free(xy[g]);
        free(index), free(tri), free(xy);
        return CM_ERR_NO_MEMORY;
    }
    for (int32_t v = 0; v < km->nv; v++) {
        if (index[v] < 0) continue;
        for (size_t g = 0; g < km->k; g++) /* boundary coordinates: copied, never recomputed */
            memcpy(xy[g] + 2 * (size_t)index[v], km->xy[g] + 2 * (size_t)v, 2 * sizeof(double));
    }
    size_t out = 0;
    for (int32_t t = 0; t < km->nt; t++)
        if (cm_kmesh_tri_live(km, t))
            for (int i = 0; i < 3; i++) tri[out++] = index[km->tri[3 * t + i]];
    for (size_t g = 0; g < m->k; g++) free(m->xy[g]);
    free(m->xy), free(m->tri);
    m->xy = xy, m->tri = tri, m->nv = nv, m->nt = nt;
    free(index);
    return CM_OK;
}

/* ---- navigation --------------------------------------------------------- */

long cm_kmesh_star(const cm_kmesh *km, int32_t v, cm_ibuf *corners)
{
    corners->n = 0;
    int32_t start = km->vc[v], c = start;
    long guard = 3L * km->nt + 3;
    if (start < 0) return -2;
    if (cm_kmesh_is_boundary(km, v)) { /* back to the triangle on edge v -> bnext[v] */
        while (km->opp[cm_prev(c)] >= 0) {
            c = cm_prev(km->opp[cm_prev(c)]);
            if (--guard < 0 || c == start) return -2;
        }
        start = c;
    }
    for (;;) {
        if (cm_ibuf_push(corners, c)) return -1;
        int32_t o = km->opp[cm_next(c)];
        if (o < 0) return cm_kmesh_is_boundary(km, v) ? (long)corners->n : -2;
        c = cm_next(o);
        if (c == start) return cm_kmesh_is_boundary(km, v) ? -2 : (long)corners->n;
        if (--guard < 0) return -2;
    }
}

/* ---- operations --------------------------------------------------------- */

/* Every write below goes through these, so the undo log sees it first. */
static void set_corner(cm_kmesh *km, int32_t c, int32_t v)
{
    cm_log_triangle(km, c / 3);
    km->tri[c] = v;
}

static void link_corners(cm_kmesh *km, int32_t a, int32_t b)
{
    cm_log_triangle(km, a / 3);
    km->opp[a] = b;
    if (b >= 0) {
        cm_log_triangle(km, b / 3);
        km->opp[b] = a;
    }
}

static void set_vertex_corner(cm_kmesh *km, int32_t v, int32_t c)
{
    cm_log_vertex(km, v);
    km->vc[v] = c;
}

static void set_position(cm_kmesh *km, size_t g, int32_t v, const double p[2])
{
    cm_log_vertex(km, v);
    km->xy[g][2 * (size_t)v] = p[0];
    km->xy[g][2 * (size_t)v + 1] = p[1];
}

static void set_bnext(cm_kmesh *km, int32_t v, int32_t next)
{
    cm_log_vertex(km, v);
    km->bnext[v] = next;
}

void cm_kmesh_flip(cm_kmesh *km, int32_t c)
{
    int32_t o = km->opp[c];
    int32_t v0 = km->tri[c], v1 = km->tri[cm_next(c)], v2 = km->tri[cm_prev(c)], v3 = km->tri[o];
    int32_t b = km->opp[cm_next(o)], d = km->opp[cm_next(c)];
    /* (v0 v1 v2) + (v3 v2 v1)  ->  (v0 v1 v3) + (v3 v2 v0) */
    set_corner(km, cm_prev(c), v3);
    set_corner(km, cm_prev(o), v0);
    link_corners(km, c, b);
    link_corners(km, o, d);
    link_corners(km, cm_next(c), cm_next(o));
    set_vertex_corner(km, v0, c), set_vertex_corner(km, v1, cm_next(c));
    set_vertex_corner(km, v2, cm_next(o)), set_vertex_corner(km, v3, o);
    cm_kmesh_touch(km, c / 3);
    cm_kmesh_touch(km, o / 3);
}

/* A new vertex at pts (one point per geometry) and two new triangles, all
 * or nothing: the vertex, or -1 out of memory. */
static int32_t new_vertex_and_two_triangles(cm_kmesh *km, const double *pts, int32_t *ta, int32_t *tb)
{
    int32_t m = new_vertex(km);
    if (m < 0) return -1;
    *ta = new_triangle(km);
    if (*ta < 0) {
        push_free_vertex(km, m);
        return -1;
    }
    *tb = new_triangle(km);
    if (*tb < 0) {
        push_free_vertex(km, m), push_free_triangle(km, *ta);
        return -1;
    }
    for (size_t g = 0; g < km->k; g++) set_position(km, g, m, pts + 2 * g);
    return m;
}

int32_t cm_kmesh_split(cm_kmesh *km, int32_t c, const double *pts)
{
    int32_t ta, tb, m = new_vertex_and_two_triangles(km, pts, &ta, &tb);
    if (m < 0) return -1;
    int32_t o = km->opp[c];
    int32_t v0 = km->tri[c], v1 = km->tri[cm_next(c)], v2 = km->tri[cm_prev(c)], v3 = km->tri[o];
    int32_t d = km->opp[cm_next(c)], b = km->opp[cm_next(o)];
    int32_t a0 = 3 * ta, b0 = 3 * tb;
    /* (v0 v1 v2) + (v3 v2 v1) -> (v0 v1 m) (v0 m v2) (v3 v2 m) (v3 m v1) */
    set_corner(km, cm_prev(c), m);
    set_corner(km, cm_prev(o), m);
    set_corner(km, a0, v0), set_corner(km, a0 + 1, m), set_corner(km, a0 + 2, v2);
    set_corner(km, b0, v3), set_corner(km, b0 + 1, m), set_corner(km, b0 + 2, v1);
    link_corners(km, c, b0);
    link_corners(km, cm_next(c), a0 + 2);
    link_corners(km, a0, o);
    link_corners(km, a0 + 1, d);
    link_corners(km, cm_next(o), b0 + 2);
    link_corners(km, b0 + 1, b);
    set_vertex_corner(km, m, cm_prev(c)), set_vertex_corner(km, v0, c);
    set_vertex_corner(km, v1, cm_next(c)), set_vertex_corner(km, v2, a0 + 2);
    set_vertex_corner(km, v3, o);
    km->live_v++, km->live_t += 2;
    cm_kmesh_touch(km, c / 3), cm_kmesh_touch(km, o / 3);
    cm_kmesh_touch(km, ta), cm_kmesh_touch(km, tb);
    return m;
}

int32_t cm_kmesh_split_boundary(cm_kmesh *km, int32_t c, const double *pts, const int32_t *edge, const double *t)
{
    int32_t m = new_vertex(km);
    if (m < 0) return -1;
    int32_t ta = new_triangle(km);
    if (ta < 0) {
        push_free_vertex(km, m);
        return -1;
    }
    for (size_t g = 0; g < km->k; g++) set_position(km, g, m, pts + 2 * g);
    int32_t v0 = km->tri[c], v1 = km->tri[cm_next(c)], v2 = km->tri[cm_prev(c)], d = km->opp[cm_next(c)];
    int32_t a0 = 3 * ta;
    /* (v0 v1 v2), v1 -> v2 on the boundary  ->  (v0 v1 m) (v0 m v2) */
    set_corner(km, cm_prev(c), m);
    set_corner(km, a0, v0), set_corner(km, a0 + 1, m), set_corner(km, a0 + 2, v2);
    link_corners(km, a0, -1);
    link_corners(km, a0 + 1, d);
    link_corners(km, cm_next(c), a0 + 2);
    set_vertex_corner(km, m, cm_prev(c)), set_vertex_corner(km, v0, c);
    set_vertex_corner(km, v1, cm_next(c)), set_vertex_corner(km, v2, a0 + 2);
    set_bnext(km, m, v2), set_bnext(km, v1, m);
    /* Labels and cap are written once, on a new slot: an undo kills it. */
    km->bcap[m] = km->bcap[v1];
    for (size_t g = 0; g < km->k; g++) km->bedge[km->k * (size_t)m + g] = edge[g], km->bt[km->k * (size_t)m + g] = t[g];
    km->live_v++, km->live_t++, km->nb++;
    cm_kmesh_touch(km, c / 3), cm_kmesh_touch(km, ta);
    return m;
}

int32_t cm_kmesh_insert(cm_kmesh *km, int32_t t, const double *pts)
{
    int32_t ta, tb, m = new_vertex_and_two_triangles(km, pts, &ta, &tb);
    if (m < 0) return -1;
    int32_t c = 3 * t, v0 = km->tri[c], v1 = km->tri[c + 1], v2 = km->tri[c + 2];
    int32_t o1 = km->opp[c + 1];
    int32_t a0 = 3 * ta, b0 = 3 * tb;
    /* (v0 v1 v2) -> (m v1 v2) (v0 m v2) (v0 v1 m): corner i of each new
     * triangle keeps the edge opposite v_i in the old one. */
    set_corner(km, c, m);
    set_corner(km, a0, v0), set_corner(km, a0 + 1, m), set_corner(km, a0 + 2, v2);
    set_corner(km, b0, v0), set_corner(km, b0 + 1, v1), set_corner(km, b0 + 2, m);
    link_corners(km, a0 + 1, o1);
    link_corners(km, b0 + 2, km->opp[c + 2]);
    link_corners(km, c + 1, a0);       /* edge m v2 */
    link_corners(km, c + 2, b0);       /* edge v1 m */
    link_corners(km, a0 + 2, b0 + 1); /* edge v0 m */
    set_vertex_corner(km, m, c), set_vertex_corner(km, v0, a0);
    set_vertex_corner(km, v1, c + 1), set_vertex_corner(km, v2, c + 2);
    km->live_v++, km->live_t += 2;
    cm_kmesh_touch(km, t), cm_kmesh_touch(km, ta), cm_kmesh_touch(km, tb);
    return m;
}

uint32_t cm_kmesh_new_stamp(cm_kmesh *km)
{
    if (++km->stamp == 0) { /* wrapped: clear the old stamps */
        memset(km->mark, 0, (size_t)km->cap_v * sizeof *km->mark);
        km->stamp = 1;
    }
    return km->stamp;
}

static long star_index(const cm_ibuf *star, int32_t c)
{
    for (size_t i = 0; i < star->n; i++)
        if (star->a[i] == c) return (long)i;
    return -1;
}

int cm_kmesh_collapse_ok_topology(cm_kmesh *km, int32_t c, const cm_ibuf *star)
{
    long m = (long)star->n, j = star_index(star, c);
    if (j < 0 || m < 3) return 0;
    int32_t v = km->tri[c], u = km->tri[cm_next(c)];
    int32_t before = km->tri[cm_next(star->a[(j + m - 1) % m])];
    int32_t after = km->tri[cm_next(star->a[(j + 1) % m])];
    cm_kmesh_new_stamp(km);
    for (long i = 0; i < m; i++) {
        int32_t w = km->tri[cm_next(star->a[i])];
        if (w != u && w != before && w != after) km->mark[w] = km->stamp;
    }
    /* Walk u's fan without a buffer: any other common neighbour fails. */
    int32_t start = km->vc[u], e = start;
    if (cm_kmesh_is_boundary(km, u)) {
        while (km->opp[cm_prev(e)] >= 0) e = cm_prev(km->opp[cm_prev(e)]);
        start = e;
        if (km->mark[km->tri[cm_next(e)]] == km->stamp) return 0;
    }
    for (;;) {
        int32_t w = km->tri[cm_prev(e)];
        if (km->mark[w] == km->stamp && w != v) return 0;
        int32_t o = km->opp[cm_next(e)];
        if (o < 0) break;
        e = cm_next(o);
        if (e == start) break;
    }
    return 1;
}

static void kill_triangle(cm_kmesh *km, int32_t t)
{
    cm_log_triangle(km, t);
    for (int i = 0; i < 3; i++) {
        km->tri[3 * t + i] = -1, km->opp[3 * t + i] = -1;
        cm_heap_remove(&km->eq, 3 * t + i);
    }
    cm_heap_remove(&km->tq, t);
    push_free_triangle(km, t);
    km->live_t--;
}

void cm_kmesh_collapse(cm_kmesh *km, int32_t c, const cm_ibuf *star)
{
    long m = (long)star->n, j = star_index(star, c);
    const int32_t *s = star->a;
    int32_t v = km->tri[c], u = km->tri[cm_next(c)];
    int32_t cj = s[j], cb = s[(j + m - 1) % m], ca = s[(j + 1) % m], cbb = s[(j + m - 2) % m];
    int32_t x = km->opp[cj], y = km->opp[cb];
    link_corners(km, cm_prev(ca), x);
    link_corners(km, cm_next(cbb), y);
    for (long i = 0; i < m; i++)
        if (i != j && i != (j + m - 1) % m) set_corner(km, s[i], u);
    set_vertex_corner(km, u, ca);
    set_vertex_corner(km, km->tri[cm_next(ca)], cm_next(ca));
    set_vertex_corner(km, km->tri[cm_prev(cbb)], cm_prev(cbb));
    kill_triangle(km, cj / 3);
    kill_triangle(km, cb / 3);
    set_vertex_corner(km, v, -1);
    push_free_vertex(km, v);
    km->live_v--;
    for (long i = 0; i < m; i++)
        if (i != j && i != (j + m - 1) % m) cm_kmesh_touch(km, s[i] / 3);
}

void cm_kmesh_move(cm_kmesh *km, size_t g, int32_t v, const double p[2], const cm_ibuf *star)
{
    for (size_t i = 0; i < star->n; i++) cm_log_triangle(km, star->a[i] / 3); /* their keys change */
    set_position(km, g, v, p);
    for (size_t i = 0; i < star->n; i++) { /* only geometry g changed */
        int32_t t = star->a[i] / 3;
        set_key(km, t, fresh_key(km, t, g, cm_dirty_smooth(g) | cm_dirty_search(g) | CM_DIRTY_OPTIMIZE));
    }
}

void cm_kmesh_slide(cm_kmesh *km, size_t g, int32_t v, const double p[2], double t, const cm_ibuf *star)
{
    cm_log_vertex(km, v); /* before the label changes: the log keeps it */
    km->bt[km->k * (size_t)v + g] = t;
    cm_kmesh_move(km, g, v, p, star);
}

/* ---- full check ---------------------------------------------------------- */

int cm_kmesh_check(const cm_kmesh *km)
{
    int32_t boundary = 0, live = 0;
    for (int32_t t = 0; t < km->nt; t++) {
        if (!cm_kmesh_tri_live(km, t)) continue;
        live++;
        const int32_t *v = km->tri + 3 * (size_t)t;
        for (size_t g = 0; g < km->k; g++)
            if (!cm_kmesh_tri_ok(km, g, v[0], v[1], v[2])) return 0;
        for (int i = 0; i < 3; i++) {
            int32_t c = 3 * t + i, o = km->opp[c];
            int32_t a = km->tri[cm_next(c)], b = km->tri[cm_prev(c)];
            if (km->vc[v[i]] < 0 || km->tri[km->vc[v[i]]] != v[i]) return 0;
            if (o < 0) {
                if (b != km->bnext[a]) return 0;
                boundary++;
            } else if (km->opp[o] != c || km->tri[cm_next(o)] != b || km->tri[cm_prev(o)] != a) {
                return 0;
            }
        }
    }
    return boundary == km->nb && live == km->live_t;
}
