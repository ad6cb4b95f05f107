/* Wall-clock seconds, for the stats' stage times and report throttling. */
#ifndef CM_BASE_CLOCK_H
#define CM_BASE_CLOCK_H

double cm_seconds_now(void);

#endif
