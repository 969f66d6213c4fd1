/* parallel.c - the only place that spreads work over threads (OpenMP). Bands are fixed by
 * the caller's band height, never by the thread count, so results are deterministic. */
#include <omp.h>
#include <stdatomic.h>

#include "graph/node.h"

/* The progress of one ssg_parallel_rows_progress: bands count from any thread, and only
   the team's thread 0 (the caller, which takes bands like the others under the dynamic
   schedule) reports, so the callback never runs on a worker thread nor inside a band. */
struct tally {
    const struct ssg_node_ctx *ctx;
    int bands;
    atomic_int finished; /* bands finished, by any thread */
    int shown;           /* last whole percentage reported; thread 0's alone */
};

static void report(const struct tally *t, int finished, int done)
{
    const struct ssg_progress_event event = {
        .instance = t->ctx->instance ? t->ctx->instance : "",
        .type = t->ctx->desc ? t->ctx->desc->name : "",
        .fraction = (double)finished / (double)t->bands,
        .done = done,
    };
    t->ctx->run->progress(t->ctx->run->user, &event);
}

static void band_finished(struct tally *t)
{
    int finished = atomic_fetch_add(&t->finished, 1) + 1;
    if (omp_get_thread_num() != 0)
        return;
    int pct = (int)((long long)finished * 100 / t->bands);
    if (pct > t->shown) {
        t->shown = pct;
        report(t, finished, 0);
    }
}

/* Every band of the frame; t (NULL = none) counts them. */
static void run_bands(int height, int rows_per_band, ssg_rows_fn fn, void *user,
                      struct tally *t)
{
    if (rows_per_band < 1)
        rows_per_band = 1;
    int bands = (height + rows_per_band - 1) / rows_per_band;
#pragma omp parallel for schedule(dynamic, 1)
    for (int b = 0; b < bands; b++) {
        int y0 = b * rows_per_band;
        int y1 = y0 + rows_per_band < height ? y0 + rows_per_band : height;
        fn(user, y0, y1);
        if (t)
            band_finished(t);
    }
}

void ssg_parallel_rows(int height, int rows_per_band, ssg_rows_fn fn, void *user)
{
    run_bands(height, rows_per_band, fn, user, NULL);
}

void ssg_parallel_rows_progress(const struct ssg_node_ctx *ctx, int height, int rows_per_band,
                                ssg_rows_fn fn, void *user)
{
    int per_band = rows_per_band < 1 ? 1 : rows_per_band;
    int bands = height > 0 ? (height + per_band - 1) / per_band : 0;
    if (!ctx->run || !ctx->run->progress || bands == 0) {
        run_bands(height, rows_per_band, fn, user, NULL);
        return;
    }
    struct tally t = {.ctx = ctx, .bands = bands, .shown = -1};
    atomic_init(&t.finished, 0);
    run_bands(height, rows_per_band, fn, user, &t);
    report(&t, bands, 1);
}
