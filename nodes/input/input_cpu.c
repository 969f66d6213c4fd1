/* input_cpu.c - the `input` node on the CPU: the supplied image copied to the output. */
#include <string.h>

#include "input.h"

/* The supplied image, or a message saying how to supply one. */
const struct ssg_image *ssg_input_image(const struct ssg_node_ctx *ctx)
{
    if (!ctx->supplied)
        ssg_node_fail(ctx, SSG_E_MISSING_INPUT, "no image was supplied (call "
                      "ssg_graph_supply(graph, \"%s\", image) before running)", ctx->instance);
    return ctx->supplied;
}

enum ssg_err ssg_input_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io)
{
    const struct ssg_image *src = ssg_input_image(ctx);
    struct ssg_image *out = io->out[SSG_INPUT_OUT_OUT];
    if (!src)
        return SSG_E_MISSING_INPUT;
    memcpy(out->data, src->data, (size_t)out->width * (size_t)out->height *
                                     (size_t)out->channels * sizeof *out->data);
    return SSG_OK;
}
