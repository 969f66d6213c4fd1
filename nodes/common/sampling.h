/* sampling.h - what the screen-space sampling nodes (ssao, hbao, ssdo, bounce, complexity)
 * share on the C side: the checks of their optional G-buffer inputs and the camera as the
 * G-buffer's resolution sees it, made once in prepare() for both backends. Its GLSL twin is
 * sampling.glsl (included by the shaders with #include "sampling.glsl"). */
#ifndef SSG_SAMPLING_H
#define SSG_SAMPLING_H

#include "graph/node.h"

/* check() of a sampling node: the optional rotation tile (n x n, 2 channels) and the
 * optional depth (1 channel, the size of position); channels 0 = unconnected. Returns
 * SSG_OK, or the error code with the reason in why. */
enum ssg_err ssg_sampling_check_rotation_depth(const struct ssg_shape *position,
                                               const struct ssg_shape *rotation,
                                               const struct ssg_shape *depth, char *why,
                                               size_t why_len);

/* prepare() of a sampling node: the frame's camera as an image of `gbuffer`'s size sees it
 * (ssg_projection_scaled: a subsampled G-buffer sees the same camera). Reports "needs a
 * frame with size and field of view" through ctx and returns SSG_E_VALUE when the frame
 * has neither. */
enum ssg_err ssg_sampling_projection(const struct ssg_node_ctx *ctx,
                                     const struct ssg_shape *gbuffer,
                                     struct ssg_projection *out);

#endif
