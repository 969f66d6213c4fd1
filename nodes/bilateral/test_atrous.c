/* test_atrous.c - the `atrous` node (edge-avoiding a-trous wavelet filter):
 * - one pass: the centre is the weighted mean of the documented weights (B3 spline x
 *   relative depth Gaussian x normal power);
 * - on flat, equal geometry the passes are plain convolutions: an impulse comes out as the
 *   B3 kernel convolved with its 2-px dilation (two passes), exactly;
 * - constants stay constant, depth steps are not blurred across (three passes reach 14 px),
 *   background passes through;
 * - noise on a flat region drops by the factor the passes' combined kernel predicts;
 * - in2 gives out2 bit for bit as a run on in2 alone; the thread count changes nothing;
 * - bad parameters are refused. */
#include <math.h>
#include <omp.h>
#include <string.h>

#include "check.h"
#include "graph/node.h"
#include "ssgraph.h"

#include "bilateral_inputs.h"

static const double B3[5] = {1 / 16.0, 4 / 16.0, 6 / 16.0, 4 / 16.0, 1 / 16.0};

/* Runs atrous on im (normals connected); out2 too when in2 is given. */
static struct ssg_image *atrous(const struct images *im, const struct ssg_image *in2,
                                const char *const *sets, int set_count,
                                struct ssg_image **out2)
{
    struct ssg_binding b[4] = {{"in", im->in}, {"depth", im->depth}, {"normal", im->normal},
                               {"in2", in2}};
    struct ssg_diags diags = {0};
    struct ssg_outputs out;
    enum ssg_err e = ssg_node_run("atrous", b, in2 ? 4 : 3, sets, set_count, NULL, &out,
                                  &diags);
    CHECK_EQ(e, SSG_OK);
    if (e != SSG_OK) {
        ssg_diags_print(&diags, stderr);
        return NULL;
    }
    if (out2)
        *out2 = out.images[1];
    else
        ssg_image_destroy(&out.images[1]);
    return out.images[0];
}

/* Flat geometry: depth 2 everywhere, normals +z. */
static struct images flat(int w, int h)
{
    struct images im = make(w, h, 1);
    for (size_t o = 0; o < (size_t)w * h; o++) {
        im.depth->data[o] = 2.0f;
        set_normal(im.normal, o, 0, 0, 1);
    }
    return im;
}

/* 5 x 5, one pass: the centre against the weights computed here in double. */
static void test_weights(void)
{
    struct images im = make(5, 5, 1);
    for (int y = 0; y < 5; y++)
        for (int x = 0; x < 5; x++) {
            size_t o = (size_t)y * 5 + (size_t)x;
            im.in->data[o] = (float)(0.1 * x + 0.37 * y * y);
            im.depth->data[o] = (float)(2.0 + 0.03 * x - 0.02 * y);
            set_normal(im.normal, o, 0.1 * (x - 2), 0.05 * y, 1.0);
        }
    const char *sets[] = {"iterations=1", "sigma_depth=0.05", "normal_power=4"};
    struct ssg_image *out = atrous(&im, NULL, sets, 3, NULL);
    if (out) {
        double num = 0, den = 0, dc = im.depth->data[12];
        const float *n = im.normal->data;
        for (int y = 0; y < 5; y++)
            for (int x = 0; x < 5; x++) {
                size_t o = (size_t)y * 5 + (size_t)x;
                double dd = im.depth->data[o] - dc;
                double c = (double)n[12] * n[o] + (double)n[25 + 12] * n[25 + o] +
                           (double)n[50 + 12] * n[50 + o];
                double w = B3[x] * B3[y] * exp(-0.5 * pow(dd / (0.05 * dc), 2)) * pow(c, 4);
                num += w * im.in->data[o];
                den += w;
            }
        /* the CPU's exp is a polynomial good to a few 1e-7 relative */
        CHECK_NEAR(out->data[12], num / den, 1e-5);
    }
    ssg_image_destroy(&out);
    release(&im);
}

/* Two passes on an impulse, flat geometry, far from the borders: out = (h x h) convolved
   with its dilation by 2, h the B3 spline, separable in x and y. */
