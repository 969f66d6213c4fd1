/* gbuffer_cpu.c - CPU kernel of the `gbuffer` node (method in README.md).
 *
 * Bands of ROWS_PER_BAND rows go to ssg_parallel_rows; a band's rows are cut into
 * segments of CHUNK pixels. A segment's primary rays go to Embree as one coherent ray
 * stream (rt.h), in pixel order. The hits are then gathered (vertex normals, material,
 * texture: the only scattered reads) into structure-of-arrays scratch, and the rest,
 * lighting included, is straight-line arithmetic over those arrays that the compiler can
 * vectorise, ending in contiguous stores into the output planes. A background pixel
 * gathers zeros and so comes out 0 everywhere without a branch. A pixel depends only on
 * its own ray, so the result does not depend on the threads. The arithmetic steps are
 * compiled per instruction set (SSG_VECTOR_CLONES, vector_loops.h: the same IEEE
 * operations lane by lane, no fused multiply-adds), so AVX2 does them 8 pixels at a time.
 * `direct` and `environment`, like `back`, `motion` and `emission`, are made only when
 * read (gbuffer.h): gi.graph reads neither. */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "gbuffer.h"
#include "scene/env.h"
#include "scene/rt.h"
#include "common/direct.h"
#include "common/stream_store.h"
#include "common/surface.h"
#include "scene/scene.h"

enum { ROWS_PER_BAND = 4, CHUNK = 128 };

/* Below float precision for any unit-scale vector; keeps 1/sqrt finite for a zero one. */
#define TINY 1e-30f

struct job {
    const struct ssg_gbuffer_consts *c;
    const struct ssg_scene *scene;
    float *pos[3], *nrm[3], *depth, *alb[3]; /* output planes */
    float *dir[3], *env[3];       /* direct and environment light; NULL = nobody reads them */
    float *back;                  /* the second layer's plane; NULL = nobody reads it */
    float *motion[3];             /* the motion planes; NULL = nobody reads them */
    float *emit[3];               /* the emission planes; NULL = nobody reads them */
    int w, h;
};

/* One row segment, pixel by pixel. */
struct chunk {
    int count;                                /* pixels */
    int any_specular;                         /* a material here has a specular colour */
    float ox[CHUNK], oy[CHUNK], oz[CHUNK];    /* ray origins: the eye */
    float wx[CHUNK], wy[CHUNK], wz[CHUNK];    /* ray directions, world */
    float vx[CHUNK], vy[CHUNK];               /* the same in view space (z = -1) */
    struct ssg_hit hits[CHUNK];
    float t[CHUNK];                           /* depth, 0 = background */
    float nx[CHUNK], ny[CHUNK], nz[CHUNK];    /* world normal, facing the camera */
    float nvx[CHUNK], nvy[CHUNK], nvz[CHUNK]; /* view normal */
    float px[CHUNK], py[CHUNK], pz[CHUNK];    /* world hit point */
    float ux[CHUNK], uy[CHUNK], uz[CHUNK];    /* unit vector to the camera */
    float ar[CHUNK], ag[CHUNK], ab[CHUNK];    /* albedo */
    float sr[CHUNK], sg[CHUNK], sb[CHUNK];    /* specular colour */
    float shin[CHUNK];                        /* shininess */
    float lx[CHUNK], ly[CHUNK], lz[CHUNK];    /* one light: unit direction to it */
    float e[CHUNK], ndh[CHUNK], spec[CHUNK];  /* its irradiance, N.H and (N.H)^s */
    float lr[CHUNK], lg[CHUNK], lb[CHUNK];    /* direct light */
    float tn[CHUNK], back[CHUNK];             /* second layer: where its ray starts, depth */
    float er[CHUNK], eg[CHUNK], eb[CHUNK];    /* emission (when read) */
};

