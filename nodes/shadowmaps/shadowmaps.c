/* shadowmaps.c - the `shadowmaps` node: the shadow buffers of the hybrid AO's global part,
 * one orthographic depth map per directional light of a light list (`lightprobe`).
 *
 * Method: Knuth and Kohlhammer, "A Hybrid Ambient Occlusion Technique for Dynamic Scenes",
 * sec. 3 "Global part" and fig. 5 (a shadow map for every light the probe became, the
 * whole scene rendered into each). The paper gives neither the fit nor the format: every
 * map here covers the scene's bounding sphere (nodes/common/shadowmap.h), so all maps share one
 * texel size 2 r / R and one depth offset suits all; a texel holds the distance from the
 * map's plane to the nearest surface along the light, SSG_SHADOW_EMPTY where there is
 * none. The CPU rasterises every triangle into each map in fixed point (shadowmaps_cpu.c),
 * GL into each layer of a texture array with a depth test: both sample the texel
 * centres. */
#include <stdio.h>

#include "graph/image.h"
#include "scene/scene.h"
#include "shadowmaps.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_shadowmaps_params *p = params;
    (void)frame;
    long long n = in[0].width, r = p->resolution;
    if (n * r * r > SSG_IMAGE_MAX_FLOATS) {
        snprintf(why, why_len, "%lld maps of %lld x %lld need %.1f GiB, over the limit of "
                 "%.1f GiB (SSG_IMAGE_MAX_FLOATS): lower the resolution or the light count",
                 n, r, r, (double)(n * r * r) * 4.0 / (1 << 30),
                 (double)SSG_IMAGE_MAX_FLOATS * 4.0 / (1 << 30));
        return SSG_E_SIZE;
    }
    out[0] = (struct ssg_shape){p->resolution, p->resolution, in[0].width, SSG_T_SHADOWMAPS};
    return SSG_OK;
}

enum ssg_err ssg_shadowmaps_check_run(const struct ssg_node_ctx *ctx,
                                      const struct ssg_shadowmaps_params *p,
                                      const struct ssg_io *io)
{
    if (!ctx->scene)
        return ssg_node_fail(ctx, SSG_E_VALUE, "needs a scene");
    return SSG_OK;
}

static const struct ssg_param_desc params[] = {
    {.name = "resolution", SSG_FIELD_INT(struct ssg_shadowmaps_params, resolution), .def = 256,
     .min = SSG_SHADOW_RES_MIN, .max = SSG_SHADOW_RES_MAX, .unit = "texels",
     .help = "side of every map (the paper's second knob: fewer texels, more bleeding)"},
};

static const struct ssg_port_desc inputs[] = {
    [SSG_SHADOWMAPS_IN_LIGHTS] = {.name = "lights", .types = SSG_T_LIGHTS,
     .doc = "light list (lightprobe)"},
};
_Static_assert(SSG_COUNT(inputs) == SSG_SHADOWMAPS_INPUTS, "one entry a port enumerator");

static const struct ssg_port_desc outputs[] = {
    [SSG_SHADOWMAPS_OUT_MAPS] = {.name = "maps", .types = SSG_T_SHADOWMAPS,
     .doc = "R x R, channel i the depth map of light i (nodes/common/shadowmap.h)"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_SHADOWMAPS_OUTPUTS, "one entry a port enumerator");

const struct ssg_node_desc ssg_node_shadowmaps = {
    .name = "shadowmaps",
    .summary = "one orthographic depth map per light of a light list (hybrid AO)",
    .method = "Knuth and Kohlhammer, A Hybrid Ambient Occlusion Technique for Dynamic Scenes, "
              "sec. 3 and fig. 5 (a shadow buffer per light); maps fitted to the scene's "
              "bounding sphere, linear depth (ours: the paper gives no fit or format)",
    .doc = "Renders the scene's depth as seen by each directional light of a light list: "
           "an orthographic map of resolution x resolution texels over the scene's bounding "
           "sphere, holding the distance from the map's plane to the nearest surface (both "
           "faces of every triangle cast shadows). Memory is lights x resolution^2 floats "
           "(128 maps of 512^2: 128 MiB; at most 2 GiB). CPU: a depth-only raster of every "
           "triangle into each map, at the texel centres; GL: a depth-tested raster of the "
           "scene into each layer of a texture array. A light of irradiance 0 (lightprobe's "
           "missing=dark) gets an empty map on both: it casts nothing.",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_shadowmaps_params),
    .needs_scene = 1,
    .check = check,
    .run_cpu = ssg_shadowmaps_run_cpu,
    .run_gl = ssg_shadowmaps_run_gl,
};
