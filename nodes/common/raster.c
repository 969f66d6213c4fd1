/* raster.c - coverage of snapped triangles (raster.h). */
#include "raster.h"

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

int ssg_raster_span(const struct ssg_raster_tri *t, int64_t Y, int64_t *x0, int64_t *x1)
{
    int64_t py = Y * SUB + SUB / 2;
    int inside = 1;
    *x0 = t->x0, *x1 = t->x1;
    for (int k = 0; k < 3 && inside; k++)
        inside = clip_span(t->A[k] * SUB, t->A[k] * (SUB / 2) + t->B[k] * py + t->C[k], x0, x1);
    return inside;
}