static void test_impulse(void)
{
    enum { W = 33, H = 33, C = 16 };
    struct images im = flat(W, H);
    memset(im.in->data, 0, sizeof(float) * W * H);
    im.in->data[C * W + C] = 1.0f;
    double k1[13] = {0}; /* h convolved with h dilated by 2: support -6 .. 6 */
    for (int a = -2; a <= 2; a++)
        for (int b = -2; b <= 2; b++)
            k1[a + 2 * b + 6] += B3[a + 2] * B3[b + 2];
    const char *sets[] = {"iterations=2"};
    struct ssg_image *out = atrous(&im, NULL, sets, 1, NULL);
    if (out) {
        double worst = 0, total = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int dx = x - C, dy = y - C;
                double want = abs(dx) <= 6 && abs(dy) <= 6 ? k1[dx + 6] * k1[dy + 6] : 0.0;
                worst = fmax(worst, fabs(out->data[y * W + x] - want));
                total += out->data[y * W + x];
            }
        CHECK(worst < 1e-7);
        CHECK_NEAR(total, 1.0, 1e-6);
    }
    ssg_image_destroy(&out);
    release(&im);
}

/* A constant on curved geometry stays constant; a value step on a depth step (1 | 2) does
   not cross it in three passes, which reach 14 px; without the depth term it does. */
static void test_constant_and_step(void)
{
    enum { W = 48, H = 20 };
    struct images im = make(W, H, 1);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t o = (size_t)y * W + (size_t)x;
            im.in->data[o] = 0.42f;
            im.depth->data[o] = (float)(2.0 + 0.03 * x + 0.01 * y * y);
            set_normal(im.normal, o, sin(0.1 * x), 0.2, 1.0);
        }
    struct ssg_image *out = atrous(&im, NULL, NULL, 0, NULL);
    double worst = 0;
    for (size_t o = 0; out && o < (size_t)W * H; o++)
        worst = fmax(worst, fabs(out->data[o] - 0.42));
    CHECK(out && worst < 1e-6);
    ssg_image_destroy(&out);
    fill_depth_step(&im);
    out = atrous(&im, NULL, NULL, 0, NULL);
    worst = 0;
    for (size_t o = 0; out && o < (size_t)W * H; o++)
        worst = fmax(worst, fabs(out->data[o] - im.in->data[o]));
    CHECK(out && worst < 1e-6);
    const char *loose[] = {"sigma_depth=1000"};
    struct ssg_image *blur = atrous(&im, NULL, loose, 1, NULL);
    CHECK(blur && blur->data[(H / 2) * W + W / 2 - 3] > 0.05f); /* the test can fail */
    ssg_image_destroy(&out);
    ssg_image_destroy(&blur);
    release(&im);
}

/* Background (depth 0) passes through untouched and lends nothing to its neighbours. */
static void test_background(void)
{
    enum { W = 24, H = 24 };
    struct images im = flat(W, H);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t o = (size_t)y * W + (size_t)x;
            int hole = x >= 8 && x < 16;
            im.depth->data[o] = hole ? 0.0f : 2.0f;
            im.in->data[o] = hole ? 7.0f : 0.25f;
        }
    struct ssg_image *out = atrous(&im, NULL, NULL, 0, NULL);
    double worst = 0;
    for (size_t o = 0; out && o < (size_t)W * H; o++)
        worst = fmax(worst, fabs(out->data[o] - im.in->data[o]));
    CHECK(out && worst < 1e-6);
    ssg_image_destroy(&out);
    release(&im);
}

/* i.i.d. noise on flat geometry: the passes are one linear filter K (the B3 spline
   convolved with its 2- and 4-px dilations, per axis), so the variance drops to
   s^2 sum K^2 away from the borders. */