/* The rays of pixels [x0, x0 + count) of row y. */
SSG_VECTOR_CLONES static void
make_rays(const struct ssg_gbuffer_consts *c, struct chunk *restrict k, int x0, int y, int w)
{
    float r[9]; /* local copies: the compiler cannot tell the stores below from them */
    memcpy(r, c->rot, sizeof r);
    const float inv_f = c->inv_f, cx = c->proj.cx, vy = -((float)y + 0.5f - c->proj.cy) * inv_f;
    const int n = x0 + CHUNK < w ? CHUNK : w - x0;
    k->count = n;
    for (int s = 0; s < n; s++) {
        k->vx[s] = ((float)(x0 + s) + 0.5f - cx) * inv_f;
        k->vy[s] = vy;
    }
    for (int s = 0; s < n; s++) { /* world = rot^T * view, view z = -1 */
        k->wx[s] = r[0] * k->vx[s] + r[3] * vy - r[6];
        k->wy[s] = r[1] * k->vx[s] + r[4] * vy - r[7];
        k->wz[s] = r[2] * k->vx[s] + r[5] * vy - r[8];
    }
}

static void trace(const struct job *j, struct chunk *k)
{
    struct ssg_rays rays = {k->count, k->ox, k->oy, k->oz, k->wx, k->wy, k->wz,
                            j->c->near_z, j->c->far_z};
    ssg_rt_intersect_rays(j->scene->rt, &rays, k->hits);
}

/* The second layer (gbuffer.h): each ray again, from past its first hit, to the next
   surface; +inf where there is none, 0 on background. Runs after gather (it reuses hits). */
static void trace_back(const struct job *j, struct chunk *k)
{
    for (int s = 0; s < k->count; s++)
        k->tn[s] = k->t[s] + k->t[s] * SSG_GBUFFER_BACK_GAP;
    struct ssg_rays rays = {k->count, k->ox, k->oy, k->oz, k->wx, k->wy, k->wz,
                            j->c->near_z, j->c->far_z};
    ssg_rt_intersect_rays_past(j->scene->rt, &rays, k->tn, k->hits);
    for (int s = 0; s < k->count; s++) {
        float next = k->hits[s].mesh >= 0 ? k->hits[s].t : INFINITY;
        k->back[s] = k->t[s] > 0.0f ? next : 0.0f;
    }
}

/* What gather keeps of the mesh of the last hit: the plain cases (no texture, vertex
   colour or normal map) are the surface.c formulas written out here, the same operations
   in the same order, so they give the same bits without a call per pixel. */
struct surface {
    int mesh, triangle;                 /* the last hit's; -1 = none yet */
    const struct ssg_mesh *m;
    int plain_normal, plain_albedo, plain_emission;
    float albedo[3], specular[3], shininess, emission[3]; /* the material's */
    const float *n0, *n1, *n2;          /* the triangle's vertex normals (plain_normal) */
};

/* The mesh's surface; 1 when its material has a specular colour. */
static int surface_of(const struct ssg_scene *s, int mesh, int face, struct surface *f)
{
    const struct ssg_mesh *m = &s->meshes[mesh];
    const struct ssg_material *mat = &s->materials[m->material];
    f->mesh = mesh, f->triangle = -1, f->m = m;
    f->plain_normal = !face && !(mat->normal_texture >= 0 && m->uvs && m->tangents);
    f->plain_albedo = !(mat->texture >= 0 && m->uvs) && !m->colors;
    f->plain_emission = mat->emission_texture < 0 || !m->uvs;
    memcpy(f->albedo, mat->albedo, sizeof f->albedo);
    memcpy(f->specular, mat->specular, sizeof f->specular);
    memcpy(f->emission, mat->emission, sizeof f->emission);
    f->shininess = mat->shininess;
    return f->specular[0] > 0.0f || f->specular[1] > 0.0f || f->specular[2] > 0.0f;
}

/* Pixel i's interpolated vertex normal (ssg_hit_normal without a normal map: not
   normalised). */
static inline void plain_normal(struct surface *f, const struct ssg_hit *h, struct chunk *k,
                                int i)
{
    if (h->triangle != f->triangle) {
        const uint32_t *tri = &f->m->indices[3 * (size_t)h->triangle];
        f->triangle = h->triangle;
        f->n0 = &f->m->normals[3 * tri[0]];
        f->n1 = &f->m->normals[3 * tri[1]];
        f->n2 = &f->m->normals[3 * tri[2]];
    }
    float w0 = 1.0f - h->u - h->v;
    k->nx[i] = w0 * f->n0[0] + h->u * f->n1[0] + h->v * f->n2[0];
    k->ny[i] = w0 * f->n0[1] + h->u * f->n1[1] + h->v * f->n2[1];
    k->nz[i] = w0 * f->n0[2] + h->u * f->n1[2] + h->v * f->n2[2];
}

