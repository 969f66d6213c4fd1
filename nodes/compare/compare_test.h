/* compare_test.h - helpers shared by the compare node's tests (test_compare*.c): a metric
 * by name from a run's outputs, an output image by name, and a seeded normal deviate for noise images. Static
 * inline functions: a test that uses one of them only compiles without a warning. */
#ifndef SSG_COMPARE_TEST_H
#define SSG_COMPARE_TEST_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "ssgraph.h"

/* The metric `name` of a compare run; a failed check (and NaN) when it was not reported. */
static inline double compare_metric(const struct ssg_outputs *out, const char *name)
{
    for (int i = 0; i < out->metric_count; i++)
        if (!strcmp(out->metric_names[i], name))
            return out->metric_values[i];
    fprintf(stderr, "metric '%s' not reported\n", name);
    CHECK(0);
    return NAN;
}

/* The image the run wrote to output `name` (ssg_node_run makes every output, on_demand
   ones too); a failed check (and NULL) when there is none. */
static inline const float *compare_output(const struct ssg_outputs *out, const char *name)
{
    for (int i = 0; i < out->count; i++)
        if (!strcmp(out->names[i], name))
            return out->images[i]->data;
    CHECK(0);
    return NULL;
}

/* A standard normal deviate (Box-Muller) from a 64-bit LCG: the same noise on every
   platform, unlike rand(). */
static inline double compare_gauss(uint64_t *state)
{
    double u[2];
    for (int i = 0; i < 2; i++) {
        *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
        u[i] = ((double)(*state >> 11) + 0.5) * (1.0 / 9007199254740992.0);
    }
    return sqrt(-2.0 * log(u[0])) * cos(2.0 * 3.14159265358979323846 * u[1]);
}

#endif
