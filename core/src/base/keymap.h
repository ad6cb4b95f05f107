/* An open-addressing hash map from nonzero 64-bit keys to 64-bit values,
 * growing at half load: the edges of a triangle list by their vertex
 * pairs, the remesher's tried moves by their keys. */
#ifndef CM_BASE_KEYMAP_H
#define CM_BASE_KEYMAP_H

#include <stddef.h>
#include <stdint.h>

typedef struct cm_keymap {
    uint64_t *keys; /* 0: an empty slot */
    int64_t *vals;
    size_t cap, used;
} cm_keymap;

/* The key of the unordered vertex pair {a, b} (a, b >= 0): never 0. */
static inline uint64_t cm_pair_key(int32_t a, int32_t b)
{
    uint64_t lo = (uint32_t)(a < b ? a : b), hi = (uint32_t)(a < b ? b : a);
    return (hi << 32 | lo) + 1;
}

/* Room for n keys without growing. 0, or -1 out of memory. */
int cm_keymap_reserve(cm_keymap *m, size_t n);

/* key's value, or NULL where key is not in the map. */
int64_t *cm_keymap_find(const cm_keymap *m, uint64_t key);

/* key's value, added with value 0 (and *added set) where it was not in
 * the map; NULL out of memory. The pointer holds until the next put. */
int64_t *cm_keymap_put(cm_keymap *m, uint64_t key, int *added);

/* Every key removed; the memory kept. */
void cm_keymap_clear(cm_keymap *m);

void cm_keymap_free(cm_keymap *m);

#endif
