/* horizon.c - prepare()'s camera and tables and the row driver of the horizon nodes
 * (horizon.h). */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>

#include "common/horizon.h"

enum ssg_err ssg_horizon_frame(const struct ssg_node_ctx *ctx, const struct ssg_shape *gbuffer,
                               struct ssg_projection *proj, float *invf, float *e1)
{
    enum ssg_err e = ssg_sampling_projection(ctx, gbuffer, proj);
    if (e)
        return e;
    *invf = 1.0f / proj->f;
    const int w = gbuffer->width;
    for (int x = 0; x < w; x++) {
        float au = ((float)x + 0.5f - proj->cx) / proj->f;
        float h = 1.0f / sqrtf(1.0f + au * au);
        e1[x] = h;
        e1[w + x] = au * h;
    }
    return SSG_OK;
}

void ssg_horizon_angles(int n, double turn, double shift, float *co, float *si)
{
    for (int k = 0; k < n; k++) {
        double a = turn * (k + shift) / n; /* k + 0.0 is k: frame 0 keeps its bits */
        co[k] = (float)cos(a);
        si[k] = (float)sin(a);
    }
}

void ssg_horizon_gbuffer(struct ssg_horizon_run *r, const struct ssg_image *position,
                         const struct ssg_image *normal, const struct ssg_image *depth)
{
    r->w = position->width;
    r->h = position->height;
    for (int ch = 0; ch < 3; ch++)
        r->nrm[ch] = ssg_image_plane(normal, ch);
    r->depth = depth ? depth->data : ssg_image_plane(position, 2);
    r->depth_sign = depth ? 1.0f : -1.0f;
}

void ssg_horizon_pad_depth(const float *depth, float sign, int w, int y0, int y1,
                           float *padded)
{
    const size_t pw = (size_t)w + 2;
    for (int y = y0; y < y1; y++) {
        const float *restrict src = depth + (size_t)y * (size_t)w;
        float *restrict dst = padded + (size_t)(y + 1) * pw;
        dst[0] = INFINITY;
        dst[w + 1] = INFINITY;
        for (int x = 0; x < w; x++) {
            float d = sign * src[x];
            dst[x + 1] = (d > 0.0f) & (d <= 3.0e38f) ? d : INFINITY;
        }
    }
}

static void pad_rows(void *user, int y0, int y1)
{
    const struct ssg_horizon_run *r = user;
    ssg_horizon_pad_depth(r->depth, r->depth_sign, r->w, y0, y1, r->padded);
    if (r->padded_back) /* +inf (none behind) stays +inf; background is never read */
        ssg_horizon_pad_depth(r->back, 1.0f, r->w, y0, y1, r->padded_back);
}

/* Chunk columns outside, rows inside: the rows of one band sample nearly the same part
   of the depth plane, which then stays in cache from one row to the next. */
static void band(void *user, int y0, int y1)
{
    const struct ssg_horizon_run *r = user;
    _Alignas(64) unsigned char chunk[SSG_HORIZON_CHUNK_BYTES];
    for (int x0 = 0; x0 < r->w; x0 += SSG_HORIZON_CHUNK) {
        int len = r->w - x0 < SSG_HORIZON_CHUNK ? r->w - x0 : SSG_HORIZON_CHUNK;
        for (int y = y0; y < y1; y++)
            r->row(r, chunk, y, x0, len);
    }
}

enum ssg_err ssg_horizon_execute(const struct ssg_node_ctx *ctx, struct ssg_horizon_run *r)
{
    const int planes = r->back ? 2 : 1;
    r->pw = r->w + 2;
    /* the node's scratch (node.h): kept between frames, no fresh pages each run; the
       padded back plane follows the padded depth */
    size_t plane = (size_t)r->pw * (size_t)(r->h + 2);
    r->padded = ssg_node_scratch(ctx, (size_t)planes * plane * sizeof *r->padded);
    if (!r->padded)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the padded depth");
    r->padded_back = r->back ? r->padded + plane : NULL;
    for (int p = 0; p < planes; p++) {
        float *first = r->padded + p * plane, *last = first + (size_t)(r->h + 1) * r->pw;
        for (int x = 0; x < r->pw; x++)
            first[x] = last[x] = INFINITY;
    }
    ssg_parallel_rows(r->h, SSG_HORIZON_ROWS_PER_BAND, pad_rows, r);
    ssg_parallel_rows(r->h, SSG_HORIZON_ROWS_PER_BAND, band, r);
    return SSG_OK;
}
