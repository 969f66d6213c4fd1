/* test_bounce.c - the indirect bounce of SSDO (Szentandrasi sec. 3.2.2, eq. 3/4 in the
 * patch form of nodes/ssdo/ssdo_sampling.h): the `bounce` node and ssdo's bounce output, on
 * G-buffers ray-cast from planes (tests/planes.h).
 *
 * - A floor beside a uniformly lit coloured wall (the corner of planes.h; light = colour L
 *   on the wall, 0 on the floor): every sender has radiance L, so bounce = albedo L sum F_i
 *   and its channel ratios are those of albedo x L (1e-4: float rounding of sums of equal
 *   colours). Magnitude: within a factor 1.5 of the patch model of exact geometry
 *   (wall_expectation) and between 1/20 and 1 times docs/analytic.md case 3's form factor.
 * - Energy: over corner and box scenes with irregular light and albedo images and a strong
 *   bounce (strength 8, so the F_i normalisation acts), bounce <= albedo max(light) per
 *   channel (1e-6 relative: the normalised sum is computed as (sum F L) / sum F), and the
 *   bound is nearly reached somewhere (the test would notice a bounce that vanished).
 * - The bounce node gives the same bytes as ssdo bounce=true on the same inputs, with and
 *   without depth and rotation; 1 and 2 threads give the same bytes.
 * - Errors: albedo or light missing, SSG_E_MISSING_INPUT. */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "graph/node.h"
#include "ssgraph.h"

#include "planes.h"

static struct ssg_image *kernel_of(int count, struct ssg_image **rotation)
{
    char c[32];
    snprintf(c, sizeof c, "count=%d", count);
    const char *sets[] = {c, "mapping=uniform"};
    struct ssg_diags diags = {0};
    struct ssg_frame f = frame();
    struct ssg_outputs out;
    enum ssg_err e = ssg_node_run("halton", NULL, 0, sets, 2, &f, &out, &diags);
    CHECK_EQ(e, SSG_OK);
    if (e != SSG_OK)
        return NULL;
    *rotation = out.images[1];
    return out.images[0];
}

/* Deterministic irregular value in [0, 1) for pixel i, channel c (an integer hash). */
static float noise(size_t i, int c, unsigned salt)
{
    uint32_t h = (uint32_t)i * 2654435761u ^ (uint32_t)(c + 1) * 40503u ^ salt * 2246822519u;
    h ^= h >> 15, h *= 2246822519u, h ^= h >> 13, h *= 3266489917u, h ^= h >> 16;
    return (float)(h >> 8) * (1.0f / 16777216.0f);
}

/* Inputs of one run: which of the optional ones to bind. */
struct run {
    const struct gbuf *g;
    const struct ssg_image *kernel, *rot, *albedo, *light;
    int use_depth;
};

/* Runs `node` ("ssdo" with bounce=true, or "bounce"); returns the bounce image (owned). */
static struct ssg_image *bounce_of(const char *node, const struct run *r,
                                   const char *const *sets, int nsets, enum ssg_err *code)
{
    struct ssg_binding b[7] = {{"position", r->g->pos}, {"normal", r->g->nrm},
                               {"kernel", r->kernel}};
    int nb = 3;
    if (r->rot)
        b[nb++] = (struct ssg_binding){"rotation", r->rot};
    if (r->use_depth)
        b[nb++] = (struct ssg_binding){"depth", r->g->depth};
    if (r->albedo)
        b[nb++] = (struct ssg_binding){"albedo", r->albedo};
    if (r->light)
        b[nb++] = (struct ssg_binding){"light", r->light};
    const char *all[8] = {0};
    int na = 0;
    int is_ssdo = strcmp(node, "ssdo") == 0;
    if (is_ssdo)
        all[na++] = "bounce=true";
    for (int i = 0; i < nsets && na < 8; i++)
        all[na++] = sets[i];
    struct ssg_diags diags = {0};
    struct ssg_frame f = frame();
    struct ssg_outputs o;
    enum ssg_err e = ssg_node_run(node, b, nb, all, na, &f, &o, &diags);
    if (code)
        *code = e;
    else
        CHECK_EQ(e, SSG_OK);
    if (e != SSG_OK)
        return NULL;
    struct ssg_image *keep = o.images[is_ssdo ? 1 : 0];
    ssg_image_destroy(&o.images[is_ssdo ? 0 : 1]);
    return keep;
}

