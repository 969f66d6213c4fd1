/* gaussian.c - the `gaussian` node's descriptor, check and prepare: a plain separable
 * Gaussian blur. The method, its sources and conventions: README.md in this folder. */
#include <math.h>
#include <stdio.h>

#include "gaussian.h"

/* The window the parameters ask for: size, or 2 ceil(3 sigma) + 1 when size is 0. */
static int window_size(const struct ssg_gaussian_params *p)
{
    if (p->size > 0)
        return p->size;
    double s = 2.0 * ceil(3.0 * (double)p->sigma) + 1.0;
    return s > SSG_GAUSSIAN_MAX_SIZE ? SSG_GAUSSIAN_MAX_SIZE + 1 : (int)s;
}

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_gaussian_params *p = params;
    int size = window_size(p);
    if (size % 2 == 0) {
        snprintf(why, why_len, "size must be odd (a window centred on the pixel), got %d",
                 p->size);
        return SSG_E_VALUE;
    }
    if (size > SSG_GAUSSIAN_MAX_SIZE) {
        snprintf(why, why_len, "sigma %g needs a window of %d px, more than %d", p->sigma,
                 size, SSG_GAUSSIAN_MAX_SIZE);
        return SSG_E_RANGE;
    }
    return SSG_OK;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    const struct ssg_gaussian_params *p = params;
    struct ssg_gaussian_consts *c = consts;
    int size = p->sigma > 0 ? window_size(p) : 0;
    if (!(p->sigma > 0) || size < 1 || size > SSG_GAUSSIAN_MAX_SIZE || size % 2 == 0) {
        return ssg_node_fail(ctx, SSG_E_VALUE, "needs sigma > 0 and an odd size up to %d",
                             SSG_GAUSSIAN_MAX_SIZE);
    }
    c->radius = (size - 1) / 2;
    double w[SSG_GAUSSIAN_MAX_SIZE], sum = 0;
    for (int i = -c->radius; i <= c->radius; i++) {
        w[i + c->radius] = exp(-0.5 * (double)i * i / ((double)p->sigma * p->sigma));
        sum += w[i + c->radius];
    }
    for (int i = 0; i < size; i++)
        c->weight[i] = (float)(w[i] / sum);
    return SSG_OK;
}

static const struct ssg_param_desc params[] = {
    {.name = "sigma", SSG_FIELD_FLOAT(struct ssg_gaussian_params, sigma),
     .def = 2, .min = 0.01, .max = 170, .unit = "px", .help = "standard deviation"},
    {.name = "size", SSG_FIELD_INT(struct ssg_gaussian_params, size),
     .def = 0, .min = 0, .max = SSG_GAUSSIAN_MAX_SIZE, .unit = "px",
     .help = "window diameter, odd; 0 = 2 ceil(3 sigma) + 1"},
};

static const struct ssg_port_desc inputs[] = {
    [SSG_GAUSSIAN_IN_IN] = {.name = "in", .types = SSG_T_SCALAR | SSG_T_COLOR | SSG_T_VECTOR,
     .doc = "image to blur"},
};
_Static_assert(SSG_COUNT(inputs) == SSG_GAUSSIAN_INPUTS, "one entry a port enumerator");

static const struct ssg_port_desc outputs[] = {
    [SSG_GAUSSIAN_OUT_OUT] = {.name = "out", .types = SSG_T_SCALAR, .same_as = "in",
     .doc = "blurred image"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_GAUSSIAN_OUTPUTS, "one entry a port enumerator");

/* Flops per pixel (node.h): two passes of size taps, a multiply and an add a channel. */
static double gaussian_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_gaussian_consts *c = consts;
    return 2.0 * (2.0 * c->radius + 1.0) * 2.0 * in[SSG_GAUSSIAN_IN_IN].channels;
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
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = gaussian_flops,
    .run_cpu = ssg_gaussian_run_cpu,
    .run_gl = ssg_gaussian_run_gl,
};
