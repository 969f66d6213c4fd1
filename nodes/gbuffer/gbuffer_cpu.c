/* gbuffer_cpu.c - CPU kernel of the `gbuffer` node (method in gbuffer.c).
 *
 * Bands of ROWS_PER_BAND rows go to ssg_parallel_rows. Within a band, pairs of rows are
 * cut into chunks of CHUNK_COLS columns whose rays are ordered in 4x2 pixel tiles, so each
 * packet of SSG_RT_PACKET rays Embree traces together covers a compact patch of the
 * screen (coherent traversal). After the chunk is traced, each hit is shaded on its own.
 * A pixel depends only on its own ray, so the result does not depend on the threads. */
#include <math.h>
#include <string.h>

#include "gbuffer.h"
#include "rt.h"
#include "scene.h"

enum { ROWS_PER_BAND = 4, CHUNK_COLS = 64, CHUNK = 2 * CHUNK_COLS };

struct job {
    const struct ssg_gbuffer_consts *c;
    const struct ssg_scene *scene;
    float *pos[3], *nrm[3], *depth, *alb[3], *dir[3]; /* output planes */
    int w, h;
};

/* The rays of one chunk and their hits. */
struct chunk {
    int count;
    int px[CHUNK], py[CHUNK];                           /* the pixel of each ray */
    float vx[CHUNK], vy[CHUNK];                         /* view direction (z = -1) */
    float ox[CHUNK], oy[CHUNK], oz[CHUNK];              /* world origin: the eye */
    float dx[CHUNK], dy[CHUNK], dz[CHUNK];              /* world direction */
    struct ssg_hit hits[CHUNK];
};

/* One surface point, everything shading needs, in world space unless named view. */
struct surface {
    float p[3];      /* hit point */
    float n[3];      /* unit normal facing the camera */
    float nv[3];     /* the same in view space */
    float v[3];      /* unit direction towards the camera */
    float albedo[3];
    const struct ssg_material *m;
};

static void rot_apply(const float r[9], const float a[3], float out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = r[3 * i] * a[0] + r[3 * i + 1] * a[1] + r[3 * i + 2] * a[2];
}

static void rot_apply_t(const float r[9], const float a[3], float out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = r[i] * a[0] + r[3 + i] * a[1] + r[6 + i] * a[2];
}

