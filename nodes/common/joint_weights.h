/* joint_weights.h - what the two geometry-aware (joint bilateral) filters, `bilateral` and
 * `upsample`, derive alike from their parameters in prepare(): the window radius, the
 * spatial Gaussian as a log-weight per px^2, the depth term's scale and the smallest
 * normal cosine that still weighs more than 1e-30. */
#ifndef SSG_JOINT_WEIGHTS_H
#define SSG_JOINT_WEIGHTS_H

#include <math.h>

struct ssg_joint_weights {
    int radius;        /* (size - 1) / 2 */
    float spatial_k;   /* -0.5 / sigma_spatial^2: ln of the spatial weight per px^2 */
    float depth_scale; /* 1 / sigma_depth */
    float normal_min;  /* cosines below this weigh c^normal_power < 1e-30: 0 */
};

/* The squarings that make `power` (a power of two up to 64), else -1: c^p by that many
   squarings of c is cheaper than exp(p ln c) and exact to an ulp or two; any other power
   goes through p ln(c) added to the exponent. */
static inline int ssg_joint_squarings(int power)
{
    for (int m = 0; m < 7; m++)
        if (power == 1 << m)
            return m;
    return -1;
}

/* Flops of one tap's weight, for the filters' flops_per_pixel (node.h), by reading
   bilateral_cpu.c and upsample_cpu.c: about 17 for the depth and spatial terms, the
   polynomial exp and the weight sum; with normals 6 more for the cosine and its squarings,
   or 14 through a log for other powers. The channels' sums are the caller's. */
static inline double ssg_joint_tap_flops(int normals, int power)
{
    if (!normals || power <= 0)
        return 17.0;
    return 17.0 + (ssg_joint_squarings(power) >= 0 ? 6.0 : 14.0);
}

/* Fills w from the filter's parameters (sigma_spatial 0 = size / 3); 0 when they are out of
 * range (size odd in 1..max_size, sigma_depth > 0, sigma_spatial >= 0, normal_power
 * 0..127): prepare() may be reached without the table's checks (a hand-built run). */
static inline int ssg_joint_weights_make(int size, int max_size, float sigma_spatial,
                                         float sigma_depth, int normal_power,
                                         struct ssg_joint_weights *w)
{
    if (size < 1 || size > max_size || size % 2 == 0 || !(sigma_depth > 0) ||
        !(sigma_spatial >= 0) || normal_power < 0 || normal_power > 127)
        return 0;
    float sigma = sigma_spatial > 0 ? sigma_spatial : (float)size / 3.0f;
    w->radius = (size - 1) / 2;
    w->spatial_k = -0.5f / (sigma * sigma);
    w->depth_scale = 1.0f / sigma_depth;
    w->normal_min = normal_power > 0 ? (float)pow(1e-30, 1.0 / normal_power) : 0.0f;
    return 1;
}

#endif
