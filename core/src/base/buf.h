/* Growable arrays: a list of int32 ids, a work list without duplicates,
 * and the doubling rule every other growable array uses. */
#ifndef CM_BASE_BUF_H
#define CM_BASE_BUF_H

#include <stddef.h>
#include <stdint.h>

/* Makes room for `need` elements of `elem` bytes in *p (capacity *cap),
 * doubling. 0, or CM_NO_MEMORY (*p unchanged). */
int cm_grow(void **p, size_t *cap, size_t need, size_t elem);

typedef struct cm_ibuf {
    int32_t *a;
    size_t n, cap;
} cm_ibuf;

/* cm_ibuf_push when b is full. */
int cm_ibuf_push_grow(cm_ibuf *b, int32_t x);
/* 0, or CM_NO_MEMORY. Inline: the remesher's work lists push in every step. */
static inline int cm_ibuf_push(cm_ibuf *b, int32_t x)
{
    if (b->n == b->cap) return cm_ibuf_push_grow(b, x);
    b->a[b->n++] = x;
    return 0;
}
void cm_ibuf_free(cm_ibuf *b);

/* A work list of ids (vertices or corners) without duplicates. */
typedef struct cm_work {
    cm_ibuf items;
    unsigned char *queued; /* id -> 1 while in items */
    size_t cap;
} cm_work;

/* cm_work_push when id is beyond w->cap. */
int cm_work_push_grow(cm_work *w, int32_t id);
static inline int cm_work_push(cm_work *w, int32_t id) /* 0, or CM_NO_MEMORY */
{
    if ((size_t)id >= w->cap) return cm_work_push_grow(w, id);
    if (w->queued[id]) return 0;
    int s = cm_ibuf_push(&w->items, id);
    if (!s) w->queued[id] = 1;
    return s;
}
int32_t cm_work_pop(cm_work *w);          /* -1 when empty */
void cm_work_free(cm_work *w);

#endif
