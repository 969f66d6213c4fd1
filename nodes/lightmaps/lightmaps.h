/* lightmaps.h - the `lightmaps` node (lightmaps.c): depth, normal and reflected flux of the
 * nearest surface on every face of the scene's own lights' maps (nodes/common/lightmap.h),
 * shared by both backends. */
#ifndef SSG_LIGHTMAPS_H
#define SSG_LIGHTMAPS_H

#include "graph/node.h"
#include "common/lightmap.h"

/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_lightmaps_output {
    SSG_LIGHTMAPS_OUT_DEPTH,
    SSG_LIGHTMAPS_OUT_NORMAL,
    SSG_LIGHTMAPS_OUT_FLUX,
    SSG_LIGHTMAPS_OUTPUTS
};

/* Bounds of the resolution parameter (texels a side). */
enum { SSG_LIGHTMAPS_RES_MIN = 16, SSG_LIGHTMAPS_RES_MAX = 8192 };

struct ssg_lightmaps_params {
    int resolution; /* map side R in texels; default 512 */
};

/* A cube face's near plane, as a fraction of the scene's bounding radius: nearer surfaces
   are cut (GL's clip and the CPU's polygon clip at the same plane). */
#define SSG_LIGHTMAPS_NEAR 1.0e-3f

/* The constants both backends read: the faces of the scene's lights. */
struct ssg_lightmaps_consts {
    int res, count;                    /* R and the face count F */
    float near_z;                      /* cube faces' near plane, scene units */
    float far_z;                       /* cube faces' far plane (GL depth range) */
    float flux[SSG_LIGHTMAP_FACES_MAX][3]; /* per face: E x texel area (orthographic) or I
                                              (cube, times the texel's solid angle) */
    struct ssg_lightmap_face faces[SSG_LIGHTMAP_FACES_MAX];
};

enum ssg_err ssg_lightmaps_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                   const struct ssg_io *io);
enum ssg_err ssg_lightmaps_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                  const struct ssg_io *io);

extern const struct ssg_node_desc ssg_node_lightmaps;

#endif
