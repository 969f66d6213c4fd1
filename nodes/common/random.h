/* random.h - the one small pseudo-random generator of ssgraph, for seed-derived choices
 * made once in prepare() (pattern shifts and permutations), never per pixel. */
#ifndef SSG_RANDOM_H
#define SSG_RANDOM_H

#include <stdint.h>

/* SplitMix64 (Steele et al. 2014): tiny and well mixed; advances *state. */
static inline uint64_t ssg_splitmix64(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* A uniform double in [0, 1) from the generator. */
static inline double ssg_random_unit(uint64_t *state)
{
    return (double)(ssg_splitmix64(state) >> 11) * 0x1.0p-53;
}

/* perm[0..n) = a seeded random permutation of 0..n-1 (Fisher-Yates). */
static inline void ssg_random_permutation(uint64_t *state, int *perm, int n)
{
    for (int k = 0; k < n; k++)
        perm[k] = k;
    for (int k = n - 1; k > 0; k--) {
        int j = (int)(ssg_splitmix64(state) % (uint64_t)(k + 1));
        int tmp = perm[k];
        perm[k] = perm[j];
        perm[j] = tmp;
    }
}

#endif
