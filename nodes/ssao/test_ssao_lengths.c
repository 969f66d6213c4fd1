/* test_ssao_lengths.c - the `ssao` node reads the rotation tile's length shift (halton
 * lengths=shifted, planes 3 and 4): each pixel's sample i keeps its direction and takes
 * the length of kernel sample (i + k) mod K plus dl. On tests/length_step.h's step
 * (answers worked out there in closed form), the modes that place points (hemisphere,
 * sphere) land each far-wall pixel's samples where the formula says for that pixel's
 * cell: a 2 x 2 tile of offsets +-1/8 and shifts 0 and 1 gives sample 0 the lengths
 * 0.75 + 1/8, 0.5 + 1/8, 0.75 - 1/8 and 0.5 - 1/8. The sphere's reflected samples lie
 * just behind the walls (depth 5 + 3 l 0.04 - bias > 5 for l >= 0.25) and land on them, on
 * screen wherever s_0 can be occluded (x >= 30, -s_0 lands at x - 11 or more): both
 * are occluded there, so clamp(2 - occluded / 2, 0, 1) reads 1 - V_0 / 2 as the
 * hemisphere's 1 - occluded / 2 does. In every mode (disc too, whose clamp hides one
 * sample's answer) shift planes of zeros give the bits of a two-plane tile. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "graph/node.h"
#include "ssgraph.h"

#include "planes.h"
#include "ssao_planes.h"
#include "length_step.h"

/* The 2 x 2 tile's shifts and sample 0's length in each cell (length_step.h). */
static const float tile_dl[4] = {0.125f, 0.125f, -0.125f, -0.125f};
static const float tile_k[4] = {1.0f, 0.0f, 1.0f, 0.0f};
static const double tile_len[4] = {0.875, 0.625, 0.625, 0.375};
static const double plain_len[1] = {0.5};

static struct ssg_image *run(const struct gbuf *g, const struct ssg_image *k,
                             const struct ssg_image *tile, const char *mode)
{
    const char *sets[] = {"radius=3", "range_check=none", mode};
    return ssao(g, k, tile, 1, sets, 3);
}

static void test_mode(const struct gbuf *g, const struct ssg_image *k, const char *mode,
                      int closed_form)
{
    static const float zero[1] = {0.0f};
    struct ssg_image *plain = step_tile(1, NULL, NULL), *zeros = step_tile(1, zero, zero);
    struct ssg_image *latin = step_tile(2, tile_dl, tile_k);
    struct ssg_image *a = run(g, k, plain, mode), *b = run(g, k, zeros, mode);
    struct ssg_image *c = run(g, k, latin, mode);
    if (a && b && c) {
        CHECK(memcmp(a->data, b->data, sizeof(float) * STEP_W * STEP_H) == 0);
        if (closed_form) {
            step_check(a, 1, plain_len);
            step_check(c, 2, tile_len);
        }
    }
    ssg_image_destroy(&a), ssg_image_destroy(&b), ssg_image_destroy(&c);
    ssg_image_destroy(&plain), ssg_image_destroy(&zeros), ssg_image_destroy(&latin);
}

int main(void)
{
    W = STEP_W, H = STEP_H;
    struct gbuf g = gbuf_from_depth(step_depth, 0);
    struct ssg_image *k = step_kernel();
    test_mode(&g, k, "mode=hemisphere", 1);
    test_mode(&g, k, "mode=sphere", 1);
    test_mode(&g, k, "mode=disc", 0);
    ssg_image_destroy(&k);
    release(&g);
    return check_report();
}
