/* @name@.c - the `@name@` node's descriptor: its tables, made from the rows in @name@.h,
 * and its backends. The method, its sources and conventions: README.md in this folder. */
#include "@name@.h"

SSG_PARAMS_TABLE(params, ssg_@name@_params, SSG_@NAME@_PARAMS);
SSG_PORT_TABLE(inputs, SSG_@NAME@_IN);
SSG_PORT_TABLE(outputs, SSG_@NAME@_OUT);

/* Flops per pixel of output 0 (graph/node.h), by reading @name@_cpu.c's inner loop: one
   multiply a channel. The profile sets it against the machine's peak. */
static double flops(const void *consts, const struct ssg_shape *in)
{
    (void)consts;
    return (double)in[SSG_@NAME@_IN_SRC].channels;
}

const struct ssg_node_desc ssg_node_@name@ = {
    .name = "@name@",
    .summary = "multiplies every channel of an image by `gain` (the node template's "
               "example method)",
    .method = "the node template's example (tools/node-template/): out = gain x src per "
              "pixel and channel; name the paper, section and equation of yours here",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_@name@_params),
    /* What it reads besides inputs and parameters (node.h): the camera too until you know
       it does not (then drop it, and tests/test_camera_deps.c checks that in a graph) */
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA,
    .flops_per_pixel = flops,
    .run_cpu = ssg_@name@_run_cpu,
    .run_gl = ssg_@name@_run_gl,
};
