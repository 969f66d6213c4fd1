/* surface.h - what the scene says about the surface at a ray hit (core/scene/rt.h): its albedo
 * (material times texture) and normal. The G-buffer's primary hits and the reference nodes'
 * secondary hits read surfaces through these, so both see the same materials.
 * Read-only on a loaded scene; thread-safe. */
#ifndef SSG_SURFACE_H
#define SSG_SURFACE_H

#include "scene/rt.h"

struct ssg_scene;

/* Diffuse albedo at a hit (hit->mesh >= 0): the material's albedo times its texture,
 * bilinear at the interpolated uv with wrap-around, linear RGB. */
void ssg_hit_albedo(const struct ssg_scene *scene, const struct ssg_hit *hit, float rgb[3]);

/* Emitted radiance at a hit (hit->mesh >= 0): the material's emission times its emission
 * texture (bilinear at the interpolated uv, as the albedo's), linear RGB; 0 for most. */
void ssg_hit_emission(const struct ssg_scene *scene, const struct ssg_hit *hit, float rgb[3]);

/* 1 when the hit's material emits light (its emission is not black). */
int ssg_hit_emits(const struct ssg_scene *scene, const struct ssg_hit *hit);

/* World normal at a hit, NOT normalised and not turned to face the ray: the interpolated
 * vertex normal bent by the material's normal map when it has one (glTF's tangent space,
 * the mesh's tangents), or with face = 1 the triangle's own normal (edge cross product,
 * no map). */
void ssg_hit_normal(const struct ssg_scene *scene, const struct ssg_hit *hit, int face,
                    float n[3]);

#endif
