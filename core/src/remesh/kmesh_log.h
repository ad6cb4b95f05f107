/* The undo log behind the mesh's transactions, for kmesh.c only: every
 * change to a triangle slot, a vertex or a free list goes through the
 * hooks first (no-ops outside a transaction; a vertex's record holds its
 * corner, position, bnext and, with boundary labels, its parameters); cm_log_undo restores what
 * they saved. */
#ifndef CM_KMESH_LOG_H
#define CM_KMESH_LOG_H

#include "remesh/kmesh.h"

enum { CM_LOG_POP_V, CM_LOG_PUSH_V, CM_LOG_POP_T, CM_LOG_PUSH_T };

void cm_log_triangle(cm_kmesh *km, int32_t t);
void cm_log_vertex(cm_kmesh *km, int32_t v);
/* Before km->vdirty[v] changes. */
void cm_log_dirty(cm_kmesh *km, int32_t v);
void cm_log_free_list(cm_kmesh *km, int32_t value, int kind);
void cm_kmesh_log_free(struct cm_kmesh_log *log);
/* Restores every saved triangle slot, vertex, dirty flag and free list and ends the
 * transaction. Returns the number of saved triangles (their keys and heap
 * entries are stale: the caller refreshes them), 0 outside a transaction,
 * -1 when the log ran out of memory (the changes then stay). */
long cm_log_undo(cm_kmesh *km);
/* The number of triangle slots the open or last transaction saved, -1
 * when its log ran out of memory. */
long cm_log_saved_count(const struct cm_kmesh_log *log);
/* The i-th triangle slot the open or just undone transaction saved. */
int32_t cm_log_saved_triangle(const struct cm_kmesh_log *log, size_t i);
/* Its key before the transaction (NaN: the slot was dead). */
double cm_log_saved_key(const struct cm_kmesh_log *log, size_t i);

#endif
