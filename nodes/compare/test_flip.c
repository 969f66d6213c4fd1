/* test_flip.c - FLIP in the `compare` node (flip.c), against properties the paper states
 * or that follow from its formulas: identical images score exactly 0; LDR-FLIP is
 * symmetric in its two images; uniform green against uniform blue is the largest colour
 * error, 1; uniform black against white is the closed form worked out below; a sharp edge
 * moved by one pixel is worse than the same edge blurred in place; the map lies in [0, 1];
 * the map and the mean do not depend on the thread count; HDR-FLIP sees an error in a dark
 * region that LDR-FLIP of the clamped images misses; `flip=off` reports no metric. */
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "compare_test.h"
#include "graph/node.h"
#include "ssgraph.h"

/* Runs compare on a against the reference b with "flip=<mode>"; out holds the metrics and
   the images (diff, flip). */
static void run(const struct ssg_image *a, const struct ssg_image *b, const char *mode,
                struct ssg_outputs *out)
{
    struct ssg_binding bind[2] = {{"a", a}, {"b", b}};
    char set[32];
    snprintf(set, sizeof set, "flip=%s", mode);
    const char *sets[1] = {set};
    struct ssg_diags diags = {0};
    enum ssg_err e = ssg_node_run("compare", bind, 2, sets, 1, NULL, out, &diags);
    if (e)
        ssg_diags_print(&diags, stderr);
    CHECK_EQ(e, SSG_OK);
}

/* A metric by name; NaN when the run did not report it (flip = off). */
static double metric(const struct ssg_outputs *out, const char *name)
{
    int i = 0;
    while (i < out->metric_count && strcmp(out->metric_names[i], name) != 0)
        i++;
    return i < out->metric_count ? out->metric_values[i] : NAN;
}

/* Noise in [-0.5, 0.5) from a hash of the pixel and channel (no state to share). */
static double hash_noise(uint32_t x, uint32_t y, uint32_t c)
{
    uint32_t v = x * 73856093u ^ y * 19349663u ^ c * 83492791u;
    v ^= v >> 16, v *= 0x7feb352du, v ^= v >> 15, v *= 0x846ca68bu, v ^= v >> 16;
    return v / 4294967296.0 - 0.5;
}

/* A checkerboard of 9 x 7 cells over a smooth wave, with noise; in [0, 1.2] (a little
   over white), so FLIP's colour, edges and points all see something. */
static struct ssg_image *textured(int w, int h, int channels, double phase)
{
    struct ssg_image *im = ssg_image_create(w, h, channels);
    for (int c = 0; c < channels; c++) {
        float *p = ssg_image_plane(im, c);
        for (int i = 0; i < w * h; i++) {
            int x = i % w, y = i / w;
            double wave = sin(0.3 * x + phase + c) * cos(0.2 * y - phase);
            double v = 0.5 + 0.3 * wave + 0.2 * ((x / 9 + y / 7) % 2) +
                       0.15 * hash_noise((uint32_t)x, (uint32_t)y, (uint32_t)(c + 300 * phase));
            p[i] = (float)(v > 0 ? v : 0);
        }
    }
    return im;
}

static struct ssg_image *uniform(int w, int h, float r, float g, float b)
{
    struct ssg_image *im = ssg_image_create(w, h, 3);
    float rgb[3] = {r, g, b};
    for (int c = 0; c < 3; c++)
        for (size_t i = 0; i < (size_t)w * h; i++)
            ssg_image_plane(im, c)[i] = rgb[c];
    return im;
}

/* Every map value in [0, 1]; returns the largest. */
static float map_range(const struct ssg_outputs *out, size_t n)
{
    const float *m = compare_output(out, "flip");
    float most = 0;
    for (size_t i = 0; i < n; i++) {
        CHECK(m[i] >= 0.0f && m[i] <= 1.0f);
        most = m[i] > most ? m[i] : most;
    }
    return most;
}

static void test_identical(void)
{
    const char *modes[] = {"ldr", "hdr"};
    for (int channels = 1; channels <= 3; channels += 2)
        for (int m = 0; m < 2; m++) {
            struct ssg_image *a = textured(41, 33, channels, 0.4);
            struct ssg_outputs out;
            run(a, a, modes[m], &out);
            CHECK(metric(&out, "flip") == 0.0);
            CHECK(map_range(&out, 41 * 33) == 0.0f);
            ssg_outputs_release(&out);
            ssg_image_destroy(&a);
        }
}

/* LDR-FLIP: every step is symmetric (|dL|, ||(da, db)||, |edge_a - edge_b|). HDR-FLIP is
   not (its exposures come from the reference), which is allowed. */
