/* raster.h - the triangle rasteriser shared by the CPU sides of `shadowmaps` and
 * `lightmaps`: which texel centres of a map a triangle covers. The caller snaps vertices to
 * 1/SSG_RASTER_SUB texel (the fixed point GPUs use) and decides what a covered texel keeps
 * (a depth, a triangle's number); this file only answers coverage, with integer edge
 * functions and an inclusive test, so two triangles sharing an edge both cover a centre on
 * it (the shared edge's function is the exact negation): no cracks. Both faces count.
 * Texel X's centre is at fixed-point X * SUB + SUB / 2.
 *
 * Ownership: nothing is allocated; a struct ssg_raster_tri is the caller's (on its stack).
 * Thread safety: every function is pure, so any thread may call any of them at any time. */
#ifndef SSG_RASTER_H
#define SSG_RASTER_H

#include <stdint.h>

#include "ssgraph.h"

struct ssg_node_ctx;
struct ssg_scene;

enum { SSG_RASTER_SUB = 256 /* fixed-point steps a texel */ };

/* The scene a map whose finest texels are `texel` scene units wide draws: ctx->scene with
   its dense meshes simplified to the proxy level whose bound is at most half such a texel
   (scene/proxy.h; its surfaces lie within about a quarter texel of the originals), filled
   into *view, or ctx->scene itself where nothing simplifies that far (texel INFINITY:
   never). Both backends of a map node draw it, so they draw the same triangles. NULL with
   the node's SSG_E_NOMEM reported. */
const struct ssg_scene *ssg_raster_scene(const struct ssg_node_ctx *ctx, float texel,
                                         struct ssg_scene *view);

/* A snapped triangle set up for drawing into rows [y0, y1) of a map res texels wide. */
struct ssg_raster_tri {
    int64_t A[3], B[3], C[3]; /* edge k (opposite vertex order[k]): A x + B y + C >= 0 inside */
    int64_t x0, x1, y0, y1;   /* the centres of its box in the rows, inclusive */
    int order[3];             /* the vertices counter-clockwise: 0, then 1, 2 or 2, 1 */
};

/* 1 when the box of snapped points (xi, yi), (xk, yk), (xl, yl) holds a texel centre of
   rows [y0, y1) of a map res wide. Inline and branch-free, for the callers' vector loops
   that drop a fine mesh's triangles (mostly between centres) a block at a time. */
static inline __attribute__((always_inline)) int32_t
ssg_raster_box_has_centre(int32_t xi, int32_t xk, int32_t xl, int32_t yi, int32_t yk,
                          int32_t yl, int res, int y0, int y1)
{
    int32_t lox = xi < xk ? xi : xk, hix = xi > xk ? xi : xk;
    int32_t loy = yi < yk ? yi : yk, hiy = yi > yk ? yi : yk;
    lox = xl < lox ? xl : lox, hix = xl > hix ? xl : hix;
    loy = yl < loy ? yl : loy, hiy = yl > hiy ? yl : hiy;
    /* first centre at or after lo, last at or before hi (first_centre in raster.c, shifts) */
    int32_t X0 = (lox + SSG_RASTER_SUB / 2 - 1) >> 8, X1 = ((hix + SSG_RASTER_SUB / 2) >> 8) - 1;
    int32_t Y0 = (loy + SSG_RASTER_SUB / 2 - 1) >> 8, Y1 = ((hiy + SSG_RASTER_SUB / 2) >> 8) - 1;
    X0 = X0 > 0 ? X0 : 0, Y0 = Y0 > y0 ? Y0 : y0;
    X1 = X1 < res - 1 ? X1 : res - 1, Y1 = Y1 < y1 - 1 ? Y1 : y1 - 1;
    return (X0 <= X1) & (Y0 <= Y1);
}
_Static_assert(SSG_RASTER_SUB == 1 << 8, "ssg_raster_box_has_centre divides with shifts");

/* Sets t up for the snapped triangle (x[k], y[k]) in rows [y0, y1) of a map res wide.
   0 when no centre of those rows is in its box or it has no area (edge-on). */
int ssg_raster_setup(const int64_t x[3], const int64_t y[3], int res, int y0, int y1,
                     struct ssg_raster_tri *t);

/* The centres [*x0, *x1] of row Y (t->y0 <= Y <= t->y1) inside the triangle; 0 when none. */
int ssg_raster_span(const struct ssg_raster_tri *t, int64_t Y, int64_t *x0, int64_t *x1);

#endif
