/* bounce.c - the `bounce` node: one indirect bounce of diffuse light in screen space, the
 * separate second pass of the two-step SSDO.
 *
 * Method: Ritschel, Grosch and Seidel, "Approximating Dynamic Global Illumination in
 * Image Space" (I3D 2009), as in Szentandrasi, "Modern Methods of Realistic Lighting in
 * Real Time", section 3.2.2 (eq. 3, 4), and Belonogov, "Global Illumination methods in
 * simulated VR environments", section 4.2 (eq. 4.3). The `light` input is the first pass's
 * direct light (ssdo mode=radiance): each kernel sample that ssdo's visibility test finds
 * occluded makes the pixel it lands on a sender patch of area A_s = strength pi radius^2 / K
 * with that light, and out = albedo sum F_i L_i with the point form factor
 * F_i = A_s cos_r cos_s / (pi max(d^2, min_distance^2)), normalised when the F_i sum to more
 * than 1. Sampling, test and form factor are ssdo's own code (ssdo_sampling.h, where
 * the deviation from eq. 4, its dropped extra delta-omega, is explained), so out is exactly
 * ssdo's bounce output for the same inputs and parameters. */
#include <stdio.h>

#include "bounce.h"
#include "common/sampling.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    enum ssg_err e = ssg_ssdo_check_shapes(in, NULL, why, why_len); /* no count input */
    if (e)
        return e;
    const struct ssg_shape *pos = &in[SSG_SSDO_IN_POSITION];
    out[0] = (struct ssg_shape){pos->width, pos->height, 3, SSG_T_COLOR};
    return SSG_OK;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_bounce_consts *c = consts;
    c->p = *(const struct ssg_bounce_params *)params;
    if (!(c->p.g.radius > 0))
        return ssg_node_fail(ctx, SSG_E_VALUE, "needs radius > 0");
    return ssg_sampling_projection(ctx, &ctx->in_shape[SSG_SSDO_IN_POSITION], &c->proj);
}

static const struct ssg_param_desc params[] = {
    SSG_SSDO_GEOM_PARAMS(struct ssg_bounce_params),
};

static const struct ssg_port_desc inputs[] = {
    SSG_SSDO_GEOM_INPUTS,
    [SSG_SSDO_IN_ALBEDO] = {.name = "albedo", .types = SSG_T_COLOR,
     .doc = "diffuse albedo of the receiver"},
    [SSG_SSDO_IN_LIGHT] = {.name = "light", .types = SSG_T_COLOR,
     .doc = "the senders' radiance: the first pass's direct light (ssdo mode=radiance)"},
};
_Static_assert(SSG_COUNT(inputs) == SSG_BOUNCE_INPUTS, "one entry a port enumerator");

static const struct ssg_port_desc outputs[] = {
    [SSG_BOUNCE_OUT_OUT] = {.name = "out", .types = SSG_T_COLOR,
     .doc = "one indirect bounce, albedo * sum F_i L_i"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_BOUNCE_OUTPUTS, "one entry a port enumerator");

/* Flops per pixel (node.h): ssdo's sampling without the lights, about 40 a sample and 100
   a pixel (ssdo.c's count). */
static double bounce_flops(const void *consts, const struct ssg_shape *in)
{
    (void)consts;
    return 100.0 + 40.0 * in[SSG_SSDO_IN_KERNEL].width;
}

const struct ssg_node_desc ssg_node_bounce = {
    .name = "bounce",
    .summary = "one screen-space indirect bounce (second pass of two-step SSDO)",
    .method = "Ritschel, Grosch and Seidel, Approximating Dynamic Global Illumination in "
              "Image Space (I3D 2009), as in Szentandrasi, Modern Methods of Realistic "
              "Lighting in Real Time, sec. 3.2.2 eq. 3-4, and Belonogov, Global "
              "Illumination methods in simulated VR environments, sec. 4.2 eq. 4.3",
    .doc = "Places the kernel samples as ssdo does and finds the occluded ones (surface more "
           "than `bias` in front of the sample, within `radius` of the pixel). The pixel "
           "each occluded sample lands on is a patch of area A_s = strength pi radius^2 / K "
           "sending its `light` with form factor F = A_s max(0, N.w) max(0, -N_i.w) / (pi "
           "max(d^2, min_distance^2)); the F are normalised when they sum to more than 1. "
           "out = albedo sum F L, exactly ssdo's bounce output for the same inputs; 0 for "
           "the background.",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_bounce_params),
    .consts_size = sizeof(struct ssg_bounce_consts),
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = bounce_flops,
    .run_cpu = ssg_bounce_run_cpu,
    .run_gl = ssg_bounce_run_gl,
};
