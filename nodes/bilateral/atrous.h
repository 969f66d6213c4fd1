/* atrous.h - the `atrous` node (atrous.c; method in atrous.md here): the edge-avoiding
 * a-trous wavelet filter, run by the bilateral node's passes (bilateral.h): one folder,
 * two descriptors, as ssdo's folder holds bounce. */
#ifndef SSG_ATROUS_H
#define SSG_ATROUS_H

#include "bilateral.h"

/* Passes at most: the footprint of n passes is 4 (2^n - 1) + 1 px wide (8: 1021 px). */
enum { SSG_ATROUS_MAX_ITERATIONS = SSG_BILATERAL_MAX_PASSES };

/* The parameters, one row each (lang/params.h): the passes, then the edge-stopping rows
   bilateral declares too. */
#define SSG_ATROUS_PARAMS(P)                                                               \
    P(INT, iterations,                                                                     \
      "passes; pass i spaces its 5 x 5 taps 2^i px apart (3: 14 px each side)", .def = 3,  \
      .min = 1, .max = SSG_ATROUS_MAX_ITERATIONS, .soft_min = 1,                           \
      .soft_max = SSG_ATROUS_MAX_ITERATIONS, .unit = "passes")                             \
    SSG_BILATERAL_EDGE_PARAMS(P)
SSG_PARAMS_STRUCT(ssg_atrous_params, SSG_ATROUS_PARAMS);

extern const struct ssg_node_desc ssg_node_atrous;

#endif
