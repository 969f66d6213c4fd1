/* rt.h - every CPU ray query of ssgraph, through Embree 3: one device and one committed
 * scene holding a triangle geometry per scene mesh (Embree geometry id == mesh index).
 *
 * ssg_scene_load builds it (scene->rt) when it loads assets; it copies the vertex and index
 * data, but an alpha-masked mesh's filter (scene/coverage.h) reads the scene's uvs,
 * materials and textures while tracing, so the scene must outlive it (it owns it). Queries are thread-safe: any number of
 * threads may intersect the same built struct ssg_rt at once. */
#ifndef SSG_RT_H
#define SSG_RT_H

#include "ssgraph.h"

struct ssg_scene;
struct ssg_rt;

/* The nearest hit of one ray. */
struct ssg_hit {
    float t; /* ray parameter of the hit: hit point = org + t * dir (dir need not be unit) */
    float u, v;   /* barycentrics: point = (1-u-v) * p0 + u * p1 + v * p2 */
    int mesh;     /* index into scene->meshes, -1 = the ray hit nothing */
    int triangle; /* triangle index within that mesh */
};

/* A batch of rays in structure-of-arrays form, sharing one [tnear, tfar] interval. */
struct ssg_rays {
    int count;
    const float *ox, *oy, *oz; /* origins, world */
    const float *dx, *dy, *dz; /* directions, world; t is measured in units of |dir| */
    float tnear, tfar;         /* hits outside [tnear, tfar] are ignored */
};

/* Builds the Embree scene of every mesh. Embree errors go to diags (SSG_E_BACKEND). */
enum ssg_err ssg_rt_build(const struct ssg_scene *scene, struct ssg_rt **out,
                          struct ssg_diags *diags);
void ssg_rt_destroy(struct ssg_rt **rt);

/* Nearest hit of one ray (incoherent: reflection, AO and shadow-like queries). */
void ssg_rt_intersect(const struct ssg_rt *rt, const float org[3], const float dir[3],
                      float tnear, float tfar, struct ssg_hit *hit);

/* Nearest hits of a batch of coherent rays, traced as one Embree ray stream with the
 * coherent flag: order them so neighbours in the batch are neighbours on screen (a row
 * segment of primary rays, for instance). hits[i] belongs to ray i. */
void ssg_rt_intersect_rays(const struct ssg_rt *rt, const struct ssg_rays *rays,
                           struct ssg_hit *hits);

/* ssg_rt_intersect_rays with ray i starting at tnears[i] in place of rays->tnear: rays
 * continued past a hit they must not find again (the G-buffer's second layer). */
void ssg_rt_intersect_rays_past(const struct ssg_rt *rt, const struct ssg_rays *rays,
                                const float *tnears, struct ssg_hit *hits);

/* 1 when anything lies on the ray within [tnear, tfar], else 0 (cheaper than a hit). */
int ssg_rt_occluded(const struct ssg_rt *rt, const float org[3], const float dir[3],
                    float tnear, float tfar);

/* Occlusion of a batch of rays (ambient-occlusion style: many rays from one point, or
 * from neighbouring points): occluded[i] = 1 when anything lies on ray i within
 * [tnear, tfar], else 0; occluded may be NULL. Returns how many rays are occluded.
 * Traced as Embree packets of 8 with the incoherent flag, the fastest style for such rays
 * (rt.c has the measurement); the answers do not depend on how rays are batched. */
int ssg_rt_occluded_rays(const struct ssg_rt *rt, const struct ssg_rays *rays,
                         unsigned char *occluded);

#endif
