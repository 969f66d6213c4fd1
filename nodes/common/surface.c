/* surface.c - albedo and normal at a ray hit (see surface.h). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "scene/coverage.h"
#include "scene/scene.h"
#include "common/surface.h"

void ssg_hit_albedo(const struct ssg_scene *s, const struct ssg_hit *h, float out[3])
{
    const struct ssg_mesh *m = &s->meshes[h->mesh];
    const struct ssg_material *mat = &s->materials[m->material];
    const uint32_t *tri = &m->indices[3 * (size_t)h->triangle];
    memcpy(out, mat->albedo, 3 * sizeof(float));
    if (mat->texture < 0 || !m->uvs)
        return;
    float w0 = 1.0f - h->u - h->v, uv[2];
    for (int i = 0; i < 2; i++)
        uv[i] = w0 * m->uvs[2 * tri[0] + i] + h->u * m->uvs[2 * tri[1] + i] +
                h->v * m->uvs[2 * tri[2] + i];
    const struct ssg_texture *t = &s->textures[mat->texture];
    ssg_texture_bilinear(t->rgb, 3, t->width, t->height, uv[0], uv[1], out);
    for (int i = 0; i < 3; i++)
        out[i] *= mat->albedo[i];
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
}
