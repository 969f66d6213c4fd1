/* distance.h - a coarse distance field of the scene's triangles, for visibility tests that
 * must be cheap and need not be exact (rsm's sender-receiver visibility: a sphere trace
 * through the grid, nodes/rsm/README.md).
 *
 * A grid of cubic voxels over the scene's bounds (SSG_DISTANCE_RES voxels on the longest
 * axis, SSG_DISTANCE_MARGIN empty voxels beyond the bounds on every side). A voxel is
 * occupied when a triangle touches it (conservative voxelisation: the triangle-box overlap
 * test of Akenine-Moller, "Fast 3D Triangle-Box Overlap Testing", JGT 6(1), 2001); every
 * voxel holds the Euclidean distance from its centre to the nearest occupied voxel's
 * centre, in voxels (0 = occupied), by the exact distance transform of Felzenszwalb and
 * Huttenlocher ("Distance Transforms of Sampled Functions", Theory of Computing 8, 2012),
 * one axis after the other.
 *
 * ssg_scene_load builds it (scene->distance) with the Embree scene, once a scene, so every
 * node and frame of a run shares it; the GL backend uploads it once a run with the scene
 * (core/gl/gl_scene.h). Pure data afterwards: any number of threads may read it. */
#ifndef SSG_DISTANCE_H
#define SSG_DISTANCE_H

#include <stddef.h>
#include <stdint.h>

#include "ssgraph.h"

struct ssg_mesh;

/* voxels on the scene's longest axis: at 64 the Cornell box's tall box, a voxel thicker on
   each side, cast a bounce shadow 0.67x the truth's brightness; at 96 0.9-1.1x (3.4 MB);
   128 gave the same means for 11 ms more of rsm a 1280x720 frame (nodes/rsm/README.md) */
enum { SSG_DISTANCE_RES = 96 };
enum { SSG_DISTANCE_MARGIN = 2 }; /* empty voxels around the bounds */

struct ssg_distance {
    int n[3];      /* voxels on x, y, z (margins included) */
    float lo[3];   /* world corner of voxel (0, 0, 0), its smallest coordinates */
    float voxel;   /* side of a voxel, world units */
    float *d;      /* n[0] n[1] n[2] distances in voxels, x fastest, then y, then z */
    /* The same distances for the CPU's traces, in a quarter of the cache lines a trace
       step touches: each voxel's squared distance (an integer, the transform's sum of
       squares) as 16 bits, in bricks of 4 x 4 x 2 voxels, one cache line each
       (ssg_distance_brick_at). NULL where one is not below 65535 (no occupied voxel) or
       out of memory: d alone then. */
    uint16_t *square;
    float *root;   /* root[q] = the distance d of every voxel whose square is q */
    int bricks[3]; /* bricks on x, y, z */
};

enum { SSG_DISTANCE_BRICK = 32 }; /* voxels a brick: 4 on x, 4 on y, 2 on z */

/* The index into `square` of voxel (x, y, z), which must lie in the grid. */
static inline size_t ssg_distance_brick_at(const struct ssg_distance *f, int x, int y, int z)
{
    size_t brick = ((size_t)(z >> 1) * f->bricks[1] + (size_t)(y >> 2)) * f->bricks[0] +
                   (size_t)(x >> 2);
    return brick * SSG_DISTANCE_BRICK + (size_t)((z & 1) * 16 + (y & 3) * 4 + (x & 3));
}

/* The field of `count` meshes' triangles with `res` voxels on the longest axis of their
 * bounds (>= 1). *out = NULL and SSG_OK when there is no triangle (nothing occludes);
 * SSG_E_NOMEM when out of memory. */
enum ssg_err ssg_distance_build(const struct ssg_mesh *meshes, int count, int res,
                                struct ssg_distance **out);
void ssg_distance_destroy(struct ssg_distance **field);

/* The distance stored at voxel (x, y, z), which must lie in the grid. */
static inline float ssg_distance_at(const struct ssg_distance *f, int x, int y, int z)
{
    return f->d[((size_t)z * f->n[1] + y) * f->n[0] + x];
}

#endif
