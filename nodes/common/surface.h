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

/* World normal at a hit, NOT normalised and not turned to face the ray: the interpolated
 * vertex normal, or with face = 1 the triangle's own normal (edge cross product). */
void ssg_hit_normal(const struct ssg_scene *scene, const struct ssg_hit *hit, int face,
                    float n[3]);

#endif
