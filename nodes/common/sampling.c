/* sampling.c - checks and camera of the screen-space sampling nodes (sampling.h). */
#include "common/vector_loops.h" /* first: see there */
#include <stdio.h>

#include "common/sampling.h"

enum ssg_err ssg_sampling_check_inputs(const struct ssg_shape *position,
                                       const struct ssg_shape *kernel,
                                       const struct ssg_shape *rotation,
                                       const struct ssg_shape *depth,
                                       const struct ssg_shape *count, char *why,
                                       size_t why_len)
{
    if (kernel && (kernel->channels != 3 || kernel->height != 1 || kernel->width < 1)) {
        snprintf(why, why_len, "kernel must be count x 1 with 3 channels, got %dx%dx%d",
                 kernel->width, kernel->height, kernel->channels);
        return SSG_E_CHANNELS;
    }
    if (rotation->channels != 0 && ((rotation->channels != 2 && rotation->channels != 4) ||
                                    rotation->width != rotation->height)) {
        snprintf(why, why_len, "rotation must be an n x n pattern with 2 or 4 channels, got "
                 "%dx%dx%d", rotation->width, rotation->height, rotation->channels);
        return SSG_E_CHANNELS;
    }
    if (depth->channels != 0 &&
        (depth->channels != 1 || !ssg_shape_same_size(depth, position))) {
        snprintf(why, why_len, "depth must be a 1-channel image the size of position");
        return SSG_E_SIZE;
    }
    if (count && count->channels != 0 &&
        (count->channels != 1 || !ssg_shape_same_size(count, position))) {
        snprintf(why, why_len, "count must be a 1-channel image the size of position");
        return SSG_E_SIZE;
    }
    return SSG_OK;
}

enum ssg_err ssg_sampling_check_ao(const struct ssg_shape *position,
                                   const struct ssg_shape *normal,
                                   const struct ssg_shape *kernel,
                                   const struct ssg_shape *rotation,
                                   const struct ssg_shape *depth,
                                   const struct ssg_shape *count, struct ssg_shape *out,
                                   char *why, size_t why_len)
{
    if (position->channels != 3 ||
        (normal->channels != 0 &&
         (normal->channels != 3 || !ssg_shape_same_size(position, normal)))) {
        snprintf(why, why_len, "position and normal must be 3-channel images of one size");
        return SSG_E_SIZE;
    }
    enum ssg_err e =
        ssg_sampling_check_inputs(position, kernel, rotation, depth, count, why, why_len);
    out[0] = (struct ssg_shape){position->width, position->height, 1, SSG_T_SCALAR};
    return e;
}

enum ssg_err ssg_sampling_projection(const struct ssg_node_ctx *ctx,
                                     const struct ssg_shape *gbuffer,
                                     struct ssg_projection *out)
{
    const struct ssg_frame *f = ctx->frame;
    const struct ssg_projection frame_proj = ssg_frame_projection(f);
    if (f->width < 1 || f->height < 1 || !(frame_proj.f > 0))
        return ssg_node_fail(ctx, SSG_E_VALUE, "needs a frame with size and field of view");
    *out = ssg_projection_scaled(&frame_proj, ssg_frame_full_width(f),
                                 ssg_frame_full_height(f), gbuffer->width, gbuffer->height);
    return SSG_OK;
}

double ssg_sampling_frame_turn(int frame)
{
    /* 1 / phi; the product is exact enough for any frame count a run reaches (2^31
       frames lose 31 of the 53 bits, leaving 2^-22 of a turn). */
    double t = (double)frame * 0.61803398874989484820;
    return t - floor(t);
}

float ssg_sampling_frame_shift(int frame)
{
    int f = frame % 64;
    return 5.588238f * (float)(f < 0 ? f + 64 : f);
}
