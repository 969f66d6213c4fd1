/* ssdo.c - the `ssdo` node: screen-space directional occlusion with one optional indirect
 * bounce.
 *
 * Method: Ritschel, Grosch and Seidel, "Approximating Dynamic Global Illumination in
 * Image Space" (I3D 2009), after Szentandrasi, "Modern Methods of Realistic Lighting in
 * Real Time", section 3.2 (eq. 1-4) and 4.1 (the one-step modulation factor), and
 * Belonogov, "Global Illumination methods in simulated VR environments", chapter 4.
 * Sampling, the visibility test (with a hard range check) and the bounce are described in
 * ssdo_sampling.h, which the `bounce` node shares. Here, per pixel and kernel sample s
 * with direction w = s / |s| (N.w = s.z / |s|), and dw = pi / sum_s N.w_s (eq. 2: the kernel
 * must be uniform over the hemisphere, `halton(mapping=uniform)`). Eq. 2's solid angle of
 * one sample is 2 pi / K; we use pi over the kernel's own cosine sum instead, which has the
 * same limit (the mean of N.w over a uniform hemisphere is 1/2) but integrates a constant
 * environment exactly at every K: 2 pi / K made an open plane under a uniform sky
 * 2 mean(N.w) too bright, +5.9 % at K = 16 (issue 16). The shapes:
 *   environment: lit += L_env(w) (N.w) V dw, full += L_env(w) (N.w) dw (eq. 2), L_env from
 *     the scene's environment as a view-space cube (core/scene/env.h, no trigonometry per sample);
 *   point and directional lights l: E_l = colour intensity max(0, N.L_l) (/ d^2 for a
 *     point light), the unshadowed irradiance gbuffer computes. A delta light cannot be hit
 *     by hemisphere samples, so its visibility is estimated from the samples near its
 *     direction: weights w_il = max(0, w_i.L_l)^lobe (N.w_i), vis_l = sum w_il V_i /
 *     sum w_il (1 when the sum is 0). This is our documented stand-in for L_in of a point
 *     light in eq. 2: the lobe spreads the light over a cone, and shadows move with it.
 * mode modulation (sec. 4.1): M = (sum_l E_l vis_l + lit) / (sum_l E_l + full), per channel
 *   (channels=3) or of the Rec. 709 luminances (channels=1); 1 where the denominator is 0
 *   and for the background. Numerator and denominator are the same sums in the same order,
 *   so an open plane (no sample occluded) gives exactly 1. It darkens what gbuffer's
 *   direct + environment light (equation 1 without the visibility) shows. `power` raises M
 *   (each channel) to a power, as ssao's does its AO: screen space sees occluders only
 *   within the radius, so M is brighter than the truth wherever anything farther shades
 *   the pixel; graphs/ssdo.graph uses power 2, chosen on every example scene under a sun,
 *   a sky and a probe against reference_gi (docs/accuracy.md). An open plane stays 1.
 * mode radiance (eq. 2, first pass of the two-step method): out = albedo / pi *
 *   (sum_l E_l vis_l + lit); the `bounce` node is its second pass.
 * bounce=true adds the bounce output (eq. 3/4, patch form, ssdo_sampling.h) with the light
 *   input as the senders' radiance (in the one-step graph gbuffer.direct +
 *   gbuffer.environment). Sec. 4.1 darkens the bounce by the modulation factor when
 *   composing; this node leaves that to the composition. bounce=false: the output is 0.
 * count input (Szentandrasi section 4.3, the `complexity` node; table 1's "SSDO with
 *   preprocessing 20-50"): pixel i uses only the first n_i = round(count_i) kernel
 *   samples (half up, clamped to [1, K], NaN = K) and n_i stands for K everywhere above:
 *   dw = pi / (sum of N.w over its first n_i samples), A_s = strength pi r^2 / n_i, every
 *   sum over its first n_i samples.
 *   With a kernel of whole Halton periods and counts multiple of the period each pixel's
 *   samples stay quasi-uniform (section 4.2, eq. 8). Unconnected: n_i = K.
 * Without a scene (ctx->scene NULL, e.g. unit tests) there are no lights and the
 * environment is a constant white of radiance 1: plain directional occlusion. dw is
 * computed at run time, from the kernel's width. */
#include <stdio.h>
#include <string.h>

#include "scene/scene.h"
#include "ssdo.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_ssdo_params *p = params;
    const int has_albedo = in[SSG_SSDO_IN_ALBEDO].channels != 0;
    if (p->mode == SSG_SSDO_MODE_RADIANCE && !has_albedo) {
        snprintf(why, why_len, "mode radiance needs input 'albedo' (out = albedo / pi * "
                 "incoming light)");
        return SSG_E_MISSING_INPUT;
    }
    if (p->bounce && (!has_albedo || in[SSG_SSDO_IN_LIGHT].channels == 0)) {
        snprintf(why, why_len, "bounce=true needs inputs 'albedo' (the receiver) and "
                 "'light' (the senders' radiance)");
        return SSG_E_MISSING_INPUT;
    }
    if (p->channels != 1 && p->channels != 3) {
        snprintf(why, why_len, "channels must be 1 (luminance) or 3 (per channel), got %d",
                 p->channels);
        return SSG_E_VALUE;
    }
    enum ssg_err e = ssg_ssdo_check_shapes(in, &in[SSG_SSDO_IN_COUNT], why, why_len);
    if (e)
        return e;
    const struct ssg_shape *pos = &in[SSG_SSDO_IN_POSITION];
    int color = p->mode == SSG_SSDO_MODE_RADIANCE || p->channels == 3;
    out[0] = (struct ssg_shape){pos->width, pos->height, color ? 3 : 1,
                                color ? SSG_T_COLOR : SSG_T_SCALAR};
    out[1] = (struct ssg_shape){pos->width, pos->height, 3, SSG_T_COLOR};
    return SSG_OK;
}

