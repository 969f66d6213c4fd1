/* input.c - the `input` node's descriptor and check: an image the caller supplies. The
 * method and the API that supplies it: README.md in this folder. */
#include "input.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_input_params *p = params;
    static const unsigned types[] = {SSG_T_SCALAR, SSG_T_VECTOR, SSG_T_COLOR};
    out[SSG_INPUT_OUT_OUT] = (struct ssg_shape){
        p->width ? p->width : ssg_frame_full_width(frame),
        p->height ? p->height : ssg_frame_full_height(frame),
        p->type == SSG_INPUT_SCALAR ? 1 : 3, types[p->type]};
    return SSG_OK;
}

static const char *const ssg_input_type_choices[] = {"scalar", "vector", "color", NULL};
SSG_PARAMS_TABLE(params, ssg_input_params, SSG_INPUT_PARAMS);
SSG_PORT_TABLE(outputs, SSG_INPUT_OUT);

const struct ssg_node_desc ssg_node_input = {
    .name = "input",
    .summary = "an image the caller supplies (an engine's G-buffer, a photo) as a source",
    .method = "none: a source node; the image comes from the library's caller "
              "(ssg_graph_supply, ssgraph.h)",
    SSG_NODE_OUTPUTS(outputs),
    SSG_NODE_PARAMS(params, struct ssg_input_params),
    .supplied = 1,
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA,
    .check = check,
    .run_cpu = ssg_input_run_cpu,
    .run_gl = ssg_input_run_gl,
};
