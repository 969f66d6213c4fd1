/* exec.h - what the graph executor and the single-node runner share: working out output
 * shapes from input shapes, and running one node (prepare, then its CPU kernel, timed).
 * Internal to libssgraph. */
#ifndef SSG_EXEC_H
#define SSG_EXEC_H

#include "node.h"

/* Most ports a node may have on either side. */
#define SSG_MAX_PORTS 8
/* Most extra named inputs (write's layers). */
#define SSG_MAX_EXTRA 16

/* Fills out[] with the default shapes (frame size and type channels, or the shape of the
 * same_as input), then lets the node's check() adjust and validate them. `in` holds the
 * shapes of connected inputs (channels 0 = unconnected). Returns SSG_OK or the node's error
 * code with a message in why. Also rejects absurd output sizes (SSG_E_SIZE). */
enum ssg_err ssg_shapes_infer(const struct ssg_node_desc *desc, const void *params,
                              const struct ssg_frame *frame, const struct ssg_shape *in,
                              struct ssg_shape *out, char *why, size_t why_len);

/* Runs prepare() and run_cpu() of one node; returns the node's error (its message is in
 * ctx->diags) and the milliseconds the two took. */
enum ssg_err ssg_node_execute(const struct ssg_node_desc *desc, const struct ssg_node_ctx *ctx,
                              const void *params, const struct ssg_io *io, double *ms);

/* Wall-clock milliseconds from an arbitrary origin. */
double ssg_now_ms(void);

/* The type of an image bound to an input port that accepts `accepted`, inferred from its
 * shape: 0 when its channel count fits none of them. */
unsigned ssg_type_of_image(unsigned accepted, const struct ssg_image *image);

#endif
