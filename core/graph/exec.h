/* exec.h - what the graph executor and the single-node runner share: working out output
 * shapes from input shapes, and running one node (prepare, then its CPU kernel, timed).
 * Internal to libssgraph. */
#ifndef SSG_EXEC_H
#define SSG_EXEC_H

#include "graph/node.h"

/* Most ports a node may have on either side (the largest node today has 10 inputs). */
#define SSG_MAX_PORTS 12
/* Most extra named inputs (write's layers). */
#define SSG_MAX_EXTRA 16

/* Fills out[] with the default shapes (frame size and type channels, or the shape of the
 * same_as input), then lets the node's check() adjust and validate them. `in` holds the
 * shapes of connected inputs (channels 0 = unconnected). Returns SSG_OK or the node's error
 * code with a message in why. Also rejects absurd output sizes (SSG_E_SIZE). */
enum ssg_err ssg_shapes_infer(const struct ssg_node_desc *desc, const void *params,
                              const struct ssg_frame *frame, const struct ssg_shape *in,
                              struct ssg_shape *out, char *why, size_t why_len);

/* Where a node runs. DEFAULT resolves to the graph's backend (CPU unless `backend gl` or
 * --backend gl), and GL to CPU for a node without a GL side. */
enum ssg_backend { SSG_BACKEND_DEFAULT, SSG_BACKEND_CPU, SSG_BACKEND_GL };
/* "cpu", "gl" (DEFAULT: "default"). */
const char *ssg_backend_name(enum ssg_backend b);
/* Parses "cpu" or "gl"; returns 1 on success. */
int ssg_backend_parse(const char *text, size_t len, enum ssg_backend *out);

/* What one node's run cost. */
struct ssg_node_timing {
    double ms;          /* wall clock of prepare + run (GL: until the GPU finished) */
    double gpu_ms;      /* GL: the timer query around the run; CPU: 0 */
    double transfer_ms; /* uploads or downloads of its inputs before it ran */
};

/* Runs prepare() and the backend's run of one node (CPU or GL, see gl_backend.h for the
 * transfers it inserts; GL must be open); returns the node's error (its message is in
 * ctx->diags) and what it cost. */
enum ssg_err ssg_node_execute(const struct ssg_node_desc *desc, const struct ssg_node_ctx *ctx,
                              const void *params, const struct ssg_io *io,
                              enum ssg_backend backend, struct ssg_node_timing *timing);

/* The two halves of ssg_node_execute, for running a node many times (--frames): its
 * constants made once by prepare() (*consts NULL when the node has none: run with the
 * params; free() them after), then any number of runs with them. */
enum ssg_err ssg_node_prepare(const struct ssg_node_desc *desc, const struct ssg_node_ctx *ctx,
                              const void *params, void **consts);
enum ssg_err ssg_node_run_prepared(const struct ssg_node_desc *desc,
                                   const struct ssg_node_ctx *ctx, const void *params,
                                   const void *consts, const struct ssg_io *io,
                                   enum ssg_backend backend, struct ssg_node_timing *timing);

/* What one run of a node moves and computes, for the profile's rates: the bytes of every
 * connected input and output image (each read or written once: the least traffic a pass
 * can have, so the memory bound it gives is a floor) and the flops the node declares
 * (flops_per_pixel times output 0's pixels; -1 when it declares none). */
struct ssg_node_cost {
    double bytes;
    double flops;
};
void ssg_node_cost_of(const struct ssg_node_desc *desc, const struct ssg_node_ctx *ctx,
                      const void *consts, int extra_count, struct ssg_node_cost *cost);

/* Verifies every image bound in io against the shapes in ctx (in_shape, out_shape,
 * extra_shape): same width, height and channels, unconnected where the shape has none.
 * On a difference reports "node 'ao' (ssao): input 'depth' is 48x32 with 1 channel,
 * expected 96x64 with 1 channel (...)" and returns SSG_E_SIZE or SSG_E_CHANNELS. Called by
 * ssg_node_run_prepared before every run, so no node checks its own images. */
enum ssg_err ssg_node_verify_io(const struct ssg_node_ctx *ctx, const struct ssg_io *io);

/* The shapes of images bound by hand (tests, micro-benchmarks, ssg_node_run), for a ctx:
 * ssg_io_shapes_of reads them off the images, ssg_node_ctx_set_shapes points ctx at them
 * (s must outlive the runs). */
struct ssg_io_shapes {
    struct ssg_shape in[SSG_MAX_PORTS], out[SSG_MAX_PORTS], extra[SSG_MAX_EXTRA];
};
void ssg_io_shapes_of(const struct ssg_node_desc *desc, const struct ssg_io *io,
                      struct ssg_io_shapes *s);
void ssg_node_ctx_set_shapes(struct ssg_node_ctx *ctx, const struct ssg_io_shapes *s);
/* An image's shape with its type among `accepted` (ssg_type_of_image; 0 when none). */
struct ssg_shape ssg_shape_of_image(const struct ssg_image *image, unsigned accepted);

/* ssg_node_run (ssgraph.h) for a descriptor in hand rather than a registered name: a node
 * not (yet) in nodes/nodes.def runs the same way, as the node template's test does
 * (tests/test_node_template.sh). The caller has checked the arguments ssg_node_run checks
 * (outputs non-NULL, counts matching their arrays). */
enum ssg_err ssg_node_run_desc(const struct ssg_node_desc *desc, const struct ssg_binding *inputs,
                               int input_count, const char *const *sets, int set_count,
                               const struct ssg_frame *frame, struct ssg_outputs *outputs,
                               struct ssg_diags *diags);

/* Wall-clock milliseconds from an arbitrary origin. */
double ssg_now_ms(void);

/* The type of an image bound to an input port that accepts `accepted`, inferred from its
 * shape: 0 when its channel count fits none of them. */
unsigned ssg_type_of_image(unsigned accepted, const struct ssg_image *image);

#endif
