/* test_bilateral.c - the `bilateral` node: constants stay constant, the weights are the
 * documented ones, depth steps and normal creases are not blurred across, background
 * passes through untouched, noise on a flat region drops by the factor its spatial
 * weights predict, and the result does not depend on the thread count. */
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "node.h"
#include "ssgraph.h"

struct images {
    struct ssg_image *in, *depth, *normal;
};

static struct images make(int w, int h, int channels)
{
    struct images im = {ssg_image_create(w, h, channels), ssg_image_create(w, h, 1),
                        ssg_image_create(w, h, 3)};
    return im;
}

static void release(struct images *im)
{
    ssg_image_destroy(&im->in);
    ssg_image_destroy(&im->depth);
    ssg_image_destroy(&im->normal);
}

static void set_normal(struct ssg_image *n, size_t o, double x, double y, double z)
{
    double len = sqrt(x * x + y * y + z * z);
    size_t plane = (size_t)n->width * (size_t)n->height;
    n->data[o] = (float)(x / len);
    n->data[plane + o] = (float)(y / len);
    n->data[2 * plane + o] = (float)(z / len);
}

/* Runs bilateral; returns the output (owned) or NULL. with_normal = 0 leaves the normal
   input unconnected. */
static struct ssg_image *filter(const struct images *im, int with_normal,
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
    return out.images[0];
}

/* Deterministic N(0, 1) numbers: a 64-bit LCG and Box-Muller. */
static uint64_t rng_state = 12345;
static double uniform01(void)
{
    rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
    return ((double)(rng_state >> 11) + 0.5) * 0x1.0p-53;
}
static double gaussian(void)
{
    return sqrt(-2 * log(uniform01())) * cos(2 * M_PI * uniform01());
}

static void test_constant(void)
{
    enum { W = 40, H = 30 };
    struct images im = make(W, H, 3);
    size_t plane = W * H;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t o = (size_t)y * W + (size_t)x;
            im.in->data[o] = 0.37f;
            im.in->data[plane + o] = 2.5f;
            im.in->data[2 * plane + o] = -1.0f;
            im.depth->data[o] = (float)(2.0 + 0.03 * x + 0.01 * y * y); /* curved */
            set_normal(im.normal, o, sin(0.1 * x), 0.2, 1.0);
        }
    const char *sets[] = {"size=7"};
    struct ssg_image *out = filter(&im, 1, sets, 1);
    if (out) {
        CHECK_EQ(out->channels, 3);
        double worst = 0;
        for (size_t o = 0; o < plane; o++) {
            worst = fmax(worst, fabs(out->data[o] - 0.37));
            worst = fmax(worst, fabs(out->data[plane + o] - 2.5) / 2.5);
            worst = fmax(worst, fabs(out->data[2 * plane + o] + 1.0));
        }
        /* A normalised mean of equal values: a few float roundings. */
        CHECK(worst < 1e-6);
    }
    ssg_image_destroy(&out);
    release(&im);
}

/* A 3 x 1 image: the centre's result is the weighted mean of the documented weights
   exp(-dx^2 / (2 s^2)) * exp(-(dd / (sigma_d d))^2 / 2) * (n.n')^p. Powers of two and
   other powers take different code paths; both are checked. */
static void test_weights(void)
{
    struct images im = make(3, 1, 1);
    const float values[3] = {1.0f, 0.0f, 3.0f};
    const float depths[3] = {2.1f, 2.0f, 1.96f};
    const double angle[3] = {0.3, 0.0, -0.5}; /* normal tilt about y, radians */
    for (int x = 0; x < 3; x++) {
        im.in->data[x] = values[x];
        im.depth->data[x] = depths[x];
        set_normal(im.normal, (size_t)x, sin(angle[x]), 0, cos(angle[x]));
    }
    static const int powers[] = {4, 3, 0};
    for (int k = 0; k < 3; k++) {
        char power[32];
        snprintf(power, sizeof power, "normal_power=%d", powers[k]);
        const char *sets[] = {"size=3", "sigma_spatial=1.5", "sigma_depth=0.05", power};
        struct ssg_image *out = filter(&im, 1, sets, 4);
        if (out) {
            double num = 0, den = 0;
            for (int x = 0; x < 3; x++) {
                double dx = x - 1, dd = (double)depths[x] - depths[1];
                double w = exp(-dx * dx / (2 * 1.5 * 1.5)) *
                           exp(-0.5 * pow(dd / (0.05 * depths[1]), 2)) *
                           pow(cos(angle[x]), powers[k]);
                num += w * values[x];
                den += w;
            }
            /* exp and ln are polynomial approximations good to a few 1e-7 relative. */
            CHECK_NEAR(out->data[1], num / den, 1e-5);
        }
        ssg_image_destroy(&out);
    }
    release(&im);
}

