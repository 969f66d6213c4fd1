/* bounce.c - the `bounce` node's descriptor, check and prepare: one screen-space indirect
 * bounce, the second pass of two-step SSDO. Method and conventions: bounce.md. */
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
    enum ssg_err e =
        ssg_sampling_projection(ctx, &ctx->in_shape[SSG_SSDO_IN_POSITION], &c->proj);
    if (e)
        return e;
    c->g = ssg_ssdo_geom_of(&c->p, c->proj.f);
    return SSG_OK;
}

SSG_PARAMS_TABLE(params, ssg_bounce_params, SSG_SSDO_GEOM_PARAMS);
SSG_UNIFORMS_AT_TABLE(uniforms, ssg_bounce_consts, SSG_SSDO_GEOM_UNIFORMS);
SSG_PORT_TABLE(inputs, SSG_BOUNCE_IN);
_Static_assert(SSG_COUNT(inputs) == SSG_BOUNCE_INPUTS, "one entry a port enumerator");
SSG_PORT_TABLE(outputs, SSG_BOUNCE_OUT);

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
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_bounce_params),
    .consts_size = sizeof(struct ssg_bounce_consts),
    .uniforms = SSG_TABLE(uniforms), /* uniforms_offset 0: rows of the consts' own fields */
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA,
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = bounce_flops,
    .run_cpu = ssg_bounce_run_cpu,
    .run_gl = ssg_bounce_run_gl,
    .parity = {.max = 0, .mean = 0}, /* bit-exact on llvmpipe (test_gl_bounce.c) */
};