/* The expected bounce / (albedo L) of a floor point at distance a from the wall, under
   the patch form with exact geometry: a sample (direction w uniform over the hemisphere,
   length l_i of the kernel) is occluded when the ray from P along w meets the wall within
   r l_i, at distance t = a / (w.x) (frame: floor normal z, wall at x = a); its patch adds
   F = (strength r^2 / K) cos_r cos_s / max(t^2, md^2) with cos_r = w.z, cos_s = a / t. So
     E = r^2 / K sum_i 1/(2 pi) integral [t < r l_i] w.z (a / t) / max(t^2, md^2) dw,
   by a midpoint rule in (theta, phi) fine enough for 1e-3. What the node does differently
   is SSDO's screen-space approximation itself: the sender P_i is where the CAMERA ray
   through the sample meets the wall, not the ray from P (moving it along the camera ray
   by up to the sample's depth behind the wall, r l_i - t), and the quadrature is K
   quasi-random directions per pixel. */
static double wall_expectation(const struct ssg_image *k, double a, double r)
{
    enum { NT = 300, NP = 300 };
    const int n = k->width;
    const double md2 = r * r / n; /* min_distance 0: sqrt(A_s / pi), strength 1 */
    double sum = 0;
    for (int it = 0; it < NT; it++) {
        double th = (it + 0.5) * (M_PI / 2) / NT, st = sin(th), ct = cos(th);
        for (int ip = 0; ip < NP; ip++) {
            double ph = -M_PI / 2 + (ip + 0.5) * M_PI / NP, wx = st * cos(ph);
            double t = a / wx, d2 = fmax(t * t, md2), g = ct * (a / t) / d2;
            int hits = 0;
            for (int i = 0; i < n; i++) {
                double x = k->data[i], y = k->data[n + i], z = k->data[2 * n + i];
                hits += t < r * sqrt(x * x + y * y + z * z);
            }
            sum += g * hits * st * ((M_PI / 2) / NT) * (M_PI / NP);
        }
    }
    return r * r / n * sum / (2 * M_PI);
}

/* docs/analytic.md case 3: the cosine-weighted fraction of the hemisphere taken by the wall
   within distance d, i.e. the form factor of that wall portion. */
static double wall_form_factor(double a, double d)
{
    double c = a / d;
    return c >= 1 ? 0 : (acos(c) - c * sqrt(1 - c * c)) / M_PI;
}

