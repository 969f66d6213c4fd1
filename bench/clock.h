/* clock.h - what every benchmark under bench/ times with: a clock in milliseconds and the
 * comparison qsort needs for medians. Header-only; not part of the library. */
#ifndef SSG_BENCH_CLOCK_H
#define SSG_BENCH_CLOCK_H

#include <time.h>

static inline double clock_ms(clockid_t clock)
{
    struct timespec ts;
    clock_gettime(clock, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

static inline int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

#endif
