/* test_gl_filters.c - CPU/GL parity (gl_parity.h) of the geometry-aware filters:
 * `bilateral` (full window and separable, every normal-term variant, no normal, 1 and 3
 * channels), `atrous` (1 to 4 dilated passes, rgb, in2, without normals), `upsample`
 * (factors 2, 3 and 4, odd sizes, in2 of 1 and 3 channels or none,
 * with and without normals, the closest-depth and centre fallbacks, samples taken all over
 * their blocks, slanted planes) and `downsample`
 * (factors 2 and 4, odd sizes, depth ties, background blocks, all or few ports).
 *
 * The G-buffer is synthetic: two tilted surfaces meeting at a depth step, a background
 * hole, a patch of zero normals (no tap has weight: pass-through or fallback) and one of
 * normals of length 2 (the centre is normalised, the taps are not). The GL shaders use the
 * CPU's polynomial exp and ln and its sum order, with `precise` against fused
 * multiply-adds, so the filters differ from the CPU only where the GPU rounds a division
 * or square root differently; downsample only selects pixels and must be exact. */
#include <math.h>

#include "check.h"
#include "gl_parity.h"

/* bilateral, atrous and upsample: each node's descriptor states its bound, 4x what these
   cases measure on llvmpipe in a Release build (bilateral max 7.8e-7, mean 9.3e-8; atrous
   3.6e-7, 4.5e-8; upsample 3.0e-7, 3.5e-8; a Debug build's CPU side gives 0). GLSL lets a
   GPU be 2.5 ulp off in a division and inexact in sqrt: with every division and 1/sqrt
   of both shaders perturbed by 3e-7 relative, these cases measured up to 9.5e-7 max and
   3.6e-7 mean, which such a GPU would need as its own bound. No border: taps outside the
   image are skipped on both sides, never clamped. downsample only selects: exact. */

struct gbuf {
    struct ssg_image *depth, *normal;
};

static float hash01(unsigned x)
{
    x = x * 1664525u + 1013904223u;
    x ^= x >> 15;
    x *= 2246822519u;
    x ^= x >> 13;
    return (float)(x >> 8) / 16777216.0f;
}

static struct ssg_image *noise_image(int w, int h, int channels, unsigned seed)
{
    struct ssg_image *im = ssg_image_create(w, h, channels);
    for (size_t i = 0; i < (size_t)w * h * channels; i++)
        im->data[i] = hash01((unsigned)i + 7919u * seed);
    return im;
}

/* Normal (nx, ny, nz) scaled by len into pixel o of an n-pixel plane. */
static void put_normal(struct ssg_image *im, size_t o, size_t n, const float v[3], float len)
{
    float l = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int c = 0; c < 3; c++)
        im->data[(size_t)c * n + o] = len * v[c] / l;
}

/* The synthetic G-buffer described at the top, w x h. */
static struct gbuf make_gbuf(int w, int h)
{
    struct gbuf g = {ssg_image_create(w, h, 1), ssg_image_create(w, h, 3)};
    size_t n = (size_t)w * h;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t o = (size_t)y * w + x;
            int right = x > w * 3 / 5;
            float nv[3] = {right ? 0.6f : 0.1f * sinf(0.3f * x), right ? 0.0f : 0.6f,
                           0.8f + 0.05f * cosf(0.4f * y)};
            g.depth->data[o] = right ? 6.0f + 0.03f * y : 3.0f + 0.02f * x + 0.01f * y;
            float len = x < w / 4 && y > h / 2 ? 2.0f : 1.0f;
            if (x > w / 3 && x < w / 3 + 5 && y < h / 3)
                len = 0.0f; /* a surface without a normal */
            put_normal(g.normal, o, n, nv, len);
            if (x > w / 2 && x < w / 2 + 9 && y > h / 2 && y < h / 2 + 7) {
                g.depth->data[o] = 0.0f; /* background hole */
                put_normal(g.normal, o, n, nv, 0.0f);
            }
        }
    return g;
}

static void free_gbuf(struct gbuf *g)
{
    ssg_image_destroy(&g->depth);
    ssg_image_destroy(&g->normal);
}

