/* downsample.c - the `downsample` node: a G-buffer at 1/2 or 1/4 of the resolution, for
 * screen-space passes computed at low resolution and brought back by `upsample`.
 *
 * Method: Szentandrasi, "Modern Methods of Realistic Lighting in Real Time", section 4.1
 * and figure 6 / table 1 (SSAO and SSDO "computed in lower resolutions", 2x subsampling,
 * then joint bilateral upsampling); Belonogov, "Global Illumination methods in simulated VR
 * environments", section 4.7.1 (subsampling; "the scene geometry features must be
 * considered, because objects can lose their fine details").
 * Neither document says how the low-resolution G-buffer is made. Averaging would invent
 * surfaces that do not exist: at a silhouette, the mean of a near and a far position is a
 * point floating in the air, with a normal that belongs to neither. So each factor x
 * factor block keeps ONE of its pixels, the same one for every image: the pixel whose
 * depth is closest to the median depth of the block's surface pixels (a block split by an
 * edge keeps its majority side; ties go to the first pixel in row-major order). The median
 * of an even count is the mean of the two middle depths. Background pixels (depth 0) are
 * left out of the median and never chosen, unless the whole block is background, when its
 * first pixel (background) is copied. Position, normal and depth then describe one real
 * surface point, which the screen-space nodes (ssao, hbao, ssdo) reproject with their
 * projection scaled to the smaller image.
 * Output size: ceil(width / factor) x ceil(height / factor); blocks at the right and
 * bottom edges of sizes not divisible by the factor are the partial blocks that exist. An
 * output whose input is unconnected is still made (at that size, all 0) so that graphs may
 * name every port. */
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

static const struct ssg_param_desc params[] = {
    {.name = "factor", SSG_FIELD_INT(struct ssg_downsample_params, factor), .def = 2, .min = 2,
     .max = SSG_DOWNSAMPLE_MAX_FACTOR, .unit = "px",
     .help = "block side: 2 (half resolution) or 4"},
};

static const struct ssg_port_desc inputs[] = {
    [SSG_DOWNSAMPLE_IN_DEPTH] = {.name = "depth", .types = SSG_T_SCALAR,
     .doc = "linear depth; 0 = background"},
    [SSG_DOWNSAMPLE_IN_POSITION] = {.name = "position", .types = SSG_T_VECTOR, .optional = 1,
     .doc = "view-space position"},
    [SSG_DOWNSAMPLE_IN_NORMAL] = {.name = "normal", .types = SSG_T_VECTOR, .optional = 1,
     .doc = "unit view-space normal"},
    [SSG_DOWNSAMPLE_IN_ALBEDO] = {.name = "albedo", .types = SSG_T_COLOR, .optional = 1,
     .doc = "albedo"},
    [SSG_DOWNSAMPLE_IN_DIRECT] = {.name = "direct", .types = SSG_T_COLOR, .optional = 1,
     .doc = "direct light"},
    [SSG_DOWNSAMPLE_IN_ENVIRONMENT] = {.name = "environment", .types = SSG_T_COLOR,
     .optional = 1, .doc = "environment light"},
};
_Static_assert(SSG_COUNT(inputs) == SSG_DOWNSAMPLE_INPUTS, "one entry a port enumerator");

static const struct ssg_port_desc outputs[] = {
    [SSG_DOWNSAMPLE_OUT_DEPTH] = {.name = "depth", .types = SSG_T_SCALAR,
     .doc = "depth of each block's chosen pixel"},
    [SSG_DOWNSAMPLE_OUT_POSITION] = {.name = "position", .types = SSG_T_VECTOR,
     .doc = "position of the chosen pixel; 0 when unconnected"},
    [SSG_DOWNSAMPLE_OUT_NORMAL] = {.name = "normal", .types = SSG_T_VECTOR,
     .doc = "normal of the chosen pixel; 0 when unconnected"},
    [SSG_DOWNSAMPLE_OUT_ALBEDO] = {.name = "albedo", .types = SSG_T_COLOR,
     .doc = "albedo of the chosen pixel; 0 when unconnected"},
    [SSG_DOWNSAMPLE_OUT_DIRECT] = {.name = "direct", .types = SSG_T_COLOR,
     .doc = "direct light of the chosen pixel; 0 when unconnected"},
    [SSG_DOWNSAMPLE_OUT_ENVIRONMENT] = {.name = "environment", .types = SSG_T_COLOR,
     .doc = "environment light of the chosen pixel; 0 when unconnected"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_DOWNSAMPLE_OUTPUTS, "one entry a port enumerator");

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
    .doc = "Splits the frame into factor x factor blocks and keeps one pixel of each: the "
           "one whose depth is closest to the median depth of the block's non-background "
           "pixels (ties: first in row-major order; a block of background only keeps its "
           "first pixel). Every output copies that same pixel, never an average across an "
           "edge, so depth, position and normal stay one surface point. Outputs are "
           "ceil(width / factor) x ceil(height / factor); an output whose input is "
           "unconnected is all 0.",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_downsample_params),
    .check = check,
    .flops_per_pixel = downsample_flops,
    .run_cpu = ssg_downsample_run_cpu,
    .run_gl = ssg_downsample_run_gl,
};
