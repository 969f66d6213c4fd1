/* ssao.c - the `ssao` node's descriptor, check and prepare: screen-space ambient occlusion
 * (hemisphere, sphere or disc). The method, its sources and conventions: README.md here. */
#include <stdio.h>

#include "common/sampling.h"
#include "ssao.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_ssao_params *p = params;
    if (p->mode == SSG_SSAO_MODE_HEMISPHERE && in[SSG_SSAO_IN_NORMAL].channels == 0) {
        snprintf(why, why_len, "needs input 'normal' (mode hemisphere orients its samples "
                 "by it; modes sphere and disc do not)");
        return SSG_E_MISSING_INPUT;
    }
    return ssg_sampling_check_ao(&in[SSG_SSAO_IN_POSITION], &in[SSG_SSAO_IN_NORMAL],
                                 &in[SSG_SSAO_IN_KERNEL], &in[SSG_SSAO_IN_ROTATION],
                                 &in[SSG_SSAO_IN_DEPTH], &in[SSG_SSAO_IN_COUNT], out, why,
                                 why_len);
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_ssao_consts *c = consts;
    c->p = *(const struct ssg_ssao_params *)params;
    enum ssg_err e =
        ssg_sampling_projection(ctx, &ctx->in_shape[SSG_SSAO_IN_POSITION], &c->u.proj);
    c->u.cap = c->p.max_screen_radius / c->u.proj.f;
    c->u.capped = c->p.max_screen_radius > 0.0f;
    c->u.inv_samples = 1.0f / (float)ctx->in_shape[SSG_SSAO_IN_KERNEL].width;
    return e;
}

static const char *const ssg_ssao_range_choices[] = {"none", "hard", "smooth", NULL};
static const char *const ssg_ssao_mode_choices[] = {"hemisphere", "sphere", "disc", NULL};
SSG_PARAMS_TABLE(params, ssg_ssao_params, SSG_SSAO_PARAMS);
SSG_UNIFORMS_TABLE(uniforms, ssg_ssao_uniforms, SSG_SSAO_UNIFORMS);

SSG_PORT_TABLE(inputs, SSG_SSAO_IN);
SSG_PORT_TABLE(outputs, SSG_SSAO_OUT);

/* Flops per pixel (node.h), by reading ssao_cpu.c: per kernel sample about 38 (placing
   and projecting it: three 4-term affine forms, a division, rounding and bounds; the
   depth test, range check and sum), about 60 per pixel for its frame and the finish. */
static double ssao_flops(const void *consts, const struct ssg_shape *in)
{
    return 60.0 + 38.0 * in[SSG_SSAO_IN_KERNEL].width;
}

const struct ssg_node_desc ssg_node_ssao = {
    .name = "ssao",
    .summary = "screen-space ambient occlusion: normal hemisphere, normal-free sphere or "
               "screen-space disc",
    .method = "hemisphere: Szentandrasi, Modern Methods of Realistic Lighting in Real Time, "
              "sec. 3.1 and fig. 1; Belonogov, Global Illumination methods in simulated VR "
              "environments, sec. 3.2 (normal-oriented hemisphere, tiled rotation). "
              "sphere: Knuth and Kohlhammer, A Hybrid Ambient Occlusion Technique for "
              "Dynamic Scenes, sec. 4 local part, fig. 9 (normal-free sphere, denser "
              "towards the centre, averaged, clamped to [0,1]). disc: Mittring, Finding "
              "Next Gen - CryEngine 2 (SIGGRAPH 2007), in the screen-space disc form of "
              "Belonogov sec. 3.2.1",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_ssao_params),
    .consts_size = sizeof(struct ssg_ssao_consts),
    SSG_NODE_UNIFORMS(uniforms, struct ssg_ssao_consts, u),
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA,
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = ssao_flops,
    .run_cpu = ssg_ssao_run_cpu,
    .run_gl = ssg_ssao_run_gl,
    /* test_gl_ssao.c: 1.8e-7, 1.3e-8 (pow): 2.8x, 3.8x */
    .parity = {.max = 5e-7, .mean = 5e-8},
};
