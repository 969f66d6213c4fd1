/* gaussian.h - parameters and prepared constants of the `gaussian` node, shared by
 * gaussian.c (descriptor, check, prepare) and gaussian_cpu.c (the CPU kernel). Method in
 * gaussian.c. Read-only after prepare(); the kernel is thread-safe. */
#ifndef SSG_GAUSSIAN_H
#define SSG_GAUSSIAN_H

#include "graph/node.h"

/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_gaussian_input {
    SSG_GAUSSIAN_IN_IN,
    SSG_GAUSSIAN_INPUTS
};
enum ssg_gaussian_output {
    SSG_GAUSSIAN_OUT_OUT,
    SSG_GAUSSIAN_OUTPUTS
};

#define SSG_GAUSSIAN_MAX_SIZE 1023 /* widest window, px */

struct ssg_gaussian_params {
    float sigma; /* standard deviation, px, > 0; default 2 */
    int size;    /* window diameter, px, odd, 0 = 2 ceil(3 sigma) + 1; default 0 */
};

struct ssg_gaussian_consts {
    int radius;                             /* (size - 1) / 2, px */
    float weight[SSG_GAUSSIAN_MAX_SIZE];    /* normalised weights of offsets -radius..radius
                                               (index offset + radius); they sum to 1 */
};

enum ssg_err ssg_gaussian_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                  const struct ssg_io *io);
enum ssg_err ssg_gaussian_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io);

#endif
