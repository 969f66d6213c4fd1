/* halton_cpu.c - CPU backend of the `halton` node (method in README.md): the kernel and
 * the rotation tile were computed by prepare() (halton.c); running is copying those bytes
 * into the two outputs, so every backend sees exactly the same samples. */
#include <string.h>

#include "halton.h"
#include "graph/node.h"

enum ssg_err ssg_halton_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io)
{
    const struct ssg_halton_consts *c = consts;
    struct ssg_image *kernel = io->out[0], *rotation = io->out[1];
    memcpy(kernel->data, c->kernel, sizeof(float) * 3 * (size_t)c->count);
    memcpy(rotation->data, c->pattern, sizeof(float) * 2 * (size_t)c->n * (size_t)c->n);
    return SSG_OK;
}