/* bilateral: each weight variant on one channel, then 3 channels and the separable form. */
static void bilateral_cases(void)
{
    const struct parity_tol tol = parity_tol_of("bilateral");
    struct gbuf g = make_gbuf(64, 48);
    struct ssg_image *ao = noise_image(64, 48, 1, 1), *rgb = noise_image(64, 48, 3, 2);
    struct ssg_binding b[3] = {{"in", ao}, {"depth", g.depth}, {"normal", g.normal}};
    const char *def[] = {"size=9"};
    parity_node("default (c^16)", "bilateral", b, 3, def, 1, NULL, tol);
    const char *general[] = {"normal_power=5", "size=7", "sigma_spatial=2"};
    parity_node("c^5 via ln", "bilateral", b, 3, general, 3, NULL, tol);
    const char *p1[] = {"normal_power=1", "sigma_depth=0.2"};
    parity_node("c^1", "bilateral", b, 3, p1, 2, NULL, tol);
    const char *p64[] = {"normal_power=64", "size=5"};
    parity_node("c^64", "bilateral", b, 3, p64, 2, NULL, tol);
    const char *p0[] = {"normal_power=0", "size=11"};
    parity_node("normal_power 0", "bilateral", b, 3, p0, 2, NULL, tol);
    parity_node("no normal", "bilateral", b, 2, def, 1, NULL, tol);
    /* depth weights broad enough that only the background rule keeps the hole out */
    const char *broad[] = {"sigma_depth=5"};
    parity_node("no normal broad depth", "bilateral", b, 2, broad, 1, NULL, tol);
    const char *one[] = {"size=1"};
    parity_node("size 1", "bilateral", b, 3, one, 1, NULL, tol);
    const char *tent[] = {"window=tent", "size=15", "separable=true"};
    parity_node("tent separable", "bilateral", b, 3, tent, 3, NULL, tol);
    const char *sep[] = {"separable=true", "size=15"};
    parity_node("separable", "bilateral", b, 3, sep, 2, NULL, tol);
    const char *sep_ln[] = {"separable=true", "normal_power=3"};
    parity_node("separable no normal", "bilateral", b, 2, sep_ln, 2, NULL, tol);
    b[0].image = rgb;
    parity_node("rgb", "bilateral", b, 3, general, 3, NULL, tol);
    parity_node("rgb separable", "bilateral", b, 3, sep_ln, 2, NULL, tol);
    /* in2 rides along: modulation + bounce (1 + 3), 3 + 1, and separable */
    struct ssg_binding b2[4] = {{"in", ao}, {"depth", g.depth}, {"normal", g.normal},
                                {"in2", rgb}};
    parity_node("in2 1+3", "bilateral", b2, 4, def, 1, NULL, tol);
    parity_node("in2 1+3 separable", "bilateral", b2, 4, sep, 2, NULL, tol);
    b2[0].image = rgb;
    b2[3].image = ao;
    parity_node("in2 3+1 via ln", "bilateral", b2, 4, general, 3, NULL, tol);
    ssg_image_destroy(&ao);
    ssg_image_destroy(&rgb);
    free_gbuf(&g);
}

/* atrous: the dilated passes (bilateral's shader with a step), 1 to 4 of them (the ping-pong
   through two scratch images from 3 on), with and without normals, rgb, and in2. */
static void atrous_cases(void)
{
    const struct parity_tol tol = parity_tol_of("atrous");
    struct gbuf g = make_gbuf(64, 48);
    struct ssg_image *ao = noise_image(64, 48, 1, 3), *rgb = noise_image(64, 48, 3, 4);
    struct ssg_binding b[3] = {{"in", ao}, {"depth", g.depth}, {"normal", g.normal}};
    const char *one[] = {"iterations=1"}, *two[] = {"iterations=2"};
    const char *def[] = {"iterations=3"}, *four[] = {"iterations=4", "normal_power=5"};
    parity_node("atrous 1 pass", "atrous", b, 3, one, 1, NULL, tol);
    parity_node("atrous 2 passes", "atrous", b, 3, two, 1, NULL, tol);
    parity_node("atrous 3 passes", "atrous", b, 3, def, 1, NULL, tol);
    parity_node("atrous 4 passes via ln", "atrous", b, 3, four, 2, NULL, tol);
    parity_node("atrous no normal", "atrous", b, 2, def, 1, NULL, tol);
    b[0].image = rgb;
    parity_node("atrous rgb", "atrous", b, 3, def, 1, NULL, tol);
    struct ssg_binding b2[4] = {{"in", ao}, {"depth", g.depth}, {"normal", g.normal},
                                {"in2", rgb}};
    parity_node("atrous in2 1+3", "atrous", b2, 4, def, 1, NULL, tol);
    ssg_image_destroy(&ao);
    ssg_image_destroy(&rgb);
    free_gbuf(&g);
}

/* One pixel of each k x k block of a full-res image, the one a hash picks (clipped to the
   image), as downsample keeps one (a low-res guide for factors downsample lacks): upsample
   finds it again by its depth on the tilted planes, so the taps sit all over their blocks. */
static struct ssg_image *subsample(const struct ssg_image *im, int k)
{
    int lw = (im->width + k - 1) / k, lh = (im->height + k - 1) / k;
    struct ssg_image *low = ssg_image_create(lw, lh, im->channels);
    for (int y = 0; y < lh; y++)
        for (int x = 0; x < lw; x++) {
            unsigned h = (unsigned)(hash01((unsigned)(y * lw + x)) * (float)(k * k));
            int px = x * k + (int)(h % (unsigned)k), py = y * k + (int)(h / (unsigned)k);
            px = px < im->width ? px : im->width - 1;
            py = py < im->height ? py : im->height - 1;
            for (int c = 0; c < im->channels; c++)
                low->data[((size_t)c * lh + y) * lw + x] =
                    im->data[((size_t)c * im->height + py) * im->width + px];
        }
    return low;
}

