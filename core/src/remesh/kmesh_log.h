/* The undo log's hooks, for kmesh.c: every change to a triangle slot, a
 * vertex or a free list goes through them first. No-ops outside a
 * transaction. */
#ifndef CM_KMESH_LOG_H
#define CM_KMESH_LOG_H

#include "remesh/kmesh.h"

enum { CM_LOG_POP_V, CM_LOG_PUSH_V, CM_LOG_POP_T, CM_LOG_PUSH_T };

void cm_log_triangle(cm_kmesh *km, int32_t t);
void cm_log_vertex(cm_kmesh *km, int32_t v);
void cm_log_free_list(cm_kmesh *km, int32_t value, int kind);
void cm_kmesh_log_free(struct cm_kmesh_log *log);

#endif
