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
