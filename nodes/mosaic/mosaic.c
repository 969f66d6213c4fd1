/* mosaic.c - the `mosaic` node's descriptor: several images side by side in one
 * frame-sized picture, labelled. Method: README.md in this folder. */
#include "mosaic.h"

SSG_PARAMS_TABLE(params, ssg_mosaic_params, SSG_MOSAIC_PARAMS);
SSG_PORT_TABLE(outputs, SSG_MOSAIC_OUT);

const struct ssg_node_desc ssg_node_mosaic = {
    .name = "mosaic",
    .summary = "contact sheet: several images side by side, labelled",
    .method = "presentation, after the documents' side-by-side figures (Belonogov fig. 5.3, "
              "Knuth and Kohlhammer fig. 11)",
    SSG_NODE_OUTPUTS(outputs),
    .extra_inputs = 1,
    SSG_NODE_PARAMS(params, struct ssg_mosaic_params),
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA,
    .run_cpu = ssg_mosaic_run_cpu,
};
