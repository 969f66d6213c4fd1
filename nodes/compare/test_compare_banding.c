/* test_compare_banding.c - the `compare` node's banding metric and region (compare.c):
 * vertical stripes A (-1)^x and horizontal ones score the definition's value (a direct
 * evaluation here, and A (1 - 1/(2r + 1)) to within the ends' share), white noise scores
 * close to s sqrt(1/H + 1/W) and far below stripes, a linear gradient scores 0 and a
 * smooth one ~0, the region restricts every metric and is cut to the frame, an empty
 * region is refused, banding is off by default (the six metrics as before), and the
 * metrics are the same bits for 1 and 4 threads on an image of several row bands. */
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "compare_test.h"
#include "graph/node.h"
#include "ssgraph.h"

static enum ssg_err run(const struct ssg_image *a, const struct ssg_image *b,
                        const char *const *sets, int set_count, struct ssg_outputs *out)
{
    struct ssg_binding bind[2] = {{"a", a}, {"b", b}};
    struct ssg_diags diags = {0};
    struct ssg_frame frame = {a->width, a->height, 45.0f, 0.05f, 100.0f, 1, 0, 0, 0};
    return ssg_node_run("compare", bind, 2, sets, set_count, &frame, out, &diags);
}

static uint64_t rng_state = 7;
static double gauss01(void) { return compare_gauss(&rng_state); }

enum { KIND_VSTRIPES, KIND_HSTRIPES, KIND_NOISE, KIND_LINEAR, KIND_SMOOTH };

/* b = 0.5 everywhere, a = b + e with e of the given kind and amplitude. */
static void make_pair(int w, int h, int kind, double amp, struct ssg_image **a,
                      struct ssg_image **b)
{
    *a = ssg_image_create(w, h, 1);
    *b = ssg_image_create(w, h, 1);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double e = kind == KIND_VSTRIPES   ? amp * (x % 2 ? -1 : 1)
                       : kind == KIND_HSTRIPES ? amp * (y % 2 ? -1 : 1)
                       : kind == KIND_NOISE    ? amp * gauss01()
                       : kind == KIND_LINEAR   ? amp * (0.7 * x / w - 0.4 * y / h)
                                               : amp * sin(1.5 * x / w) * cos(1.0 * y / h);
            (*b)->data[(size_t)y * w + x] = 0.5f;
            (*a)->data[(size_t)y * w + x] = (float)(0.5 + e);
        }
}

/* The definition, written out directly: line means m_i, the least-squares line through
   (j - i, m_j) for |j - i| <= r at 0, mean of the squared differences. */
static double direct_ms(const double *m, int n, int r)
{
    double ms = 0;
    for (int i = 0; i < n; i++) {
        double sx = 0, sxx = 0, sy = 0, sxy = 0, k = 0;
        for (int j = i - r; j <= i + r; j++) {
            if (j < 0 || j >= n)
                continue;
            double d = j - i;
            k += 1, sx += d, sxx += d * d, sy += m[j], sxy += d * m[j];
        }
        double slope = (k * sxy - sx * sy) / (k * sxx - sx * sx);
        double fit = (sy - slope * sx) / k;
        ms += (m[i] - fit) * (m[i] - fit);
    }
    return ms / n;
}

/* Banding of a whole single-channel image pair, written out directly (float e as the
   node reads it). */
static double direct_banding(const struct ssg_image *a, const struct ssg_image *b, int r)
{
    int w = a->width, h = a->height;
    double rows[512] = {0}, cols[512] = {0};
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double e = (double)a->data[(size_t)y * w + x] - (double)b->data[(size_t)y * w + x];
            rows[y] += e / w;
            cols[x] += e / h;
        }
    return sqrt(direct_ms(rows, h, r) + direct_ms(cols, w, r));
}

static void test_stripes(void)
{
    const double amp = 0.05;
    const char *sets[] = {"banding=8"};
    for (int kind = KIND_VSTRIPES; kind <= KIND_HSTRIPES; kind++) {
        struct ssg_image *a, *b;
        make_pair(200, 160, kind, amp, &a, &b);
        struct ssg_outputs out;
        CHECK_EQ(run(a, b, sets, 1, &out), SSG_OK);
        double band = compare_metric(&out, "banding");
        CHECK_NEAR(band, direct_banding(a, b, 8), 1e-9);
        /* A (1 - 1/17) in the interior; the 2 x 8 end lines of each side fit a line to
           alternating values and keep a little more. */
        CHECK(band > amp * 16.0 / 17.0 && band < amp * 1.06);
        /* Vertical stripes are all column structure, horizontal all row structure. */
        const char *on = kind == KIND_VSTRIPES ? "banding_cols" : "banding_rows";
        const char *off = kind == KIND_VSTRIPES ? "banding_rows" : "banding_cols";
        CHECK_NEAR(compare_metric(&out, on), band, 1e-12);
        CHECK(compare_metric(&out, off) < 1e-7);
        ssg_outputs_release(&out);
        ssg_image_destroy(&a);
        ssg_image_destroy(&b);
    }
}

