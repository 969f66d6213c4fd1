/* direct_light_cpu.c - CPU side of the `direct_light` node (method in README.md).
 * Rows in fixed bands; a band's rows in chunks of DL_CHUNK pixels. Per light, the
 * unshadowed irradiance of the whole chunk is one vectorised loop (nodes/common/direct.h,
 * the G-buffer's own code); only the pixels it reaches are located on the light's maps and
 * filtered, and only those the maps leave lit march for contact shadows, each step as one
 * loop over those pixels (direct_light_cpu.h, "Why lanes"); the sums are again straight
 * loops. A pixel depends only on its own inputs: the result does not depend on the
 * threads. */
#include "common/vector_loops.h" /* first: see there */
#include <limits.h>
#include <math.h>
#include <stdlib.h>

#include "common/direct.h"
#include "common/luminance.h"
#include "direct_light_cpu.h"

enum { ROWS_PER_BAND = 8 };

struct chunk {
    struct dl_pixels px;
    float sum[3][DL_CHUNK], lum_lit[DL_CHUNK], lum_all[DL_CHUNK];
};

/* The chunk's world positions and normals (background: normal 0). */
SSG_VECTOR_CLONES
static void load(const struct dl_job *j, int y, int x0, int len, struct chunk *restrict k)
{
    const struct ssg_image *pos = j->io->in[SSG_DIRECT_LIGHT_IN_POSITION];
    const struct ssg_image *nrm = j->io->in[SSG_DIRECT_LIGHT_IN_NORMAL];
    const float *r = j->c->u.rot, *eye = j->c->u.eye;
    size_t at = (size_t)y * j->w + x0, plane = (size_t)j->w * j->h;
    struct dl_pixels *restrict px = &k->px;
    px->len = len;
    for (int i = 0; i < len; i++) {
        float vx = pos->data[at + i], vy = pos->data[plane + at + i];
        float vz = pos->data[2 * plane + at + i];
        float mx = nrm->data[at + i], my = nrm->data[plane + at + i];
        float mz = nrm->data[2 * plane + at + i];
        px->p[0][i] = eye[0] + r[0] * vx + r[3] * vy + r[6] * vz;
        px->p[1][i] = eye[1] + r[1] * vx + r[4] * vy + r[7] * vz;
        px->p[2][i] = eye[2] + r[2] * vx + r[5] * vy + r[8] * vz;
        px->n[0][i] = r[0] * mx + r[3] * my + r[6] * mz;
        px->n[1][i] = r[1] * mx + r[4] * my + r[7] * mz;
        px->n[2][i] = r[2] * mx + r[5] * my + r[8] * mz;
        k->sum[0][i] = k->sum[1][i] = k->sum[2][i] = 0.0f;
        k->lum_lit[i] = k->lum_all[i] = 0.0f;
    }
}

/* Light l's unshadowed irradiance over the chunk: the G-buffer's formulas; point: the
   light's kind, a constant where this is inlined (a straight loop). Visibility 0 for now. */
static inline __attribute__((always_inline)) int
irradiance_of(const struct ssg_direct_light_light *l, int point, struct dl_pixels *restrict px)
{
    int any = 0;
    const float pos[3] = {l->pos[0], l->pos[1], l->pos[2]};
    const float dir[3] = {l->dir[0], l->dir[1], l->dir[2]}, intensity = l->intensity;
    const struct ssg_direct_cone cone = {{dir[0], dir[1], dir[2]}, l->cone_scale,
                                         l->cone_offset};
    for (int i = 0; i < px->len; i++) {
        float d[3];
        float e = point ? ssg_point_irradiance(pos, &cone, intensity, px->p[0][i],
                                               px->p[1][i], px->p[2][i], px->n[0][i],
                                               px->n[1][i], px->n[2][i], d)
                        : ssg_directional_irradiance(dir, intensity, px->n[0][i],
                                                     px->n[1][i], px->n[2][i], d);
        px->e[i] = e, px->v[i] = 0.0f;
        px->l[0][i] = d[0], px->l[1][i] = d[1], px->l[2][i] = d[2];
        any |= e > 0.0f;
    }
    return any;
}

/* irradiance_of for each kind of light; whether the light reaches any pixel. */
SSG_VECTOR_CLONES
static int irradiance(const struct ssg_direct_light_light *l, struct dl_pixels *restrict px)
{
    return l->point ? irradiance_of(l, 1, px) : irradiance_of(l, 0, px);
}