static void test_noise(void)
{
    enum { W = 256, H = 256, R = 14 };
    const double s = 0.1;
    struct images im = flat(W, H);
    for (size_t o = 0; o < (size_t)W * H; o++)
        im.in->data[o] = (float)(0.5 + s * gaussian());
    double k[2 * R + 1] = {0}, k2[2 * R + 1] = {0};
    k[R] = 1.0;
    for (int pass = 0; pass < 3; pass++) {
        memset(k2, 0, sizeof k2);
        for (int x = -R; x <= R; x++)
            for (int t = -2; t <= 2; t++) {
                int from = x - t * (1 << pass);
                if (from >= -R && from <= R)
                    k2[x + R] += B3[t + 2] * k[from + R];
            }
        memcpy(k, k2, sizeof k);
    }
    double sum2 = 0;
    for (int x = 0; x <= 2 * R; x++)
        sum2 += k[x] * k[x];
    double factor = sum2 * sum2; /* the 2D kernel is the product of two such */
    struct ssg_image *out = atrous(&im, NULL, NULL, 0, NULL);
    if (out) {
        double mean = 0, var = 0;
        int n = 0;
        for (int y = R; y < H - R; y++)
            for (int x = R; x < W - R; x++)
                mean += out->data[y * W + x], n++;
        mean /= n;
        for (int y = R; y < H - R; y++)
            for (int x = R; x < W - R; x++)
                var += pow(out->data[y * W + x] - mean, 2);
        var /= n - 1;
        /* neighbouring outputs share most of their inputs: the estimate is loose */
        CHECK_NEAR(var / (factor * s * s), 1.0, 0.2);
        CHECK(factor < 0.01);
    }
    ssg_image_destroy(&out);
    release(&im);
}

/* in2 rides along: out2 is what a run on in2 alone gives, bit for bit; and one thread
   gives the bits of two. */
static void test_in2_and_threads(void)
{
    enum { W = 70, H = 45 };
    struct images im = make(W, H, 1);
    struct ssg_image *rgb = ssg_image_create(W, H, 3);
    for (size_t o = 0; o < (size_t)W * H; o++) {
        im.in->data[o] = (float)uniform01();
        for (int c = 0; c < 3; c++)
            rgb->data[(size_t)c * W * H + o] = (float)uniform01();
        im.depth->data[o] = (float)(1.0 + 0.2 * uniform01());
        set_normal(im.normal, o, uniform01() - 0.5, uniform01() - 0.5, 1.0);
    }
    struct ssg_image *out2 = NULL;
    omp_set_num_threads(1);
    struct ssg_image *one = atrous(&im, rgb, NULL, 0, &out2);
    omp_set_num_threads(2);
    struct ssg_image *two = atrous(&im, NULL, NULL, 0, NULL);
    struct images alone = im;
    alone.in = rgb;
    struct ssg_image *rgb_alone = atrous(&alone, NULL, NULL, 0, NULL);
    if (one && two && out2 && rgb_alone) {
        CHECK(memcmp(one->data, two->data, sizeof(float) * W * H) == 0);
        CHECK(memcmp(out2->data, rgb_alone->data, sizeof(float) * 3 * W * H) == 0);
    }
    ssg_image_destroy(&one);
    ssg_image_destroy(&two);
    ssg_image_destroy(&out2);
    ssg_image_destroy(&rgb_alone);
    ssg_image_destroy(&rgb);
    release(&im);
}

static void test_rejects(void)
{
    struct images im = make(8, 8, 1);
    struct ssg_image *small = ssg_image_create(4, 8, 1);
    struct ssg_diags diags = {0};
    struct ssg_outputs out;
    struct ssg_binding b[2] = {{"in", im.in}, {"depth", im.depth}};
    const char *zero[] = {"iterations=0"}, *nine[] = {"iterations=9"};
    CHECK(ssg_node_run("atrous", b, 2, zero, 1, NULL, &out, &diags) != SSG_OK);
    ssg_outputs_release(&out);
    CHECK(ssg_node_run("atrous", b, 2, nine, 1, NULL, &out, &diags) != SSG_OK);
    ssg_outputs_release(&out);
    b[1].image = small;
    CHECK_EQ(ssg_node_run("atrous", b, 2, NULL, 0, NULL, &out, &diags), SSG_E_SIZE);
    ssg_outputs_release(&out);
    ssg_image_destroy(&small);
    release(&im);
}

int main(void)
{
    test_weights();
    test_impulse();
    test_constant_and_step();
    test_background();
    test_noise();
    test_in2_and_threads();
    test_rejects();
    return check_report();
}
