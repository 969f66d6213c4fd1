/* proxy.h - the scene as the map rasterisers draw it: every dense mesh simplified to the
 * fewest triangles whose surface stays within a stated distance of the original.
 *
 * Why: a shadow or light map is a grid of texels, and a fine mesh's triangles are mostly
 * smaller than a texel; drawing all of them into every map made the map nodes' cost grow
 * with triangles times maps (the probe's 384 shadow maps of a million-triangle sphere:
 * 1.7 s). A surface within a fraction of a texel of the original moves a map's depths and
 * edges by less than its own sampling does. The simplification is meshoptimizer's
 * (Garland-Heckbert quadrics with topology kept, meshopt_simplify), run once a scene and
 * level and kept until the scene is destroyed.
 *
 * Which meshes: those of at least SSG_PROXY_MIN_TRIANGLES triangles whose material is not
 * masked (an alpha mask is read at interpolated uvs, which a simplified triangle would
 * move), and only where the simplified mesh has at most half the triangles; every other
 * mesh is the original, so a scene of boxes and planes draws the same maps as before.
 *
 * Levels: errors are quantised to level k, bound R 2^-k (R: half the diagonal of the
 * scene's bounding box), k at most SSG_PROXY_FINEST; a finer request gets the original
 * scene. The finest level is simplified from the original, and each coarser level from the
 * next finer one, each step to an eighth of its level's bound in meshoptimizer's measure
 * (the quadric distance at the vertices it keeps): the steps sum to a quarter of the bound,
 * and a triangle's interior, which that measure does not see, was found up to twice as far
 * (a 16 k-triangle sphere: its proxies' worst point is 0.33 to 0.48 of the bound,
 * tests/test_proxy.c). Every level's triangles depend only on the scene, never on which
 * level a run asked for first (deterministic output). The finest level, R / 1024, suits a
 * map of up to 1024 texels across the scene (half a texel); a finer map draws every
 * triangle: the first step from a million triangles is most of the cost (0.5 s on 2
 * threads), and a finer one saved less than it cost.
 *
 * A proxy keeps the original's vertices it uses (positions, uvs, tangents, colours,
 * renumbered in first-use order) and its material, so every function that reads a struct
 * ssg_mesh or a scene reads a proxy alike; its triangle numbers are its own. Its vertex
 * normals are its own (area-weighted over its triangles, on the original's side): the
 * original normals at a coarse triangle's corners can point along it, not off it.
 *
 * Thread safety: ssg_scene_proxy may be called from any thread (a lock guards the cache);
 * the views it fills are read-only and stay valid until the scene is destroyed. */
#ifndef SSG_PROXY_H
#define SSG_PROXY_H

#include "scene/scene.h"

enum {
    SSG_PROXY_MIN_TRIANGLES = 4096, /* smaller meshes are always drawn as they are */
    SSG_PROXY_FINEST = 10           /* the finest level: an error of R / 1024 */
};

/* How a caller lends its threads (core/graph/node.h's ssg_parallel_rows fits): fn over
   [0, count) in bands of per_band, on any threads; NULL runs on the caller's. */
typedef void (*ssg_proxy_parallel)(int count, int per_band,
                                   void (*fn)(void *user, int i0, int i1), void *user);

/* Fills *view with a copy of *scene whose meshes are the proxies of the level with the
   largest error at most max_error (scene units): view->meshes is the level's array and
   view->proxy_of the scene. Without a level that fine (max_error below R 2^-FINEST, or not
   positive), or without a mesh to simplify, *view is *scene itself (view->proxy_of NULL).
   A view of a view is a view of the same scene. A mesh of 131,072 triangles or more is
   simplified in pieces of 65,536 on `parallel`'s threads (the pieces, not the thread
   count, fix the result). SSG_OK, or SSG_E_NOMEM. */
enum ssg_err ssg_scene_proxy(const struct ssg_scene *scene, float max_error,
                             ssg_proxy_parallel parallel, struct ssg_scene *view);

/* 1 when mesh `mesh` of the scene is one a proxy may simplify: large enough and not
   masked (above). */
int ssg_proxy_mesh_dense(const struct ssg_scene *scene, int mesh);

/* The distance bound of view's meshes from the scene's (0 for the scene itself). */
float ssg_scene_proxy_error(const struct ssg_scene *view);

/* The cache ssg_scene_load gives every scene (NULL: no memory, and no proxies), and its
   end with the levels made, before the scene's meshes go (ssg_scene_destroy). */
struct ssg_scene_proxies *ssg_scene_proxies_new(void);
void ssg_scene_proxies_release(struct ssg_scene *scene);

#endif
