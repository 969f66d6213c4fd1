/* shadowmaps.h - the `shadowmaps` node (shadowmaps.c): one orthographic depth map per
 * light of a light list, as nodes/common/shadowmap.h defines them. */
#ifndef SSG_SHADOWMAPS_H
#define SSG_SHADOWMAPS_H

#include "graph/node.h"
#include "common/shadowmap.h"

/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_shadowmaps_input {
    SSG_SHADOWMAPS_IN_LIGHTS,
    SSG_SHADOWMAPS_INPUTS
};
enum ssg_shadowmaps_output {
    SSG_SHADOWMAPS_OUT_MAPS,
    SSG_SHADOWMAPS_OUTPUTS
};

struct ssg_shadowmaps_params {
    int resolution; /* map side R in texels; default 256 */
};

enum ssg_err ssg_shadowmaps_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                    const struct ssg_io *io);
enum ssg_err ssg_shadowmaps_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                   const struct ssg_io *io);
/* Both backends' run-time checks: a scene, a light list, maps of its count. */
enum ssg_err ssg_shadowmaps_check_run(const struct ssg_node_ctx *ctx,
                                      const struct ssg_shadowmaps_params *p,
                                      const struct ssg_io *io);

extern const struct ssg_node_desc ssg_node_shadowmaps;

#endif
