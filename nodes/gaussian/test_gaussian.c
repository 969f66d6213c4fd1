/* test_gaussian.c - the `gaussian` node against its definition: out(x, y) =
 * sum_{i,j} w_i w_j in(clamp(x + i), clamp(y + j)), w_i = exp(-i^2 / (2 sigma^2)) /
 * sum_k exp(-k^2 / (2 sigma^2)) over |i| <= radius, radius = (size - 1) / 2 with
 * size = 2 ceil(3 sigma) + 1 unless given. The weights are computed here in double,
 * independently of the node. */
#include <math.h>
#include <omp.h>
#include <string.h>

#include "check.h"
#include "ssgraph.h"

enum { W = 48, H = 40 };

/* The normalised weights of offsets -radius..radius into w[0..2 radius]. */
static int weights(double sigma, int size, double *w)
{
    int radius = size > 0 ? (size - 1) / 2 : (int)ceil(3 * sigma);
    double sum = 0;
    for (int i = -radius; i <= radius; i++)
        sum += w[i + radius] = exp(-0.5 * i * i / (sigma * sigma));
    for (int i = 0; i <= 2 * radius; i++)
        w[i] /= sum;
    return radius;
}

/* Runs gaussian on `in`; returns the output (owned) or NULL. */
static struct ssg_image *blur(const struct ssg_image *in, const char *const *sets, int n)
{
    struct ssg_binding b[1] = {{"in", in}};
    struct ssg_diags diags = {0};
    struct ssg_frame f = {W, H, 45.0f, 0.05f, 100.0f, 1, 0, 0, 0};
    struct ssg_outputs out;
    enum ssg_err e = ssg_node_run("gaussian", b, 1, sets, n, &f, &out, &diags);
    CHECK_EQ(e, SSG_OK);
    if (e != SSG_OK) {
        ssg_diags_print(&diags, stderr);
        return NULL;
    }
    CHECK_EQ(out.count, 1);
    return out.images[0];
}

/* A constant stays constant (the weights sum to 1 up to float rounding of the taps),
   in every channel of a 3-channel image, borders included. */
static void test_constant(void)
{
    struct ssg_image *in = ssg_image_create(W, H, 3);
    static const float value[3] = {0.25f, 1.0f, 7.5f};
    for (int c = 0; c < 3; c++)
        for (int i = 0; i < W * H; i++)
            in->data[c * W * H + i] = value[c];
    const char *sets[] = {"sigma=2.5"};
    struct ssg_image *out = blur(in, sets, 1);
    if (out) {
        CHECK_EQ(out->channels, 3);
        double worst = 0;
        for (int c = 0; c < 3; c++)
            for (int i = 0; i < W * H; i++)
                worst = fmax(worst, fabs(out->data[c * W * H + i] - value[c]) / value[c]);
        CHECK(worst < 2e-6);
    }
    ssg_image_destroy(&in);
    ssg_image_destroy(&out);
}

/* An impulse away from the borders gives the separable product of the normalised
   weights, exactly 0 outside the window, and keeps its sum. For the default size
   (sigma 2: 13 taps) and a given one (size 5: 5 taps renormalised). */
static void test_impulse(void)
{
    struct ssg_image *in = ssg_image_create(W, H, 1);
    const int x0 = 20, y0 = 17;
    in->data[y0 * W + x0] = 1.0f;
    static const char *const variants[][2] = {{"sigma=2", "size=0"}, {"sigma=2", "size=5"}};
    static const int sizes[] = {0, 5};
    for (int v = 0; v < 2; v++) {
        struct ssg_image *out = blur(in, variants[v], 2);
        if (!out)
            continue;
        double w[64];
        int radius = weights(2.0, sizes[v], w);
        CHECK_EQ(radius, v ? 2 : 6);
        double sum = 0, worst = 0;
        int outside_zero = 1;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                double o = out->data[y * W + x];
                int dx = x - x0, dy = y - y0;
                sum += o;
                if (abs(dx) > radius || abs(dy) > radius) {
                    outside_zero &= o == 0.0;
                    continue;
                }
                double want = w[dx + radius] * w[dy + radius];
                worst = fmax(worst, fabs(o - want) / want);
            }
        CHECK(outside_zero);
        CHECK(worst < 1e-6);
        CHECK_NEAR(sum, 1.0, 1e-6);
        ssg_image_destroy(&out);
    }
    ssg_image_destroy(&in);
}

/* Clamp to edge: an impulse in the corner pixel is repeated beyond the border, so
   out(x, y) = (sum_{k <= -x} w_k) (sum_{k <= -y} w_k) near it. */
static void test_edges(void)
{
    struct ssg_image *in = ssg_image_create(W, H, 1);
    in->data[0] = 1.0f;
    const char *sets[] = {"sigma=1.5"};
    struct ssg_image *out = blur(in, sets, 1);
    double w[64];
    int radius = weights(1.5, 0, w);
    if (out) {
        double worst = 0;
        for (int y = 0; y <= radius; y++)
            for (int x = 0; x <= radius; x++) {
                double cx = 0, cy = 0;
                for (int k = -radius; k <= -x; k++)
                    cx += w[k + radius];
                for (int k = -radius; k <= -y; k++)
                    cy += w[k + radius];
                worst = fmax(worst, fabs(out->data[y * W + x] - cx * cy) / (cx * cy));
            }
        CHECK(worst < 1e-6);
        CHECK_EQ(out->data[(radius + 1) * W], 0.0f);
    }
    ssg_image_destroy(&in);
    ssg_image_destroy(&out);
}

/* 1 and 2 threads give the same bytes. */
static void test_threads(void)
{
    struct ssg_image *in = ssg_image_create(W, H, 3);
    for (int i = 0; i < 3 * W * H; i++)
        in->data[i] = (float)((i * 7919) % 1000) / 1000.0f;
    const char *sets[] = {"sigma=3"};
    omp_set_num_threads(1);
    struct ssg_image *one = blur(in, sets, 1);
    omp_set_num_threads(2);
    struct ssg_image *two = blur(in, sets, 1);
    if (one && two)
        CHECK(memcmp(one->data, two->data, sizeof(float) * 3 * W * H) == 0);
    ssg_image_destroy(&in);
    ssg_image_destroy(&one);
    ssg_image_destroy(&two);
}

/* An even window and a zero sigma are refused with a code. */
static void test_rejects(void)
{
    struct ssg_image *in = ssg_image_create(8, 8, 1);
    struct ssg_binding b[1] = {{"in", in}};
    struct ssg_frame f = {8, 8, 45.0f, 0.05f, 100.0f, 1, 0, 0, 0};
    struct ssg_outputs out;
    struct ssg_diags diags = {0};
    const char *even[] = {"size=4"};
    CHECK_EQ(ssg_node_run("gaussian", b, 1, even, 1, &f, &out, &diags), SSG_E_VALUE);
    ssg_outputs_release(&out);
    const char *zero[] = {"sigma=0"};
    CHECK_EQ(ssg_node_run("gaussian", b, 1, zero, 1, &f, &out, &diags), SSG_E_RANGE);
    ssg_outputs_release(&out);
    ssg_image_destroy(&in);
}

int main(void)
{
    test_constant();
    test_impulse();
    test_edges();
    test_threads();
    test_rejects();
    return check_report();
}
