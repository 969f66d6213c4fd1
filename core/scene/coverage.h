/* coverage.h - where a surface is: an alpha-masked material (glTF alphaMode MASK, an OBJ
 * map_d, a scene file's alpha_mode=mask) is a surface only where its opacity times its
 * texture's alpha reaches the cutoff. Every path that finds surfaces asks these, so a
 * masked leaf is a leaf alike to the camera, to a light and to the truth: Embree's filter
 * functions (rt.c: the CPU G-buffer, reference_ao, reference_gi and every CPU ray), the
 * CPU rasterisers of shadowmaps and lightmaps, and nodes/common/surface.glsl's twin of
 * ssg_material_covers on GL. Also the one bilinear texture lookup both the albedo
 * (nodes/common/surface.c) and the coverage read.
 *
 * Read-only on a loaded scene; thread-safe. */
#ifndef SSG_COVERAGE_H
#define SSG_COVERAGE_H

#include "scene/scene.h"

/* Bilinear lookup of a texture's `channels`-float texels at (u, v) between texel centres,
   wrapping around (texture coordinates repeat), into out[0 .. channels). */
void ssg_texture_bilinear(const float *texels, int channels, int width, int height, float u,
                          float v, float *out);

/* 1 when the material is masked (MASK or BLEND): it has places without a surface. */
int ssg_material_masked(const struct ssg_material *m);

/* The mesh's material is masked: its hits must be asked ssg_mesh_covers. */
int ssg_mesh_masked(const struct ssg_scene *scene, int mesh);

/* 1 when triangle `tri` of mesh `mesh` is a surface at barycentrics (u, v) (point =
   (1-u-v) p0 + u p1 + v p2): always for an opaque material; for a masked one when opacity
   x alpha (bilinear at the interpolated uv) >= alpha_cutoff. */
int ssg_mesh_covers(const struct ssg_scene *scene, int mesh, int tri, float u, float v);

/* Barycentrics (u, v) where the line o + t d meets triangle `tri` of `mesh` (Moeller and
   Trumbore in double, clamped into the triangle: a texel centre may lie a rounding outside
   it). The rasterisers' texels use it to find what they cover. */
void ssg_ray_barycentrics(const struct ssg_mesh *m, int tri, const double o[3],
                          const double d[3], float *u, float *v);

#endif
