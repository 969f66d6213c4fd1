/* reference_gi_cpu.c - CPU kernel of the `reference_gi` node (method and estimators in
 * README.md).
 *
 * Bands of ROWS_PER_BAND rows go to ssg_parallel_rows. Per pixel, a scalar setup (world
 * point, normal and albedo, raised origin, rotated tangent frame, the hashed
 * Cranley-Patterson shifts: the helpers of nodes/common/trace.h, shared with reference_ao) is
 * followed by the estimators, each in batches of BATCH:
 * - the lights' shadow rays from x, one scalar occlusion query each;
 * - the environment samples: drawn into structure-of-arrays scratch, those above the
 *   surface go to Embree as one occlusion batch (ssg_rt_occluded_rays);
 * - the bounce paths: directions from the table (Malley, no trigonometry), their nearest
 *   hits one ssg_rt_intersect each (the paths leave over the whole hemisphere: on the
 *   Cornell box at 640x480, 64 samples, one thread, that took 2.9-3.0 s against 4.9-5.5 s
 *   through the coherent stream of ssg_rt_intersect_rays, with the same bytes out), the
 *   hits compacted with their normals, albedos and raised origins, then per light one
 *   occlusion batch over all live paths, and one for their environment samples.
 * Sums run in sample order into doubles, so a pixel depends only on its inputs, (x, y),
 * the seed and the table, never on the threads. The bands go through
 * ssg_parallel_rows_progress, which reports the run's progress (the command line's bar on
 * a terminal); nothing in the output depends on it. */
#include <math.h>

#include "scene/env.h"
#include "reference_gi.h"
#include "scene/rt.h"
#include "scene/scene.h"
#include "common/surface.h"
#include "common/trace.h"

enum { ROWS_PER_BAND = 2, BATCH = 128 };

/* Keeps 1/sqrt finite for a zero vector; below float precision for unit-scale ones. */
#define TINY 1e-30f

struct job {
    const struct ssg_reference_gi_consts *c;
    const struct ssg_scene *scene;
    const float *pos[3], *nrm[3], *alb[3]; /* input planes */
    float *direct[3], *bounce[3], *out[3]; /* output planes */
    int w, h;
    int lit;              /* any light, environment or emitter to bounce: 0 = no rays */
    int emitters;         /* a material emits: the paths and the camera see emission */
};

/* What the rays of one pixel share. */
struct pixel {
    float p[3];       /* the G-buffer point, world */
    float o[3];       /* ray origin, world: p raised off its surface */
    float n[3];       /* unit normal, world */
    float rho[3];     /* albedo */
    float t[3], b[3]; /* tangent frame, turned by the pixel's bounce angle */
    float bounce_u;   /* Cranley-Patterson shift of u for the bounce directions */
    float env_u[2];   /* shifts of (u, v) for the direct term's environment samples */
    float end_u[2];   /* shifts of (phi3, phi5) for the paths' environment samples */
};

/* Bounce paths of one batch, structure of arrays. The hit quantities are compacted: entry
   m belongs to the m-th path that hit something. */
struct paths {
    int count, live;                           /* paths, and those that hit */
    float dx[BATCH], dy[BATCH], dz[BATCH];     /* unit directions */
    struct ssg_hit hits[BATCH];
    int index[BATCH];                          /* sample index of live path m */
    float yx[BATCH], yy[BATCH], yz[BATCH];     /* hit point y */
    float nx[BATCH], ny[BATCH], nz[BATCH];     /* unit normal at y, facing the ray */
    float qx[BATCH], qy[BATCH], qz[BATCH];     /* shadow-ray origin, y raised */
    float ar[BATCH], ag[BATCH], ab[BATCH];     /* albedo at y */
    float er[BATCH], eg[BATCH], eb[BATCH];     /* irradiance at y so far */
    float lr[BATCH], lg[BATCH], lb[BATCH];     /* radiance y emits (its material's) */
};