static void test_symmetry(void)
{
    enum { W = 57, H = 45 };
    struct ssg_image *a = textured(W, H, 3, 0.1), *b = textured(W, H, 3, 0.9);
    struct ssg_outputs ab, ba;
    run(a, b, "ldr", &ab);
    run(b, a, "ldr", &ba);
    const float *m1 = compare_output(&ab, "flip"), *m2 = compare_output(&ba, "flip");
    for (int i = 0; i < W * H; i++)
        CHECK_NEAR(m1[i], m2[i], 1e-6);
    CHECK(metric(&ab, "flip") > 0.05);
    CHECK_NEAR(metric(&ab, "flip"), metric(&ba, "flip"), 1e-6);
    map_range(&ab, W * H);
    ssg_outputs_release(&ab);
    ssg_outputs_release(&ba);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
}

/* Uniform images have no features (dEf = 0), so FLIP is the colour term alone. Green
   against blue is the paper's normalising pair: HyAB^qc = cmax, mapped to exactly 1. */
static void test_green_blue(void)
{
    struct ssg_image *g = uniform(40, 30, 0, 1, 0), *b = uniform(40, 30, 0, 0, 1);
    struct ssg_outputs out;
    run(g, b, "ldr", &out);
    CHECK_NEAR(metric(&out, "flip"), 1.0, 1e-3);
    CHECK_NEAR(compare_output(&out, "flip")[15 * 40 + 20], 1.0, 1e-3);
    ssg_outputs_release(&out);
    ssg_image_destroy(&g);
    ssg_image_destroy(&b);
}

/* Black against white, worked by hand from the formulas (HPG 2020: Hunt-adjusted
 * L*a*b*, HyAB, the qc/pc/pt mapping):
 *   black: XYZ = 0, f(0) = 4/29, L = 116 * 4/29 - 16 = 0, a = b = 0.
 *   white: XYZ / white = 1, f(1) = 1, L = 100, a = b = 0 (Hunt: 0.01 L * 0 = 0).
 *   HyAB = |100 - 0| + 0 = 100; HyAB^0.7 = 10^1.4 = 25.118864.
 *   cmax: green (0, 1, 0) -> Hunt-adjusted L*a*b* (87.736211, -75.609930, 72.981231),
 *         blue (0, 0, 1) -> (32.298170, 25.578083, -34.836366);
 *         HyAB = 55.438041 + hypot(101.188013, 107.817597) = 203.301655;
 *         cmax = 203.301655^0.7 = 41.276098; the knee pc cmax = 16.510439.
 *   25.118864 >= 16.510439, so dEc = pt + (25.118864 - 16.510439) / (41.276098 - 16.510439)
 *         * (1 - pt) = 0.95 + 0.347592 * 0.05 = 0.967380.
 *   Uniform: dEf = 0, FLIP = dEc^1 = 0.967380. */
static void test_black_white(void)
{
    struct ssg_image *k = uniform(40, 30, 0, 0, 0), *w = uniform(40, 30, 1, 1, 1);
    struct ssg_outputs out;
    run(k, w, "ldr", &out);
    CHECK_NEAR(metric(&out, "flip"), 0.967380, 1e-4);
    ssg_outputs_release(&out);
    /* a grey (1-channel) image is the same as its colour: the value on all three */
    struct ssg_image *k1 = ssg_image_create(40, 30, 1), *w1 = ssg_image_create(40, 30, 1);
    for (int i = 0; i < 40 * 30; i++)
        k1->data[i] = 0.0f, w1->data[i] = 1.0f;
    run(k1, w1, "auto", &out);
    CHECK_NEAR(metric(&out, "flip"), 0.967380, 1e-4);
    ssg_outputs_release(&out);
    ssg_image_destroy(&k);
    ssg_image_destroy(&w);
    ssg_image_destroy(&k1);
    ssg_image_destroy(&w1);
}

/* A vertical grey edge from 0.2 to 0.8 at x0, optionally blurred over `ramp` pixels. */
static struct ssg_image *edge(int w, int h, double x0, int ramp)
{
    struct ssg_image *im = ssg_image_create(w, h, 1);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double t = ramp ? (x + 0.5 - x0) / ramp + 0.5 : (x >= x0 ? 1.0 : 0.0);
            t = t < 0 ? 0 : t > 1 ? 1 : t;
            im->data[(size_t)y * w + x] = (float)(0.2 + 0.6 * t);
        }
    return im;
}

/* The edge moved by one pixel changes where the edge is (both the colour and the feature
   terms see it); blurring it in place over 3 px keeps its position, which the CSF filter
   mostly hides. Both are errors; the move is the larger. */