/* A depth step (1 | 2) carrying a value step (0 | 1): with sigma_depth 0.05 the weights
   across are exp(-200) and exp(-50), so nothing crosses. */
static void test_depth_step(void)
{
    enum { W = 32, H = 16 };
    struct images im = make(W, H, 1);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t o = (size_t)y * W + (size_t)x;
            im.in->data[o] = x < W / 2 ? 0.0f : 1.0f;
            im.depth->data[o] = x < W / 2 ? 1.0f : 2.0f;
            set_normal(im.normal, o, 0, 0, 1);
        }
    const char *sets[] = {"size=9"};
    struct ssg_image *out = filter(&im, 1, sets, 1);
    if (out) {
        double worst = 0;
        for (size_t o = 0; o < (size_t)W * H; o++)
            worst = fmax(worst, fabs(out->data[o] - im.in->data[o]));
        CHECK(worst < 1e-6);
    }
    /* Without the depth term's help (a huge sigma_depth) it does blur: the test can
       fail. */
    const char *loose[] = {"size=9", "sigma_depth=1000"};
    struct ssg_image *blur = filter(&im, 1, loose, 2);
    if (blur)
        CHECK(blur->data[(size_t)(H / 2) * W + W / 2 - 1] > 0.1f);
    ssg_image_destroy(&out);
    ssg_image_destroy(&blur);
    release(&im);
}

/* A V-shaped crease: depth continuous (5 + 0.02 |x - c|), normals 90 degrees apart on
   the two sides, values 0 | 1. The normal term (n.n' = 0) stops the blur; without it the
   depth term alone (differences under 1.6% at the crease) lets it through. */
static void test_crease(void)
{
    enum { W = 32, H = 16 };
    struct images im = make(W, H, 1);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t o = (size_t)y * W + (size_t)x;
            int left = x < W / 2;
            im.in->data[o] = left ? 0.0f : 1.0f;
            im.depth->data[o] = (float)(5.0 + 0.02 * fabs(x + 0.5 - W / 2));
            set_normal(im.normal, o, left ? -1 : 1, 0, 1);
        }
    const char *with[] = {"size=9", "normal_power=16"};
    const char *without[] = {"size=9", "normal_power=0"};
    struct ssg_image *a = filter(&im, 1, with, 2);
    struct ssg_image *b = filter(&im, 1, without, 2);
    struct ssg_image *c = filter(&im, 0, with, 2); /* no normal input: no normal term */
    if (a && b && c) {
        double worst = 0;
        for (size_t o = 0; o < (size_t)W * H; o++)
            worst = fmax(worst, fabs(a->data[o] - im.in->data[o]));
        CHECK(worst < 1e-6);
        size_t edge = (size_t)(H / 2) * W + W / 2 - 1;
        CHECK(b->data[edge] > 0.1f);
        CHECK(memcmp(b->data, c->data, sizeof(float) * W * H) == 0);
    }
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
    ssg_image_destroy(&c);
    release(&im);
}

/* Background (depth 0) keeps its value and lends none: a region of 100s beside a
   surface of 0.5s changes neither. */
static void test_background(void)
{
    enum { W = 24, H = 24 };
    struct images im = make(W, H, 1);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t o = (size_t)y * W + (size_t)x;
            int bg = x + y < W;
            im.in->data[o] = bg ? 100.0f : 0.5f;
            im.depth->data[o] = bg ? 0.0f : 3.0f;
            set_normal(im.normal, o, 0, 0, bg ? 0 : 1);
        }
    const char *sets[] = {"size=9"};
    struct ssg_image *out = filter(&im, 1, sets, 1);
    if (out) {
        double worst = 0;
        for (size_t o = 0; o < (size_t)W * H; o++)
            worst = fmax(worst, fabs(out->data[o] - im.in->data[o]));
        CHECK(worst < 1e-6);
    }
    ssg_image_destroy(&out);
    release(&im);
}

/* Gaussian noise of variance s^2 on a fronto-parallel plane: depth and normal weights are
   1, so each output is sum w_q x_q / sum w_q with the spatial weights w, of variance
   F s^2, F = sum w^2 / (sum w)^2. The sample variance over N interior pixels of this
   correlated Gaussian field has relative standard error sqrt(2 sum_l rho(l)^2 / N), rho
   the weights' normalised autocorrelation; the tolerance is four of those. */