/* The scene's lights in view space: view = R (world - eye). */
static enum ssg_err prepare_lights(const struct ssg_node_ctx *ctx, const float rot[9],
                                   struct ssg_ssdo_consts *c)
{
    const struct ssg_scene *s = ctx->scene;
    if (s->light_count > SSG_SSDO_MAX_LIGHTS) {
        return ssg_node_fail(ctx, SSG_E_SCENE,
                             "the scene has %d lights, at most %d are supported",
                             s->light_count, SSG_SSDO_MAX_LIGHTS);
    }
    c->light_count = s->light_count;
    for (int l = 0; l < s->light_count; l++) {
        const struct ssg_light *sl = &s->lights[l];
        struct ssg_ssdo_light *vl = &c->lights[l];
        float d[3];
        vl->directional = sl->kind == SSG_LIGHT_DIRECTIONAL;
        for (int i = 0; i < 3; i++) {
            d[i] = vl->directional ? -sl->direction[i]
                                   : sl->position[i] - s->camera.position[i];
            vl->rgb[i] = sl->color[i] * sl->intensity;
        }
        for (int r = 0; r < 3; r++)
            vl->v[r] = rot[3 * r] * d[0] + rot[3 * r + 1] * d[1] + rot[3 * r + 2] * d[2];
        float len = sqrtf(vl->v[0] * vl->v[0] + vl->v[1] * vl->v[1] + vl->v[2] * vl->v[2]);
        for (int i = 0; vl->directional && len > 0.0f && i < 3; i++)
            vl->v[i] /= len;
    }
    return SSG_OK;
}

/* Lights and environment of the scene in view space; without a scene none and white. */
static enum ssg_err prepare_light(const struct ssg_node_ctx *ctx, struct ssg_ssdo_consts *c)
{
    const struct ssg_scene *s = ctx->scene;
    c->env = SSG_SSDO_ENV_CONSTANT;
    c->light_count = 0;
    if (!s) {
        c->env_rgb[0] = c->env_rgb[1] = c->env_rgb[2] = 1.0f;
        return SSG_OK;
    }
    float m[16], rot[9], to_world[9];
    ssg_camera_view_matrix(&s->camera, m);
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 3; k++) {
            rot[3 * r + k] = m[4 * k + r];      /* world -> view, row-major */
            to_world[3 * k + r] = m[4 * k + r]; /* its transpose */
        }
    enum ssg_err e = prepare_lights(ctx, rot, c);
    if (e)
        return e;
    const struct ssg_env *env = s->env;
    if (!env || !env->has_light) {
        c->env_rgb[0] = c->env_rgb[1] = c->env_rgb[2] = 0.0f;
    } else if (!env->has_image) {
        memcpy(c->env_rgb, env->constant, sizeof c->env_rgb);
    } else {
        c->env = SSG_SSDO_ENV_CUBE;
        ssg_env_cube_build(env, to_world, &c->cube);
    }
    return SSG_OK;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_ssdo_consts *c = consts;
    c->p = *(const struct ssg_ssdo_params *)params;
    if (!(c->p.g.radius > 0) || c->p.lobe < 1 || c->p.lobe > 64 ||
        (c->p.channels != 1 && c->p.channels != 3))
        return ssg_node_fail(ctx, SSG_E_VALUE, "needs radius > 0, lobe 1..64, channels 1 or 3");
    enum ssg_err e =
        ssg_sampling_projection(ctx, &ctx->in_shape[SSG_SSDO_IN_POSITION], &c->proj);
    if (e)
        return e;
    c->out_channels = ctx->out_shape[0].channels;
    return prepare_light(ctx, c);
}

static const char *const mode_choices[] = {"modulation", "radiance", NULL};

