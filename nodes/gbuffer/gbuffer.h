/* gbuffer.h - parameters and prepared constants of the `gbuffer` node, shared by
 * gbuffer.c (descriptor, prepare) and gbuffer_cpu.c (the CPU kernel). Method and
 * conventions are described in gbuffer.c. */
#ifndef SSG_GBUFFER_H
#define SSG_GBUFFER_H

#include "graph/node.h"

/* Output ports, in order. */
/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_gbuffer_output {
    SSG_GBUFFER_OUT_POSITION,
    SSG_GBUFFER_OUT_NORMAL,
    SSG_GBUFFER_OUT_DEPTH,
    SSG_GBUFFER_OUT_ALBEDO,
    SSG_GBUFFER_OUT_DIRECT,
    SSG_GBUFFER_OUT_ENVIRONMENT,
    SSG_GBUFFER_OUT_BACK, /* on demand: only computed when something reads it */
    SSG_GBUFFER_OUTPUTS
};

/* The second layer (`back`) is the nearest surface whose depth exceeds depth + depth *
   SSG_GBUFFER_BACK_GAP (float operations in that order, on both backends): the first
   surface, and a coplanar or edge-adjacent triangle at its depth, is never found again.
   1e-4 is 1000 times the float rounding of a depth and of the GL rasteriser's
   interpolated depth, and thinner than any modelled wall (0.1 mm at 1 m). */
#define SSG_GBUFFER_BACK_GAP 1e-4f

enum ssg_gbuffer_normals {
    SSG_GBUFFER_NORMALS_SMOOTH, /* interpolated vertex normals */
    SSG_GBUFFER_NORMALS_FACE,   /* the triangle's geometric normal */
};

struct ssg_gbuffer_params {
    int normals; /* enum ssg_gbuffer_normals; default smooth */
};

struct ssg_gbuffer_consts {
    struct ssg_gbuffer_params p;
    struct ssg_projection proj; /* ssg_frame_projection of the frame */
    float rot[9];               /* world -> view rotation, row-major */
    float eye[3];               /* camera position, world */
    float near_z, far_z;        /* visible depth range, scene units */
};

enum ssg_err ssg_gbuffer_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io);
/* The GL side (gbuffer_gl.c): rasterised visibility, then the same formulas per pixel. */
enum ssg_err ssg_gbuffer_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io);

#endif
