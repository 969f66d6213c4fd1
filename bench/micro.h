/* micro.h - what the kernel micro-benchmarks (ssao_micro.c, hbao_micro.c) share: the
 * 1080p frame, clocks, sorting for medians, and the synthetic corner G-buffer they time
 * their kernels on. Header-only; not part of the library. */
#ifndef SSG_BENCH_MICRO_H
#define SSG_BENCH_MICRO_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "clock.h"
#include "graph/node.h"
#include "ssgraph.h"

enum { W = 1920, H = 1080 };

/* Runs the node's CPU kernel once to warm caches and threads, then `runs` times: the
   wall and process CPU milliseconds of each run into ms and cpu, sorted (medians at
   runs / 2). */
static inline void micro_time(const struct ssg_node_desc *d, const struct ssg_node_ctx *ctx,
                       const void *consts, const struct ssg_io *io, int runs, double *ms,
                       double *cpu)
{
    d->run_cpu(ctx, consts, io);
    for (int r = 0; r < runs; r++) {
        double t0 = clock_ms(CLOCK_MONOTONIC), c0 = clock_ms(CLOCK_PROCESS_CPUTIME_ID);
        d->run_cpu(ctx, consts, io);
        ms[r] = clock_ms(CLOCK_MONOTONIC) - t0;
        cpu[r] = clock_ms(CLOCK_PROCESS_CPUTIME_ID) - c0;
    }
    qsort(ms, (size_t)runs, sizeof *ms, cmp_double);
    qsort(cpu, (size_t)runs, sizeof *cpu, cmp_double);
}

/* An FNV-1a hash of the bits of n floats (to compare builds and variants), and their
   mean into *mean. */
static inline uint64_t micro_hash(const float *v, size_t n, double *mean)
{
    uint64_t hash = 1469598103934665603ull;
    double sum = 0;
    for (size_t i = 0; i < n; i++) {
        uint32_t bits;
        memcpy(&bits, &v[i], sizeof bits);
        hash = (hash ^ bits) * 1099511628211ull;
        sum += v[i];
    }
    *mean = sum / (double)n;
    return hash;
}

/* Ray-casts the corner; the floor gets a relief of height 0.05 by bending its normal
   and position along it (a G-buffer, not a consistent surface: enough for timing). */
static void make_gbuffer(const struct ssg_frame *frame, struct ssg_image *pos,
                         struct ssg_image *nrm)
{
    struct ssg_projection p = ssg_frame_projection(frame);
    const double s = sqrt(0.5);
    const double na[3] = {0, s, s}, nb[3] = {0, -s, s}, p0z = -5;
    size_t plane = (size_t)W * H;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double d[3] = {(x + 0.5 - p.cx) / p.f, -(y + 0.5 - p.cy) / p.f, -1};
            double da = na[0] * d[0] + na[1] * d[1] + na[2] * d[2];
            double db = nb[0] * d[0] + nb[1] * d[1] + nb[2] * d[2];
            double ta = da < 0 ? na[2] * p0z / da : INFINITY;
            double tb = db < 0 ? nb[2] * p0z / db : INFINITY;
            const double *n = ta < tb ? na : nb;
            double t = fmin(ta, tb);
            double bump = ta < tb ? 0.05 * sin(t * d[0] * 9.0) * sin(t * 7.0) : 0;
            double nn[3] = {n[0] + 0.3 * bump * 20, n[1], n[2]};
            double len = sqrt(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]);
            size_t o = (size_t)y * W + (size_t)x;
            for (int c = 0; c < 3; c++) {
                pos->data[c * plane + o] = (float)(t * d[c] + n[c] * bump);
                nrm->data[c * plane + o] = (float)(nn[c] / len);
            }
        }
}

#endif
