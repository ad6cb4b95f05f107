/* GMP's memory without aborts.
 *
 * GMP has no way to report a failed allocation: its default functions
 * abort the process. The core routes GMP's allocations through its own
 * functions, which fall back to a reserve when malloc fails, so the exact
 * computation under way finishes correctly, and mark the calling thread
 * out of memory; the next cancel check (progress.h) then stops the run and
 * the call returns CM_ERR_NO_MEMORY. The numbers the core keeps alive at
 * once are a few dozen of at most a few thousand bits, far inside the
 * reserve; only a reserve exhausted as well ends the process.
 *
 * The functions are installed once, at the first public call, and only
 * over GMP's defaults: a host program that installed its own keeps them. */
#ifndef CM_BASE_GMP_MEMORY_H
#define CM_BASE_GMP_MEMORY_H

/* Installs the functions (once per process; every public entry calls it)
 * and clears the calling thread's mark. */
void cm_gmp_memory_begin(void);
/* 1 when a GMP allocation of this thread needed the reserve since the
 * last cm_gmp_memory_begin. */
int cm_gmp_memory_exhausted(void);

#endif