static void test_noise(void)
{
    enum { W = 256, H = 256, SIZE = 9, R = SIZE / 2 };
    const double sigma_s = SIZE / 3.0, s = 0.1;
    struct images im = make(W, H, 1);
    for (size_t o = 0; o < (size_t)W * H; o++) {
        im.in->data[o] = (float)(0.5 + s * gaussian());
        im.depth->data[o] = 3.0f;
        set_normal(im.normal, o, 0, 0, 1);
    }
    double w[SIZE][SIZE], sum = 0, sum2 = 0;
    for (int dy = -R; dy <= R; dy++)
        for (int dx = -R; dx <= R; dx++) {
            w[dy + R][dx + R] = exp(-(dx * dx + dy * dy) / (2 * sigma_s * sigma_s));
            sum += w[dy + R][dx + R];
            sum2 += w[dy + R][dx + R] * w[dy + R][dx + R];
        }
    double factor = sum2 / (sum * sum), rho2 = 0;
    for (int ly = -2 * R; ly <= 2 * R; ly++)
        for (int lx = -2 * R; lx <= 2 * R; lx++) {
            double c = 0;
            for (int y = 0; y < SIZE; y++)
                for (int x = 0; x < SIZE; x++) {
                    int y2 = y + ly, x2 = x + lx;
                    if (y2 >= 0 && y2 < SIZE && x2 >= 0 && x2 < SIZE)
                        c += w[y][x] * w[y2][x2];
                }
            rho2 += (c / sum2) * (c / sum2);
        }
    const char *sets[] = {"size=9"};
    struct ssg_image *out = filter(&im, 1, sets, 1);
    if (out) {
        double mean = 0, var = 0;
        int n = 0;
        for (int y = R; y < H - R; y++)
            for (int x = R; x < W - R; x++)
                mean += out->data[(size_t)y * W + (size_t)x], n++;
        mean /= n;
        for (int y = R; y < H - R; y++)
            for (int x = R; x < W - R; x++) {
                double d = out->data[(size_t)y * W + (size_t)x] - mean;
                var += d * d;
            }
        var /= n - 1;
        double expected = factor * s * s, rel_se = sqrt(2 * rho2 / n);
        CHECK_NEAR(var / expected, 1.0, 4 * rel_se);
        if (getenv("BILATERAL_DEBUG"))
            fprintf(stderr, "noise: factor %.5f, ratio %.4f, tolerance %.4f\n", factor,
                    var / expected, 4 * rel_se);
        CHECK(factor < 0.05); /* it is a real reduction: about 1/69 for size 9 */
    }
    ssg_image_destroy(&out);
    release(&im);
}

static void test_threads(void)
{
    enum { W = 120, H = 77 };
    struct images im = make(W, H, 3);
    for (size_t o = 0; o < (size_t)W * H; o++) {
        for (int c = 0; c < 3; c++)
            im.in->data[(size_t)c * W * H + o] = (float)uniform01();
        im.depth->data[o] = (float)(1.0 + 0.2 * uniform01());
        set_normal(im.normal, o, uniform01() - 0.5, uniform01() - 0.5, 1.0);
    }
    const char *sets[] = {"size=11"};
    omp_set_num_threads(1);
    struct ssg_image *one = filter(&im, 1, sets, 1);
    omp_set_num_threads(2);
    struct ssg_image *two = filter(&im, 1, sets, 1);
    if (one && two)
        CHECK(memcmp(one->data, two->data, sizeof(float) * 3 * W * H) == 0);
    ssg_image_destroy(&one);
    ssg_image_destroy(&two);
    release(&im);
}

static void test_rejects(void)
{
    struct images im = make(8, 8, 1);
    struct ssg_diags diags = {0};
    struct ssg_outputs out;
    const char *even[] = {"size=8"};
    struct ssg_binding b[2] = {{"in", im.in}, {"depth", im.depth}};
    CHECK_EQ(ssg_node_run("bilateral", b, 2, even, 1, NULL, &out, &diags), SSG_E_VALUE);
    ssg_outputs_release(&out);
    CHECK_EQ(ssg_node_run("bilateral", b, 1, NULL, 0, NULL, &out, &diags),
             SSG_E_MISSING_INPUT);
    ssg_outputs_release(&out);
    release(&im);
}

int main(void)
{
    test_constant();
    test_weights();
    test_depth_step();
    test_crease();
    test_background();
    test_noise();
    test_threads();
    test_rejects();
    return check_report();
}
