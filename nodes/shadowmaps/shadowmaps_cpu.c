/* shadowmaps_cpu.c - CPU side of the `shadowmaps` node (method in shadowmaps.c): each map
 * row is one coherent Embree ray stream from the texel centres along -l; bands of rows of
 * all maps run in parallel. */
#include <stdlib.h>

#include "scene/rt.h"
#include "scene/scene.h"
#include "shadowmaps.h"

enum { MAX_RES = SSG_SHADOW_RES_MAX };

struct job {
    const struct ssg_scene *scene;
    const struct ssg_shadow_frame *frames; /* one per light */
    struct ssg_image *maps;
    int res;
};

static void map_row(const struct job *j, int light, int y, float *buf, struct ssg_hit *hits)
{
    const struct ssg_shadow_frame *f = &j->frames[light];
    int r = j->res;
    float *ox = buf, *oy = buf + r, *oz = buf + 2 * r;
    float *dx = buf + 3 * r, *dy = buf + 4 * r, *dz = buf + 5 * r;
    for (int x = 0; x < r; x++) {
        float p[3];
        ssg_shadow_texel_origin(f, r, x, y, p);
        ox[x] = p[0], oy[x] = p[1], oz[x] = p[2];
        dx[x] = -f->l[0], dy[x] = -f->l[1], dz[x] = -f->l[2];
    }
    struct ssg_rays rays = {r, ox, oy, oz, dx, dy, dz, 0.0f, 2.0f * f->radius};
    ssg_rt_intersect_rays(j->scene->rt, &rays, hits);
    float *out = ssg_image_plane(j->maps, light) + (size_t)y * r;
    for (int x = 0; x < r; x++)
        out[x] = hits[x].mesh >= 0 ? hits[x].t : SSG_SHADOW_EMPTY;
}

/* Rows y0..y1 of the stacked maps (row light * R + y). */
static void map_rows(void *user, int y0, int y1)
{
    const struct job *j = user;
    float buf[6 * MAX_RES]; /* 96 KiB + 80 KiB on the band's stack at the largest maps */
    struct ssg_hit hits[MAX_RES];
    for (int row = y0; row < y1; row++)
        map_row(j, row / j->res, row % j->res, buf, hits);
}

enum ssg_err ssg_shadowmaps_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                    const struct ssg_io *io)
{
    const struct ssg_shadowmaps_params *p = consts;
    enum ssg_err e = ssg_shadowmaps_check_run(ctx, p, io);
    if (e)
        return e;
    const struct ssg_image *lights = io->in[0];
    int n = lights->width;
    struct ssg_shadow_frame *frames = malloc(sizeof *frames * (size_t)n);
    if (!frames)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory");
    struct ssg_bounding_sphere sphere = ssg_scene_bounding_sphere(ctx->scene);
    for (int i = 0; i < n; i++) {
        float l[3];
        for (int c = 0; c < 3; c++)
            l[c] = ssg_image_plane(lights, c)[i]; /* row 0 of channel c */
        frames[i] = ssg_shadow_frame_make(&sphere, l);
    }
    struct job j = {ctx->scene, frames, io->out[0], p->resolution};
    ssg_parallel_rows(n * p->resolution, 8, map_rows, &j);
    free(frames);
    return SSG_OK;
}
