/* @name@_cpu.c - the CPU kernel of the `@name@` node (method in README.md): the reference
 * the GL side is tested against. Fixed bands of rows (ssg_parallel_rows), each pixel
 * computed from its own inputs alone, so the result does not depend on the thread count;
 * the inner loop is contiguous and the compiler vectorises it. */
#include "@name@.h"

enum { ROWS_PER_BAND = 16 };

struct job {
    const struct ssg_@name@_params *p;
    const struct ssg_image *src;
    struct ssg_image *out;
};

static void rows(void *user, int y0, int y1)
{
    const struct job *j = user;
    const size_t w = (size_t)j->src->width, first = (size_t)y0 * w;
    const size_t n = (size_t)(y1 - y0) * w;
    for (int ch = 0; ch < j->src->channels; ch++) {
        const float *restrict s = ssg_image_plane(j->src, ch) + first;
        float *restrict o = ssg_image_plane(j->out, ch) + first;
        for (size_t i = 0; i < n; i++)
            o[i] = j->p->gain * s[i];
    }
}

enum ssg_err ssg_@name@_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io)
{
    (void)ctx;
    struct job j = {.p = consts, .src = io->in[SSG_@NAME@_IN_SRC],
                    .out = io->out[SSG_@NAME@_OUT_OUT]};
    ssg_parallel_rows(j.src->height, ROWS_PER_BAND, rows, &j);
    return SSG_OK;
}
