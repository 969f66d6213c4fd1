/* shadowmaps.h - the `shadowmaps` node (shadowmaps.c): one orthographic depth map per
 * light of a light list, as nodes/common/shadowmap.h defines them (method: README.md). */
#ifndef SSG_SHADOWMAPS_H
#define SSG_SHADOWMAPS_H

#include "graph/node.h"
#include "common/shadowmap.h"

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields. */
#define SSG_SHADOWMAPS_IN(X) \
    X(SSG_SHADOWMAPS_IN_LIGHTS, "lights", SSG_T_LIGHTS, "light list (lightprobe)")
#define SSG_SHADOWMAPS_OUT(X)                                                              \
    X(SSG_SHADOWMAPS_OUT_MAPS, "maps", SSG_T_SHADOWMAPS,                                   \
      "R x R, channel i the depth map of light i (nodes/common/shadowmap.h)")
SSG_PORT_ENUM(ssg_shadowmaps_input, SSG_SHADOWMAPS_IN, SSG_SHADOWMAPS_INPUTS);
SSG_PORT_ENUM(ssg_shadowmaps_output, SSG_SHADOWMAPS_OUT, SSG_SHADOWMAPS_OUTPUTS);

/* The parameters, one row each (lang/params.h). The map size is the output's shape, so
   no shader reads a parameter: the rows are host_only. */
#define SSG_SHADOWMAPS_PARAMS(P)                                                           \
    P(INT, resolution,                                                                     \
      "side of every map (the paper's second knob: fewer texels, more bleeding)",          \
      .def = 256, .min = SSG_SHADOW_RES_MIN, .max = SSG_SHADOW_RES_MAX, .soft_min = 16,    \
      .soft_max = 2048, .unit = "texels",                                                  \
      .host_only = 1)                                                                      \
    P(BOOL, proxy,                                                                         \
      "draw each dense mesh (4096 triangles or more, not alpha-masked) as its simplified "  \
      "proxy, within about a quarter texel of it (core/scene/proxy.h): the maps then cost " \
      "what a texel can show, not the triangle count; false draws every triangle",        \
      .def = 1, .host_only = 1)
SSG_PARAMS_STRUCT(ssg_shadowmaps_params, SSG_SHADOWMAPS_PARAMS);

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
