/* hbao_cpu.h - private to the CPU kernel of the `hbao` node: the job that hbao_cpu.c
 * (the march, the hot code) and hbao_pattern.c (the tables prepared before
 * it) share. Method and geometry are in README.md, the kernel's layout in hbao_cpu.c.
 * A job is filled once per run by ssg_hbao_run_cpu (its tables by
 * ssg_hbao_pattern_unroll and ssg_hbao_rows_pad), then only read by the bands that run
 * in parallel; the caller owns the tables and the padded plane and frees them. */
#ifndef SSG_HBAO_CPU_H
#define SSG_HBAO_CPU_H

#include "hbao.h"

/* One run of the kernel: its inputs, tables and output (filled by ssg_hbao_run_cpu). */
struct job {
    const struct ssg_hbao_consts *c;
    const float *nrm[3];  /* planes of the normal */
    const float *depth;   /* plane the depth is read from */
    float depth_sign;     /* depth = depth_sign * plane: 1 for depth, -1 for z */
    float *padded;        /* the depth, (w + 2) x (h + 2), with background (0), garbage
                             (negative, NaN, inf) and a one-pixel border set to +inf */
    int pw;               /* w + 2, the padded row length */
    /* The pattern unrolled to full rows, n rows of w: cos and sin of the tile angle at
       (x mod n, y mod n) and the step jitter u of the cell half a tile away (README.md). */
    const float *rot_c, *rot_s, *jitter;
    int n;                /* tile side; 1 without a pattern */
    const float *e1x, *e1z; /* per column: e1 = (1, 0, a_u) / sqrt(1 + a_u^2) (consts'
                               e1, made by prepare()) */
    const float *cnt;     /* per-pixel direction counts, NULL = all directions */
    float *out;
    int w, h;
    float f, cx, cy;      /* projection of this resolution */
};

/* Fills j's pattern rows; returns their one allocation or NULL. */
float *ssg_hbao_pattern_unroll(const struct ssg_image *rot, int w, struct job *j);
/* ssg_parallel_rows callback: fills rows [y0, y1) of j->padded (user is the job). */
void ssg_hbao_rows_pad(void *user, int y0, int y1);

#endif
