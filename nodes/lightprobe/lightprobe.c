/* lightprobe.c - the `lightprobe` node: the scene's environment (an HDR lat-long light
 * probe or a constant sky) as N directional lights, the input of the hybrid AO's global
 * part (shadowmaps, probe_light).
 *
 * Method: Knuth and Kohlhammer, "A Hybrid Ambient Occlusion Technique for Dynamic Scenes",
 * sec. 3 "Global part" ("the process starts by converting the light probe into a set of
 * directional light sources") and sec. 4 ("we get our light setup by sampling the light
 * probe uniformly"): uniform = a spherical Fibonacci set. importance = Hammersley points
 * drawn by the probe's luminance (after Knuth and Fuhrmann 2005), so bright regions get
 * more, smaller lights. Each light's irradiance is the probe's integral over its Voronoi
 * region (lightprobe_regions.c; the paper gives no rule), so the lights' total equals the
 * probe's and an unshadowed surface of normal n receives about sum_i max(0, n.l_i) E_i
 * = E(n). Made once in prepare(); the backends copy it out. */
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
    (void)why;
    (void)why_len;
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
    if (p->count < SSG_LIGHTS_MIN || p->count > SSG_LIGHTS_MAX)
        return ssg_node_fail(ctx, SSG_E_VALUE, "count out of range");
    if (!ctx->scene || !ctx->scene->env)
        return ssg_node_fail(ctx, SSG_E_VALUE, "needs a scene");
    if (!ctx->scene->env->has_light && p->missing)
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
        ssg_lightprobe_directions(ctx->scene->env, p->sampling, p->count, dirs);
        e = ssg_lightprobe_regions(ctx->scene->env, dirs, p->count, irradiance);
    }
    if (!e)
        store_lights(c, dirs, irradiance);
    free(dirs);
    free(irradiance);
    return e ? ssg_node_fail(ctx, e, "out of memory") : SSG_OK;
}

static const char *const sampling_choices[] = {"uniform", "importance", NULL};
static const char *const missing_choices[] = {"error", "dark", NULL};

static const struct ssg_param_desc params[] = {
    {.name = "count", SSG_FIELD_INT(struct ssg_lightprobe_params, count), .def = 128,
     .min = SSG_LIGHTS_MIN, .max = SSG_LIGHTS_MAX, .unit = "lights",
     .help = "directional lights N (the paper: 128 and 512, 2048 for its reference)"},
    {.name = "sampling", SSG_FIELD_ENUM(struct ssg_lightprobe_params, sampling),
     .def = SSG_LIGHTPROBE_UNIFORM, .choices = sampling_choices,
     .help = "uniform: equal-area Fibonacci set (the paper); importance: denser where the "
             "probe is bright"},
    {.name = "missing", SSG_FIELD_ENUM(struct ssg_lightprobe_params, missing), .def = 0,
     .choices = missing_choices,
     .help = "a scene without environment light: error, or dark (N lights of irradiance 0, "
             "so one graph serves scenes with and without a probe)"},
};

static const struct ssg_port_desc outputs[] = {
    [SSG_LIGHTPROBE_OUT_LIGHTS] = {.name = "lights", .types = SSG_T_LIGHTS,
     .doc = "N x 2: row 0 the unit world direction towards each light, row 1 its RGB "
            "irradiance; the irradiances add up to the probe's integral"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_LIGHTPROBE_OUTPUTS, "one entry a port enumerator");

const struct ssg_node_desc ssg_node_lightprobe = {
    .name = "lightprobe",
    .summary = "the scene's HDR light probe as N directional lights (hybrid AO)",
    .method = "Knuth and Kohlhammer, A Hybrid Ambient Occlusion Technique for Dynamic Scenes, "
              "sec. 3 and 4 (global part: probe sampled uniformly into directional lights); "
              "importance sampling after Knuth and Fuhrmann 2005; each light's irradiance is "
              "its Voronoi region's integral of the probe (ours: the paper gives none)",
    .doc = "Turns the scene's environment (environment(image=...) lat-long probe, or a "
           "constant colour) into a light list: N directions, uniform (a spherical "
           "Fibonacci set, about equal solid angles) or by importance (more lights where "
           "the probe is bright), and for each the integral of the probe's radiance over "
           "the directions nearer to it than to any other light, so the lights carry "
           "exactly the probe's energy. Made once before the run (0.1 s for a 1024 x 512 "
           "probe and 512 lights); feeds shadowmaps and probe_light. A scene without an "
           "environment light is an error, or with missing=dark a list of lights that carry "
           "nothing.",
    SSG_NODE_OUTPUTS(outputs),
    SSG_NODE_PARAMS(params, struct ssg_lightprobe_params),
    .consts_size = sizeof(struct ssg_lightprobe_consts),
    .needs_scene = 1,
    .check = check,
    .prepare = prepare,
    .run_cpu = ssg_lightprobe_run_cpu,
    .run_gl = ssg_lightprobe_run_gl,
};
