/* hbao_cpu.h - private to the CPU kernel of the `hbao` node: the job that hbao_cpu.c
 * (the integrator, the hot code) and hbao_pattern.c (the pattern prepared before it)
 * share. Method and geometry are in README.md, the kernel's layout in hbao_cpu.c, the
 * march it runs on in nodes/common/horizon.h. A job is filled once per run by
 * ssg_hbao_run_cpu (its pattern rows by ssg_hbao_pattern_unroll), then only read by the
 * bands that run in parallel; the caller owns the pattern rows and frees them. */
#ifndef SSG_HBAO_CPU_H
#define SSG_HBAO_CPU_H

#include "common/horizon.h"
#include "hbao.h"

/* One run of the kernel: its inputs, tables and output (filled by ssg_hbao_run_cpu). */
struct job {
    struct ssg_horizon_run r; /* the G-buffer and the march (horizon.h); first */
    const struct ssg_hbao_consts *c;
    /* The pattern unrolled to full rows, n rows of w: cos and sin of the tile angle at
       (x mod n, y mod n) and the step jitter u of the cell half a tile away (README.md). */
    const float *rot_c, *rot_s, *jitter;
    int n;                /* tile side; 1 without a pattern */
    const float *cnt;     /* per-pixel direction counts, NULL = all directions */
    float *out;
};

/* Fills j's pattern rows; returns their one allocation or NULL. */
float *ssg_hbao_pattern_unroll(const struct ssg_image *rot, int w, struct job *j);

#endif
