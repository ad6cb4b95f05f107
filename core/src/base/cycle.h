/* Index neighbours in a cycle of m items (0 <= i < m), without the
 * division of (i + 1) % m: a polygon walk's innermost step. */
#ifndef CM_CYCLE_H
#define CM_CYCLE_H

static inline long cm_cycle_next(long i, long m) { return i + 1 < m ? i + 1 : 0; }
static inline long cm_cycle_prev(long i, long m) { return i > 0 ? i - 1 : m - 1; }

#endif
