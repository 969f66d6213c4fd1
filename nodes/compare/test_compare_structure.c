/* test_compare_structure.c - the `compare` node's structure measure (structure.c, README.md)
 * on a case with a known answer: a flat reference b = 0.5 on two surfaces (depth 2 left,
 * 3 right), a = b (1 + A sin(2 pi x / lambda)) plus white noise, plus a bright seam along
 * the depth edge. The Gaussian of deviation sigma passes the sinusoid at
 * H = sum_t g_t cos(2 pi t / lambda) (the cut kernel's response; exp(-2 pi^2 sigma^2 /
 * lambda^2) for the whole Gaussian), so d = A H sin(2 pi x / lambda): peak to peak 2 A H,
 * RMS A H / sqrt(2). The noise must not count, the seam must be masked by the depth input
 * (and counts without it), the measured pixels are those 3 sigma from every edge, the map
 * holds d, a reference that is not smooth at the scale is left out, the measure is off by
 * default, and its bits do not depend on the thread count. */
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "compare_test.h"
#include "ssgraph.h"

#define PI 3.14159265358979323846

enum { W = 256, H = 128, LAMBDA = 32, SIGMA = 4 };
static const double AMP = 0.2, NOISE = 0.05, SEAM = 1.0;

static uint64_t rng_state = 11;
static double gauss01(void) { return compare_gauss(&rng_state); }

/* The pair and its depth: sine of relative amplitude amp, noise of deviation noise,
   a seam of height seam on the four columns around the depth edge at x = 128. */
static void make_case(double amp, double noise, double seam, struct ssg_image **a,
                      struct ssg_image **b, struct ssg_image **z)
{
    *a = ssg_image_create(W, H, 1), *b = ssg_image_create(W, H, 1);
    *z = ssg_image_create(W, H, 1);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t i = (size_t)y * W + (size_t)x;
            double v = 0.5 * (1.0 + amp * sin(2.0 * PI * x / LAMBDA)) + noise * gauss01();
            (*a)->data[i] = (float)(v + (x >= 126 && x <= 129 ? seam : 0.0));
            (*b)->data[i] = 0.5f;
            (*z)->data[i] = x < 128 ? 2.0f : 3.0f;
        }
}

static enum ssg_err run(const struct ssg_image *a, const struct ssg_image *b,
                        const struct ssg_image *z, int on, struct ssg_outputs *out)
{
    struct ssg_binding bind[3] = {{"a", a}, {"b", b}, {"depth", z}};
    const char *sets[] = {"structure=true", "structure_sigma=0.015625", "flip=off"};
    struct ssg_diags diags = {0};
    struct ssg_frame frame = {W, H, 45.0f, 0.05f, 100.0f, 1, 0, 0, 0};
    enum ssg_err e = ssg_node_run("compare", bind, z ? 3 : 2, sets, on ? 3 : 0, &frame, out,
                                  &diags);
    ssg_diags_print(&diags, stderr);
    return e;
}

static int has(const struct ssg_outputs *out, const char *name)
{
    for (int i = 0; i < out->metric_count; i++)
        if (!strcmp(out->metric_names[i], name))
            return 1;
    return 0;
}


/* The response of the node's kernel (deviation 4 px, cut at 3 sigma = 12 taps a side)
   to a sine of wavelength LAMBDA: sum_t g_t cos(2 pi t / lambda) / sum_t g_t. */
static double response(void)
{
    double num = 0, den = 0;
    for (int t = -3 * SIGMA; t <= 3 * SIGMA; t++) {
        double g = exp(-(double)t * t / (2.0 * SIGMA * SIGMA));
        num += g * cos(2.0 * PI * t / LAMBDA);
        den += g;
    }
    return num / den;
}

static void release(struct ssg_outputs *out, struct ssg_image **a, struct ssg_image **b,
                    struct ssg_image **z)
{
    ssg_outputs_release(out);
    ssg_image_destroy(a), ssg_image_destroy(b), ssg_image_destroy(z);
}