static void test_edge(void)
{
    enum { W = 64, H = 24 };
    struct ssg_image *ref = edge(W, H, 32, 0), *moved = edge(W, H, 33, 0);
    struct ssg_image *blurred = edge(W, H, 32, 3);
    struct ssg_outputs m, bl;
    run(moved, ref, "ldr", &m);
    run(blurred, ref, "ldr", &bl);
    double fm = metric(&m, "flip"), fb = metric(&bl, "flip");
    printf("edge moved by 1 px: flip %.6f, blurred over 3 px: %.6f\n", fm, fb);
    CHECK(fb > 0.0);
    CHECK(fm > fb);
    map_range(&m, W * H);
    ssg_outputs_release(&m);
    ssg_outputs_release(&bl);
    ssg_image_destroy(&ref);
    ssg_image_destroy(&moved);
    ssg_image_destroy(&blurred);
}

/* 131 rows (3 row bands of compare's 64, 9 of FLIP's 16; the last short), odd width. */
static void test_threads(void)
{
    enum { W = 77, H = 131 };
    struct ssg_image *a = textured(W, H, 3, 0.2), *b = textured(W, H, 3, 0.25);
    const char *modes[] = {"ldr", "hdr"};
    for (int m = 0; m < 2; m++) {
        struct ssg_outputs one, two;
        omp_set_num_threads(1);
        run(a, b, modes[m], &one);
        omp_set_num_threads(2);
        run(a, b, modes[m], &two);
        double f1 = metric(&one, "flip"), f2 = metric(&two, "flip");
        CHECK(memcmp(&f1, &f2, sizeof f1) == 0);
        CHECK(memcmp(compare_output(&one, "flip"), compare_output(&two, "flip"), sizeof(float) * W * H) == 0);
        map_range(&one, W * H);
        ssg_outputs_release(&one);
        ssg_outputs_release(&two);
    }
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
}

/* A difference far above white (10 against 12: both clamp to 1 in LDR) and one in a dark
   corner (0.001 against 0.002): HDR-FLIP's exposures, from the reference's range, see both;
   LDR-FLIP sees neither well. */
static void test_hdr(void)
{
    enum { W = 48, H = 32 };
    struct ssg_image *ref = uniform(W, H, 0.2f, 0.2f, 0.2f);
    struct ssg_image *test = uniform(W, H, 0.2f, 0.2f, 0.2f);
    for (int c = 0; c < 3; c++)
        for (int y = 0; y < 8; y++)
            for (int x = 0; x < 8; x++) {
                ssg_image_plane(ref, c)[y * W + x] = 10.0f;
                ssg_image_plane(test, c)[y * W + x] = 12.0f;
                ssg_image_plane(ref, c)[(H - 1 - y) * W + W - 1 - x] = 0.001f;
                ssg_image_plane(test, c)[(H - 1 - y) * W + W - 1 - x] = 0.002f;
            }
    struct ssg_outputs ldr, hdr;
    run(test, ref, "ldr", &ldr);
    run(test, ref, "hdr", &hdr);
    const float *ml = compare_output(&ldr, "flip"), *mh = compare_output(&hdr, "flip");
    int bright = 4 * W + 4, dark = (H - 5) * W + W - 5;
    printf("bright square: ldr %.4f hdr %.4f; dark square: ldr %.4f hdr %.4f\n", ml[bright],
           mh[bright], ml[dark], mh[dark]);
    CHECK(ml[bright] == 0.0f); /* 10 and 12 both clamp to white */
    CHECK(mh[bright] > 0.05f);
    CHECK(mh[dark] > 2.0f * ml[dark]);
    map_range(&hdr, W * H);
    ssg_outputs_release(&ldr);
    ssg_outputs_release(&hdr);
    ssg_image_destroy(&ref);
    ssg_image_destroy(&test);
}

static void test_off(void)
{
    struct ssg_image *a = textured(20, 16, 1, 0.3), *b = textured(20, 16, 1, 0.5);
    struct ssg_outputs out;
    run(a, b, "off", &out);
    CHECK(isnan(metric(&out, "flip")));
    CHECK_EQ(out.metric_count, 8);
    ssg_outputs_release(&out);
    run(a, b, "auto", &out);
    CHECK_EQ(out.metric_count, 9);
    CHECK(!strcmp(out.metric_names[8], "flip"));
    ssg_outputs_release(&out);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
}

int main(void)
{
    test_identical();
    test_symmetry();
    test_green_blue();
    test_black_white();
    test_edge();
    test_threads();
    test_hdr();
    test_off();
    return check_report();
}
