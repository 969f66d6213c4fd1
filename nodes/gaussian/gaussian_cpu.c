/* gaussian_cpu.c - CPU kernel of the `gaussian` node (method in README.md).
 *
 * Two passes per channel, each a ssg_parallel_rows over fixed bands. Horizontal: each row
 * is copied into a scratch row padded by `radius` edge pixels on both sides (clamp to
 * edge), then for each tap one loop over the row adds weight * shifted row into the
 * result. Vertical: for each output row, one loop per tap adds weight * (clamped) source
 * row. Both inner loops are contiguous multiply-adds the compiler vectorises, and every
 * pixel sums its taps in the same order (left to right, top to bottom) whatever the
 * threads, so the output does not depend on the thread count. */
#include <stdlib.h>
#include <string.h>

#include "gaussian.h"

enum { ROWS_PER_BAND = 16 };

struct job {
    const struct ssg_gaussian_consts *c;
    const float *src;  /* plane being filtered */
    float *tmp;        /* horizontal result, one plane */
    float *dst;        /* output plane */
    float *scratch;    /* per band: one padded row of w + 2 radius floats */
    int w, h;
};

static void horizontal(void *user, int y0, int y1)
{
    const struct job *j = user;
    const int r = j->c->u.radius, w = j->w, taps = 2 * r + 1;
    float *restrict pad = j->scratch + (size_t)(y0 / ROWS_PER_BAND) * (size_t)(w + 2 * r);
    for (int y = y0; y < y1; y++) {
        const float *restrict row = j->src + (size_t)y * (size_t)w;
        float *restrict acc = j->tmp + (size_t)y * (size_t)w;
        for (int i = 0; i < r; i++) {
            pad[i] = row[0];
            pad[r + w + i] = row[w - 1];
        }
        memcpy(pad + r, row, (size_t)w * sizeof *pad);
        memset(acc, 0, (size_t)w * sizeof *acc);
        for (int t = 0; t < taps; t++) {
            const float wt = j->c->weight[t];
            const float *restrict p = pad + t;
            for (int x = 0; x < w; x++)
                acc[x] += wt * p[x];
        }
    }
}

static void vertical(void *user, int y0, int y1)
{
    const struct job *j = user;
    const int r = j->c->u.radius, w = j->w, h = j->h, taps = 2 * r + 1;
    for (int y = y0; y < y1; y++) {
        float *restrict acc = j->dst + (size_t)y * (size_t)w;
        memset(acc, 0, (size_t)w * sizeof *acc);
        for (int t = 0; t < taps; t++) {
            int sy = y + t - r;
            sy = sy < 0 ? 0 : sy >= h ? h - 1 : sy;
            const float wt = j->c->weight[t];
            const float *restrict p = j->tmp + (size_t)sy * (size_t)w;
            for (int x = 0; x < w; x++)
                acc[x] += wt * p[x];
        }
    }
}

enum ssg_err ssg_gaussian_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                  const struct ssg_io *io)
{
    const struct ssg_gaussian_consts *c = consts;
    const struct ssg_image *in = io->in[SSG_GAUSSIAN_IN_IN];
    struct ssg_image *out = io->out[SSG_GAUSSIAN_OUT_OUT];
    struct job j = {.c = c, .w = in->width, .h = in->height};
    size_t plane = (size_t)j.w * (size_t)j.h;
    size_t bands = (size_t)(j.h + ROWS_PER_BAND - 1) / ROWS_PER_BAND;
    /* the intermediate image, then the bands' padded rows, in the node's scratch (node.h):
       kept between frames, no fresh pages each run */
    size_t rows = bands * (size_t)(j.w + 2 * c->u.radius);
    j.tmp = ssg_node_scratch(ctx, (plane + rows) * sizeof *j.tmp);
    if (!j.tmp)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the intermediate image");
    j.scratch = j.tmp + plane;
    for (int ch = 0; ch < in->channels; ch++) {
        j.src = ssg_image_plane(in, ch);
        j.dst = ssg_image_plane(out, ch);
        ssg_parallel_rows(j.h, ROWS_PER_BAND, horizontal, &j);
        ssg_parallel_rows(j.h, ROWS_PER_BAND, vertical, &j);
    }
    return SSG_OK;
}
