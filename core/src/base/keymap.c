/* The key map (keymap.h): linear probing from a Fibonacci hash. */
#include "base/keymap.h"

#include <stdlib.h>
#include <string.h>

static size_t slot_of(const uint64_t *keys, size_t cap, uint64_t key)
{
    size_t i = (size_t)((key * 0x9E3779B97F4A7C15ull) >> 17) & (cap - 1);
    while (keys[i] && keys[i] != key) i = (i + 1) & (cap - 1);
    return i;
}

int cm_keymap_reserve(cm_keymap *m, size_t n)
{
    size_t cap = m->cap ? m->cap : 16;
    while (cap < 2 * n + 2) cap *= 2;
    if (cap == m->cap) return 0;
    uint64_t *keys = calloc(cap, sizeof *keys);
    int64_t *vals = malloc(cap * sizeof *vals);
    if (!keys || !vals) {
        free(keys), free(vals);
        return -1;
    }
    for (size_t i = 0; i < m->cap; i++)
        if (m->keys[i]) {
            size_t j = slot_of(keys, cap, m->keys[i]);
            keys[j] = m->keys[i], vals[j] = m->vals[i];
        }
    free(m->keys), free(m->vals);
    m->keys = keys, m->vals = vals, m->cap = cap;
    return 0;
}

int64_t *cm_keymap_find(const cm_keymap *m, uint64_t key)
{
    if (!m->cap) return NULL;
    size_t i = slot_of(m->keys, m->cap, key);
    return m->keys[i] ? m->vals + i : NULL;
}

int64_t *cm_keymap_put(cm_keymap *m, uint64_t key, int *added)
{
    if (cm_keymap_reserve(m, m->used + 1)) return NULL;
    size_t i = slot_of(m->keys, m->cap, key);
    *added = !m->keys[i];
    if (*added) m->keys[i] = key, m->vals[i] = 0, m->used++;
    return m->vals + i;
}

void cm_keymap_clear(cm_keymap *m)
{
    if (m->cap) memset(m->keys, 0, m->cap * sizeof *m->keys);
    m->used = 0;
}

void cm_keymap_free(cm_keymap *m)
{
    free(m->keys), free(m->vals);
    memset(m, 0, sizeof *m);
}
