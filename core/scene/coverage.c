/* coverage.c - alpha-masked surfaces and the shared texture lookup (see coverage.h). */
#include "scene/coverage.h"

#include <math.h>
#include <stdint.h>

void ssg_texture_bilinear(const float *texels, int channels, int width, int height, float u,
                          float v, float *out)
{
    float fx = u * (float)width - 0.5f, fy = v * (float)height - 0.5f;
    float x0f = floorf(fx), y0f = floorf(fy), ax = fx - x0f, ay = fy - y0f;
    int x0 = (int)fmodf(x0f, (float)width), y0 = (int)fmodf(y0f, (float)height);
    x0 += x0 < 0 ? width : 0;
    y0 += y0 < 0 ? height : 0;
    int x1 = x0 + 1 < width ? x0 + 1 : 0, y1 = y0 + 1 < height ? y0 + 1 : 0;
    size_t n = (size_t)channels, w = (size_t)width;
    const float *a = &texels[n * ((size_t)y0 * w + (size_t)x0)];
    const float *b = &texels[n * ((size_t)y0 * w + (size_t)x1)];
    const float *c = &texels[n * ((size_t)y1 * w + (size_t)x0)];
    const float *d = &texels[n * ((size_t)y1 * w + (size_t)x1)];
    for (int i = 0; i < channels; i++)
        out[i] = (1 - ay) * ((1 - ax) * a[i] + ax * b[i]) + ay * ((1 - ax) * c[i] + ax * d[i]);
}

int ssg_material_masked(const struct ssg_material *m)
{
    return m->alpha_mode != SSG_ALPHA_OPAQUE;
}

int ssg_mesh_masked(const struct ssg_scene *s, int mesh)
{
    return ssg_material_masked(&s->materials[s->meshes[mesh].material]);
}

int ssg_mesh_covers(const struct ssg_scene *s, int mesh, int tri, float u, float v)
{
    const struct ssg_mesh *m = &s->meshes[mesh];
    const struct ssg_material *mat = &s->materials[m->material];
    if (!ssg_material_masked(mat))
        return 1;
    float alpha = 1.0f;
    const struct ssg_texture *t = mat->texture >= 0 ? &s->textures[mat->texture] : NULL;
    if (t && t->alpha && m->uvs) {
        const uint32_t *k = &m->indices[3 * (size_t)tri];
        float w0 = 1.0f - u - v, uv[2];
        for (int i = 0; i < 2; i++)
            uv[i] = w0 * m->uvs[2 * k[0] + i] + u * m->uvs[2 * k[1] + i] +
                    v * m->uvs[2 * k[2] + i];
        ssg_texture_bilinear(t->alpha, 1, t->width, t->height, uv[0], uv[1], &alpha);
    }
    return mat->opacity * alpha >= mat->alpha_cutoff;
}

void ssg_ray_barycentrics(const struct ssg_mesh *m, int t, const double o[3], const double d[3],
                          float *u, float *v)
{
    const uint32_t *tri = &m->indices[3 * (size_t)t];
    const float *p0 = &m->positions[3 * (size_t)tri[0]];
    const float *p1 = &m->positions[3 * (size_t)tri[1]];
    const float *p2 = &m->positions[3 * (size_t)tri[2]];
    double e1[3], e2[3], s[3], p[3], q[3];
    for (int k = 0; k < 3; k++)
        e1[k] = (double)p1[k] - p0[k], e2[k] = (double)p2[k] - p0[k], s[k] = o[k] - p0[k];
    p[0] = d[1] * e2[2] - d[2] * e2[1], p[1] = d[2] * e2[0] - d[0] * e2[2];
    p[2] = d[0] * e2[1] - d[1] * e2[0];
    q[0] = s[1] * e1[2] - s[2] * e1[1], q[1] = s[2] * e1[0] - s[0] * e1[2];
    q[2] = s[0] * e1[1] - s[1] * e1[0];
    double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    double inv = det != 0.0 ? 1.0 / det : 0.0;
    double bu = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) * inv;
    double bv = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) * inv;
    bu = bu > 0.0 ? (bu < 1.0 ? bu : 1.0) : 0.0;
    bv = bv > 0.0 ? (bv < 1.0 - bu ? bv : 1.0 - bu) : 0.0;
    *u = (float)bu, *v = (float)bv;
}
