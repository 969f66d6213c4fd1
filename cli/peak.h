/* peak.h - the machine's measured limits (bench/peak.c measures them once and caches them)
 * and each profiled node's achieved fraction of them: a roofline, the node's least memory
 * traffic and declared flops against the run's time. */
#ifndef SSG_CLI_PEAK_H
#define SSG_CLI_PEAK_H

#include <stddef.h>

#include "ssgraph.h"

struct ssg_peak {
    int threads;   /* threads the peaks were measured on */
    double gflops; /* vector FMA throughput, the widest the CPU has */
    double gbps;   /* STREAM triad bandwidth */
};

/* The cache file: $SSGRAPH_PEAK, else $XDG_CACHE_HOME/ssgraph/peak.json, else
 * $HOME/.cache/ssgraph/peak.json; 0 when none can be named. */
int ssg_peak_path(char *out, size_t len);
/* Reads the cache; 0 when there is none or it is not peak's (then *p is zeroed). */
int ssg_peak_load(struct ssg_peak *p);

/* A node's rates over its average run: GB/s and GFLOP/s (-1 when it declares no flops);
 * with a peak, which bound applies ("memory" or "compute", the larger of bytes / bandwidth
 * and flops / (peak flops scaled to the run's threads)) and the run's fraction of it
 * (bound time / measured time); bound NULL and fraction -1 when it cannot be said. */
struct ssg_rates {
    double gbps, gflops;
    const char *bound;
    double fraction;
};
void ssg_rates_of(const struct ssg_run_node *n, int threads, const struct ssg_peak *peak,
                  struct ssg_rates *r);

#endif
