/* test_compare.c - the `compare` node: identical images score rmse 0, psnr inf and ssim
 * exactly 1; a constant offset gives its closed-form rmse, mae and psnr; constant images
 * give SSIM's closed form; SSIM agrees with a direct, unseparated evaluation of the
 * definition (windows renormalised over counted pixels) on structured images with a mask;
 * the mask restricts every metric; the diff colours are the documented ones; mismatched
 * shapes are rejected; metrics and diff do not depend on the thread count. */
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "compare_test.h"
#include "graph/node.h"
#include "ssgraph.h"

/* Runs compare; mask may be NULL. Returns the error code; out is filled on success. */
static enum ssg_err run(const struct ssg_image *a, const struct ssg_image *b,
                        const struct ssg_image *mask, const char *const *sets, int set_count,
                        struct ssg_outputs *out)
{
    struct ssg_binding bind[3] = {{"a", a}, {"b", b}, {"mask", mask}};
    struct ssg_diags diags = {0};
    enum ssg_err e = ssg_node_run("compare", bind, mask ? 3 : 2, sets, set_count, NULL, out,
                                  &diags);
    if (e && getenv("COMPARE_DEBUG"))
        ssg_diags_print(&diags, stderr);
    return e;
}


static uint64_t rng_state = 99;
static double uniform01(void)
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rng_state >> 11) * (1.0 / 9007199254740992.0);
}

/* Smooth structure plus noise, in [0, 1]: SSIM's terms all matter on it. */
static struct ssg_image *textured(int w, int h, int channels, double phase)
{
    struct ssg_image *im = ssg_image_create(w, h, channels);
    for (int c = 0; c < channels; c++)
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                double v = 0.5 + 0.3 * sin(0.35 * x + phase + c) * cos(0.2 * y - phase) +
                           0.15 * (uniform01() - 0.5);
                ssg_image_plane(im, c)[(size_t)y * w + x] = (float)v;
            }
    return im;
}

static struct ssg_image *constant(int w, int h, int channels, float v)
{
    struct ssg_image *im = ssg_image_create(w, h, channels);
    for (size_t i = 0; i < (size_t)w * h * channels; i++)
        im->data[i] = v;
    return im;
}

static void test_identical(void)
{
    for (int channels = 1; channels <= 3; channels += 2) {
        struct ssg_image *a = textured(37, 29, channels, 0.3);
        struct ssg_image *b = ssg_image_create(37, 29, channels);
        memcpy(b->data, a->data, sizeof(float) * 37 * 29 * channels);
        struct ssg_outputs out;
        CHECK_EQ(run(a, b, NULL, NULL, 0, &out), SSG_OK);
        CHECK_EQ(out.metric_count, 9);
        const char *order[] = {"rmse", "mae", "bias", "psnr", "ssim", "pixels", "mean",
                               "reference_mean", "flip"};
        for (int i = 0; i < 9 && i < out.metric_count; i++)
            CHECK(!strcmp(out.metric_names[i], order[i]));
        CHECK(compare_metric(&out, "rmse") == 0.0);
        CHECK(compare_metric(&out, "mae") == 0.0);
        CHECK(compare_metric(&out, "bias") == 0.0);
        CHECK(isinf(compare_metric(&out, "psnr")) && compare_metric(&out, "psnr") > 0);
        CHECK(compare_metric(&out, "ssim") == 1.0);
        CHECK_EQ(compare_metric(&out, "pixels"), 37 * 29);
        /* diff is white everywhere */
        CHECK_EQ(out.images[0]->channels, 3);
        for (size_t i = 0; i < (size_t)3 * 37 * 29; i++)
            if (out.images[0]->data[i] != 1.0f) {
                CHECK(0);
                break;
            }
        ssg_outputs_release(&out);
        ssg_image_destroy(&a);
        ssg_image_destroy(&b);
    }
}

