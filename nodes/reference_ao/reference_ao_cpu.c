/* reference_ao_cpu.c - CPU kernel of the `reference_ao` node (method in README.md).
 *
 * Bands of ROWS_PER_BAND rows go to ssg_parallel_rows. Per pixel, a short scalar setup
 * (world point and normal, raised origin, rotated tangent frame, the hashed shift of u:
 * the helpers of nodes/common/trace.h, shared with reference_gi) is followed by the rays in
 * batches of BATCH: ssg_malley_dirs builds the directions from the prepared table (two
 * square roots, no trigonometry; the compiler vectorises it) into structure-of-arrays
 * scratch, and the batch goes to Embree as one occlusion query
 * (ssg_rt_occluded_rays, which says why it uses the query style it does). A pixel
 * depends only on its inputs, (x, y), the seed and the table, and its count of occluded
 * rays is an integer sum, so the output does not depend on the threads. The bands go
 * through ssg_parallel_rows_progress, which reports the run's progress (the command
 * line's bar on a terminal); nothing in the output depends on it. */
#include "reference_ao.h"
#include "scene/rt.h"
#include "scene/scene.h"
#include "common/trace.h"

enum { ROWS_PER_BAND = 2, BATCH = 256 };

struct job {
    const struct ssg_reference_ao_consts *c;
    const struct ssg_rt *rt;
    const struct ssg_scene *scene;
    const float *pos[3], *nrm[3]; /* input planes */
    float *out;
    int w, h;
};

/* What the rays of one pixel share. */
struct pixel {
    float o[3];       /* ray origin, world */
    float t[3], b[3]; /* tangent frame, turned by the pixel's angle */
    float n[3];       /* unit shading normal, world: the cosine */
    float ng[3];      /* unit face normal, world: the horizon (ssg_trace_face_normal) */
    int clipped;      /* 1 = n and ng differ, so some directions leave below the surface */
    float shift;      /* Cranley-Patterson shift of u, [0, 1) */
};

/* Rays of one batch, structure of arrays. */
struct batch {
    float ox[BATCH], oy[BATCH], oz[BATCH];
    float dx[BATCH], dy[BATCH], dz[BATCH];
    unsigned char occluded[BATCH];
};

/* Occluded rays of a batch when the shading normal tilts away from the face: a direction
   below the face's plane enters the object, so it counts as blocked whatever Embree finds
   beyond the raised origin (a path tracer's answer). */
static int occluded_clipped(const struct job *j, const struct pixel *px, struct batch *k,
                            const struct ssg_rays *rays)
{
    ssg_rt_occluded_rays(j->rt, rays, k->occluded);
    int occluded = 0;
    for (int i = 0; i < rays->count; i++) {
        float up = k->dx[i] * px->ng[0] + k->dy[i] * px->ng[1] + k->dz[i] * px->ng[2];
        occluded += k->occluded[i] | (up <= 0.0f);
    }
    return occluded;
}

/* Per-pixel setup; 0 for background (a zero normal). */
static int setup_pixel(const struct job *j, int x, int y, struct pixel *px)
{
    const struct ssg_reference_ao_consts *c = j->c;
    size_t o = (size_t)y * (size_t)j->w + (size_t)x;
    struct ssg_trace_point pt;
    if (!ssg_trace_point(c->rot, c->eye, c->p.offset, j->pos, j->nrm, o, &pt))
        return 0;
    float sa[2];
    ssg_hash_shifts(ssg_pixel_hash(c->seed, x, y), sa);
    px->shift = sa[0];
    ssg_turned_basis(pt.n, sa[1], px->t, px->b);
    for (int i = 0; i < 3; i++)
        px->o[i] = pt.o[i], px->n[i] = pt.n[i];
    ssg_trace_face_normal(j->scene, c->eye, &pt, px->ng);
    px->clipped = px->ng[0] != px->n[0] || px->ng[1] != px->n[1] || px->ng[2] != px->n[2];
    return 1;
}

/* Visibility of one foreground pixel. */
static float trace_pixel(const struct job *j, const struct pixel *px, struct batch *k)
{
    const int n = j->c->p.rays;
    for (int i = 0; i < BATCH; i++)
        k->ox[i] = px->o[0], k->oy[i] = px->o[1], k->oz[i] = px->o[2];
    int occluded = 0;
    for (int first = 0; first < n; first += BATCH) {
        int count = n - first < BATCH ? n - first : BATCH;
        const struct ssg_reference_ao_consts *c = j->c; /* Malley, shifted table */
        ssg_malley_dirs(c->u + first, c->c + first, c->s + first, count, px->shift, px->t,
                        px->b, px->n, k->dx, k->dy, k->dz);
        struct ssg_rays rays = {count, k->ox, k->oy, k->oz, k->dx, k->dy, k->dz, 0.0f,
                                j->c->p.max_distance};
        occluded += px->clipped ? occluded_clipped(j, px, k, &rays)
                                : ssg_rt_occluded_rays(j->rt, &rays, NULL);
    }
    return (float)(n - occluded) / (float)n;
}

static void rows(void *user, int y0, int y1)
{
    struct job *j = user;
    struct batch k;
    struct pixel px;
    for (int y = y0; y < y1; y++)
        for (int x = 0; x < j->w; x++)
            j->out[(size_t)y * (size_t)j->w + (size_t)x] =
                setup_pixel(j, x, y, &px) ? trace_pixel(j, &px, &k) : 1.0f;
}

enum ssg_err ssg_reference_ao_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                      const struct ssg_io *io)
{
    const struct ssg_image *pos = io->in[SSG_REFERENCE_AO_IN_POSITION];
    const struct ssg_image *nrm = io->in[SSG_REFERENCE_AO_IN_NORMAL];
    struct ssg_image *out = io->out[SSG_REFERENCE_AO_OUT_OUT];
    struct job j = {.c = consts,
                    .rt = ctx->scene->rt,
                    .scene = ctx->scene,
                    .out = out->data,
                    .w = pos->width,
                    .h = pos->height};
    for (int i = 0; i < 3; i++) {
        j.pos[i] = ssg_image_plane(pos, i);
        j.nrm[i] = ssg_image_plane(nrm, i);
    }
    ssg_parallel_rows_progress(ctx, j.h, ROWS_PER_BAND, rows, &j);
    return SSG_OK;
}