/* upsample from a w x h frame by k: 1-channel in and in2 of in2_ch channels (0 = none),
   with normals or not. Low-res background is widened by a block so that some full-res
   surface pixels see only background taps (centre fallback). */
static void upsample_case(const char *label, int w, int h, int k, int in_ch, int in2_ch,
                          int normals, const char *const *sets, int set_count)
{
    const struct parity_tol tol = parity_tol_of("upsample");
    struct gbuf g = make_gbuf(w, h);
    struct ssg_image *ld = subsample(g.depth, k), *ln = subsample(g.normal, k);
    for (int y = 0; y < 3 && y < ld->height; y++)
        for (int x = ld->width / 4; x < ld->width / 4 + 3; x++)
            ld->data[(size_t)y * ld->width + x] = 0.0f;
    struct ssg_image *in = noise_image(ld->width, ld->height, in_ch, 3);
    struct ssg_image *in2 = in2_ch ? noise_image(ld->width, ld->height, in2_ch, 4) : NULL;
    struct ssg_binding b[6] = {{"in", in}, {"depth", g.depth}, {"low_depth", ld}};
    int n = 3;
    if (normals) {
        b[n++] = (struct ssg_binding){"normal", g.normal};
        b[n++] = (struct ssg_binding){"low_normal", ln};
    }
    if (in2)
        b[n++] = (struct ssg_binding){"in2", in2};
    parity_node(label, "upsample", b, n, sets, set_count, NULL, tol);
    ssg_image_destroy(&in);
    ssg_image_destroy(&in2);
    ssg_image_destroy(&ld);
    ssg_image_destroy(&ln);
    free_gbuf(&g);
}

static void upsample_cases(void)
{
    const char *def[] = {"size=3"};
    upsample_case("k2 default", 64, 48, 2, 1, 0, 1, def, 1);
    upsample_case("k2 odd in2 rgb", 63, 47, 2, 1, 3, 1, def, 1);
    const char *wide[] = {"size=5", "normal_power=5", "sigma_spatial=1.2"};
    upsample_case("k4 rgb + in2", 64, 48, 4, 3, 1, 1, wide, 3);
    upsample_case("k3 odd no normal", 65, 49, 3, 3, 3, 0, wide, 3);
    const char *broad[] = {"sigma_depth=5"};
    upsample_case("k2 no normal broad depth", 64, 48, 2, 1, 0, 0, broad, 1);
    const char *big[] = {"size=9", "sigma_depth=0.5", "normal_power=0"};
    upsample_case("k2 size 9 p0", 64, 48, 2, 1, 1, 1, big, 3);
    const char *one[] = {"size=1"};
    upsample_case("k4 odd size 1", 61, 45, 4, 1, 0, 1, one, 1);
}

/* downsample: depths from a few levels (ties of median distance), background pixels and a
   background block; every port connected (motion's rescaling included) or only depth and
   normal. */
static void downsample_case(const char *label, int w, int h, int factor, int ports)
{
    static const char *const names[7] = {"depth", "position", "normal", "albedo", "direct",
                                         "environment", "motion"};
    const struct parity_tol exact = parity_tol_of("downsample");
    struct ssg_image *im[7];
    im[0] = ssg_image_create(w, h, 1);
    for (size_t o = 0; o < (size_t)w * h; o++) {
        unsigned q = (unsigned)(hash01((unsigned)o) * 5.0f);
        im[0]->data[o] = q == 4 ? 0.0f : 1.0f + 0.5f * (float)q;
    }
    for (int y = 0; y < 4; y++)
        for (int x = 8; x < 12; x++)
            im[0]->data[(size_t)y * w + x] = 0.0f;
    struct ssg_binding b[7] = {{names[0], im[0]}};
    for (int k = 1; k < 7; k++) {
        im[k] = noise_image(w, h, 3, 10u + (unsigned)k);
        b[k] = (struct ssg_binding){names[k], im[k]};
    }
    char set[32];
    snprintf(set, sizeof set, "factor=%d", factor);
    const char *sets[] = {set};
    if (ports == 2)
        b[1] = b[2]; /* depth and normal only */
    parity_node(label, "downsample", b, ports, sets, 1, NULL, exact);
    for (int k = 0; k < 7; k++)
        ssg_image_destroy(&im[k]);
}

int main(void)
{
    bilateral_cases();
    atrous_cases();
    upsample_cases();
    downsample_case("k2 all ports", 64, 48, 2, 7);
    downsample_case("k2 odd", 61, 37, 2, 7);
    downsample_case("k4 odd depth+normal", 63, 45, 4, 2);
    downsample_case("k4 all ports", 64, 48, 4, 7);
    return check_report();
}
