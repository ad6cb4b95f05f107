/* The mesh's undo log. Copy on first write: within a transaction every
 * triangle slot and vertex is saved before its first change, and every
 * free-list operation is recorded, so a rollback restores the mesh
 * exactly; kmesh.c then re-keys the restored triangles. The log only
 * records and restores: it calls nothing in kmesh.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "remesh/kmesh.h"
#include "remesh/kmesh_log.h"

typedef struct { double *a; size_t n, cap; } cm_dbuf;

struct cm_kmesh_log {
    int active, failed;
    uint32_t id;
    uint32_t *tseen, *vseen; /* slot -> id of the transaction that saved it */
    size_t tcap, vcap;
    cm_ibuf tsave;           /* 7 per triangle: t, tri[3], opp[3] */
    cm_ibuf vsave;           /* 3 per vertex: v, vc, bnext */
    cm_dbuf keys;            /* tkey per saved triangle (NaN: was dead) */
    cm_dbuf pos;             /* 2k per saved vertex */
    cm_dbuf bt;              /* k per saved vertex with boundary labels */
    cm_ibuf flog;            /* free-list operations, 4 * value + kind */
    cm_ibuf dlog;            /* vdirty changes, 2 per change: v, old value */
    int32_t nv, nt, live_v, live_t, nb;
};

static int grow_seen(uint32_t **seen, size_t *cap, size_t need)
{
    if (need <= *cap) return 0;
    size_t c = *cap ? *cap : 64;
    while (c < need) c *= 2;
    uint32_t *a = realloc(*seen, c * sizeof *a);
    if (!a) return -1;
    memset(a + *cap, 0, (c - *cap) * sizeof *a);
    *seen = a, *cap = c;
    return 0;
}

static int push_double(cm_dbuf *b, double x)
{
    if (b->n == b->cap) {
        size_t c = b->cap ? 2 * b->cap : 256;
        double *a = realloc(b->a, c * sizeof *a);
        if (!a) return -1;
        b->a = a, b->cap = c;
    }
    b->a[b->n++] = x;
    return 0;
}

static int logging(const cm_kmesh *km)
{
    return km->log && km->log->active && !km->log->failed;
}

/* 1 when slot id is changed for the first time in this transaction (it
 * is marked as saved now), 0 when saved already. */
static int first_change(struct cm_kmesh_log *log, uint32_t **seen, size_t *cap, int32_t id)
{
    if (grow_seen(seen, cap, (size_t)id + 1)) {
        log->failed = 1;
        return 0;
    }
    if ((*seen)[id] == log->id) return 0;
    (*seen)[id] = log->id;
    return 1;
}

void cm_log_triangle(cm_kmesh *km, int32_t t)
{
    if (!logging(km)) return;
    struct cm_kmesh_log *log = km->log;
    if (!first_change(log, &log->tseen, &log->tcap, t)) return;
    int32_t rec[7] = {t};
    for (int i = 0; i < 3; i++) rec[1 + i] = km->tri[3 * t + i], rec[4 + i] = km->opp[3 * t + i];
    for (int i = 0; i < 7; i++)
        if (cm_ibuf_push(&log->tsave, rec[i])) goto fail;
    if (push_double(&log->keys, km->tri[3 * t] >= 0 ? km->tkey[t] : NAN)) goto fail;
    return;
fail:
    log->failed = 1;
}

void cm_log_vertex(cm_kmesh *km, int32_t v)
{
    if (!logging(km)) return;
    struct cm_kmesh_log *log = km->log;
    if (!first_change(log, &log->vseen, &log->vcap, v)) return;
    if (cm_ibuf_push(&log->vsave, v) || cm_ibuf_push(&log->vsave, km->vc[v]) || cm_ibuf_push(&log->vsave, km->bnext[v]))
        goto fail;
    for (size_t g = 0; g < km->k; g++)
        if (push_double(&log->pos, km->xy[g][2 * (size_t)v]) || push_double(&log->pos, km->xy[g][2 * (size_t)v + 1]))
            goto fail;
    for (size_t g = 0; km->bt && g < km->k; g++) /* a slid boundary point's parameter */
        if (push_double(&log->bt, km->bt[km->k * (size_t)v + g])) goto fail;
    return;
fail:
    log->failed = 1;
}

void cm_log_dirty(cm_kmesh *km, int32_t v)
{
    if (logging(km) && (cm_ibuf_push(&km->log->dlog, v) || cm_ibuf_push(&km->log->dlog, km->vdirty[v])))
        km->log->failed = 1;
}

