/* parallel.c - the only place that spreads work over threads (OpenMP). Bands are fixed by
 * the caller's band height, never by the thread count, so results are deterministic. */
#include <omp.h>

#include "graph/node.h"

void ssg_parallel_rows(int height, int rows_per_band, ssg_rows_fn fn, void *user)
{
    if (rows_per_band < 1)
        rows_per_band = 1;
    int bands = (height + rows_per_band - 1) / rows_per_band;
#pragma omp parallel for schedule(dynamic, 1)
    for (int b = 0; b < bands; b++) {
        int y0 = b * rows_per_band;
        int y1 = y0 + rows_per_band < height ? y0 + rows_per_band : height;
        fn(user, y0, y1);
    }
}
