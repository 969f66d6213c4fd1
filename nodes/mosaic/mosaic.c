/* mosaic.c - the `mosaic` node: several images side by side in one frame-sized picture,
 * each labelled with the name it was given, like the documents' figures that show the
 * methods next to each other (the thesis's figure 5.3, the hybrid paper's figure 11).
 * Scalars show as grey, vectors (normals, positions) as 0.5 + 0.5 v, colours as they are;
 * each image is scaled to fit its cell keeping its aspect ratio (area-averaged when it
 * shrinks). CPU only: it is for looking at results, not a real-time pass. */
#include <stdio.h>

#include "mosaic.h"

static const struct ssg_param_desc params[] = {
    {.name = "columns", SSG_FIELD_INT(struct ssg_mosaic_params, columns), .def = 0, .min = 0,
     .max = 16, .help = "cells a row; 0 = about square"},
    {.name = "labels", SSG_FIELD_BOOL(struct ssg_mosaic_params, labels), .def = 1,
     .help = "write each image's name in its cell (needs the DejaVu Sans font)"},
    {.name = "gap", SSG_FIELD_INT(struct ssg_mosaic_params, gap), .def = 4, .min = 0,
     .max = 256, .unit = "px", .help = "black space between cells"},
    {.name = "font_size", SSG_FIELD_INT(struct ssg_mosaic_params, font_size), .def = 0,
     .min = 0, .max = 512, .unit = "px",
     .help = "label height; 0 = a sixteenth of a cell, at least 10"},
};

static const struct ssg_port_desc outputs[] = {
    [SSG_MOSAIC_OUT_OUT] = {.name = "out", .types = SSG_T_COLOR,
     .doc = "the contact sheet, frame sized, linear RGB (write it to see it)"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_MOSAIC_OUTPUTS, "one entry a port enumerator");

const struct ssg_node_desc ssg_node_mosaic = {
    .name = "mosaic",
    .summary = "contact sheet: several images side by side, labelled",
    .method = "presentation, after the documents' side-by-side figures (Belonogov fig. 5.3, "
              "Knuth and Kohlhammer fig. 11)",
    .doc = "Lays out every extra name=node.port argument in a grid of `columns` cells (in "
           "argument order), each image scaled to fit its cell with its aspect ratio kept "
           "and its name written in the top-left corner. Scalars (AO, depth) show as grey, "
           "vectors as 0.5 + 0.5 v, colours unchanged. Example: sheet = mosaic(ssao=ao.out, "
           "hbao=h.out, truth=ref.out), then write(sheet.out, \"sheet\").",
    SSG_NODE_OUTPUTS(outputs),
    .extra_inputs = 1,
    SSG_NODE_PARAMS(params, struct ssg_mosaic_params),
    .run_cpu = ssg_mosaic_run_cpu,
};