void cm_log_free_list(cm_kmesh *km, int32_t value, int kind)
{
    if (logging(km) && cm_ibuf_push(&km->log->flog, 4 * value + kind)) km->log->failed = 1;
}

int cm_kmesh_tx_begin(cm_kmesh *km)
{
    if (!km->log && !(km->log = calloc(1, sizeof *km->log))) return -1;
    struct cm_kmesh_log *log = km->log;
    if (++log->id == 0) { /* wrapped: forget the old marks */
        memset(log->tseen, 0, log->tcap * sizeof *log->tseen);
        memset(log->vseen, 0, log->vcap * sizeof *log->vseen);
        log->id = 1;
    }
    log->active = 1, log->failed = 0;
    log->tsave.n = log->vsave.n = log->flog.n = log->dlog.n = 0, log->keys.n = log->pos.n = log->bt.n = 0;
    log->nv = km->nv, log->nt = km->nt, log->live_v = km->live_v, log->live_t = km->live_t, log->nb = km->nb;
    return 0;
}

int cm_kmesh_tx_region(const cm_kmesh *km, double *before, double *after)
{
    const struct cm_kmesh_log *log = km->log;
    *before = *after = CM_PI;
    if (!log || log->failed) return -1;
    for (size_t i = 0; i < log->tsave.n / 7; i++) {
        int32_t t = log->tsave.a[7 * i];
        double old = log->keys.a[i];
        if (!isnan(old)) *before = fmin(*before, old);
        if (km->tri[3 * t] >= 0) *after = fmin(*after, km->tkey[t]);
    }
    return 0;
}

void cm_kmesh_tx_commit(cm_kmesh *km)
{
    if (km->log) km->log->active = 0;
}

static void undo_free_lists(cm_kmesh *km)
{
    const cm_ibuf *f = &km->log->flog;
    for (size_t i = f->n; i-- > 0;) {
        int32_t value = f->a[i] / 4;
        switch (f->a[i] % 4) {
        case CM_LOG_POP_V: km->free_v.a[km->free_v.n++] = value; break;
        case CM_LOG_PUSH_V: km->free_v.n--; break;
        case CM_LOG_POP_T: km->free_t.a[km->free_t.n++] = value; break;
        case CM_LOG_PUSH_T: km->free_t.n--; break;
        }
    }
}

long cm_log_undo(cm_kmesh *km)
{
    struct cm_kmesh_log *log = km->log;
    if (!log || !log->active) return 0;
    log->active = 0;
    if (log->failed) return -1;
    undo_free_lists(km);
    size_t nt = log->tsave.n / 7, d = 0, l = 0;
    for (size_t i = 0; i < nt; i++) {
        const int32_t *rec = log->tsave.a + 7 * i;
        for (int j = 0; j < 3; j++) km->tri[3 * rec[0] + j] = rec[1 + j], km->opp[3 * rec[0] + j] = rec[4 + j];
    }
    for (size_t i = 0; i < log->vsave.n / 3; i++) {
        int32_t v = log->vsave.a[3 * i];
        km->vc[v] = log->vsave.a[3 * i + 1], km->bnext[v] = log->vsave.a[3 * i + 2];
        for (size_t g = 0; g < km->k; g++, d += 2)
            km->xy[g][2 * (size_t)v] = log->pos.a[d], km->xy[g][2 * (size_t)v + 1] = log->pos.a[d + 1];
        for (size_t g = 0; km->bt && g < km->k; g++) km->bt[km->k * (size_t)v + g] = log->bt.a[l++];
    }
    for (size_t i = log->dlog.n / 2; i-- > 0;) km->vdirty[log->dlog.a[2 * i]] = (uint16_t)log->dlog.a[2 * i + 1];
    km->nv = log->nv, km->nt = log->nt, km->live_v = log->live_v, km->live_t = log->live_t, km->nb = log->nb;
    return (long)nt;
}

long cm_log_saved_count(const struct cm_kmesh_log *log)
{
    return !log ? 0 : log->failed ? -1 : (long)(log->tsave.n / 7);
}

int32_t cm_log_saved_triangle(const struct cm_kmesh_log *log, size_t i)
{
    return log->tsave.a[7 * i];
}

double cm_log_saved_key(const struct cm_kmesh_log *log, size_t i)
{
    return log->keys.a[i];
}

void cm_kmesh_log_free(struct cm_kmesh_log *log)
{
    if (!log) return;
    free(log->tseen), free(log->vseen), free(log->keys.a), free(log->pos.a), free(log->bt.a);
    cm_ibuf_free(&log->tsave), cm_ibuf_free(&log->vsave), cm_ibuf_free(&log->flog), cm_ibuf_free(&log->dlog);
    free(log);
}