/* The other cases through surface.c, out of line: their arrays stay off the plain path. */
static __attribute__((noinline)) void mapped_surface(const struct ssg_scene *s,
                                                     const struct surface *f,
                                                     const struct ssg_hit *h, int face,
                                                     int emit, struct chunk *k, int i)
{
    float n[3], albedo[3], e[3];
    if (!f->plain_normal) {
        ssg_hit_normal(s, h, face, n);
        k->nx[i] = n[0], k->ny[i] = n[1], k->nz[i] = n[2];
    }
    if (!f->plain_albedo) {
        ssg_hit_albedo(s, h, albedo);
        k->ar[i] = albedo[0], k->ag[i] = albedo[1], k->ab[i] = albedo[2];
    }
    if (emit && !f->plain_emission) {
        ssg_hit_emission(s, h, e);
        k->er[i] = e[0], k->eg[i] = e[1], k->eb[i] = e[2];
    }
}

/* A background pixel: 0 everywhere (shininess 1). */
static void background(struct chunk *k, int i)
{
    k->t[i] = 0.0f;
    k->nx[i] = k->ny[i] = k->nz[i] = 0.0f;
    k->ar[i] = k->ag[i] = k->ab[i] = 0.0f;
    k->sr[i] = k->sg[i] = k->sb[i] = 0.0f;
    k->shin[i] = 1.0f;
    k->er[i] = k->eg[i] = k->eb[i] = 0.0f;
}

/* The scattered reads: per hit, its normal, depth and material (and emission when read). */
static void gather(const struct job *j, struct chunk *k)
{
    const struct ssg_scene *s = j->scene;
    const int face = j->c->p.normals == SSG_GBUFFER_NORMALS_FACE, emit = j->emit[0] != NULL;
    struct surface f = {.mesh = -1};
    k->any_specular = 0;
    for (int i = 0; i < k->count; i++) {
        const struct ssg_hit *h = &k->hits[i];
        if (h->mesh < 0) {
            background(k, i);
            continue;
        }
        if (h->mesh != f.mesh)
            k->any_specular |= surface_of(s, h->mesh, face, &f);
        k->t[i] = h->t;
        if (f.plain_normal)
            plain_normal(&f, h, k, i);
        k->ar[i] = f.albedo[0], k->ag[i] = f.albedo[1], k->ab[i] = f.albedo[2];
        k->sr[i] = f.specular[0], k->sg[i] = f.specular[1], k->sb[i] = f.specular[2];
        k->shin[i] = f.shininess;
        k->er[i] = f.emission[0], k->eg[i] = f.emission[1], k->eb[i] = f.emission[2];
        if (!f.plain_normal || !f.plain_albedo || (emit && !f.plain_emission))
            mapped_surface(s, &f, h, face, emit, k, i);
    }
}

/* Unit normals turned to face the camera, in world and view space, and hit points. */
SSG_VECTOR_CLONES static void geometry(const struct ssg_gbuffer_consts *c, struct chunk *restrict k)
{
    float r[9], eye[3];
    memcpy(r, c->rot, sizeof r);
    memcpy(eye, c->eye, sizeof eye);
    const int n = k->count;
    for (int s = 0; s < n; s++) {
        float inv = 1.0f / sqrtf(k->nx[s] * k->nx[s] + k->ny[s] * k->ny[s] +
                                 k->nz[s] * k->nz[s] + TINY);
        float nx = k->nx[s] * inv, ny = k->ny[s] * inv, nz = k->nz[s] * inv;
        float vx = r[0] * nx + r[1] * ny + r[2] * nz;
        float vy = r[3] * nx + r[4] * ny + r[5] * nz;
        float vz = r[6] * nx + r[7] * ny + r[8] * nz;
        /* seen from behind (n . view direction > 0): shade the side facing the camera */
        float flip = 1.0f - 2.0f * (float)(vx * k->vx[s] + vy * k->vy[s] - vz > 0.0f);
        k->nx[s] = flip * nx, k->ny[s] = flip * ny, k->nz[s] = flip * nz;
        k->nvx[s] = flip * vx, k->nvy[s] = flip * vy, k->nvz[s] = flip * vz;
        k->px[s] = eye[0] + k->t[s] * k->wx[s];
        k->py[s] = eye[1] + k->t[s] * k->wy[s];
        k->pz[s] = eye[2] + k->t[s] * k->wz[s];
    }
}

