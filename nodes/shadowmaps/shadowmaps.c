/* shadowmaps.c - the `shadowmaps` node's descriptor and checks: one orthographic depth map
 * per light of a light list (hybrid AO). The method and its sources: README.md here. */
#include <stdio.h>

#include "graph/image.h"
#include "scene/env.h"
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

/* A scene without environment light gets maps of one texel: its light list (lightprobe
   missing=dark) carries nothing, probe_light skips every light, and 384 maps of 512 would
   be 384 MB filled with "empty" for no reader (README.md, "Dark lights"). */
static enum ssg_err check_scene(const void *params, const struct ssg_scene *scene,
                                const struct ssg_shape *in, struct ssg_shape *out, char *why,
                                size_t why_len)
{
    (void)params, (void)in, (void)why, (void)why_len;
    if (scene && !(scene->env && scene->env->has_light))
        out[0].width = out[0].height = 1;
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

SSG_PARAMS_TABLE(params, ssg_shadowmaps_params, SSG_SHADOWMAPS_PARAMS);

SSG_PORT_TABLE(inputs, SSG_SHADOWMAPS_IN);
SSG_PORT_TABLE(outputs, SSG_SHADOWMAPS_OUT);

const struct ssg_node_desc ssg_node_shadowmaps = {
    .name = "shadowmaps",
    .summary = "one orthographic depth map per light of a light list (hybrid AO)",
    .method = "Knuth and Kohlhammer, A Hybrid Ambient Occlusion Technique for Dynamic Scenes, "
              "sec. 3 and fig. 5 (a shadow buffer per light); maps fitted to the scene's "
              "bounding sphere, linear depth (ours: the paper gives no fit or format)",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_shadowmaps_params),
    /* world-space maps around the scene's bounding sphere */
    .reads = SSG_READS_INPUTS | SSG_READS_SCENE | SSG_READS_LIGHTS,
    .check = check,
    .check_scene = check_scene,
    .run_cpu = ssg_shadowmaps_run_cpu,
    .run_gl = ssg_shadowmaps_run_gl,
};