static void test_wall(void)
{
    struct scene s;
    corner_scene(&s);
    struct gbuf g;
    cast(&s, &g);
    const float wall[3] = {0.9f, 0.5f, 0.2f}, alb[3] = {0.4f, 0.6f, 0.8f};
    struct ssg_image *albedo = ssg_image_create(W, H, 3), *light = ssg_image_create(W, H, 3);
    for (size_t i = 0; i < (size_t)W * H; i++)
        for (int c = 0; c < 3; c++) {
            albedo->data[c * (size_t)W * H + i] = alb[c];
            light->data[c * (size_t)W * H + i] = g.which[i] == 1 ? wall[c] : 0.0f;
        }
    struct ssg_image *rot, *kernel = kernel_of(256, &rot);
    struct run r = {&g, kernel, rot, albedo, light, 0};
    struct ssg_image *b = kernel ? bounce_of("bounce", &r, NULL, 0, NULL) : NULL;
    if (b) {
        int rows = 0;
        double worst_hue = 0, lo_ratio = 1e9, hi_ratio = 0, lo_ff = 1e9, hi_ff = 0;
        for (int y = 0; y < H; y++) {
            size_t o = (size_t)y * W + W / 2;
            if (g.which[o] != 0)
                continue;
            double p[3] = {g.pos->data[o], g.pos->data[W * H + o], g.pos->data[2 * W * H + o]};
            double a = dot3(s.pl[1].n, p) - dot3(s.pl[1].n, s.pl[1].p0);
            double v[3];
            int n;
            for (int c = 0; c < 3; c++) {
                struct ssg_image plane = {.width = W, .height = H, .channels = 1,
                                          .data = b->data + c * (size_t)W * H};
                v[c] = mean_over(&plane, g.which, W / 4, y, 3 * W / 4, y + 1, 0, &n);
            }
            if (a >= 0.5) { /* out of reach: nothing */
                CHECK_EQ(v[0] + v[1] + v[2], 0.0);
                continue;
            }
            if (a < 0.2 || a > 0.35)
                continue; /* nearer the edge the sender shift (r l - t) is large against
                             the distance t itself; nearer the radius only a handful of
                             samples reach the wall */
            for (int c = 1; c < 3; c++) {
                double want = (alb[c] * wall[c]) / (alb[0] * wall[0]);
                worst_hue = fmax(worst_hue, fabs(v[c] / v[0] - want) / want);
            }
            double e = wall_expectation(kernel, a, 0.5), ff = wall_form_factor(a, 0.5);
            double got = v[0] / (alb[0] * wall[0]);
            lo_ratio = fmin(lo_ratio, got / e);
            hi_ratio = fmax(hi_ratio, got / e);
            lo_ff = fmin(lo_ff, got / ff);
            hi_ff = fmax(hi_ff, got / ff);
            rows++;
            if (getenv("SSDO_DEBUG"))
                fprintf(stderr, "  wall a=%.3f: bounce/(albedo L) %.5f, patch model %.5f, "
                        "form factor (case 3) %.5f\n", a, got, e, ff);
        }
        CHECK(rows >= 6);
        CHECK(worst_hue <= 1e-4);
        /* For 0.2 <= a <= 0.35 the screen-space sender position and the quasi-random
           quadrature (see wall_expectation) must not move the result by more than a
           factor 1.5 either way from the patch model of exact geometry (observed 0.74 to
           1.19). The patch model itself is far below docs/analytic.md case 3's form factor
           (0.06 against 0.24 at a = 0.21): A_s = pi r^2 / K spreads the K samples over
           the base disc, but a kernel packed towards the centre (halton falloff 2) sends
           few of them as far as the wall; SSDO_DEBUG prints all three. */
        CHECK(lo_ratio > 1 / 1.5 && hi_ratio < 1.5);
        /* Against the analytic form factor itself (the true one-bounce answer for this
           wall portion): at strength 1 the bounce stays below it and above a twentieth of
           it (observed 0.08 to 0.19). The graphs raise `strength` to 4, calibrated
           against reference_gi (README, SSDO section). */
        CHECK(hi_ff < 1.0);
        CHECK(lo_ff > 0.05);
        if (getenv("SSDO_DEBUG") || !(lo_ratio > 1 / 1.5 && hi_ratio < 1.5))
            fprintf(stderr, "  wall: node / model in [%.3f, %.3f], node / form factor in "
                    "[%.3f, %.3f]\n", lo_ratio, hi_ratio, lo_ff, hi_ff);
    }
    ssg_image_destroy(&b);
    ssg_image_destroy(&kernel);
    ssg_image_destroy(&rot);
    ssg_image_destroy(&albedo);
    ssg_image_destroy(&light);
    release(&g);
}

/* Corner and box (floor, wall and a side wall), irregular albedo and light, strength 8. */
static void test_energy(const struct ssg_image *kernel, const struct ssg_image *rot)
{
    struct scene scenes[2];
    corner_scene(&scenes[0]);
    scenes[1] = scenes[0];
    scenes[1].count = 3;
    plane_at(&scenes[1].pl[2], 1, 0, 0.5, -1.2, 0, -5);
    for (int si = 0; si < 2; si++) {
        struct gbuf g;
        cast(&scenes[si], &g);
        struct ssg_image *albedo = ssg_image_create(W, H, 3),
                         *light = ssg_image_create(W, H, 3);
        float lmax[3] = {0, 0, 0};
        for (size_t i = 0; i < (size_t)W * H; i++)
            for (int c = 0; c < 3; c++) {
                float l = 3.0f * noise(i, c, 7u + si);
                albedo->data[c * (size_t)W * H + i] = noise(i, c, 11u + si);
                light->data[c * (size_t)W * H + i] = l;
                lmax[c] = fmaxf(lmax[c], l);
            }
        struct run r = {&g, kernel, rot, albedo, light, 0};
        const char *sets[] = {"strength=8", "radius=0.8"};
        struct ssg_image *b = bounce_of("bounce", &r, sets, 2, NULL);
        double worst = 0, closest = 0;
        for (size_t i = 0; b && i < (size_t)W * H; i++)
            for (int c = 0; c < 3; c++) {
                double bound = albedo->data[c * (size_t)W * H + i] * (double)lmax[c];
                double v = b->data[c * (size_t)W * H + i];
                worst = fmax(worst, v - bound * (1 + 1e-6));
                if (bound > 0.1)
                    closest = fmax(closest, v / bound);
            }
        CHECK(b && worst <= 0);
        CHECK(closest > 0.3);
        if (getenv("SSDO_DEBUG"))
            fprintf(stderr, "  energy scene %d: largest bounce / bound %.4f\n", si, closest);
        ssg_image_destroy(&b);
        ssg_image_destroy(&albedo);
        ssg_image_destroy(&light);
        release(&g);
    }
}

