/* Sets of common diagonals; see diagset.h. */
#include "construct/diagset.h"

#include <stdlib.h>

int cm_diagset_init(cm_diagset *s, long n)
{
    s->n = n, s->stride = ((size_t)n + 63) / 64;
    s->bits = calloc(s->stride * (size_t)(n > 0 ? n : 1), sizeof *s->bits);
    return s->bits ? 0 : -1;
}

void cm_diagset_clear(cm_diagset *s)
{
    free(s->bits);
    s->bits = NULL, s->n = 0, s->stride = 0;
}

int cm_diagset_from_matrix(cm_diagset *s, long n, const unsigned char *matrix)
{
    if (cm_diagset_init(s, n) != 0) return -1;
    for (long i = 0; i < n; i++)
        for (long j = 0; j < n; j++)
            if (matrix[(size_t)i * (size_t)n + (size_t)j]) s->bits[(size_t)i * s->stride + (size_t)j / 64] |= (uint64_t)1 << (j % 64);
    return 0;
}

int cm_diagrows_open(cm_diagrows *r, const cm_diagview *view, long m)
{
    const cm_diagset *set = view->set;
    r->view = view;
    r->member = calloc(set->stride > 0 ? set->stride : 1, sizeof *r->member);
    r->local_of = malloc((size_t)(set->n > 0 ? set->n : 1) * sizeof *r->local_of);
    if (!r->member || !r->local_of) {
        cm_diagrows_close(r);
        return -1;
    }
    for (long i = 0; i < m; i++) {
        long x = view->map ? view->map[i] : i;
        r->member[x / 64] |= (uint64_t)1 << (x % 64);
        r->local_of[x] = (int32_t)i;
    }
    return 0;
}

long cm_diagrows_row(const cm_diagrows *r, long a, int32_t *out)
{
    const cm_diagset *set = r->view->set;
    long x = r->view->map ? r->view->map[a] : a, count = 0;
    const uint64_t *row = set->bits + (size_t)x * set->stride;
    for (size_t w = 0; w < set->stride; w++)
        for (uint64_t bits = row[w] & r->member[w]; bits; bits &= bits - 1)
            out[count++] = r->local_of[64 * w + (size_t)cm_lowest_bit(bits)];
    return count;
}

void cm_diagrows_close(cm_diagrows *r)
{
    free(r->member), free(r->local_of);
    r->member = NULL, r->local_of = NULL;
}