/* The RMS about its mean of sin(2 pi x / lambda) over the measured columns (13..114 and
   141..242: 102 each, not whole periods, so not quite 1 / sqrt(2)). */
static double sine_rms(void)
{
    double s = 0, s2 = 0;
    int n = 0;
    for (int x = 13; x <= 242; x++) {
        if (x > 114 && x < 141)
            continue;
        double v = sin(2.0 * PI * x / LAMBDA);
        s += v, s2 += v * v, n++;
    }
    return sqrt(s2 / n - (s / n) * (s / n));
}

/* The sine alone: the kernel's response, on exactly the pixels 3 sigma = 12 px from the
   border and the depth edge (columns 13..114 and 141..242, rows 13..114), the peaks
   (x = 8 mod 32 and 24 mod 32) among them. */
static void test_sine(void)
{
    double hr = response();
    /* The sampled, cut kernel is within 0.5 % of the whole Gaussian's
       exp(-2 pi^2 sigma^2 / lambda^2) = 0.7346 (0.7374 here). */
    CHECK_NEAR(hr, exp(-2.0 * PI * PI * SIGMA * SIGMA / (LAMBDA * LAMBDA)), 5e-3);
    struct ssg_image *a, *b, *z;
    make_case(AMP, 0, SEAM, &a, &b, &z);
    struct ssg_outputs out;
    CHECK_EQ(run(a, b, z, 1, &out), SSG_OK);
    CHECK_EQ(compare_metric(&out, "structure_pixels"), 2.0 * 102 * 102);
    /* Within 1 % (the seam's tail at 3 sigma, test_no_depth). */
    CHECK_NEAR(compare_metric(&out, "structure_pp"), 2.0 * AMP * hr, 0.01 * AMP * hr);
    CHECK_NEAR(compare_metric(&out, "structure_rms"), AMP * hr * sine_rms(), 0.01 * AMP * hr);
    /* The map: d at a crest (x = 40 = 8 + 32, row 64), 0 outside the measured pixels. */
    const float *map = compare_output(&out, "structure");
    CHECK_NEAR(map[64 * W + 40], AMP * hr, 0.01 * AMP * hr);
    CHECK(map[64 * W + 5] == 0.0f && map[64 * W + 128] == 0.0f && map[3 * W + 40] == 0.0f);
    release(&out, &a, &b, &z);
}

/* The smoothness test: where the reference itself carries a sine of wavelength 64 and
   relative amplitude 0.6 (left half), its blurs of deviation 4 and 8 pass it at 0.926 and
   0.735 of that, so they differ by 0.6 x 0.191 |sin| = 0.115 |sin|: over the threshold
   0.05 where |sin| > 0.435, a part of the left half's columns. A threshold no difference
   reaches keeps every pixel the flat reference keeps. */
static void test_smooth(void)
{
    struct ssg_image *a, *b, *z;
    make_case(0, 0, 0, &a, &b, &z);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W / 2; x++) {
            float v = (float)(0.5 * (1.0 + 0.6 * sin(2.0 * PI * x / 64)));
            a->data[(size_t)y * W + (size_t)x] = b->data[(size_t)y * W + (size_t)x] = v;
        }
    struct ssg_binding bind[3] = {{"a", a}, {"b", b}, {"depth", z}};
    struct ssg_frame frame = {W, H, 45.0f, 0.05f, 100.0f, 1, 0, 0, 0};
    const char *sets[] = {"structure=true", "structure_sigma=0.015625", "flip=off",
                          "structure_smooth=1e6"};
    struct ssg_diags diags = {0};
    struct ssg_outputs out;
    CHECK_EQ(ssg_node_run("compare", bind, 3, sets, 3, &frame, &out, &diags), SSG_OK);
    double kept = compare_metric(&out, "structure_pixels");
    CHECK(kept > 102.0 * 102 && kept < 1.8 * 102 * 102); /* the right half, some of the left */
    CHECK(compare_metric(&out, "structure_pp") < 1e-6);  /* a = b: no error anywhere */
    ssg_outputs_release(&out);
    CHECK_EQ(ssg_node_run("compare", bind, 3, sets, 4, &frame, &out, &diags), SSG_OK);
    CHECK_EQ(compare_metric(&out, "structure_pixels"), 2.0 * 102 * 102);
    release(&out, &a, &b, &z);
}

