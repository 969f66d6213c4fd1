/* test_ssdo_lengths.c - the `ssdo` node reads the rotation tile's length shift (halton
 * lengths=shifted, planes 3 and 4): each pixel's sample i keeps its direction, which the
 * light and environment weights see, and takes the length of kernel sample (i + k) mod K
 * plus dl, which places it. On tests/length_step.h's step (answers worked out there in
 * closed form), with no lights and the constant environment, the modulation of the two
 * samples of equal N.w is 1 - V_0 / 2: 0.5 exactly where the formula occludes s_0 at that
 * pixel's length, per cell of the 2 x 2 tile of test_ssao_lengths.c, else 1 (the hard
 * range check passes: the occluder lies within sqrt(0.5^2 + 2.7^2) < 3 of P). Shift
 * planes of zeros give the bits of a two-plane tile. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "graph/node.h"
#include "ssgraph.h"

#include "planes.h"
#include "ssao_planes.h"
#include "length_step.h"

static struct ssg_image *run(const struct gbuf *g, const struct ssg_image *k,
                             const struct ssg_image *tile)
{
    struct ssg_binding b[5] = {{"position", g->pos}, {"normal", g->nrm}, {"kernel", k},
                               {"rotation", tile}, {"depth", g->depth}};
    const char *sets[] = {"radius=3", "bias=0.02", "power=1"};
    struct ssg_diags diags = {0};
    struct ssg_frame f = frame();
    struct ssg_outputs out;
    enum ssg_err e = ssg_node_run("ssdo", b, 5, sets, 3, &f, &out, &diags);
    CHECK_EQ(e, SSG_OK);
    if (e != SSG_OK)
        return NULL;
    ssg_image_destroy(&out.images[1]);
    return out.images[0];
}

int main(void)
{
    W = STEP_W, H = STEP_H;
    struct gbuf g = gbuf_from_depth(step_depth, 0);
    struct ssg_image *k = step_kernel();
    static const float dl[4] = {0.125f, 0.125f, -0.125f, -0.125f}, ks[4] = {1, 0, 1, 0};
    static const double len[4] = {0.875, 0.625, 0.625, 0.375}, plain_len[1] = {0.5};
    static const float zero[1] = {0.0f};
    struct ssg_image *plain = step_tile(1, NULL, NULL), *zeros = step_tile(1, zero, zero);
    struct ssg_image *latin = step_tile(2, dl, ks);
    struct ssg_image *a = run(&g, k, plain), *b = run(&g, k, zeros), *c = run(&g, k, latin);
    if (a && b && c) {
        step_check(a, 1, plain_len);
        CHECK(memcmp(a->data, b->data, sizeof(float) * STEP_W * STEP_H) == 0);
        step_check(c, 2, len);
    }
    ssg_image_destroy(&a), ssg_image_destroy(&b), ssg_image_destroy(&c);
    ssg_image_destroy(&plain), ssg_image_destroy(&zeros), ssg_image_destroy(&latin);
    ssg_image_destroy(&k);
    release(&g);
    return check_report();
}
