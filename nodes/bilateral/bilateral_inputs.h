/* bilateral_inputs.h - the images and helpers the bilateral tests share: in, depth and
 * normal planes of one size, a unit normal setter, one run of the node, and deterministic
 * uniform and Gaussian numbers. */
#ifndef SSG_TEST_BILATERAL_INPUTS_H
#define SSG_TEST_BILATERAL_INPUTS_H

#include <math.h>
#include <stdint.h>

#include "check.h"
#include "ssgraph.h"

struct images {
    struct ssg_image *in, *depth, *normal;
};

static inline struct images make(int w, int h, int channels)
{
    struct images im = {ssg_image_create(w, h, channels), ssg_image_create(w, h, 1),
                        ssg_image_create(w, h, 3)};
    return im;
}

static inline void release(struct images *im)
{
    ssg_image_destroy(&im->in);
    ssg_image_destroy(&im->depth);
    ssg_image_destroy(&im->normal);
}

static inline void set_normal(struct ssg_image *n, size_t o, double x, double y, double z)
{
    double len = sqrt(x * x + y * y + z * z);
    size_t plane = (size_t)n->width * (size_t)n->height;
    n->data[o] = (float)(x / len);
    n->data[plane + o] = (float)(y / len);
    n->data[2 * plane + o] = (float)(z / len);
}

/* A depth step (1 | 2) carrying a value step (0 | 1) at the middle column, normals +z. */
static inline void fill_depth_step(struct images *im)
{
    const int w = im->in->width, h = im->in->height;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t o = (size_t)y * (size_t)w + (size_t)x;
            im->in->data[o] = x < w / 2 ? 0.0f : 1.0f;
            im->depth->data[o] = x < w / 2 ? 1.0f : 2.0f;
            set_normal(im->normal, o, 0, 0, 1);
        }
}

/* Runs bilateral; returns the output (owned) or NULL. with_normal = 0 leaves the normal
   input unconnected. */
static inline struct ssg_image *filter(const struct images *im, int with_normal,
                                const char *const *sets, int set_count)
{
    struct ssg_binding b[3] = {{"in", im->in}, {"depth", im->depth}, {"normal", im->normal}};
    struct ssg_diags diags = {0};
    struct ssg_outputs out;
    enum ssg_err e = ssg_node_run("bilateral", b, with_normal ? 3 : 2, sets, set_count, NULL,
                                  &out, &diags);
    CHECK_EQ(e, SSG_OK);
    if (e != SSG_OK) {
        ssg_diags_print(&diags, stderr);
        return NULL;
    }
    ssg_image_destroy(&out.images[1]); /* out2: in2 is not connected here */
    return out.images[0];
}

/* Deterministic N(0, 1) numbers: a 64-bit LCG and Box-Muller. */
static uint64_t rng_state = 12345;
static inline double uniform01(void)
{
    rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
    return ((double)(rng_state >> 11) + 0.5) * 0x1.0p-53;
}
static inline double gaussian(void)
{
    return sqrt(-2 * log(uniform01())) * cos(6.283185307179586 * uniform01()) /* 2 pi */;
}

#endif
