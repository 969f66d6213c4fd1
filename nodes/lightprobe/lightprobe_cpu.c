/* lightprobe_cpu.c - CPU side of the `lightprobe` node (README.md): the light list was
 * made in prepare(); running copies it into the output. */
#include <string.h>

#include "lightprobe.h"

enum ssg_err ssg_lightprobe_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                    const struct ssg_io *io)
{
    const struct ssg_lightprobe_consts *c = consts;
    memcpy(io->out[0]->data, c->lights, sizeof(float) * 6 * (size_t)c->count);
    return SSG_OK;
}
