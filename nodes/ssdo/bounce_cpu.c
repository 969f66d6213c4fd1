/* bounce_cpu.c - CPU kernel of the `bounce` node (method in bounce.md). The sampling,
 * visibility test and form factors are ssdo's shared code (ssdo_sampling.h), run in
 * the same order per pixel as ssdo_cpu.c runs them, so the output has the same bits as
 * ssdo's bounce output. Layout: chunks of a row in structure-of-arrays scratch, chunk
 * columns outside and a band's rows inside (see ssao_cpu.c); bands of rows go to
 * ssg_parallel_rows, so the result does not depend on the thread count. */
#include "common/vector_loops.h" /* first: see there */
#include <stdlib.h>

#include "bounce.h"

struct job {
    struct ssg_ssdo_job s; /* what the shared sampling reads */
    float *out[3];         /* planes of the output */
};

/* One chunk of one row, start to end: loads, frame, every kernel sample in order, the
   bounce. Compiled per instruction set (SSG_VECTOR_CLONES, vector_loops.h): the same
   clone and order as ssdo_cpu.c, so the same bits as ssdo's bounce output. */
SSG_VECTOR_CLONES
static void
bounce_chunk_row(const struct job *jb, struct ssg_ssdo_chunk *k, int y, int x0, int len)
{
    const struct ssg_ssdo_job *j = &jb->s;
    const int count = j->count, own = j->own_depth;
    ssg_ssdo_load(j, k, y, x0, len);
    ssg_ssdo_setup(j, k, len);
    for (int s = 0; s < count; s++) {
        if (own)
            ssg_ssdo_sample(j, k, len, s, 1, 1);
        else
            ssg_ssdo_sample(j, k, len, s, 0, 1);
    }
    ssg_ssdo_finish_bounce(j, k, len, (size_t)y * (size_t)j->w + (size_t)x0, jb->out);
}

static void band(void *user, int y0, int y1)
{
    const struct job *j = user;
    struct ssg_ssdo_chunk k;
    for (int x0 = 0; x0 < j->s.w; x0 += SSG_SSDO_CHUNK) {
        int len = j->s.w - x0 < SSG_SSDO_CHUNK ? j->s.w - x0 : SSG_SSDO_CHUNK;
        for (int y = y0; y < y1; y++)
            bounce_chunk_row(j, &k, y, x0, len);
    }
}

enum ssg_err ssg_bounce_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io)
{
    const struct ssg_bounce_consts *c = consts;
    struct job j;
    ssg_ssdo_job_init(&j.s, io, &c->g, &c->proj, 1);
    for (int ch = 0; ch < 3; ch++)
        j.out[ch] = ssg_image_plane(io->out[0], ch);
    float *lens = malloc(sizeof(float) * 2 * (size_t)j.s.count);
    if (!lens)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the kernel's lengths");
    ssg_sampling_lengths(j.s.kernel, j.s.count, lens);
    j.s.lens = lens;
    ssg_parallel_rows(j.s.h, SSG_SSDO_ROWS_PER_BAND, band, &j);
    free(lens);
    return SSG_OK;
}
