/* combine.c - the `combine` node's descriptor, check and prepare: final shading from the
 * light, the albedo, AO or SSDO's modulation and indirect light. Method: README.md. */
#include <stddef.h>

#include <stdio.h>

#include "combine.h"
#include "scene/scene.h"

/* Every connected input must have the output's size (the frame's): combine reads them
   pixel by pixel. Channels follow from the ports' types. */
static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len);

static enum ssg_err check_scene(const void *params, const struct ssg_scene *scene,
                                const struct ssg_shape *in, struct ssg_shape *out, char *why,
                                size_t why_len);

SSG_PORT_TABLE(inputs, SSG_COMBINE_IN);
SSG_PORT_TABLE(outputs, SSG_COMBINE_OUT);
SSG_PARAMS_TABLE(param_table, ssg_combine_params, SSG_COMBINE_PARAMS);
SSG_UNIFORMS_TABLE(uniforms, ssg_combine_uniforms, SSG_COMBINE_UNIFORMS);

/* The ambient factor and the modulation's planes, once for both backends. */
static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_combine_consts *c = consts;
    c->p = *(const struct ssg_combine_params *)params;
    for (int i = 0; i < 3; i++)
        c->u.k[i] = c->p.ambient * c->p.ambient_color[i];
    c->u.modulation_last = ctx->in_shape[SSG_COMBINE_IN_MODULATION].channels == 3 ? 2 : 0;
    return SSG_OK;
}

/* Flops per pixel (node.h): about 6 a colour channel (the light sum, the albedo product,
   modulation and ambient terms), whichever inputs are bound. */
static double combine_flops(const void *consts, const struct ssg_shape *in)
{
    (void)consts, (void)in;
    return 18.0;
}

/* far_visibility V only scales the environment and ambient light (q = min(1, M / V)) and,
   with far_bounce, sends max(0, M - V) of them back: with the environment all +0, no
   ambient and no far bounce each of those terms is a zero (combine_cpu.c), whatever V.
   Its sign could flip only where the modulation M is negative and the direct light -0,
   which no node makes (SSDO's M is in [0, 1], light is +0 or more). */
static unsigned ignored_inputs(const void *params, unsigned zero_in)
{
    const struct ssg_combine_params *p = params;
    int dark = (zero_in >> SSG_COMBINE_IN_ENVIRONMENT & 1u) && p->ambient == 0.0f &&
               !p->far_bounce;
    return dark ? 1u << SSG_COMBINE_IN_FAR_VISIBILITY : 0u;
}

const struct ssg_node_desc ssg_node_combine = {
    .name = "combine",
    .summary = "final shading: light darkened by AO or the SSDO modulation, plus indirect",
    .method = "out = (darken_direct ? M : 1) direct + M ao (environment + ambient ambient_color albedo) + "
              "(darken_indirect ? M : 1) indirect + M ao albedo irradiance; AO darkens the ambient term only "
              "(Szentandrasi, Modern Methods of Realistic Lighting in Real Time, sec. 3.1; "
              "Belonogov, Global Illumination methods in simulated VR environments, sec. "
              "2.2.3 eq. 2.5 and sec. 3.2); the SSDO modulation factor M darkens light and "
              "bounce (Szentandrasi sec. 4.1); with far_visibility V (shadow-mapped "
              "environment) the environment is darkened by min(1, M / V) and far_bounce adds "
              "albedo max(0, M - V) own (one bounce from surroundings like the receiver, "
              "after Jimenez et al. 2016)",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(param_table, struct ssg_combine_params),
    .consts_size = sizeof(struct ssg_combine_consts),
    SSG_NODE_UNIFORMS(uniforms, struct ssg_combine_consts, u),
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA,
    .ignored_inputs = ignored_inputs,
    .check = check,
    .check_scene = check_scene,
    .prepare = prepare,
    .flops_per_pixel = combine_flops,
    .run_cpu = ssg_combine_run_cpu,
    .run_gl = ssg_combine_run_gl,
    .parity = {.max = 0, .mean = 0}, /* bit-exact on llvmpipe (test_gl_misc.c) */
};

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    for (int i = 0; i < SSG_COMBINE_INPUTS; i++) {
        if (in[i].channels != 0 && !ssg_shape_same_size(&in[i], &out[0])) {
            snprintf(why, why_len, "input '%s' is %dx%d, expected the frame's %dx%d",
                     inputs[i].name, in[i].width, in[i].height, out[0].width,
                     out[0].height);
            return SSG_E_SIZE;
        }
    }
    return SSG_OK;
}

/* A warning (why with SSG_OK, node.h): an ambient_occlusion input that darkens nothing.
   AO darkens the environment, ambient and irradiance terms; with none of them lit the
   image is the same without it, and a table of methods shows SSAO equal to no occlusion
   (gi_error.graph on the Cornell box under its own light, issue 46). */
static enum ssg_err check_scene(const void *params, const struct ssg_scene *scene,
                                const struct ssg_shape *in, struct ssg_shape *out, char *why,
                                size_t why_len)
{
    const struct ssg_combine_params *p = params;
    (void)out;
    int env_lit = in[SSG_COMBINE_IN_ENVIRONMENT].channels > 0 &&
                  ssg_scene_environment_lit(scene);
    if (in[SSG_COMBINE_IN_AMBIENT_OCCLUSION].channels > 0 && !env_lit && p->ambient == 0 &&
        in[SSG_COMBINE_IN_IRRADIANCE].channels == 0)
        snprintf(why, why_len, "its ambient_occlusion darkens nothing, and its image is the "
                 "same without it: AO darkens environment and ambient light, and the scene "
                 "has no environment light while ambient=0 (light it with one: --lights "
                 "examples/lights/sky.scene, or give ambient a value)");
    return SSG_OK;
}
