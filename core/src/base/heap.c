/* Indexed binary min-heap. */
#include <stdlib.h>

#include "base/heap.h"

int cm_heap_init(cm_heap *h, int32_t cap)
{
    h->ids = NULL, h->pos = NULL, h->key = NULL;
    h->size = h->cap = 0;
    return cm_heap_reserve(h, cap);
}

void cm_heap_free(cm_heap *h)
{
    free(h->ids), free(h->pos), free(h->key);
    h->ids = h->pos = NULL, h->key = NULL;
    h->size = h->cap = 0;
}

int cm_heap_reserve(cm_heap *h, int32_t cap)
{
    if (cap <= h->cap) return 0;
    int32_t c = h->cap ? h->cap : 16;
    while (c < cap) c *= 2;
    int32_t *ids = realloc(h->ids, (size_t)c * sizeof *ids);
    if (ids) h->ids = ids;
    int32_t *pos = realloc(h->pos, (size_t)c * sizeof *pos);
    if (pos) h->pos = pos;
    double *key = realloc(h->key, (size_t)c * sizeof *key);
    if (key) h->key = key;
    if (!ids || !pos || !key) return -1;
    for (int32_t i = h->cap; i < c; i++) h->pos[i] = -1;
    h->cap = c;
    return 0;
}

/* Smaller key first, equal keys by id: the order is total, so what the
 * heap yields never depends on the order of the updates that built it. */
static inline int before(const cm_heap *h, int32_t a, int32_t b)
{
    return h->key[a] < h->key[b] || (h->key[a] == h->key[b] && a < b);
}

static void place(cm_heap *h, int32_t i, int32_t id)
{
    h->ids[i] = id;
    h->pos[id] = i;
}

static void sift_up(cm_heap *h, int32_t i)
{
    int32_t id = h->ids[i];
    while (i > 0) {
        int32_t parent = (i - 1) / 2;
        if (!before(h, id, h->ids[parent])) break;
        place(h, i, h->ids[parent]);
        i = parent;
    }
    place(h, i, id);
}

static void sift_down(cm_heap *h, int32_t i)
{
    int32_t id = h->ids[i];
    for (;;) {
        int32_t child = 2 * i + 1;
        if (child >= h->size) break;
        if (child + 1 < h->size && before(h, h->ids[child + 1], h->ids[child])) child++;
        if (!before(h, h->ids[child], id)) break;
        place(h, i, h->ids[child]);
        i = child;
    }
    place(h, i, id);
}

void cm_heap_set(cm_heap *h, int32_t id, double key)
{
    int32_t i = h->pos[id];
    if (i < 0) {
        h->key[id] = key;
        place(h, h->size, id);
        sift_up(h, h->size++);
        return;
    }
    double old = h->key[id];
    h->key[id] = key;
    if (key < old) sift_up(h, i);
    else if (key > old) sift_down(h, i);
}

void cm_heap_remove(cm_heap *h, int32_t id)
{
    if (id >= h->cap) return;
    int32_t i = h->pos[id];
    if (i < 0) return;
    h->pos[id] = -1;
    int32_t last = h->ids[--h->size];
    if (i == h->size) return;
    place(h, i, last);
    sift_up(h, i);
    sift_down(h, h->pos[last]);
}

int32_t cm_heap_pop(cm_heap *h)
{
    int32_t id = cm_heap_top(h);
    if (id >= 0) cm_heap_remove(h, id);
    return id;
}

/* Best-first walk of the heap tree with a small heap of tree indices
 * (work, ordered by key): each step yields the next smallest key. */
int32_t cm_heap_smallest(const cm_heap *h, int32_t max, double below, int32_t *out,
                         int32_t *work)
{
    int32_t count = 0, nw = 0;
    if (h->size == 0 || max <= 0) return 0;
    work[nw++] = 0;
    while (nw > 0 && count < max) {
        int32_t best = 0; /* the frontier stays below 2 * max: a linear scan is enough */
        for (int32_t j = 1; j < nw; j++)
            if (before(h, h->ids[work[j]], h->ids[work[best]])) best = j;
        int32_t i = work[best];
        work[best] = work[--nw];
        if (h->key[h->ids[i]] >= below) break;
        out[count++] = h->ids[i];
        for (int32_t child = 2 * i + 1; child <= 2 * i + 2; child++)
            if (child < h->size) work[nw++] = child;
    }
    return count;
}
