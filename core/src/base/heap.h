/* An indexed binary min-heap over ids 0..cap-1, keyed by doubles (equal
 * keys: the smaller id first): the remesher's priority queues (worst
 * triangle first, best collapse first) with O(log n) insert, update and
 * removal by id. */
#ifndef CM_HEAP_H
#define CM_HEAP_H

#include <stddef.h>
#include <stdint.h>

typedef struct cm_heap {
    int32_t *ids;  /* heap order */
    int32_t *pos;  /* id -> index in ids, -1 when absent */
    double *key;   /* id -> key */
    int32_t size, cap;
} cm_heap;

/* Returns 0, or -1 out of memory (the heap is then empty but usable). */
int cm_heap_init(cm_heap *h, int32_t cap);
void cm_heap_free(cm_heap *h);
/* Makes room for ids < cap. Returns 0 or -1 out of memory. */
int cm_heap_reserve(cm_heap *h, int32_t cap);
/* Inserts id or changes its key. */
void cm_heap_set(cm_heap *h, int32_t id, double key);
void cm_heap_remove(cm_heap *h, int32_t id);
static inline int cm_heap_contains(const cm_heap *h, int32_t id)
{
    return id < h->cap && h->pos[id] >= 0;
}
/* Smallest key's id, -1 when empty. */
static inline int32_t cm_heap_top(const cm_heap *h) { return h->size ? h->ids[0] : -1; }
int32_t cm_heap_pop(cm_heap *h);

/* Writes up to max ids with the smallest keys below `below`, smallest
 * first, into out (scratch: 2 * max ints of work space after out[max]).
 * Returns how many. Does not change the heap. */
int32_t cm_heap_smallest(const cm_heap *h, int32_t max, double below, int32_t *out,
                         int32_t *work);

#endif
