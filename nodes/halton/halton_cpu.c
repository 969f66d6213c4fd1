/* halton_cpu.c - CPU backend of the `halton` node (method in README.md): prepare()
 * (halton.c) computed frame 0's kernel and rotation tile; ssg_halton_frame makes the
 * running frame's from them (a copy in frame 0), and running is copying those bytes into
 * the two outputs, so every backend sees exactly the same samples. */
#include "halton.h"
#include "graph/node.h"

enum ssg_err ssg_halton_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io)
{
    const struct ssg_halton_consts *c = consts;
    ssg_halton_frame(c, ctx->frame_index, io->out[0]->data, io->out[1]->data);
    return SSG_OK;
}
