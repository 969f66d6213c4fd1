/* downsample.c - the `downsample` node's descriptor and check: a G-buffer at 1/2 or 1/4 of
 * the resolution, one representative pixel per block. Method: README.md in this folder. */
#include <stdio.h>

#include "downsample.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_downsample_params *p = params;
    const struct ssg_shape *dep = &in[SSG_DOWNSAMPLE_IN_DEPTH];
    if (p->factor != 2 && p->factor != 4) {
        snprintf(why, why_len, "factor must be 2 or 4, got %d", p->factor);
        return SSG_E_VALUE;
    }
    if (dep->channels != 1) {
        snprintf(why, why_len, "depth must be a 1-channel image");
        return SSG_E_CHANNELS;
    }
    int w = (dep->width + p->factor - 1) / p->factor;
    int h = (dep->height + p->factor - 1) / p->factor;
    for (int k = 0; k < SSG_DOWNSAMPLE_INPUTS; k++) {
        if (in[k].channels != 0 && !ssg_shape_same_size(&in[k], dep)) {
            snprintf(why, why_len, "every input must have the size of depth (%dx%d)",
                     dep->width, dep->height);
            return SSG_E_SIZE;
        }
        out[k].width = w;
        out[k].height = h;
    }
    return SSG_OK;
}

SSG_PARAMS_TABLE(params, ssg_downsample_params, SSG_DOWNSAMPLE_PARAMS);

SSG_PORT_TABLE(inputs, SSG_DOWNSAMPLE_IN);
SSG_PORT_TABLE(outputs, SSG_DOWNSAMPLE_OUT);

/* Flops per output pixel (node.h): the block's depths against their median and the choice,
   about 4 a full-resolution pixel of the 2x2 block (the copies move no flops). */
static double downsample_flops(const void *consts, const struct ssg_shape *in)
{
    (void)consts, (void)in;
    return 16.0;
}

const struct ssg_node_desc ssg_node_downsample = {
    .name = "downsample",
    .summary = "depth-aware G-buffer subsampling: one representative pixel per block",
    .method = "Szentandrasi, Modern Methods of Realistic Lighting in Real Time, sec. 4.1 and "
              "fig. 6 / table 1 (2x subsampling); Belonogov, Global Illumination methods in "
              "simulated VR environments, sec. 4.7.1 (subsampling); the representative "
              "(median-depth) sample is our choice",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_downsample_params),
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA,
    .check = check,
    .flops_per_pixel = downsample_flops,
    .run_cpu = ssg_downsample_run_cpu,
    .run_gl = ssg_downsample_run_gl,
    .parity = {.max = 0, .mean = 0}, /* selects pixels: bit-exact (test_gl_filters.c) */
};
