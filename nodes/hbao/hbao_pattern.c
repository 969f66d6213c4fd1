/* hbao_pattern.c - what the CPU kernel of the `hbao` node reads, prepared before the
 * march (hbao_cpu.c): the rotation pattern (Bavoil, Sainz and Dimitrov, "Image-Space
 * Horizon-Based Ambient Occlusion", SIGGRAPH 2008: per-pixel random rotation of the
 * directions and jitter of the steps, from a tiled n x n texture) unrolled to full rows.
 * Method and geometry are in README.md; the job is in hbao_cpu.h. */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#include "hbao_cpu.h"

/* The pattern unrolled to n full rows (see struct job; without a pattern one row of
   cos 1, sin 0, u 1). Returns the one allocation holding them, or NULL. */
float *ssg_hbao_pattern_unroll(const struct ssg_image *rot, int w, struct job *j)
{
    int n = rot ? rot->width : 1;
    size_t row = (size_t)w, plane = (size_t)n * row, cells = (size_t)n * (size_t)n;
    float *mem = malloc(3 * plane * sizeof *mem);
    if (!mem)
        return NULL;
    float *rc = mem, *rs = mem + plane, *ju = mem + 2 * plane;
    for (int y = 0; y < n; y++)
        for (int x = 0; x < w; x++) {
            size_t o = (size_t)y * row + (size_t)x;
            if (!rot) {
                rc[o] = 1.0f, rs[o] = 0.0f, ju[o] = 1.0f;
                continue;
            }
            size_t cell = (size_t)y * n + (size_t)(x % n);
            size_t half = (size_t)((y + n / 2) % n) * n + (size_t)((x + n / 2) % n);
            rc[o] = rot->data[cell];
            rs[o] = rot->data[cells + cell];
            /* u = 1 - frac(phi / 2 pi) in (0, 1], phi the angle of the cell half a tile
               away. */
            double a = atan2(rot->data[cells + half], rot->data[half]) / (2.0 * M_PI);
            float u = (float)(1.0 - (a - floor(a)));
            ju[o] = u > 0.0f ? u : 1.0f;
        }
    j->n = n;
    j->rot_c = rc;
    j->rot_s = rs;
    j->jitter = ju;
    return mem;
}

