/* surface.c - albedo and normal at a ray hit (see surface.h). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "scene/coverage.h"
#include "scene/scene.h"
#include "common/surface.h"

/* The hit's interpolated texture coordinates (its mesh has uvs). */
static void hit_uv(const struct ssg_mesh *m, const struct ssg_hit *h, float uv[2])
{
    const uint32_t *tri = &m->indices[3 * (size_t)h->triangle];
    float w0 = 1.0f - h->u - h->v;
    for (int i = 0; i < 2; i++)
        uv[i] = w0 * m->uvs[2 * tri[0] + i] + h->u * m->uvs[2 * tri[1] + i] +
                h->v * m->uvs[2 * tri[2] + i];
}

int ssg_hit_emits(const struct ssg_scene *s, const struct ssg_hit *h)
{
    return ssg_material_emits(&s->materials[s->meshes[h->mesh].material]);
}

void ssg_hit_emission(const struct ssg_scene *s, const struct ssg_hit *h, float out[3])
{
    const struct ssg_mesh *m = &s->meshes[h->mesh];
    const struct ssg_material *mat = &s->materials[m->material];
    memcpy(out, mat->emission, 3 * sizeof(float));
    if (mat->emission_texture < 0 || !m->uvs || !ssg_hit_emits(s, h))
        return;
    float uv[2], rgb[3];
    hit_uv(m, h, uv);
    const struct ssg_texture *t = &s->textures[mat->emission_texture];
    ssg_texture_bilinear(t->rgb, 3, t->width, t->height, uv[0], uv[1], rgb);
    for (int i = 0; i < 3; i++)
        out[i] *= rgb[i];
}

void ssg_hit_albedo(const struct ssg_scene *s, const struct ssg_hit *h, float out[3])
{
    const struct ssg_mesh *m = &s->meshes[h->mesh];
    const struct ssg_material *mat = &s->materials[m->material];
    memcpy(out, mat->albedo, 3 * sizeof(float));
    if (mat->texture >= 0 && m->uvs) {
        float uv[2];
        hit_uv(m, h, uv);
        const struct ssg_texture *t = &s->textures[mat->texture];
        ssg_texture_bilinear(t->rgb, 3, t->width, t->height, uv[0], uv[1], out);
        for (int i = 0; i < 3; i++)
            out[i] *= mat->albedo[i];
    }
    if (m->colors) { /* glTF COLOR_0 multiplies the base colour */
        const uint32_t *k = &m->indices[3 * (size_t)h->triangle];
        float w0 = 1.0f - h->u - h->v;
        for (int i = 0; i < 3; i++)
            out[i] *= w0 * m->colors[3 * k[0] + i] + h->u * m->colors[3 * k[1] + i] +
                      h->v * m->colors[3 * k[2] + i];
    }
}

/* The material's tangent-space normal map bends the interpolated normal n (in place, not
   normalised): n' = x t + y b + z n with (x, y, z) = 2 rgb - 1 (x, y times normal_scale), t
   the interpolated tangent made orthogonal to unit n and b = cross(n, t) w (glTF 2.0,
   3.9.3). No map, uvs or tangents: n stays. surface.glsl's shading_normal is the twin. */
static void normal_map(const struct ssg_scene *s, const struct ssg_hit *h, float n[3])
{
    const struct ssg_mesh *m = &s->meshes[h->mesh];
    const struct ssg_material *mat = &s->materials[m->material];
    if (mat->normal_texture < 0 || !m->uvs || !m->tangents)
        return;
    const uint32_t *k = &m->indices[3 * (size_t)h->triangle];
    float w0 = 1.0f - h->u - h->v, uv[2], t[4], rgb[3];
    for (int i = 0; i < 2; i++)
        uv[i] = w0 * m->uvs[2 * k[0] + i] + h->u * m->uvs[2 * k[1] + i] +
                h->v * m->uvs[2 * k[2] + i];
    for (int i = 0; i < 4; i++)
        t[i] = w0 * m->tangents[4 * k[0] + i] + h->u * m->tangents[4 * k[1] + i] +
               h->v * m->tangents[4 * k[2] + i];
    float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0.0f))
        return;
    float u[3] = {n[0] / len, n[1] / len, n[2] / len};
    float d = t[0] * u[0] + t[1] * u[1] + t[2] * u[2];
    for (int i = 0; i < 3; i++)
        t[i] -= u[i] * d;
    float tl = sqrtf(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    if (!(tl > 0.0f))
        return;
    float sign = t[3] < 0.0f ? -1.0f : 1.0f;
    for (int i = 0; i < 3; i++)
        t[i] /= tl;
    float b[3] = {(u[1] * t[2] - u[2] * t[1]) * sign, (u[2] * t[0] - u[0] * t[2]) * sign,
                  (u[0] * t[1] - u[1] * t[0]) * sign};
    const struct ssg_texture *tex = &s->textures[mat->normal_texture];
    ssg_texture_bilinear(tex->rgb, 3, tex->width, tex->height, uv[0], uv[1], rgb);
    float x = (2.0f * rgb[0] - 1.0f) * mat->normal_scale;
    float y = (2.0f * rgb[1] - 1.0f) * mat->normal_scale, z = 2.0f * rgb[2] - 1.0f;
    for (int i = 0; i < 3; i++)
        n[i] = x * t[i] + y * b[i] + z * u[i];
}

void ssg_hit_normal(const struct ssg_scene *s, const struct ssg_hit *h, int face, float n[3])
{
    const struct ssg_mesh *m = &s->meshes[h->mesh];
    const uint32_t *tri = &m->indices[3 * (size_t)h->triangle];
    if (face) {
        const float *p0 = &m->positions[3 * tri[0]], *p1 = &m->positions[3 * tri[1]];
        const float *p2 = &m->positions[3 * tri[2]];
        float e1[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
        float e2[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        return;
    }
    float w0 = 1.0f - h->u - h->v;
    for (int i = 0; i < 3; i++)
        n[i] = w0 * m->normals[3 * tri[0] + i] + h->u * m->normals[3 * tri[1] + i] +
               h->v * m->normals[3 * tri[2] + i];
    normal_map(s, h, n);
}