/* Unit direction to the camera; only the specular term needs it. */
SSG_VECTOR_CLONES static void view_vectors(struct chunk *restrict k)
{
    const int n = k->count;
    for (int s = 0; s < n; s++) {
        float inv =
            1.0f / sqrtf(k->wx[s] * k->wx[s] + k->wy[s] * k->wy[s] + k->wz[s] * k->wz[s]);
        k->ux[s] = -k->wx[s] * inv, k->uy[s] = -k->wy[s] * inv, k->uz[s] = -k->wz[s] * inv;
    }
}

/* Irradiance E of a point or spot light and unit L (nodes/common/direct.h, shared with
   direct_light). */
SSG_VECTOR_CLONES static void point_light(struct chunk *restrict k, const struct ssg_light *l)
{
    const struct ssg_direct_cone cone = ssg_direct_cone_of(l);
    const float lp[3] = {l->position[0], l->position[1], l->position[2]};
    const float intensity = l->intensity;
    const int n = k->count;
    for (int s = 0; s < n; s++) {
        float d[3];
        k->e[s] = ssg_point_irradiance(lp, &cone, intensity, k->px[s], k->py[s],
                                       k->pz[s], k->nx[s], k->ny[s], k->nz[s], d);
        k->lx[s] = d[0], k->ly[s] = d[1], k->lz[s] = d[2];
    }
}

/* Irradiance E of a directional light and L (nodes/common/direct.h). */
SSG_VECTOR_CLONES static void
directional_light(struct chunk *restrict k, const struct ssg_light *l)
{
    const float dir[3] = {l->direction[0], l->direction[1], l->direction[2]};
    const float intensity = l->intensity;
    const int n = k->count;
    for (int s = 0; s < n; s++) {
        float d[3];
        k->e[s] = ssg_directional_irradiance(dir, intensity, k->nx[s], k->ny[s],
                                             k->nz[s], d);
        k->lx[s] = d[0], k->ly[s] = d[1], k->lz[s] = d[2];
    }
}

/* Blinn-Phong (N.H)^shininess with H = normalize(L + V), where the light reaches. */
SSG_VECTOR_CLONES static void specular(struct chunk *restrict k)
{
    const int n = k->count;
    for (int s = 0; s < n; s++) {
        float hx = k->lx[s] + k->ux[s], hy = k->ly[s] + k->uy[s], hz = k->lz[s] + k->uz[s];
        float hinv = 1.0f / sqrtf(hx * hx + hy * hy + hz * hz + TINY);
        float ndh = (k->nx[s] * hx + k->ny[s] * hy + k->nz[s] * hz) * hinv;
        k->ndh[s] = ndh > 0.0f ? ndh : 0.0f;
    }
    for (int s = 0; s < n; s++) /* powf does not vectorise: a loop of its own */
        k->spec[s] = k->e[s] > 0.0f ? powf(k->ndh[s], k->shin[s]) : 0.0f;
}

/* One light's Lambert + Blinn-Phong term added to lr, lg, lb. */
SSG_VECTOR_CLONES static void accumulate(struct chunk *restrict k, const float color[3])
{
    const float inv_pi = (float)(1.0 / M_PI), cr = color[0], cg = color[1], cb = color[2];
    const int n = k->count;
    for (int s = 0; s < n; s++) {
        k->lr[s] += (k->ar[s] * inv_pi + k->sr[s] * k->spec[s]) * cr * k->e[s];
        k->lg[s] += (k->ag[s] * inv_pi + k->sg[s] * k->spec[s]) * cg * k->e[s];
        k->lb[s] += (k->ab[s] * inv_pi + k->sb[s] * k->spec[s]) * cb * k->e[s];
    }
}

/* Sums every light's Lambert + Blinn-Phong term into lr, lg, lb (README.md). */
static void lighting(const struct job *j, struct chunk *k)
{
    const struct ssg_scene *sc = j->scene;
    for (int s = 0; s < k->count; s++) {
        k->lr[s] = k->lg[s] = k->lb[s] = 0.0f;
        k->spec[s] = 0.0f;
    }
    if (k->any_specular)
        view_vectors(k);
    for (int li = 0; li < sc->light_count; li++) {
        const struct ssg_light *l = &sc->lights[li];
        if (l->kind != SSG_LIGHT_DIRECTIONAL)
            point_light(k, l);
        else
            directional_light(k, l);
        if (k->any_specular) /* matte chunks (most of a typical frame) skip it */
            specular(k);
        accumulate(k, l->color);
    }
}

