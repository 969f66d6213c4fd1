/* lightprobe.c - the `lightprobe` node's descriptor and prepare: the scene's environment as
 * N directional lights, made once in prepare(). The method and its sources: README.md here. */
#include <stdio.h>
#include <stdlib.h>

#include "lightprobe.h"
#include "scene/scene.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_lightprobe_params *p = params;
    (void)frame;
    (void)in;
    if (p->uniform_share > 0 && p->sampling != SSG_LIGHTPROBE_IMPORTANCE) {
        snprintf(why, why_len, "uniform_share %g needs sampling=importance (the uniform set "
                 "is uniform already)", (double)p->uniform_share);
        return SSG_E_VALUE;
    }
    out[0] = (struct ssg_shape){p->count, 2, 3, SSG_T_LIGHTS};
    return SSG_OK;
}

static void store_lights(struct ssg_lightprobe_consts *c, const float *dirs,
                         const double *irradiance)
{
    int n = c->count;
    for (int i = 0; i < n; i++)
        for (int ch = 0; ch < 3; ch++) {
            c->lights[(ch * 2 + 0) * n + i] = dirs[3 * i + ch];
            c->lights[(ch * 2 + 1) * n + i] = (float)irradiance[3 * i + ch];
        }
}

/* count lights that carry nothing (straight up, irradiance 0): the environment-less scene
   of a graph that asked for missing=dark, so the far field adds 0 and its visibility is 1. */
static enum ssg_err dark_lights(const struct ssg_node_ctx *ctx, int count,
                                struct ssg_lightprobe_consts *c)
{
    (void)ctx;
    c->count = count;
    for (int i = 0; i < count; i++)
        for (int ch = 0; ch < 3; ch++) {
            c->lights[(ch * 2 + 0) * count + i] = ch == 1 ? 1.0f : 0.0f;
            c->lights[(ch * 2 + 1) * count + i] = 0.0f;
        }
    return SSG_OK;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    const struct ssg_lightprobe_params *p = params;
    struct ssg_lightprobe_consts *c = consts;
    if (!ctx->scene || !ctx->scene->env)
        return ssg_node_fail(ctx, SSG_E_VALUE, "needs a scene");
    if (!ctx->scene->env->has_light && p->missing == SSG_LIGHTPROBE_MISSING_DARK)
        return dark_lights(ctx, p->count, c);
    if (!ctx->scene->env->has_light) {
        char what[1400];
        const char *relit = ctx->scene->lights_path;
        snprintf(what, sizeof what, "scene '%s'%s%s%s has no environment light: the hybrid's "
                 "global part is lit by the environment alone (add environment(image="
                 "\"probe.exr\") or environment(color=[...]) to the %s)",
                 ctx->scene->path, relit[0] ? " relit by '" : "", relit,
                 relit[0] ? "'" : "", relit[0] ? "lights file" : "scene");
        return ssg_node_fail(ctx, SSG_E_VALUE, "%s", what);
    }
    c->count = p->count;
    float *dirs = malloc(sizeof(float) * 3 * (size_t)p->count);
    double *irradiance = malloc(sizeof(double) * 3 * (size_t)p->count);
    enum ssg_err e = dirs && irradiance ? SSG_OK : SSG_E_NOMEM;
    if (!e) {
        if (p->sampling == SSG_LIGHTPROBE_IMPORTANCE)
            ssg_env_lights_importance(ctx->scene->env, p->count, p->uniform_share, dirs);
        else
            ssg_env_lights_fibonacci(p->count, dirs);
        e = ssg_env_lights_regions(ctx->scene->env, dirs, p->count, irradiance);
    }
    if (!e)
        store_lights(c, dirs, irradiance);
    free(dirs);
    free(irradiance);
    return e ? ssg_node_fail(ctx, e, "out of memory") : SSG_OK;
}

/* The consts hold the list itself: 6 count floats after the header. */
static size_t consts_size_of(const void *params, const struct ssg_shape *in)
{
    (void)in;
    const struct ssg_lightprobe_params *p = params;
    return sizeof(struct ssg_lightprobe_consts) + sizeof(float) * 6 * (size_t)p->count;
}

static const char *const ssg_lightprobe_sampling_choices[] = {"uniform", "importance", NULL};
static const char *const ssg_lightprobe_missing_choices[] = {"error", "dark", NULL};
SSG_PARAMS_TABLE(params, ssg_lightprobe_params, SSG_LIGHTPROBE_PARAMS);

SSG_PORT_TABLE(outputs, SSG_LIGHTPROBE_OUT);

const struct ssg_node_desc ssg_node_lightprobe = {
    .name = "lightprobe",
    .summary = "the scene's HDR light probe as N directional lights (hybrid AO)",
    .method = "Knuth and Kohlhammer, A Hybrid Ambient Occlusion Technique for Dynamic Scenes, "
              "sec. 3 and 4 (global part: probe sampled uniformly into directional lights); "
              "importance sampling after Knuth and Fuhrmann 2005; each light's irradiance is "
              "its Voronoi region's integral of the probe (ours: the paper gives none)",
    SSG_NODE_OUTPUTS(outputs),
    SSG_NODE_PARAMS(params, struct ssg_lightprobe_params),
    .consts_size_of = consts_size_of,
    /* the environment map alone makes the lights */
    .reads = SSG_READS_INPUTS | SSG_READS_SCENE | SSG_READS_LIGHTS,
    .check = check,
    .prepare = prepare,
    .run_cpu = ssg_lightprobe_run_cpu,
    .run_gl = ssg_lightprobe_run_gl,
    .parity = {.max = 0, .mean = 0}, /* the same bytes (test_lightprobe.c) */
};