/* b = a + d exactly (multiples of 1/1024 add without rounding). */
static void test_offset(void)
{
    const double d = 0.125;
    struct ssg_image *a = ssg_image_create(23, 17, 3), *b = ssg_image_create(23, 17, 3);
    for (size_t i = 0; i < (size_t)3 * 23 * 17; i++) {
        a->data[i] = (float)(floor(uniform01() * 512) / 1024);
        b->data[i] = a->data[i] + (float)d;
    }
    struct ssg_outputs out;
    CHECK_EQ(run(a, b, NULL, NULL, 0, &out), SSG_OK);
    CHECK_NEAR(compare_metric(&out, "rmse"), d, 1e-15);
    CHECK_NEAR(compare_metric(&out, "mae"), d, 1e-15);
    CHECK_NEAR(compare_metric(&out, "bias"), -d, 1e-15); /* a = b - d: a is darker */
    double sum_a = 0;
    for (size_t i = 0; i < (size_t)3 * 23 * 17; i++)
        sum_a += a->data[i];
    CHECK_NEAR(compare_metric(&out, "mean"), sum_a / (3 * 23 * 17), 1e-12);
    CHECK_NEAR(compare_metric(&out, "reference_mean"), sum_a / (3 * 23 * 17) + d, 1e-12);
    CHECK_NEAR(compare_metric(&out, "psnr"), 10 * log10(1 / (d * d)), 1e-12);
    ssg_outputs_release(&out);
    /* PSNR scales with the peak: 20 log10(peak / rmse) */
    const char *peak2[] = {"peak=2"};
    CHECK_EQ(run(a, b, NULL, peak2, 1, &out), SSG_OK);
    CHECK_NEAR(compare_metric(&out, "psnr"), 20 * log10(2 / d), 1e-12);
    ssg_outputs_release(&out);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
}

/* Constant images: variances and covariance vanish and SSIM is
   (2 c1 c2 + C1) / (c1^2 + c2^2 + C1), C1 = (0.01 peak)^2. */
static void test_ssim_constant(void)
{
    const double c1 = 0.3, c2 = 0.6;
    struct ssg_image *a = constant(16, 13, 1, (float)c1), *b = constant(16, 13, 1, (float)c2);
    double fa = (float)c1, fb = (float)c2;
    for (int peak = 1; peak <= 2; peak++) {
        const char *sets[] = {peak == 1 ? "peak=1" : "peak=2"};
        double k1 = (0.01 * peak) * (0.01 * peak);
        struct ssg_outputs out;
        CHECK_EQ(run(a, b, NULL, sets, 1, &out), SSG_OK);
        CHECK_NEAR(compare_metric(&out, "ssim"), (2 * fa * fb + k1) / (fa * fa + fb * fb + k1), 1e-12);
        ssg_outputs_release(&out);
    }
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
}

/* The definition evaluated directly: for every counted pixel, the 11x11 Gaussian window
   (sigma 1.5) over counted pixels inside the image, weights renormalised; mean, variance
   and covariance in the two-pass form; SSIM eq. 13; mean over pixels, then channels. */
static int on(const struct ssg_image *mask, int x, int y)
{
    int w = mask ? mask->width : 0, h = mask ? mask->height : 0;
    return !mask || (x >= 0 && y >= 0 && x < w && y < h && mask->data[y * w + x] > 0.5f);
}

static double ssim_pixel(const float *pa, const float *pb, const struct ssg_image *mask,
                         int w, int h, int x, int y, double peak)
{
    double ws = 0, ma = 0, mb = 0, va = 0, vb = 0, cv = 0;
    for (int pass = 0; pass < 2; pass++) {
        for (int dy = -5; dy <= 5; dy++)
            for (int dx = -5; dx <= 5; dx++) {
                int qx = x + dx, qy = y + dy;
                if (qx < 0 || qy < 0 || qx >= w || qy >= h || !on(mask, qx, qy))
                    continue;
                double g = exp(-(dx * dx + dy * dy) / 4.5);
                double u = pa[qy * w + qx], v = pb[qy * w + qx];
                if (pass == 0) {
                    ws += g, ma += g * u, mb += g * v;
                } else {
                    va += g * (u - ma) * (u - ma);
                    vb += g * (v - mb) * (v - mb);
                    cv += g * (u - ma) * (v - mb);
                }
            }
        if (pass == 0)
            ma /= ws, mb /= ws;
    }
    va /= ws, vb /= ws, cv /= ws;
    double c1 = (0.01 * peak) * (0.01 * peak), c2 = (0.03 * peak) * (0.03 * peak);
    return (2 * ma * mb + c1) * (2 * cv + c2) / ((ma * ma + mb * mb + c1) * (va + vb + c2));
}

static double ssim_direct(const struct ssg_image *a, const struct ssg_image *b,
                          const struct ssg_image *mask, double peak)
{
    int w = a->width, h = a->height;
    double total = 0;
    for (int c = 0; c < a->channels; c++) {
        double sum = 0;
        long long n = 0;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++)
                if (on(mask, x, y)) {
                    sum += ssim_pixel(ssg_image_plane(a, c), ssg_image_plane(b, c), mask, w,
                                      h, x, y, peak);
                    n++;
                }
        total += sum / (double)n;
    }
    return total / a->channels;
}

/* A disc mask with a hole, so that windows are cut by mask edges and image borders. */
static struct ssg_image *disc_mask(int w, int h)
{
    struct ssg_image *m = ssg_image_create(w, h, 1);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double dx = x - 0.45 * w, dy = y - 0.5 * h, r2 = dx * dx + dy * dy;
            m->data[y * w + x] = r2 < 0.2 * w * w && r2 > 9 ? 1.0f : 0.0f;
        }
    return m;
}

