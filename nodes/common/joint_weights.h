/* joint_weights.h - what the geometry-aware (joint bilateral) filters, `bilateral`,
 * `atrous` and `upsample`, derive alike from their parameters in prepare(): the window
 * radius, the spatial Gaussian as a log-weight per px^2, the depth term's scale, how the
 * normal term's power is taken and the smallest normal cosine that still weighs more
 * than 1e-30. Both backends read these from the consts; neither recomputes one. */
#ifndef SSG_JOINT_WEIGHTS_H
#define SSG_JOINT_WEIGHTS_H

#include <math.h>

struct ssg_joint_weights {
    int radius;        /* (size - 1) / 2 */
    float spatial_k;   /* -0.5 / sigma_spatial^2: ln of the spatial weight per px^2 */
    float depth_scale; /* 1 / sigma_depth */
    float normal_min;  /* cosines below this weigh c^normal_power < 1e-30: 0 */
    int squarings;     /* ssg_joint_squarings(normal_power): c^p by that many squarings,
                          -1 = p ln(c) in the exponent */
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

/* Fills w from the filter's parameters (sigma_spatial 0 = size / 3), which the parameter
 * tables hold in range (size 1..max, sigma_depth > 0, sigma_spatial >= 0, normal_power
 * 0..127) and check() keeps odd. */
static inline void ssg_joint_weights_make(int size, float sigma_spatial, float sigma_depth,
                                          int normal_power, struct ssg_joint_weights *w)
{
    float sigma = sigma_spatial > 0 ? sigma_spatial : (float)size / 3.0f;
    w->radius = (size - 1) / 2;
    w->spatial_k = -0.5f / (sigma * sigma);
    w->depth_scale = 1.0f / sigma_depth;
    w->normal_min = normal_power > 0 ? (float)pow(1e-30, 1.0 / normal_power) : 0.0f;
    w->squarings = ssg_joint_squarings(normal_power);
}

#endif