/* Noise of deviation 0.05 (10 % of b a pixel) adds little: the blur leaves
   0.1 / (2 sqrt(pi) sigma) = 0.7 % relative (about 0.06 peak to peak over 20808 pixels),
   and the sine's numbers barely move. */
static void test_noise(void)
{
    double hr = response();
    struct ssg_image *a, *b, *z;
    make_case(0, NOISE, SEAM, &a, &b, &z);
    struct ssg_outputs out;
    CHECK_EQ(run(a, b, z, 1, &out), SSG_OK);
    CHECK(compare_metric(&out, "structure_rms") < 0.01);
    CHECK(compare_metric(&out, "structure_pp") < 0.1);
    CHECK(compare_metric(&out, "rmse") > 0.045); /* rmse sees the noise in full */
    release(&out, &a, &b, &z);
    make_case(AMP, NOISE, SEAM, &a, &b, &z);
    CHECK_EQ(run(a, b, z, 1, &out), SSG_OK);
    CHECK_NEAR(compare_metric(&out, "structure_rms"), AMP * hr * sine_rms(), 0.03 * AMP * hr);
    CHECK_NEAR(compare_metric(&out, "structure_pp"), 2.0 * AMP * hr, 0.07);
    release(&out, &a, &b, &z);
}

/* Without the depth the seam's surroundings are measured, and the seam counts. */
static void test_no_depth(void)
{
    struct ssg_image *a, *b, *z;
    make_case(0, 0, SEAM, &a, &b, &z);
    struct ssg_outputs out;
    CHECK_EQ(run(a, b, z, 1, &out), SSG_OK);
    /* The seam masked: only its tail at 3 sigma and more, 2 sum_{k=12..15} g_k = 0.004
       (1D, the seam being whole columns) at x = 141 */
    CHECK(compare_metric(&out, "structure_pp") < 0.006);
    ssg_outputs_release(&out);
    CHECK_EQ(run(a, b, NULL, 1, &out), SSG_OK);
    CHECK_EQ(compare_metric(&out, "structure_pixels"), 230.0 * 102);
    /* 4 columns of +2 relative, blurred: 2 x 2 (g(0.5) + g(1.5)) = 0.76 at the middle */
    CHECK(compare_metric(&out, "structure_pp") > 0.7);
    release(&out, &a, &b, &z);
}

/* Off by default: no structure metric, and the map output all 0. */
static void test_off(void)
{
    struct ssg_image *a, *b, *z;
    make_case(AMP, 0, SEAM, &a, &b, &z);
    struct ssg_outputs out;
    CHECK_EQ(run(a, b, z, 0, &out), SSG_OK);
    CHECK(!has(&out, "structure_pp") && !has(&out, "structure_rms"));
    CHECK(has(&out, "rmse"));
    release(&out, &a, &b, &z);
}

/* The same bits on 1 and 4 threads. */
static void test_threads(void)
{
    struct ssg_image *a, *b, *z;
    make_case(AMP, NOISE, SEAM, &a, &b, &z);
    struct ssg_outputs one, four;
    omp_set_num_threads(1);
    CHECK_EQ(run(a, b, z, 1, &one), SSG_OK);
    omp_set_num_threads(4);
    CHECK_EQ(run(a, b, z, 1, &four), SSG_OK);
    CHECK_EQ(one.metric_count, four.metric_count);
    for (int i = 0; i < one.metric_count; i++)
        CHECK(!memcmp(&one.metric_values[i], &four.metric_values[i], sizeof(double)));
    ssg_outputs_release(&four);
    release(&one, &a, &b, &z);
}

int main(void)
{
    test_sine();
    test_noise();
    test_no_depth();
    test_smooth();
    test_off();
    test_threads();
    return check_report();
}