static void test_ssim_direct(void)
{
    /* sizes above and below a band (32 rows) and the window (11) */
    const int sizes[][3] = {{41, 70, 1}, {9, 7, 1}, {30, 45, 3}};
    for (int s = 0; s < 3; s++) {
        int w = sizes[s][0], h = sizes[s][1], ch = sizes[s][2];
        struct ssg_image *a = textured(w, h, ch, 0.1), *b = textured(w, h, ch, 0.4);
        struct ssg_image *m = disc_mask(w, h);
        struct ssg_outputs out;
        const char *peak[] = {"peak=1.5"};
        CHECK_EQ(run(a, b, NULL, peak, 1, &out), SSG_OK);
        double plain = compare_metric(&out, "ssim");
        CHECK_NEAR(plain, ssim_direct(a, b, NULL, 1.5), 1e-10);
        ssg_outputs_release(&out);
        CHECK_EQ(run(a, b, m, NULL, 0, &out), SSG_OK);
        CHECK_NEAR(compare_metric(&out, "ssim"), ssim_direct(a, b, m, 1.0), 1e-10);
        CHECK(plain > 0.05 && plain < 0.95); /* a case where SSIM is far from trivial */
        ssg_outputs_release(&out);
        ssg_image_destroy(&a);
        ssg_image_destroy(&b);
        ssg_image_destroy(&m);
    }
}

/* Differences only outside the mask: nothing measured. */
static void test_mask(void)
{
    enum { W = 40, H = 36 };
    struct ssg_image *a = textured(W, H, 1, 0.0), *b = ssg_image_create(W, H, 1);
    struct ssg_image *m = disc_mask(W, H);
    long long inside = 0;
    for (int i = 0; i < W * H; i++) {
        int in = m->data[i] > 0.5f;
        inside += in;
        b->data[i] = in ? a->data[i] : (i % 3 ? NAN : 5.0f); /* NaN outside must not leak */
    }
    struct ssg_outputs out;
    CHECK_EQ(run(a, b, m, NULL, 0, &out), SSG_OK);
    CHECK(compare_metric(&out, "rmse") == 0.0);
    CHECK(compare_metric(&out, "mae") == 0.0);
    CHECK(isinf(compare_metric(&out, "psnr")));
    CHECK(compare_metric(&out, "ssim") == 1.0);
    CHECK_EQ(compare_metric(&out, "pixels"), inside);
    CHECK(inside > 100 && inside < W * H - 100);
    const float *r = ssg_image_plane(out.images[0], 0);
    for (int i = 0; i < W * H; i++)
        if (r[i] != (m->data[i] > 0.5f ? 1.0f : 0.0f)) {
            CHECK(0); /* white inside, black outside */
            break;
        }
    ssg_outputs_release(&out);
    /* without the mask the difference counts */
    for (int i = 0; i < W * H; i++)
        b->data[i] = m->data[i] > 0.5f ? a->data[i] : a->data[i] + 0.5f;
    CHECK_EQ(run(a, b, NULL, NULL, 0, &out), SSG_OK);
    CHECK_NEAR(compare_metric(&out, "mae"), 0.5 * (W * H - inside) / (W * H), 1e-7);
    CHECK(compare_metric(&out, "ssim") < 0.99);
    ssg_outputs_release(&out);
    /* an empty mask counts nothing: the metrics are undefined */
    memset(m->data, 0, sizeof(float) * W * H);
    CHECK_EQ(run(a, b, m, NULL, 0, &out), SSG_OK);
    CHECK_EQ(compare_metric(&out, "pixels"), 0);
    CHECK(isnan(compare_metric(&out, "rmse")) && isnan(compare_metric(&out, "psnr")));
    CHECK(isnan(compare_metric(&out, "ssim")));
    ssg_outputs_release(&out);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
    ssg_image_destroy(&m);
}

