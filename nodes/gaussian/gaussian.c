/* gaussian.c - the `gaussian` node's descriptor, check and prepare: a plain separable
 * Gaussian blur. The method, its sources and conventions: README.md in this folder. */
#include <math.h>
#include <stdio.h>

#include "gaussian.h"

/* The window the parameters ask for: size, or 2 ceil(3 sigma) + 1 when size is 0 (at most
   SSG_GAUSSIAN_MAX_SIZE for any sigma the table admits: gaussian.h). */
static int window_size(const struct ssg_gaussian_params *p)
{
    return p->size > 0 ? p->size : 2 * (int)ceil(3.0 * (double)p->sigma) + 1;
}

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_gaussian_params *p = params;
    if (window_size(p) % 2 == 0) {
        snprintf(why, why_len, "size must be odd (a window centred on the pixel), got %d",
                 p->size);
        return SSG_E_VALUE;
    }
    return SSG_OK;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    const struct ssg_gaussian_params *p = params;
    struct ssg_gaussian_consts *c = consts;
    int size = window_size(p);
    c->u.radius = (size - 1) / 2;
    double w[SSG_GAUSSIAN_MAX_SIZE], sum = 0;
    for (int i = -c->u.radius; i <= c->u.radius; i++) {
        w[i + c->u.radius] = exp(-0.5 * (double)i * i / ((double)p->sigma * p->sigma));
        sum += w[i + c->u.radius];
    }
    for (int i = 0; i < size; i++)
        c->weight[i] = (float)(w[i] / sum);
    return SSG_OK;
}

SSG_PARAMS_TABLE(params, ssg_gaussian_params, SSG_GAUSSIAN_PARAMS);
SSG_UNIFORMS_TABLE(uniforms, ssg_gaussian_uniforms, SSG_GAUSSIAN_UNIFORMS);
SSG_PORT_TABLE(inputs, SSG_GAUSSIAN_IN);
SSG_PORT_TABLE(outputs, SSG_GAUSSIAN_OUT);

/* Flops per pixel (node.h): two passes of size taps, a multiply and an add a channel. */
static double gaussian_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_gaussian_consts *c = consts;
    return 2.0 * (2.0 * c->u.radius + 1.0) * 2.0 * in[SSG_GAUSSIAN_IN_IN].channels;
}

const struct ssg_node_desc ssg_node_gaussian = {
    .name = "gaussian",
    .summary = "separable Gaussian blur (the plain-blur baseline)",
    .method = "Belonogov, Global Illumination methods in simulated VR environments, sec. "
              "4.3.1 (Gaussian blur, horizontal then vertical pass); Szentandrasi, Modern "
              "Methods of Realistic Lighting in Real Time, sec. 4.1 (why it bleeds)",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_gaussian_params),
    .consts_size = sizeof(struct ssg_gaussian_consts),
    SSG_NODE_UNIFORMS(uniforms, struct ssg_gaussian_consts, u),
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA,
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = gaussian_flops,
    .run_cpu = ssg_gaussian_run_cpu,
    .run_gl = ssg_gaussian_run_gl,
    .parity = {.max = 0, .mean = 0}, /* bit-exact on llvmpipe (test_gl_gaussian.c) */
};
