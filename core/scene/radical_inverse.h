/* radical_inverse.h - the radical inverse behind every Halton point of ssgraph: the
 * `halton` node's kernels and rotation tiles (nodes/halton), the importance-sampled
 * directions of the environment's lights (env_lights.c) and the sub-pixel offsets of a
 * graph's `jitter` line (core/graph/graph_time.c). Szentandrasi, section 4.2, eq. 5
 * and 6; the sequence itself is in nodes/halton/README.md. Pure and thread-safe. */
#ifndef SSG_RADICAL_INVERSE_H
#define SSG_RADICAL_INVERSE_H

#include <stdint.h>

/* Radical inverse Phi_b(i) of eq. 6: the base-b digits of i (eq. 5) mirrored about the
 * radix point. Exact (correctly rounded) for i < 2^32 and b <= 1000. */
static inline double ssg_halton_radical_inverse(uint64_t i, int base)
{
    /* Mirror the digits into an integer numerator over base^digits and divide once, so
       the result is the correctly rounded value of eq. 6 rather than a sum of rounded
       powers. */
    uint64_t b = (uint64_t)base, num = 0, den = 1;
    while (i > 0) {
        num = num * b + i % b;
        den *= b;
        i /= b;
    }
    return (double)num / (double)den;
}

#endif