/* Blue-white-red of a - b at scale 0.25; 3 channels: the largest difference, signed. */
static void test_diff_colours(void)
{
    struct ssg_image *a = ssg_image_create(5, 1, 3), *b = ssg_image_create(5, 1, 3);
    struct ssg_image *m = constant(5, 1, 1, 1.0f);
    /* per pixel, channel differences a - b */
    const float d[5][3] = {{0.25f, 0, 0}, {0, -0.125f, 0.0625f}, {0, 0, 0}, {1, 0, 0.5f},
                           {0.1f, 0.1f, 0.1f}};
    const float want[5][3] = {{1, 0, 0}, {0.5f, 0.5f, 1}, {1, 1, 1}, {1, 0, 0}, {0, 0, 0}};
    for (int x = 0; x < 5; x++)
        for (int c = 0; c < 3; c++) {
            b->data[c * 5 + x] = 0.5f;
            a->data[c * 5 + x] = 0.5f + d[x][c];
        }
    m->data[4] = 0.25f; /* not counted: black */
    struct ssg_outputs out;
    CHECK_EQ(run(a, b, m, NULL, 0, &out), SSG_OK);
    for (int x = 0; x < 5; x++)
        for (int c = 0; c < 3; c++)
            CHECK_NEAR(ssg_image_plane(out.images[0], c)[x], want[x][c], 1e-6);
    ssg_outputs_release(&out);
    const char *scale[] = {"scale=0.5"};
    CHECK_EQ(run(a, b, m, scale, 1, &out), SSG_OK);
    CHECK_NEAR(ssg_image_plane(out.images[0], 1)[0], 0.5, 1e-6); /* t = 0.5: (1, .5, .5) */
    CHECK_NEAR(ssg_image_plane(out.images[0], 2)[0], 0.5, 1e-6);
    ssg_outputs_release(&out);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
    ssg_image_destroy(&m);
}

static void test_rejects(void)
{
    struct ssg_image *a = constant(8, 8, 1, 0.5f), *wide = constant(9, 8, 1, 0.5f);
    struct ssg_image *rgb = constant(8, 8, 3, 0.5f), *small = constant(8, 7, 1, 1.0f);
    struct ssg_outputs out;
    CHECK_EQ(run(a, wide, NULL, NULL, 0, &out), SSG_E_SIZE);
    CHECK_EQ(run(a, rgb, NULL, NULL, 0, &out), SSG_E_TYPE);
    CHECK_EQ(run(rgb, a, NULL, NULL, 0, &out), SSG_E_TYPE);
    CHECK_EQ(run(a, a, small, NULL, 0, &out), SSG_E_SIZE);
    CHECK_EQ(run(a, a, rgb, NULL, 0, &out), SSG_E_CHANNELS); /* mask is scalar */
    const char *zero[] = {"scale=0"};
    CHECK_EQ(run(a, a, NULL, zero, 1, &out), SSG_E_RANGE);
    struct ssg_binding only_a[1] = {{"a", a}};
    struct ssg_diags diags = {0};
    CHECK_EQ(ssg_node_run("compare", only_a, 1, NULL, 0, NULL, &out, &diags),
             SSG_E_MISSING_INPUT);
    ssg_image_destroy(&a);
    ssg_image_destroy(&wide);
    ssg_image_destroy(&rgb);
    ssg_image_destroy(&small);
}

/* The metrics (every one: the band sums of rmse, mae, bias, the means and SSIM, FLIP's mean,
   banding's line sums) and the diff, byte for byte, with 1, 2 and 3 threads. 151 x 261 is
   5 of compare's 64-row bands (the last of 5 rows) and 17 of FLIP's 16: with 2 or 3
   threads several bands meet in each sum, so a sum per thread instead of per band, or in
   finishing order, changes the last bits. 101 rows (two bands) hid that: two partial sums
   add the same either way, and squared float differences add exactly in double; 133 rows
   (3 bands) showed a per-thread sum in 1 to 8 of the 12 comparisons, 261 rows in 8 to 12.
   Each count runs 3 times: under dynamic scheduling one run may hand every band to one
   thread. */
static void test_threads(void)
{
    enum { W = 151, H = 261 };
    struct ssg_image *a = textured(W, H, 3, 0.2), *b = textured(W, H, 3, 0.25);
    struct ssg_image *m = disc_mask(W, H);
    const char *banding[] = {"banding=6"};
    for (int on = 0; on < 2; on++) {
        struct ssg_outputs one, other;
        omp_set_num_threads(1);
        CHECK_EQ(run(a, b, m, banding, on, &one), SSG_OK);
        CHECK_EQ(one.metric_count, on ? 12 : 9);
        for (int k = 0; k < 6; k++) {
            omp_set_num_threads(2 + k % 2);
            CHECK_EQ(run(a, b, m, banding, on, &other), SSG_OK);
            CHECK_EQ(one.metric_count, other.metric_count);
            CHECK(memcmp(one.metric_values, other.metric_values,
                         sizeof one.metric_values) == 0);
            CHECK(memcmp(one.images[0]->data, other.images[0]->data,
                         sizeof(float) * 3 * W * H) == 0);
            ssg_outputs_release(&other);
        }
        ssg_outputs_release(&one);
    }
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
    ssg_image_destroy(&m);
}

int main(void)
{
    test_identical();
    test_offset();
    test_ssim_constant();
    test_ssim_direct();
    test_mask();
    test_diff_colours();
    test_rejects();
    test_threads();
    return check_report();
}