/* bounce == ssdo's bounce output (same bytes), with or without depth and rotation;
   1 and 2 threads the same bytes; missing albedo or light is SSG_E_MISSING_INPUT. */
static void test_same_as_ssdo(const struct ssg_image *kernel, const struct ssg_image *rot)
{
    struct scene s;
    corner_scene(&s);
    s.count = 3;
    plane_at(&s.pl[2], 1, 0, 0.5, -1.2, 0, -5);
    struct gbuf g;
    cast(&s, &g);
    struct ssg_image *albedo = ssg_image_create(W, H, 3), *light = ssg_image_create(W, H, 3);
    for (size_t i = 0; i < (size_t)W * H * 3; i++) {
        albedo->data[i] = noise(i, 0, 3u);
        light->data[i] = 2.0f * noise(i, 1, 5u);
    }
    const size_t bytes = sizeof(float) * 3 * (size_t)W * H;
    const char *sets[] = {"radius=0.7", "strength=2", "bias=0.01"};
    for (int variant = 0; variant < 2; variant++) {
        struct run r = {&g, kernel, variant ? NULL : rot, albedo, light, variant};
        struct ssg_image *a = bounce_of("ssdo", &r, sets, 3, NULL);
        omp_set_num_threads(1);
        struct ssg_image *b1 = bounce_of("bounce", &r, sets, 3, NULL);
        omp_set_num_threads(2);
        struct ssg_image *b2 = bounce_of("bounce", &r, sets, 3, NULL);
        CHECK(a && b1 && b2);
        if (a && b1 && b2) {
            CHECK(memcmp(a->data, b1->data, bytes) == 0);
            CHECK(memcmp(b1->data, b2->data, bytes) == 0);
            int nonzero = 0;
            for (size_t i = 0; i < (size_t)W * H * 3; i++)
                nonzero += a->data[i] > 0;
            CHECK(nonzero > W * H / 10); /* the comparison is not of zeros */
        }
        ssg_image_destroy(&a);
        ssg_image_destroy(&b1);
        ssg_image_destroy(&b2);
    }
    enum ssg_err e;
    struct run no_light = {&g, kernel, rot, albedo, NULL, 0};
    struct run no_albedo = {&g, kernel, rot, NULL, light, 0};
    CHECK(bounce_of("bounce", &no_light, NULL, 0, &e) == NULL);
    CHECK_EQ(e, SSG_E_MISSING_INPUT);
    CHECK(bounce_of("bounce", &no_albedo, NULL, 0, &e) == NULL);
    CHECK_EQ(e, SSG_E_MISSING_INPUT);
    CHECK(bounce_of("ssdo", &no_light, NULL, 0, &e) == NULL);
    CHECK_EQ(e, SSG_E_MISSING_INPUT);
    ssg_image_destroy(&albedo);
    ssg_image_destroy(&light);
    release(&g);
}

int main(void)
{
    test_wall();
    struct ssg_image *rot, *kernel = kernel_of(16, &rot);
    if (kernel) {
        test_energy(kernel, rot);
        test_same_as_ssdo(kernel, rot);
    }
    ssg_image_destroy(&kernel);
    ssg_image_destroy(&rot);
    (void)count_not_one; /* planes.h helper the ssdo test uses */
    return check_report();
}
