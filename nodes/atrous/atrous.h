/* atrous.h - the `atrous` node (atrous.c): the edge-avoiding a-trous wavelet filter, run by
 * the bilateral node's passes (nodes/bilateral/bilateral.h). */
#ifndef SSG_ATROUS_H
#define SSG_ATROUS_H

#include "bilateral/bilateral.h"

/* Passes at most: the footprint of n passes is 4 (2^n - 1) + 1 px wide (8: 1021 px). */
enum { SSG_ATROUS_MAX_ITERATIONS = SSG_BILATERAL_MAX_PASSES };

struct ssg_atrous_params {
    int iterations;    /* passes, 1..8, tap spacing 1, 2, 4, ... px; default 3 */
    float sigma_depth; /* depth difference as a fraction of the centre depth; default 0.05 */
    int normal_power;  /* p of max(0, n.n')^p, 0..127, 0 = no normal term; default 16 */
};

extern const struct ssg_node_desc ssg_node_atrous;

#endif