/* albedo / pi * E_env(N) per hit pixel into lr, lg, lb; 0 for the background. */
static void environment_light(const struct job *j, struct chunk *k)
{
    const struct ssg_env *env = j->scene->env;
    const float inv_pi = (float)(1.0 / M_PI);
    /* The lookup (two inverse trigonometric functions and a bilinear read) depends on the
       normal alone, and neighbouring pixels of a flat surface have the very same normal
       (bit for bit): the last one's result is reused, the same bits. Measured: the
       courtyard's G-buffer 23 -> 20 ms at 720p. */
    float last_n[3] = {0, 0, 0}, last_e[3] = {0, 0, 0};
    int have = 0;
    for (int s = 0; s < k->count; s++) {
        float e[3] = {0, 0, 0}, n[3] = {k->nx[s], k->ny[s], k->nz[s]};
        if (k->t[s] > 0.0f && env && env->has_light) {
            if (!have || memcmp(n, last_n, sizeof n) != 0) {
                ssg_env_irradiance(env, n, last_e);
                memcpy(last_n, n, sizeof last_n);
                have = 1;
            }
            memcpy(e, last_e, sizeof e);
        }
        k->lr[s] = k->ar[s] * inv_pi * e[0];
        k->lg[s] = k->ag[s] * inv_pi * e[1];
        k->lb[s] = k->ab[s] * inv_pi * e[2];
    }
}

/* Three chunk arrays into three planes at o, streaming (nodes/common/stream_store.h: a
   frame's planes are far larger than the caches). The band ends with a fence (rows). */
static void store3(float *const to[3], size_t o, const float *a, const float *b, const float *c,
                   int n)
{
    ssg_stream_store(to[0] + o, a, n);
    ssg_stream_store(to[1] + o, b, n);
    ssg_stream_store(to[2] + o, c, n);
}

/* The view position t (vx, vy, -1) into the world-point arrays, no longer needed. */
SSG_VECTOR_CLONES static void view_positions(struct chunk *restrict k)
{
    const int n = k->count;
    for (int x = 0; x < n; x++) {
        float t = k->t[x];
        k->px[x] = t * k->vx[x];
        k->py[x] = t * k->vy[x];
        k->pz[x] = 0.0f - t; /* +0, not -0, for background */
    }
}

/* The segment into the output planes: view position and depth, normal, albedo. */
static void store(const struct job *j, struct chunk *k, size_t o)
{
    const int n = k->count;
    view_positions(k);
    store3(j->pos, o, k->px, k->py, k->pz, n);
    ssg_stream_store(j->depth + o, k->t, n);
    store3(j->nrm, o, k->nvx, k->nvy, k->nvz, n);
    store3(j->alb, o, k->ar, k->ag, k->ab, n);
}

/* Motion to the previous frame (README.md, `motion`) into px, py, pz (after store).
   q = the hit t (vx, vy, -1) in the previous view, divided by t, so that for the same
   camera (m_rot the identity, m_move 0) q is the ray itself and the motion is exactly
   0; the previous pixel minus this one is f' (q.xy / -q.z - v) + (f' - f) v (y flipped:
   rows go down), which keeps the rounding relative to the motion, not to the pixel's
   distance from the centre. A point nearer than near in the previous view (behind its
   camera, z <= 0, included) had no pixel there: x = y = 0, z as it is. gbuffer_motion.glsl
   has the same operations. */
SSG_VECTOR_CLONES static void motion(const struct ssg_gbuffer_consts *c, struct chunk *restrict k)
{
    float m[9], mv[3];
    memcpy(m, c->m_rot, sizeof m);
    memcpy(mv, c->m_move, sizeof mv);
    const float fp = c->prev_f, df = c->prev_f - c->proj.f, near_z = c->near_z;
    const int n = k->count;
    for (int s = 0; s < n; s++) {
        float t = k->t[s], vx = k->vx[s], vy = k->vy[s];
        float inv_t = t > 0.0f ? 1.0f / t : 0.0f;
        float qx = m[0] * vx + m[1] * vy - m[2] + mv[0] * inv_t;
        float qy = m[3] * vx + m[4] * vy - m[5] + mv[1] * inv_t;
        float zq = 0.0f - (m[6] * vx + m[7] * vy - m[8] + mv[2] * inv_t);
        float z = t > 0.0f ? t * zq : 0.0f;
        int seen = z >= near_z;
        float d = seen ? zq : 1.0f;
        float mx = fp * (qx / d - vx) + df * vx, my = 0.0f - (fp * (qy / d - vy) + df * vy);
        k->px[s] = seen ? mx : 0.0f;
        k->py[s] = seen ? my : 0.0f;
        k->pz[s] = z;
    }
}