static float dot3(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void normalize3(float v[3])
{
    float len2 = dot3(v, v);
    float s = len2 > 0.0f ? 1.0f / sqrtf(len2) : 0.0f;
    v[0] *= s, v[1] *= s, v[2] *= s;
}

/* Rays for rows y and y+1 (when inside the image), columns [x0, x0 + CHUNK_COLS), in 4x2
 * tiles (8x1 when only one row is left). */
static void make_rays(const struct job *j, struct chunk *k, int x0, int y, int rows)
{
    const struct ssg_gbuffer_consts *c = j->c;
    int tile_w = SSG_RT_PACKET / rows, x1 = x0 + CHUNK_COLS < j->w ? x0 + CHUNK_COLS : j->w;
    float inv_f = 1.0f / c->proj.f;
    k->count = 0;
    for (int tx = x0; tx < x1; tx += tile_w)
        for (int lane = 0; lane < SSG_RT_PACKET; lane++) {
            int x = tx + lane % tile_w, yy = y + lane / tile_w;
            if (x >= x1)
                continue;
            int i = k->count++;
            float dv[3] = {((float)x + 0.5f - c->proj.cx) * inv_f,
                           -((float)yy + 0.5f - c->proj.cy) * inv_f, -1.0f}, dw[3];
            rot_apply_t(c->rot, dv, dw);
            k->px[i] = x, k->py[i] = yy;
            k->vx[i] = dv[0], k->vy[i] = dv[1];
            k->ox[i] = c->eye[0], k->oy[i] = c->eye[1], k->oz[i] = c->eye[2];
            k->dx[i] = dw[0], k->dy[i] = dw[1], k->dz[i] = dw[2];
        }
}

static void trace(const struct job *j, struct chunk *k)
{
    struct ssg_rays rays = {k->count, k->ox, k->oy, k->oz, k->dx, k->dy, k->dz,
                            j->c->near_z, j->c->far_z};
    ssg_rt_intersect_rays(j->scene->rt, &rays, k->hits);
}

/* Bilinear lookup with wrap-around (uv tiles the texture), row 0 at v = 0. */
static void sample_texture(const struct ssg_texture *t, float u, float v, float out[3])
{
    float fx = u * (float)t->width - 0.5f, fy = v * (float)t->height - 0.5f;
    float x0f = floorf(fx), y0f = floorf(fy), ax = fx - x0f, ay = fy - y0f;
    int x0 = (int)fmodf(x0f, (float)t->width), y0 = (int)fmodf(y0f, (float)t->height);
    x0 += x0 < 0 ? t->width : 0;
    y0 += y0 < 0 ? t->height : 0;
    int x1 = x0 + 1 < t->width ? x0 + 1 : 0, y1 = y0 + 1 < t->height ? y0 + 1 : 0;
    const float *a = &t->rgb[3 * ((size_t)y0 * (size_t)t->width + (size_t)x0)];
    const float *b = &t->rgb[3 * ((size_t)y0 * (size_t)t->width + (size_t)x1)];
    const float *cc = &t->rgb[3 * ((size_t)y1 * (size_t)t->width + (size_t)x0)];
    const float *d = &t->rgb[3 * ((size_t)y1 * (size_t)t->width + (size_t)x1)];
    for (int i = 0; i < 3; i++)
        out[i] = (1 - ay) * ((1 - ax) * a[i] + ax * b[i]) + ay * ((1 - ax) * cc[i] + ax * d[i]);
}

static void surface_albedo(const struct ssg_scene *s, const struct ssg_mesh *m,
                           const uint32_t *tri, const struct ssg_hit *h, struct surface *sf)
{
    memcpy(sf->albedo, sf->m->albedo, sizeof sf->albedo);
    if (sf->m->texture < 0 || !m->uvs)
        return;
    float w0 = 1.0f - h->u - h->v, uv[2], tex[3];
    for (int i = 0; i < 2; i++)
        uv[i] = w0 * m->uvs[2 * tri[0] + i] + h->u * m->uvs[2 * tri[1] + i] +
                h->v * m->uvs[2 * tri[2] + i];
    sample_texture(&s->textures[sf->m->texture], uv[0], uv[1], tex);
    for (int i = 0; i < 3; i++)
        sf->albedo[i] *= tex[i];
}

static void surface_normal(const struct ssg_mesh *m, const uint32_t *tri,
                           const struct ssg_hit *h, int face, float n[3])
{
    if (face) {
        const float *p0 = &m->positions[3 * tri[0]], *p1 = &m->positions[3 * tri[1]];
        const float *p2 = &m->positions[3 * tri[2]];
        float e1[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
        float e2[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    } else {
        float w0 = 1.0f - h->u - h->v;
        for (int i = 0; i < 3; i++)
            n[i] = w0 * m->normals[3 * tri[0] + i] + h->u * m->normals[3 * tri[1] + i] +
                   h->v * m->normals[3 * tri[2] + i];
    }
    normalize3(n);
}

/* Builds the surface of hit i of the chunk; returns its view-space depth. */
static float make_surface(const struct job *j, const struct chunk *k, int i, struct surface *sf)
{
    const struct ssg_hit *h = &k->hits[i];
    const struct ssg_mesh *m = &j->scene->meshes[h->mesh];
    const uint32_t *tri = &m->indices[3 * (size_t)h->triangle];
    const float dw[3] = {k->dx[i], k->dy[i], k->dz[i]}, dv[3] = {k->vx[i], k->vy[i], -1.0f};
    sf->m = &j->scene->materials[m->material];
    surface_normal(m, tri, h, j->c->p.normals == SSG_GBUFFER_NORMALS_FACE, sf->n);
    rot_apply(j->c->rot, sf->n, sf->nv);
    if (dot3(sf->nv, dv) > 0.0f) /* seen from behind: shade the side facing the camera */
        for (int a = 0; a < 3; a++)
            sf->n[a] = -sf->n[a], sf->nv[a] = -sf->nv[a];
    for (int a = 0; a < 3; a++) {
        sf->p[a] = j->c->eye[a] + h->t * dw[a];
        sf->v[a] = -dw[a];
    }
    normalize3(sf->v);
    surface_albedo(j->scene, m, tri, h, sf);
    return h->t;
}

/* Lambert + Blinn-Phong of every light at the surface, no shadows (gbuffer.c). */
static void direct_light(const struct ssg_scene *s, const struct surface *sf, float out[3])
{
    const struct ssg_material *m = sf->m;
    int specular = m->specular[0] > 0.0f || m->specular[1] > 0.0f || m->specular[2] > 0.0f;
    out[0] = out[1] = out[2] = 0.0f;
    for (int li = 0; li < s->light_count; li++) {
        const struct ssg_light *l = &s->lights[li];
        float dir[3], falloff = 1.0f;
        if (l->kind == SSG_LIGHT_POINT) {
            for (int a = 0; a < 3; a++)
                dir[a] = l->position[a] - sf->p[a];
            float d2 = dot3(dir, dir);
            falloff = d2 > 0.0f ? 1.0f / d2 : 0.0f;
            normalize3(dir);
        } else {
            for (int a = 0; a < 3; a++)
                dir[a] = -l->direction[a];
        }
        float ndl = dot3(sf->n, dir);
        if (ndl <= 0.0f)
            continue;
        float spec = 0.0f;
        if (specular) {
            float hv[3] = {dir[0] + sf->v[0], dir[1] + sf->v[1], dir[2] + sf->v[2]};
            normalize3(hv);
            float ndh = dot3(sf->n, hv);
            spec = ndh > 0.0f ? powf(ndh, m->shininess) : 0.0f;
        }
        float e = l->intensity * ndl * falloff;
        for (int a = 0; a < 3; a++)
            out[a] += (sf->albedo[a] * (float)(1.0 / M_PI) + m->specular[a] * spec) * l->color[a] * e;
    }
}

static void write_pixel(const struct job *j, const struct chunk *k, int i)
{
    size_t o = (size_t)k->py[i] * (size_t)j->w + (size_t)k->px[i];
    if (k->hits[i].mesh < 0) {
        for (int a = 0; a < 3; a++)
            j->pos[a][o] = j->nrm[a][o] = j->alb[a][o] = j->dir[a][o] = 0.0f;
        j->depth[o] = 0.0f;
        return;
    }
    struct surface sf;
    float t = make_surface(j, k, i, &sf), direct[3];
    direct_light(j->scene, &sf, direct);
    const float p[3] = {t * k->vx[i], t * k->vy[i], -t};
    for (int a = 0; a < 3; a++) {
        j->pos[a][o] = p[a];
        j->nrm[a][o] = sf.nv[a];
        j->alb[a][o] = sf.albedo[a];
        j->dir[a][o] = direct[a];
    }
    j->depth[o] = t;
}

static void rows(void *user, int y0, int y1)
{
    const struct job *j = user;
    struct chunk k;
    for (int y = y0; y < y1; y += 2) {
        int n = y + 1 < y1 ? 2 : 1;
        for (int x0 = 0; x0 < j->w; x0 += CHUNK_COLS) {
            make_rays(j, &k, x0, y, n);
            trace(j, &k);
            for (int i = 0; i < k.count; i++)
                write_pixel(j, &k, i);
        }
    }
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
        j.dir[a] = ssg_image_plane(out[SSG_GBUFFER_OUT_DIRECT], a);
    }
    j.depth = ssg_image_plane(out[SSG_GBUFFER_OUT_DEPTH], 0);
    ssg_parallel_rows(j.h, ROWS_PER_BAND, rows, &j);
    return SSG_OK;
}
