/* Comparators for qsort over plain values. */
#ifndef CM_BASE_ORDER_H
#define CM_BASE_ORDER_H

/* Ascending doubles (no NaN expected). */
int cm_compare_doubles(const void *a, const void *b);

#endif