/* Shadow rays, structure of arrays, with what each adds where it is unoccluded. */
struct shadows {
    int count;
    int slot[BATCH];                       /* the receiver (live path) of ray i */
    float ox[BATCH], oy[BATCH], oz[BATCH];
    float dx[BATCH], dy[BATCH], dz[BATCH];
    float wr[BATCH], wg[BATCH], wb[BATCH]; /* irradiance it carries */
    unsigned char occluded[BATCH];
};

/* (a + b) mod 1 for a, b in [0, 1): the Cranley-Patterson rotation. */
static inline float wrap(float a, float b)
{
    float s = a + b;
    return s >= 1.0f ? s - 1.0f : s;
}

static inline float dot3(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Per-pixel setup; 0 for background (a zero normal). */
static int setup_pixel(const struct job *j, int x, int y, struct pixel *px)
{
    const struct ssg_reference_gi_consts *c = j->c;
    size_t o = (size_t)y * (size_t)j->w + (size_t)x;
    struct ssg_trace_point pt;
    if (!ssg_trace_point(c->rot, c->eye, c->p.offset, j->pos, j->nrm, o, &pt))
        return 0;
    for (int i = 0; i < 3; i++) {
        px->p[i] = pt.p[i], px->o[i] = pt.o[i], px->n[i] = pt.n[i];
        px->rho[i] = j->alb[i][o];
    }
    uint64_t h = ssg_pixel_hash(c->seed, x, y);
    float sa[2];
    ssg_hash_shifts(h, sa);
    px->bounce_u = sa[0];
    ssg_turned_basis(px->n, sa[1], px->t, px->b);
    h = ssg_mix64(h);
    ssg_hash_shifts(h, px->env_u);
    ssg_hash_shifts(ssg_mix64(h), px->end_u);
    return 1;
}

/* Irradiance (without colour) that light l gives a point y with unit normal n, and the
   direction of the shadow ray from q (unnormalised for a point light: t in [0, 1]).
   Returns 0 when y faces away from the light. The geometry is the gbuffer node's. */
static float light_at(const struct ssg_light *l, const float y[3], const float n[3],
                      const float q[3], float dir[3])
{
    if (l->kind != SSG_LIGHT_DIRECTIONAL) {
        float d[3] = {l->position[0] - y[0], l->position[1] - y[1], l->position[2] - y[2]};
        float inv = 1.0f / sqrtf(dot3(d, d) + TINY), ndl = dot3(n, d) * inv;
        float w[3] = {-d[0] * inv, -d[1] * inv, -d[2] * inv}; /* from the light */
        for (int i = 0; i < 3; i++)
            dir[i] = l->position[i] - q[i];
        return ndl > 0.0f ? l->intensity * ssg_light_cone(l, w) * ndl * inv * inv : 0.0f;
    }
    for (int i = 0; i < 3; i++)
        dir[i] = -l->direction[i];
    float ndl = dot3(n, dir);
    return ndl > 0.0f ? l->intensity * ndl : 0.0f;
}

/* Where a light's shadow ray ends: at the point light (t = 1), or nowhere. */
static float light_tfar(const struct ssg_light *l)
{
    return l->kind != SSG_LIGHT_DIRECTIONAL ? 1.0f : INFINITY;
}

static void add_shadow(struct shadows *s, int slot, const float o[3], const float d[3],
                       float wr, float wg, float wb)
{
    int i = s->count++;
    s->slot[i] = slot;
    s->ox[i] = o[0], s->oy[i] = o[1], s->oz[i] = o[2];
    s->dx[i] = d[0], s->dy[i] = d[1], s->dz[i] = d[2];
    s->wr[i] = wr, s->wg[i] = wg, s->wb[i] = wb;
}

static void trace_shadows(const struct job *j, struct shadows *s, float tfar)
{
    struct ssg_rays rays = {s->count, s->ox, s->oy, s->oz, s->dx, s->dy, s->dz, 0.0f, tfar};
    ssg_rt_occluded_rays(j->scene->rt, &rays, s->occluded);
}

/* Irradiance at x from the point, spot and directional lights, with shadows. */
static void lights_direct(const struct job *j, const struct pixel *px, double e[3])
{
    const struct ssg_scene *sc = j->scene;
    for (int li = 0; li < sc->light_count; li++) {
        const struct ssg_light *l = &sc->lights[li];
        float dir[3], w = light_at(l, px->p, px->n, px->o, dir);
        if (w > 0.0f && !ssg_rt_occluded(sc->rt, px->o, dir, 0.0f, light_tfar(l)))
            for (int i = 0; i < 3; i++)
                e[i] += (double)(w * l->color[i]);
    }
}

/* Irradiance at x from the environment: `samples` importance-sampled directions. */
static void env_direct(const struct job *j, const struct pixel *px, struct shadows *s,
                       double e[3])
{
    const struct ssg_reference_gi_table *t = &j->c->t;
    const int n = j->c->p.samples;
    double sum[3] = {0, 0, 0};
    for (int first = 0; first < n; first += BATCH) {
        int count = n - first < BATCH ? n - first : BATCH;
        s->count = 0;
        for (int i = first; i < first + count; i++) {
            float d[3], rgb[3];
            float pdf = ssg_env_sample(j->scene->env, wrap(t->u[i], px->env_u[0]),
                                       wrap(t->v[i], px->env_u[1]), d, rgb);
            float cosine = dot3(px->n, d);
            if (pdf > 0.0f && cosine > 0.0f) /* under the surface: weight 0, no ray */
                add_shadow(s, 0, px->o, d, rgb[0] * cosine / pdf, rgb[1] * cosine / pdf,
                           rgb[2] * cosine / pdf);
        }
        trace_shadows(j, s, INFINITY);
        for (int i = 0; i < s->count; i++)
            if (!s->occluded[i])
                sum[0] += s->wr[i], sum[1] += s->wg[i], sum[2] += s->wb[i];
    }
    for (int i = 0; i < 3; i++)
        e[i] += sum[i] / n;
}

/* Compacts the paths that hit: point, normal facing the ray, raised origin, albedo. */
static void gather_hits(const struct job *j, const struct pixel *px, struct paths *k,
                        int first)
{
    const struct ssg_scene *sc = j->scene;
    k->live = 0;
    for (int i = 0; i < k->count; i++) {
        const struct ssg_hit *h = &k->hits[i];
        if (h->mesh < 0)
            continue; /* escaped: the environment seen directly is the direct term's */
        int m = k->live++;
        float w[3] = {k->dx[i], k->dy[i], k->dz[i]}, y[3], n[3], a[3];
        const float *o = px->o;
        float scale = h->t;
        for (int c = 0; c < 3; c++) {
            y[c] = o[c] + h->t * w[c];
            float ay = fabsf(y[c]);
            scale = ay > scale ? ay : scale; /* fmaxf is a libm call here (NaN rules) */
        }
        ssg_hit_normal(sc, h, 0, n);
        float inv = 1.0f / sqrtf(dot3(n, n) + TINY);
        inv = dot3(n, w) > 0.0f ? -inv : inv; /* face the arriving ray */
        float e = ssg_trace_offset(j->c->p.offset, scale);
        ssg_hit_albedo(sc, h, a);
        k->index[m] = first + i;
        k->yx[m] = y[0], k->yy[m] = y[1], k->yz[m] = y[2];
        k->nx[m] = n[0] * inv, k->ny[m] = n[1] * inv, k->nz[m] = n[2] * inv;
        k->qx[m] = y[0] + e * (k->nx[m] - w[0]);
        k->qy[m] = y[1] + e * (k->ny[m] - w[1]);
        k->qz[m] = y[2] + e * (k->nz[m] - w[2]);
        k->ar[m] = a[0], k->ag[m] = a[1], k->ab[m] = a[2];
        k->er[m] = k->eg[m] = k->eb[m] = 0.0f;
        float le[3] = {0, 0, 0}; /* an emitter sends its own light down the path too */
        if (j->emitters && ssg_hit_emits(sc, h))
            ssg_hit_emission(sc, h, le);
        k->lr[m] = le[0], k->lg[m] = le[1], k->lb[m] = le[2];
    }
}

/* Adds the unoccluded shadow rays' irradiance to their paths' ends. */
static void add_unoccluded(struct paths *k, const struct shadows *s)
{
    for (int i = 0; i < s->count; i++)
        if (!s->occluded[i]) {
            int m = s->slot[i];
            k->er[m] += s->wr[i], k->eg[m] += s->wg[i], k->eb[m] += s->wb[i];
        }
}

/* One shadow ray per live path to light l. */
static void ends_light(const struct job *j, struct paths *k, struct shadows *s,
                       const struct ssg_light *l)
{
    s->count = 0;
    for (int m = 0; m < k->live; m++) {
        float y[3] = {k->yx[m], k->yy[m], k->yz[m]}, n[3] = {k->nx[m], k->ny[m], k->nz[m]};
        float q[3] = {k->qx[m], k->qy[m], k->qz[m]}, dir[3];
        float w = light_at(l, y, n, q, dir);
        if (w > 0.0f)
            add_shadow(s, m, q, dir, w * l->color[0], w * l->color[1], w * l->color[2]);
    }
    trace_shadows(j, s, light_tfar(l));
    add_unoccluded(k, s);
}

/* One environment sample per live path, at (phi3(i), phi5(i)) shifted by the pixel. */
static void ends_env(const struct job *j, const struct pixel *px, struct paths *k,
                     struct shadows *s)
{
    const struct ssg_reference_gi_table *t = &j->c->t;
    s->count = 0;
    for (int m = 0; m < k->live; m++) {
        int i = k->index[m];
        float d[3], rgb[3], n[3] = {k->nx[m], k->ny[m], k->nz[m]};
        float q[3] = {k->qx[m], k->qy[m], k->qz[m]};
        float pdf = ssg_env_sample(j->scene->env, wrap(t->e1[i], px->end_u[0]),
                                   wrap(t->e2[i], px->end_u[1]), d, rgb);
        float cosine = dot3(n, d);
        if (pdf > 0.0f && cosine > 0.0f)
            add_shadow(s, m, q, d, rgb[0] * cosine / pdf, rgb[1] * cosine / pdf,
                       rgb[2] * cosine / pdf);
    }
    trace_shadows(j, s, INFINITY);
    add_unoccluded(k, s);
}

/* Sum over the pixel's paths of L_out(y) = rho_y / pi * E_y (the cosine pdf cancels). */
static void bounce_paths(const struct job *j, const struct pixel *px, struct paths *k,
                         struct shadows *s, double sum[3])
{
    const struct ssg_scene *sc = j->scene;
    const int n = j->c->p.samples;
    const float inv_pi = (float)(1.0 / M_PI);
    for (int first = 0; first < n; first += BATCH) {
        k->count = n - first < BATCH ? n - first : BATCH;
        const struct ssg_reference_gi_table *t = &j->c->t; /* Malley, shifted table */
        ssg_malley_dirs(t->u + first, t->c + first, t->s + first, k->count, px->bounce_u,
                        px->t, px->b, px->n, k->dx, k->dy, k->dz);
        for (int i = 0; i < k->count; i++) { /* incoherent: one query each (file comment) */
            float d[3] = {k->dx[i], k->dy[i], k->dz[i]};
            ssg_rt_intersect(sc->rt, px->o, d, 0.0f, INFINITY, &k->hits[i]);
        }
        gather_hits(j, px, k, first);
        for (int li = 0; li < sc->light_count; li++)
            ends_light(j, k, s, &sc->lights[li]);
        if (j->c->use_env)
            ends_env(j, px, k, s);
        for (int m = 0; m < k->live; m++) {
            sum[0] += (double)(k->ar[m] * inv_pi * k->er[m] + k->lr[m]);
            sum[1] += (double)(k->ag[m] * inv_pi * k->eg[m] + k->lg[m]);
            sum[2] += (double)(k->ab[m] * inv_pi * k->eb[m] + k->lb[m]);
        }
    }
}

/* The radiance the surface at x emits towards the camera: its hit found again along the
   eye's ray to p (t = 1 at p), within a hair of p on either side, so that nothing nearer
   than the G-buffer's near plane can stand in for it. */
static void emitted(const struct job *j, const struct pixel *px, float le[3])
{
    const float *eye = j->c->eye;
    float d[3] = {px->p[0] - eye[0], px->p[1] - eye[1], px->p[2] - eye[2]};
    struct ssg_hit h;
    ssg_rt_intersect(j->scene->rt, eye, d, 0.999f, 1.001f, &h);
    if (h.mesh >= 0 && ssg_hit_emits(j->scene, &h))
        ssg_hit_emission(j->scene, &h, le);
}

/* All outputs of one pixel. */
static void shade_pixel(const struct job *j, int x, int y, struct paths *k, struct shadows *s)
{
    size_t o = (size_t)y * (size_t)j->w + (size_t)x;
    struct pixel px;
    float dir[3] = {0, 0, 0}, bnc[3] = {0, 0, 0}, le[3] = {0, 0, 0};
    if (setup_pixel(j, x, y, &px)) {
        if (j->emitters)
            emitted(j, &px, le);
        double e[3] = {0, 0, 0}, sum[3] = {0, 0, 0};
        lights_direct(j, &px, e);
        if (j->c->use_env)
            env_direct(j, &px, s, e);
        int dark = px.rho[0] == 0.0f && px.rho[1] == 0.0f && px.rho[2] == 0.0f;
        if (j->c->p.bounce && j->lit && !dark)
            bounce_paths(j, &px, k, s, sum);
        for (int i = 0; i < 3; i++) {
            dir[i] = (float)(px.rho[i] / M_PI * e[i]);
            bnc[i] = (float)(px.rho[i] * sum[i] / j->c->p.samples);
        }
    }
    for (int i = 0; i < 3; i++) {
        j->direct[i][o] = dir[i];
        j->bounce[i][o] = bnc[i];
        j->out[i][o] = j->emitters ? dir[i] + bnc[i] + le[i] : dir[i] + bnc[i];
    }
}

static void rows(void *user, int y0, int y1)
{
    struct job *j = user;
    struct paths k;
    struct shadows s;
    for (int y = y0; y < y1; y++)
        for (int x = 0; x < j->w; x++)
            shade_pixel(j, x, y, &k, &s);
}

enum ssg_err ssg_reference_gi_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                      const struct ssg_io *io)
{
    const struct ssg_image *pos = io->in[SSG_REFERENCE_GI_IN_POSITION];
    const struct ssg_image *nrm = io->in[SSG_REFERENCE_GI_IN_NORMAL];
    const struct ssg_image *alb = io->in[SSG_REFERENCE_GI_IN_ALBEDO];
    const int w = pos->width, h = pos->height;
    struct job j = {.c = consts, .scene = ctx->scene, .w = w, .h = h};
    const struct ssg_reference_gi_consts *c = consts;
    j.emitters = ssg_scene_has_emission(ctx->scene);
    j.lit = ctx->scene->light_count > 0 || c->use_env || j.emitters;
    for (int i = 0; i < 3; i++) {
        j.pos[i] = ssg_image_plane(pos, i);
        j.nrm[i] = ssg_image_plane(nrm, i);
        j.alb[i] = ssg_image_plane(alb, i);
        j.direct[i] = ssg_image_plane(io->out[SSG_REFERENCE_GI_OUT_DIRECT], i);
        j.bounce[i] = ssg_image_plane(io->out[SSG_REFERENCE_GI_OUT_BOUNCE], i);
        j.out[i] = ssg_image_plane(io->out[SSG_REFERENCE_GI_OUT_OUT], i);
    }
    ssg_parallel_rows_progress(ctx, j.h, ROWS_PER_BAND, rows, &j);
    return SSG_OK;
}