/* One segment, pixels [x0, x0 + CHUNK) of row y: every output that is read. The light
   outputs go first, while the world points and lr, lg, lb are free; motion reuses px,
   py, pz after store. */
static void segment(const struct job *j, struct chunk *k, int x0, int y)
{
    const size_t o = (size_t)y * (size_t)j->w + (size_t)x0;
    make_rays(j->c, k, x0, y, j->w);
    trace(j, k);
    gather(j, k);
    if (j->back)
        trace_back(j, k);
    geometry(j->c, k);
    if (j->dir[0]) {
        lighting(j, k);
        store3(j->dir, o, k->lr, k->lg, k->lb, k->count);
    }
    if (j->env[0]) {
        environment_light(j, k);
        store3(j->env, o, k->lr, k->lg, k->lb, k->count);
    }
    store(j, k, o);
    if (j->back)
        ssg_stream_store(j->back + o, k->back, k->count);
    if (j->motion[0]) {
        motion(j->c, k);
        store3(j->motion, o, k->px, k->py, k->pz, k->count);
    }
    if (j->emit[0])
        store3(j->emit, o, k->er, k->eg, k->eb, k->count);
}

static void rows(void *user, int y0, int y1)
{
    const struct job *j = user;
    struct chunk k;
    for (int s = 0; s < CHUNK; s++)
        k.ox[s] = j->c->eye[0], k.oy[s] = j->c->eye[1], k.oz[s] = j->c->eye[2];
    for (int y = y0; y < y1; y++)
        for (int x0 = 0; x0 < j->w; x0 += CHUNK)
            segment(j, &k, x0, y);
    ssg_stream_fence(); /* the streaming stores are visible before the band counts as done */
}

enum ssg_err ssg_gbuffer_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io)
{
    struct job j = {.c = consts, .scene = ctx->scene};
    struct ssg_image *const *out = io->out;
    j.w = out[SSG_GBUFFER_OUT_DEPTH]->width;
    j.h = out[SSG_GBUFFER_OUT_DEPTH]->height;
    for (int a = 0; a < 3; a++) {
        j.pos[a] = ssg_image_plane(out[SSG_GBUFFER_OUT_POSITION], a);
        j.nrm[a] = ssg_image_plane(out[SSG_GBUFFER_OUT_NORMAL], a);
        j.alb[a] = ssg_image_plane(out[SSG_GBUFFER_OUT_ALBEDO], a);
    }
    j.depth = ssg_image_plane(out[SSG_GBUFFER_OUT_DEPTH], 0);
    j.back = out[SSG_GBUFFER_OUT_BACK] ? out[SSG_GBUFFER_OUT_BACK]->data : NULL;
    for (int a = 0; a < 3; a++) { /* on demand: only when something reads it */
        j.dir[a] = out[SSG_GBUFFER_OUT_DIRECT] ? ssg_image_plane(out[SSG_GBUFFER_OUT_DIRECT], a)
                                                : NULL;
        j.env[a] = out[SSG_GBUFFER_OUT_ENVIRONMENT]
                       ? ssg_image_plane(out[SSG_GBUFFER_OUT_ENVIRONMENT], a)
                       : NULL;
        j.motion[a] = out[SSG_GBUFFER_OUT_MOTION] ? ssg_image_plane(out[SSG_GBUFFER_OUT_MOTION], a)
                                                  : NULL;
        j.emit[a] = out[SSG_GBUFFER_OUT_EMISSION]
                        ? ssg_image_plane(out[SSG_GBUFFER_OUT_EMISSION], a)
                        : NULL;
    }
    ssg_parallel_rows(j.h, ROWS_PER_BAND, rows, &j);
    return SSG_OK;
}
