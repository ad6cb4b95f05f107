/* Growable arrays (buf.h). */
#include <stdlib.h>
#include <string.h>

#include "base/buf.h"
#include "base/error.h"

int cm_grow(void **p, size_t *cap, size_t need, size_t elem)
{
    if (need <= *cap) return 0;
    size_t c = *cap ? *cap : 16;
    while (c < need) c *= 2;
    void *q = realloc(*p, c * elem);
    if (!q) return CM_NO_MEMORY;
    *p = q;
    *cap = c;
    return 0;
}

int cm_ibuf_push_grow(cm_ibuf *b, int32_t x)
{
    if (b->n == b->cap) {
        size_t cap = b->cap ? 2 * b->cap : 32;
        int32_t *a = realloc(b->a, cap * sizeof *a);
        if (!a) return CM_NO_MEMORY;
        b->a = a, b->cap = cap;
    }
    b->a[b->n++] = x;
    return 0;
}

void cm_ibuf_free(cm_ibuf *b)
{
    free(b->a);
    b->a = NULL, b->n = b->cap = 0;
}

int cm_work_push_grow(cm_work *w, int32_t id)
{
    if ((size_t)id >= w->cap) {
        size_t cap = w->cap ? w->cap : 64;
        while (cap <= (size_t)id) cap *= 2;
        unsigned char *q = realloc(w->queued, cap);
        if (!q) return CM_NO_MEMORY;
        memset(q + w->cap, 0, cap - w->cap);
        w->queued = q, w->cap = cap;
    }
    if (w->queued[id]) return 0;
    if (cm_ibuf_push(&w->items, id)) return CM_NO_MEMORY;
    w->queued[id] = 1;
    return 0;
}

int32_t cm_work_pop(cm_work *w)
{
    if (!w->items.n) return -1;
    int32_t id = w->items.a[--w->items.n];
    w->queued[id] = 0;
    return id;
}

void cm_work_free(cm_work *w)
{
    cm_ibuf_free(&w->items);
    free(w->queued);
    w->queued = NULL, w->cap = 0;
}
