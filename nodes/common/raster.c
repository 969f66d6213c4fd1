/* raster.c - coverage of snapped triangles, and the scene a map draws (raster.h). */
#include "raster.h"

#include <math.h>
#include <stdlib.h>

#include "graph/node.h"
#include "scene/proxy.h"

const struct ssg_scene *ssg_raster_scene(const struct ssg_node_ctx *ctx, float texel,
                                         struct ssg_scene *view)
{
    if (!(texel < INFINITY))
        return ctx->scene; /* no face drawn, or proxies off */
    enum ssg_err e = ssg_scene_proxy(ctx->scene, 0.5f * texel, ssg_parallel_rows, view);
    if (e) {
        ssg_node_fail(ctx, e, "out of memory for the simplified meshes");
        return NULL;
    }
    return view->proxy_of ? view : ctx->scene; /* the scene's own address: GL keeps it */
}

enum { SUB = SSG_RASTER_SUB };

static int64_t floor_div(int64_t n, int64_t d) /* d > 0 */
{
    return n >= 0 ? n / d : -((-n + d - 1) / d);
}

/* The texel index of the first centre at or right of fixed-point coordinate c. */
static int64_t first_centre(int64_t c)
{
    return -floor_div(SUB / 2 - c, SUB);
}

/* The span [*x0, *x1] of centres of a row on the inner side of one edge whose function is
   a X + r at centre X (a, r in 1/SUB^2). 0 when no centre of the row is. */
static int clip_span(int64_t a, int64_t r, int64_t *x0, int64_t *x1)
{
    if (a > 0) { /* a X + r >= 0 from X = ceil(-r / a) on */
        int64_t from = -floor_div(r, a);
        *x0 = from > *x0 ? from : *x0;
    } else if (a < 0) { /* up to floor(r / -a) */
        int64_t to = floor_div(r, -a);
        *x1 = to < *x1 ? to : *x1;
    } else if (r < 0) {
        return 0;
    }
    return *x0 <= *x1;
}

int ssg_raster_setup(const int64_t x[3], const int64_t y[3], int res, int y0, int y1,
                     struct ssg_raster_tri *t)
{
    int64_t lox = x[0] < x[1] ? x[0] : x[1], hix = x[0] > x[1] ? x[0] : x[1];
    int64_t loy = y[0] < y[1] ? y[0] : y[1], hiy = y[0] > y[1] ? y[0] : y[1];
    lox = x[2] < lox ? x[2] : lox, hix = x[2] > hix ? x[2] : hix;
    loy = y[2] < loy ? y[2] : loy, hiy = y[2] > hiy ? y[2] : hiy;
    int64_t X0 = first_centre(lox), X1 = first_centre(hix + 1) - 1;
    int64_t Y0 = first_centre(loy), Y1 = first_centre(hiy + 1) - 1;
    t->x0 = X0 > 0 ? X0 : 0, t->y0 = Y0 > y0 ? Y0 : y0;
    t->x1 = X1 < res - 1 ? X1 : res - 1, t->y1 = Y1 < y1 - 1 ? Y1 : y1 - 1;
    int64_t area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    if (t->x0 > t->x1 || t->y0 > t->y1 || area == 0)
        return 0;
    const int *o = t->order;
    t->order[0] = 0, t->order[1] = area > 0 ? 1 : 2, t->order[2] = area > 0 ? 2 : 1;
    for (int k = 0; k < 3; k++) {
        int s = o[(k + 1) % 3], e = o[(k + 2) % 3];
        t->A[k] = -(y[e] - y[s]), t->B[k] = x[e] - x[s];
        t->C[k] = -(t->A[k] * x[s] + t->B[k] * y[s]);
    }
    return 1;
}

/* ssg_raster_span for a box at most NARROW centres wide: the edge functions at each
   centre instead of three divisions a row (most of a map's triangles are a few texels
   wide and many rows tall: a column's flutes, a leaf card on edge). The same inclusive
   test at the same centres, so the same span; a triangle's centres in a row are
   contiguous (it is convex). */
enum { NARROW = 8 };
static int narrow_span(const struct ssg_raster_tri *t, int64_t py, int64_t *x0, int64_t *x1)
{
    int64_t first = t->x1 + 1, last = t->x0 - 1;
    for (int64_t X = t->x0; X <= t->x1; X++) {
        int64_t px = X * SUB + SUB / 2;
        int in = 1;
        for (int k = 0; k < 3; k++)
            in &= t->A[k] * px + t->B[k] * py + t->C[k] >= 0;
        first = in && X < first ? X : first;
        last = in ? X : last;
    }
    *x0 = first, *x1 = last;
    return first <= last;
}

int ssg_raster_span(const struct ssg_raster_tri *t, int64_t Y, int64_t *x0, int64_t *x1)
{
    int64_t py = Y * SUB + SUB / 2;
    if (t->x1 - t->x0 < NARROW)
        return narrow_span(t, py, x0, x1);
    int inside = 1;
    *x0 = t->x0, *x1 = t->x1;
    for (int k = 0; k < 3 && inside; k++)
        inside = clip_span(t->A[k] * SUB, t->A[k] * (SUB / 2) + t->B[k] * py + t->C[k], x0, x1);
    return inside;
}
