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
 * than 1. Sampling, test and form factor are ssdo's own code (ssdo/ssdo_sampling.h, where
 * the deviation from eq. 4, its dropped extra delta-omega, is explained), so out is exactly
 * ssdo's bounce output for the same inputs and parameters. */
#include <stdio.h>

#include "bounce.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    enum ssg_err e = ssg_ssdo_check_shapes(in, why, why_len);
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
    c->proj = ssg_frame_projection(ctx->frame);
    c->frame_width = ctx->frame->width;
    c->frame_height = ctx->frame->height;
    if (!(c->p.g.radius > 0) || c->frame_width < 1 || c->frame_height < 1 || !(c->proj.f > 0)) {
        ssg_diag_at(ctx->diags, SSG_E_VALUE, (struct ssg_loc){0},
                    "bounce '%s': needs radius > 0 and a frame with size and field of view",
                    ctx->instance ? ctx->instance : "");
        return SSG_E_VALUE;
    }
    return SSG_OK;
}

#define GEOM(field) offsetof(struct ssg_bounce_params, g) + offsetof(struct ssg_ssdo_geom, field)

static const struct ssg_param_desc params[] = {
    {.name = "radius", .type = SSG_P_FLOAT, .offset = GEOM(radius), .def = 0.5, .min = 1e-6,
     .max = 1e6, .unit = "scene units", .help = "r_max: hemisphere radius around the pixel"},
    {.name = "bias", .type = SSG_P_FLOAT, .offset = GEOM(bias), .def = 0.02, .min = 0,
     .max = 1e6, .unit = "scene units",
     .help = "a sample is occluded only when the surface is this much in front of it"},
    {.name = "strength", .type = SSG_P_FLOAT, .offset = GEOM(strength), .def = 1, .min = 0,
     .max = 64, .help = "multiplies the sender patch area A_s = pi radius^2 / K"},
    {.name = "min_distance", .type = SSG_P_FLOAT, .offset = GEOM(min_distance), .def = 0,
     .min = 0, .max = 1e6, .unit = "scene units",
     .help = "sender distance clamp against 1/d^2; 0 = sqrt(A_s/pi), where one patch's "
             "form factor reaches 1"},
    {.name = "max_screen_radius", .type = SSG_P_FLOAT, .offset = GEOM(max_screen_radius),
     .def = 0, .min = 0, .max = 16384, .unit = "px",
     .help = "caps the projected radius; 0 = no cap"},
};

static const struct ssg_port_desc inputs[] = {
    {.name = "position", .types = SSG_T_VECTOR, .doc = "view-space position"},
    {.name = "normal", .types = SSG_T_VECTOR, .doc = "unit view-space normal"},
    {.name = "kernel", .types = SSG_T_KERNEL,
     .doc = "hemisphere samples, uniform in solid angle (halton mapping=uniform)"},
    {.name = "rotation", .types = SSG_T_PATTERN, .optional = 1,
     .doc = "per-pixel rotation tile (halton.rotation); none = no rotation"},
    {.name = "depth", .types = SSG_T_SCALAR, .optional = 1,
     .doc = "linear depth for the occluder lookup; none = -position.z"},
    {.name = "albedo", .types = SSG_T_COLOR, .doc = "diffuse albedo of the receiver"},
    {.name = "light", .types = SSG_T_COLOR,
     .doc = "the senders' radiance: the first pass's direct light (ssdo mode=radiance)"},
};

static const struct ssg_port_desc outputs[] = {
    {.name = "out", .types = SSG_T_COLOR, .doc = "one indirect bounce, albedo * sum F_i L_i"},
};

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
    .inputs = inputs,
    .input_count = SSG_COUNT(inputs),
    .outputs = outputs,
    .output_count = SSG_COUNT(outputs),
    .params = SSG_TABLE(params),
    .params_size = sizeof(struct ssg_bounce_params),
    .consts_size = sizeof(struct ssg_bounce_consts),
    .check = check,
    .prepare = prepare,
    .run_cpu = ssg_bounce_run_cpu,
};
