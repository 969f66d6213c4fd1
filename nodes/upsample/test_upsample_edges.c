/* test_upsample_edges.c - `upsample` where surfaces slant and meet at an edge: a tap's
 * spatial weight is measured from the full-res pixel its sample was taken at, its depth
 * term against the pixel's own plane (README.md), worked by hand on a steep 4 x 4 plane;
 * and a slanted depth step between two tilted planes, brought down by `downsample`, comes
 * back with every pixel holding exactly its own side's value: no staircase along the
 * diagonal, no blend across it. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "ssgraph.h"

/* Runs upsample (no normals) on the given images with `sets`; NULL on failure. */
static struct ssg_image *run_upsample(struct ssg_image *in, struct ssg_image *depth,
                                      struct ssg_image *low_depth, const char *const *sets,
                                      int set_count)
{
    struct ssg_binding b[3] = {{"in", in}, {"depth", depth}, {"low_depth", low_depth}};
    struct ssg_diags diags = {0};
    struct ssg_outputs out;
    enum ssg_err e = ssg_node_run("upsample", b, 3, sets, set_count, NULL, &out, &diags);
    CHECK_EQ(e, SSG_OK);
    if (e != SSG_OK) {
        ssg_diags_print(&diags, stderr);
        return NULL;
    }
    struct ssg_image *first = out.images[0];
    out.images[0] = NULL;
    ssg_outputs_release(&out);
    return first;
}

/* A 4 x 4 plane of depth 1 + 0.25 x + 0.125 y (a steep one: 20 % a pixel), factor 2. Each
   low-res pixel was taken at the block pixel nearest the middle of the frame, (1,1),
   (2,1), (1,2), (2,2): its depth is that pixel's, 1.375, 1.625, 1.5, 1.75 (each once in its
   block, so that is where upsample finds it), its value 0, 1, 2, 3. Every slope is exact
   (0.25 and 0.125), so each tap lies on the pixel's plane: the depth term is 1 and only
   the spatial Gaussian weighs, sigma 1 low-res px = 2 full-res px, e^(-r^2 / 8). Pixel
   (1,1) is 0, 1, 1, 2 px^2 from the four samples: weights 1, e^-1/8, e^-1/8, e^-1/4, so
   out = (3 e^-1/8 + 3 e^-1/4) / (1 + 2 e^-1/8 + e^-1/4) = 4.983893 / 3.543795 = 1.406372;
   pixel (2,2) mirrors it, 3 - 1.406372 = 1.593628. The block-centre grid and the depth
   compared with the pixel's own (the method before) give 0.260 and 2.556 here: a tap on
   the slant 0.25 deeper than the pixel weighs e^-6.6 there. */
static void test_slanted_plane(void)
{
    struct ssg_image *depth = ssg_image_create(4, 4, 1), *in = ssg_image_create(2, 2, 1);
    struct ssg_image *low_depth = ssg_image_create(2, 2, 1);
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++)
            depth->data[y * 4 + x] = 1.0f + 0.25f * (float)x + 0.125f * (float)y;
    static const float low[4] = {1.375f, 1.625f, 1.5f, 1.75f}, values[4] = {0, 1, 2, 3};
    memcpy(low_depth->data, low, sizeof low);
    memcpy(in->data, values, sizeof values);
    struct ssg_image *out = run_upsample(in, depth, low_depth, NULL, 0);
    if (out) {
        CHECK_NEAR(out->data[1 * 4 + 1], 1.406372, 1e-5);
        CHECK_NEAR(out->data[2 * 4 + 2], 1.593628, 1e-5);
    }
    ssg_image_destroy(&out);
    ssg_image_destroy(&depth);
    ssg_image_destroy(&in);
    ssg_image_destroy(&low_depth);
}

/* A near plane (depth 1 + 0.02 x + 0.01 y, value 0) in front of a far one (3 + 0.05 y,
   value 1), the edge a slope of 3 in 5 (y < 0.6 x + 3: the near side above), so that the
   2 x 2 blocks straddle it in every phase. The low-res depth is `downsample`'s, the value
   follows it (0 where the low depth is below 2). Across the edge the depth differs by at
   least 1.5 (the far plane is 3 or more, the near at most 1.7), so a tap across weighs
   below 1e-30 and every full-res pixel is exactly its own side's value (to float rounding,
   1e-6) along the whole diagonal. Two pixels at the image border, (0,3) far and (29,20)
   near, have along x only a neighbour across the edge: that difference (-2.1, -2.22) is
   steeper than a quarter of their depth, so their plane counts as flat; taken as their
   slope it would put the other side's taps on their plane and blend them in (0.54 and 1
   there). With the depth term off (sigma_depth 1000) the edge blurs: the test can fail. */
static void test_diagonal_step(void)
{
    enum { W = 30, H = 24 };
    struct ssg_image *depth = ssg_image_create(W, H, 1);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int near = 5 * y < 3 * x + 15;
            depth->data[y * W + x] = near ? 1.0f + 0.02f * (float)x + 0.01f * (float)y
                                          : 3.0f + 0.05f * (float)y;
        }
    struct ssg_binding b[1] = {{"depth", depth}};
    struct ssg_diags diags = {0};
    struct ssg_outputs low;
    CHECK_EQ(ssg_node_run("downsample", b, 1, NULL, 0, NULL, &low, &diags), SSG_OK);
    struct ssg_image *low_depth = low.images[0];
    low.images[0] = NULL;
    ssg_outputs_release(&low);
    int lw = low_depth->width, lh = low_depth->height;
    struct ssg_image *in = ssg_image_create(lw, lh, 1);
    for (int i = 0; i < lw * lh; i++)
        in->data[i] = low_depth->data[i] < 2.0f ? 0.0f : 1.0f;
    struct ssg_image *out = run_upsample(in, depth, low_depth, NULL, 0);
    const char *loose[] = {"sigma_depth=1000"};
    struct ssg_image *blur = run_upsample(in, depth, low_depth, loose, 1);
    if (out && blur) {
        double worst = 0, blurred = 0;
        for (int i = 0; i < W * H; i++) {
            double want = depth->data[i] < 2.0f ? 0.0 : 1.0;
            worst = fmax(worst, fabs(out->data[i] - want));
            blurred = fmax(blurred, fabs(blur->data[i] - want));
        }
        CHECK(worst < 1e-6);
        CHECK(blurred > 0.1);
    }
    ssg_image_destroy(&out);
    ssg_image_destroy(&blur);
    ssg_image_destroy(&in);
    ssg_image_destroy(&low_depth);
    ssg_image_destroy(&depth);
}

int main(void)
{
    test_slanted_plane();
    test_diagonal_step();
    return check_report();
}