static void test_noise_and_gradients(void)
{
    const double amp = 0.05;
    const char *sets[] = {"banding=8"};
    struct ssg_image *a, *b;
    struct ssg_outputs out;
    make_pair(200, 160, KIND_NOISE, amp, &a, &b);
    CHECK_EQ(run(a, b, sets, 1, &out), SSG_OK);
    double noise = compare_metric(&out, "banding");
    double floor_ = amp * sqrt(1.0 / 160 + 1.0 / 200);
    CHECK_NEAR(noise, direct_banding(a, b, 8), 1e-9);
    CHECK(noise > 0.7 * floor_ && noise < 1.3 * floor_);
    CHECK(noise < 0.15 * amp);
    ssg_outputs_release(&out);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
    make_pair(200, 160, KIND_LINEAR, 1.0, &a, &b);
    CHECK_EQ(run(a, b, sets, 1, &out), SSG_OK);
    CHECK(compare_metric(&out, "banding") < 1e-6); /* float images: e rounded to ~3e-8 */
    ssg_outputs_release(&out);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
    make_pair(200, 160, KIND_SMOOTH, 1.0, &a, &b);
    CHECK_EQ(run(a, b, sets, 1, &out), SSG_OK);
    /* A large error, hardly any of it banding: a curvature c leaves c r (r + 1) / 3. */
    CHECK(compare_metric(&out, "rmse") > 0.3);
    CHECK(compare_metric(&out, "banding") < 0.002 * compare_metric(&out, "rmse"));
    ssg_outputs_release(&out);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
}

/* Stripes only inside [40, 30, 120, 90): the region sees them all, the rest of the image
   none; off by default: the metrics of old. */
static void test_region(void)
{
    struct ssg_image *a, *b;
    make_pair(200, 160, KIND_VSTRIPES, 0.05, &a, &b);
    for (int y = 0; y < 160; y++)
        for (int x = 0; x < 200; x++)
            if (x < 40 || x >= 120 || y < 30 || y >= 90)
                a->data[(size_t)y * 200 + x] = 0.5f;
    struct ssg_outputs in, whole;
    const char *sets[] = {"banding=8", "region=[40, 30, 120, 90]"};
    CHECK_EQ(run(a, b, sets, 2, &in), SSG_OK);
    CHECK_EQ(compare_metric(&in, "pixels"), 80 * 60);
    CHECK_NEAR(compare_metric(&in, "rmse"), 0.05, 1e-6);
    CHECK(compare_metric(&in, "banding") > 0.05 * 16.0 / 17.0);
    CHECK_EQ(run(a, b, NULL, 0, &whole), SSG_OK);
    CHECK_EQ(whole.metric_count, 9); /* with flip */
    CHECK_EQ(compare_metric(&whole, "pixels"), 200 * 160);
    ssg_outputs_release(&in);
    ssg_outputs_release(&whole);
    /* Cut to the frame: 160 columns x 60 rows; wholly outside: no pixel, NaN. */
    const char *part[] = {"region=[40, 30, 900, 90]"};
    CHECK_EQ(run(a, b, part, 1, &whole), SSG_OK);
    CHECK_EQ(compare_metric(&whole, "pixels"), 160 * 60);
    ssg_outputs_release(&whole);
    const char *outside[] = {"region=[300, 200, 400, 300]", "banding=4"};
    CHECK_EQ(run(a, b, outside, 2, &whole), SSG_OK);
    CHECK_EQ(compare_metric(&whole, "pixels"), 0);
    CHECK(isnan(compare_metric(&whole, "rmse")) && isnan(compare_metric(&whole, "banding")));
    ssg_outputs_release(&whole);
    const char *empty[] = {"region=[40, 30, 40, 90]"};
    CHECK_EQ(run(a, b, empty, 1, &whole), SSG_E_VALUE);
    const char *three[] = {"region=[1, 2, 3]"};
    CHECK_EQ(run(a, b, three, 1, &whole), SSG_E_RANGE);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
}

/* 3 channels over 300 rows (5 row bands of 64): the same bits for 1 and 4 threads. */
static void test_threads(void)
{
    enum { W = 170, H = 300 };
    struct ssg_image *a = ssg_image_create(W, H, 3), *b = ssg_image_create(W, H, 3);
    for (size_t i = 0; i < (size_t)W * H * 3; i++) {
        a->data[i] = (float)(0.5 + 0.1 * gauss01() + 0.01 * ((i % W) % 3));
        b->data[i] = 0.5f;
    }
    const char *sets[] = {"banding=6", "region=[3, 5, 160, 290]"};
    struct ssg_outputs one, four;
    omp_set_num_threads(1);
    CHECK_EQ(run(a, b, sets, 2, &one), SSG_OK);
    omp_set_num_threads(4);
    CHECK_EQ(run(a, b, sets, 2, &four), SSG_OK);
    CHECK_EQ(one.metric_count, 12); /* with flip */
    CHECK_EQ(one.metric_count, four.metric_count);
    CHECK(memcmp(one.metric_values, four.metric_values, sizeof one.metric_values) == 0);
    CHECK(compare_metric(&one, "banding_cols") > 0.003); /* the period-3 column pattern */
    ssg_outputs_release(&one);
    ssg_outputs_release(&four);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
}

int main(void)
{
    test_stripes();
    test_noise_and_gradients();
    test_region();
    test_threads();
    return check_report();
}