/* The light's shadowed irradiance of the chunk added to its sums. */
SSG_VECTOR_CLONES
static void accumulate(const struct ssg_direct_light_light *l, const struct dl_pixels *restrict px,
                       struct chunk *restrict k)
{
    const float el = ssg_luminance(l->color[0], l->color[1], l->color[2]);
    const float color[3] = {l->color[0], l->color[1], l->color[2]};
    for (int i = 0; i < px->len; i++) {
        float lit = px->v[i] * px->e[i];
        k->sum[0][i] += lit * color[0], k->sum[1][i] += lit * color[1];
        k->sum[2][i] += lit * color[2];
        k->lum_lit[i] += lit * el, k->lum_all[i] += px->e[i] * el;
    }
}

/* Light li's shadowed irradiance added to the chunk's sums: the map visibility of the
   pixels it reaches (lanes), times their contact shadows' where the maps let it through. */
static void add_light(const struct dl_job *j, int li, int y, int x0, struct chunk *restrict k)
{
    const struct ssg_direct_light_light *l = &j->c->light[li];
    struct dl_pixels *px = &k->px;
    if (!irradiance(l, px))
        return; /* a light behind the whole chunk adds exact zeros */
    struct dl_lanes lanes;
    dl_lanes_fill(j, li, y, x0, px, &lanes);
    dl_lanes_visibility(j, li, &lanes, px);
    if (j->c->p.contact > 0.0f)
        dl_contact(j, y, x0, px);
    accumulate(l, px, k);
}

/* The chunk's sums as the outputs: albedo / pi x the sum, the lit share of the luminance
   (background: 0 and 1; vis NULL: not made); the planes from the chunk's first pixel,
   plane floats apart.
   Every value is made and the pixel's kept: a straight loop. */
SSG_VECTOR_CLONES
static void store(const float *restrict alb, const float *restrict nrm, size_t plane, int len,
                  const struct chunk *restrict k, float *restrict out, float *restrict vis)
{
    const float inv_pi = (float)(1.0 / M_PI);
    int bg[DL_CHUNK];
    for (int i = 0; i < len; i++) /* dl_is_surface's negation */
        bg[i] = (nrm[i] == 0.0f) & (nrm[plane + i] == 0.0f) & (nrm[2 * plane + i] == 0.0f);
    for (int c = 0; c < 3; c++)
        for (int i = 0; i < len; i++) {
            float lit = alb[c * plane + i] * inv_pi * k->sum[c][i];
            out[c * plane + i] = bg[i] ? 0.0f : lit;
        }
    if (!vis)
        return; /* nobody reads it (on_demand) */
    for (int i = 0; i < len; i++) {
        float share = k->lum_lit[i] / k->lum_all[i];
        vis[i] = bg[i] | !(k->lum_all[i] > 0.0f) ? 1.0f : share;
    }
}

static void rows(void *user, int y0, int y1)
{
    const struct dl_job *j = user;
    struct chunk k;
    for (int y = y0; y < y1; y++)
        for (int x0 = 0; x0 < j->w; x0 += DL_CHUNK) {
            int len = j->w - x0 < DL_CHUNK ? j->w - x0 : DL_CHUNK;
            load(j, y, x0, len, &k);
            for (int li = 0; li < j->c->u.lights; li++)
                add_light(j, li, y, x0, &k);
            size_t at = (size_t)y * j->w + x0, plane = (size_t)j->w * j->h;
            float *vis = j->io->out[SSG_DIRECT_LIGHT_OUT_VISIBILITY]
                             ? j->io->out[SSG_DIRECT_LIGHT_OUT_VISIBILITY]->data
                             : NULL;
            store(j->io->in[SSG_DIRECT_LIGHT_IN_ALBEDO]->data + at,
                  j->io->in[SSG_DIRECT_LIGHT_IN_NORMAL]->data + at, plane, len, &k,
                  j->io->out[SSG_DIRECT_LIGHT_OUT_OUT]->data + at,
                  vis ? vis + at : NULL);
        }
}

enum ssg_err ssg_direct_light_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                      const struct ssg_io *io)
{
    (void)ctx;
    const struct ssg_direct_light_consts *c = consts;
    const struct ssg_image *pos = io->in[SSG_DIRECT_LIGHT_IN_POSITION];
    const size_t elements = (size_t)c->face_count * c->u.res * c->u.res;
    struct dl_job j = {c, io, io->in[SSG_DIRECT_LIGHT_IN_MAPS]->data, pos->width, pos->height,
                       elements <= INT_MAX};
    ssg_parallel_rows(pos->height, ROWS_PER_BAND, rows, &j);
    return SSG_OK;
}