static const struct ssg_param_desc params[] = {
    SSG_SSDO_GEOM_PARAMS(struct ssg_ssdo_params),
    {.name = "mode", SSG_FIELD_ENUM(struct ssg_ssdo_params, mode),
     .def = SSG_SSDO_MODE_MODULATION, .choices = mode_choices,
     .help = "modulation: lit / unoccluded light (one-step, sec. 4.1); radiance: albedo/pi "
             "* directional light (eq. 2)"},
    {.name = "channels", SSG_FIELD_INT(struct ssg_ssdo_params, channels), .def = 1, .min = 1,
     .max = 3,
     .help = "modulation: 1 = one factor of the luminances, 3 = one per colour channel"},
    {.name = "bounce", SSG_FIELD_BOOL(struct ssg_ssdo_params, bounce), .def = 0,
     .help = "compute the indirect bounce output (needs albedo and light)"},
    {.name = "lobe", SSG_FIELD_INT(struct ssg_ssdo_params, lobe), .def = 4, .min = 1, .max = 64,
     .help = "cosine power of the cone over which a point or directional light is sampled"},
    {.name = "power", SSG_FIELD_FLOAT(struct ssg_ssdo_params, power), .def = 1, .min = 0,
     .max = 8,
     .help = "modulation: out = M^power, the darkening ssao's power gives its AO (ssdo.graph "
             "uses 2, measured: docs/accuracy.md)"},
};

static const struct ssg_port_desc inputs[] = {
    SSG_SSDO_GEOM_INPUTS,
    [SSG_SSDO_IN_ALBEDO] = {.name = "albedo", .types = SSG_T_COLOR, .optional = 1,
     .doc = "diffuse albedo (mode radiance and bounce)"},
    [SSG_SSDO_IN_LIGHT] = {.name = "light", .types = SSG_T_COLOR, .optional = 1,
     .doc = "outgoing radiance of each pixel, the bounce's senders (bounce)"},
    [SSG_SSDO_IN_COUNT] = {.name = "count", .types = SSG_T_SCALAR, .optional = 1,
     .doc = "per-pixel sample count (complexity.count): the first n of the kernel; none = "
            "all"},
};
_Static_assert(SSG_COUNT(inputs) == SSG_SSDO_INPUTS, "one entry a port enumerator");

static const struct ssg_port_desc outputs[] = {
    [SSG_SSDO_OUT_OUT] = {.name = "out", .types = SSG_T_SCALAR | SSG_T_COLOR,
     .doc = "modulation factor (scalar, or color with channels=3; 1 = unoccluded) or, "
            "mode radiance, the directional light (color)"},
    [SSG_SSDO_OUT_BOUNCE] = {.name = "bounce", .types = SSG_T_COLOR,
     .doc = "one indirect bounce, albedo * sum F_i L_i; 0 when bounce=false"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_SSDO_OUTPUTS, "one entry a port enumerator");

/* Flops per pixel (node.h), by reading ssdo_cpu.c and ssdo_sampling.h: per kernel sample
   about 45 (placing and the depth test as ssao, the environment weight, the survivors'
   range check and bounce spread over all samples) and 10 a light for its lobe; per pixel
   about 120 for the frame, the finish and the bounce, and 20 a light. A probe adds about
   30 a sample for its cube lookup. */
static double ssdo_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_ssdo_consts *c = consts;
    double per_sample = 45.0 + 10.0 * c->light_count + (c->env == SSG_SSDO_ENV_CUBE ? 30 : 0);
    return 120.0 + 20.0 * c->light_count + per_sample * in[SSG_SSDO_IN_KERNEL].width;
}

const struct ssg_node_desc ssg_node_ssdo = {
    .name = "ssdo",
    .summary = "screen-space directional occlusion (modulation or radiance) with one "
               "indirect bounce",
    .method = "Ritschel, Grosch and Seidel, Approximating Dynamic Global Illumination in "
              "Image Space (I3D 2009), as in Szentandrasi, Modern Methods of Realistic "
              "Lighting in Real Time, sec. 3.2 eq. 1-4 and sec. 4.1 (one-step modulation "
              "factor), and Belonogov, Global Illumination methods in simulated VR "
              "environments, ch. 4",
    .doc = "Kernel samples (uniform hemisphere, dw = pi / sum N.w, so that a constant sky "
           "integrates exactly) are placed at P + radius s "
           "about the normal (turned by the rotation tile) and projected; a sample is "
           "occluded when the surface there is more than `bias` in front of it and within "
           "`radius` of P. The environment (scene probe as a view-space cube; constant "
           "white 1 without a scene) adds L(w) (N.w) dw to `full` and, when visible, to "
           "`lit`; each point or directional light adds its unshadowed irradiance E_l, "
           "with visibility vis_l = sum w V / sum w over weights w = max(0, w.L)^lobe "
           "(N.w). modulation: out = (sum E_l vis_l + lit) / (sum E_l + full) per "
           "channel or of luminances, exactly 1 on an open plane and the background; "
           "radiance: out = albedo / pi (sum E_l vis_l + lit). bounce=true: each occluded "
           "sample's pixel is a patch of area A_s = strength pi radius^2 / K sending its "
           "`light` with form factor F = A_s cos_r cos_s / (pi max(d^2, min_distance^2)) "
           "(eq. 4 without its extra dw), the F normalised when their sum exceeds 1; "
           "bounce = albedo sum F L. At most 8 lights. With the count input a pixel uses "
           "only the first n = round(count) kernel samples (clamped to [1, K]): dw and "
           "A_s with those n, every sum over them.",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_ssdo_params),
    .consts_size = sizeof(struct ssg_ssdo_consts),
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = ssdo_flops,
    .run_cpu = ssg_ssdo_run_cpu,
    .run_gl = ssg_ssdo_run_gl,
};
