/* GMP's allocation functions with a reserve (gmp_memory.h). */
#include <pthread.h>
#include <stdalign.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gmp.h>

#include "base/gmp_memory.h"

/* GMP's own functions, exported by libgmp; declared here because gmp.h
 * does not. Only compared against, to leave a host's functions alone. */
void *__gmp_default_allocate(size_t);
void *__gmp_default_reallocate(void *, size_t, size_t);
void __gmp_default_free(void *, size_t);

/* The reserve: bump allocation, emptied when its last block is freed. */
#define RESERVE_BYTES (1u << 20)
static alignas(max_align_t) unsigned char reserve[RESERVE_BYTES];
static size_t reserve_used, reserve_live;
static pthread_mutex_t reserve_lock = PTHREAD_MUTEX_INITIALIZER;

static _Thread_local int exhausted;

static int in_reserve(const void *p)
{
    uintptr_t a = (uintptr_t)p, r = (uintptr_t)reserve;
    return a >= r && a < r + RESERVE_BYTES;
}

static void *from_reserve(size_t size)
{
    size_t step = (size + alignof(max_align_t) - 1) / alignof(max_align_t) * alignof(max_align_t);
    void *p = NULL;
    pthread_mutex_lock(&reserve_lock);
    if (step <= RESERVE_BYTES - reserve_used) {
        p = reserve + reserve_used;
        reserve_used += step;
        reserve_live++;
    }
    pthread_mutex_unlock(&reserve_lock);
    if (!p) {
        /* Both the heap and the reserve are gone; GMP cannot be told. */
        fputs("compatmesh: out of memory inside GMP, reserve exhausted\n", stderr);
        abort();
    }
    exhausted = 1;
    return p;
}

static void release(void *p)
{
    if (!in_reserve(p)) {
        free(p);
        return;
    }
    pthread_mutex_lock(&reserve_lock);
    if (--reserve_live == 0) reserve_used = 0;
    pthread_mutex_unlock(&reserve_lock);
}

static void *gmp_allocate(size_t size)
{
    void *p = malloc(size);
    return p ? p : from_reserve(size);
}

static void *gmp_reallocate(void *old, size_t old_size, size_t new_size)
{
    if (!in_reserve(old)) {
        void *p = realloc(old, new_size);
        if (p) return p;
    }
    /* A reserve block, or realloc failed (the old block is still valid). */
    void *p = malloc(new_size);
    if (!p) p = from_reserve(new_size);
    memcpy(p, old, old_size < new_size ? old_size : new_size);
    release(old);
    return p;
}

static void gmp_free(void *p, size_t size)
{
    (void)size;
    release(p);
}

static void install(void)
{
    void *(*a)(size_t);
    void *(*r)(void *, size_t, size_t);
    void (*f)(void *, size_t);
    mp_get_memory_functions(&a, &r, &f);
    /* Blocks GMP's defaults made before are malloc's: ours free them. */
    if (a == __gmp_default_allocate && r == __gmp_default_reallocate && f == __gmp_default_free)
        mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_free);
}

void cm_gmp_memory_begin(void)
{
    static pthread_once_t once = PTHREAD_ONCE_INIT;
    pthread_once(&once, install);
    exhausted = 0;
}

int cm_gmp_memory_exhausted(void) { return exhausted; }
