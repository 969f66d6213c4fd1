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
    SSG_GBUFFER_OUTPUTS
};

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
