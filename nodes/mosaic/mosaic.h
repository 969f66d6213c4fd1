/* mosaic.h - ports and parameters of the `mosaic` node, shared by mosaic.c (descriptor)
 * and mosaic_cpu.c (layout and resampling): a contact sheet of several images. Method in
 * README.md. */
#ifndef SSG_MOSAIC_H
#define SSG_MOSAIC_H

#include "graph/node.h"

/* Ports, one row each (node.h); the images come as extra name=node.port inputs. */
#define SSG_MOSAIC_OUT(X)                                                                  \
    X(SSG_MOSAIC_OUT_OUT, "out", SSG_T_COLOR,                                              \
      "the contact sheet, frame sized, linear RGB (write it to see it)")
SSG_PORT_ENUM(ssg_mosaic_output, SSG_MOSAIC_OUT, SSG_MOSAIC_OUTPUTS);

/* The parameters, one row each (lang/params.h); the struct below and the table in
   mosaic.c are made from these rows. */
#define SSG_MOSAIC_PARAMS(P)                                                               \
    P(INT, columns, "cells a row; 0 = about square", .def = 0, .min = 0, .max = 16,        \
      .soft_min = 0, .soft_max = 16)                                                       \
    P(BOOL, labels, "write each image's name in its cell (needs the DejaVu Sans font)",    \
      .def = 1)                                                                            \
    P(INT, gap, "black space between cells", .def = 4, .min = 0, .max = 256,               \
      .soft_min = 0, .soft_max = 32, .unit = "px")                                         \
    P(INT, font_size, "label height; 0 = a sixteenth of a cell, at least 10", .def = 0,    \
      .min = 0, .max = 512, .soft_min = 0, .soft_max = 64, .unit = "px")
SSG_PARAMS_STRUCT(ssg_mosaic_params, SSG_MOSAIC_PARAMS);

enum ssg_err ssg_mosaic_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io);

extern const struct ssg_node_desc ssg_node_mosaic;

#endif
