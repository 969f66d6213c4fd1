/* mosaic.h - the `mosaic` node (mosaic.c): a contact sheet of several images. */
#ifndef SSG_MOSAIC_H
#define SSG_MOSAIC_H

#include "graph/node.h"

/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_mosaic_output {
    SSG_MOSAIC_OUT_OUT,
    SSG_MOSAIC_OUTPUTS
};

struct ssg_mosaic_params {
    int columns;   /* 0 = about square: ceil(sqrt(images)) */
    int labels;    /* 1 = each cell's name written in its corner */
    int gap;       /* px between cells */
    int font_size; /* px; 0 = a sixteenth of the cell's height, at least 10 */
};

enum ssg_err ssg_mosaic_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io);

extern const struct ssg_node_desc ssg_node_mosaic;

#endif
