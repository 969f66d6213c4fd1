/* test_lightprobe.c - the `lightprobe` node (hybrid AO's light list) against closed forms:
 * - a constant sky L: the lights' irradiances add up to 4 pi L, each about 4 pi L / N, and
 *   an upward plane receives about pi L;
 * - a probe black but for one bright texel: exactly one light carries it, the light
 *   nearest to the texel, with the texel's radiance times its solid angle;
 * - the courtyard probe, N = 128, both samplings: the total equals the probe's integral
 *   (the sum over its texels of L dOmega) and the irradiance of an unoccluded upward plane,
 *   sum_i max(0, l_i.y) E_i, is within a stated tolerance of the exact integral of
 *   L max(0, y) over the probe's texels;
 * - importance sampling puts more lights where the probe is bright; it is the uniform set
 *   for a constant sky, and uniform_share keeps that share of the uniform set;
 * - errors (no environment, count out of range) and CPU/GL parity (the same bytes);
 * - the lights' irradiances, as doubles, the same bits for 1, 2 and 3 threads on a probe of
 *   many bands. */
#include <omp.h>
#include <string.h>

#include "check.h"
#include "scene/env.h"
#include "io/imageio.h"
#include "lightprobe/lightprobe.h"
#include "scene_node.h"

static const struct ssg_frame FRAME = {64, 48, 45, 0.05f, 100, 1, 0, 0, 0};

struct lights {
    int n;
    struct ssg_image *im;
};

static const float *dir_of(const struct lights *l, int i, float d[3])
{
    for (int c = 0; c < 3; c++)
        d[c] = l->im->data[(c * 2 + 0) * l->n + i];
    return d;
}

static double irr(const struct lights *l, int i, int c)
{
    return l->im->data[(c * 2 + 1) * l->n + i];
}

/* extra: one more parameter (NULL: none) */
static struct lights run_probe_with(const struct ssg_scene *s, int n, const char *sampling,
                                    const char *extra, enum ssg_backend backend)
{
    char count[32], mode[48];
    snprintf(count, sizeof count, "count=%d", n);
    snprintf(mode, sizeof mode, "sampling=%s", sampling);
    const char *sets[] = {count, mode, extra};
    void *params = node_params(&ssg_node_lightprobe, sets, extra ? 3 : 2);
    struct lights l = {n, ssg_image_create(n, 2, 3)};
    struct ssg_image *out[1] = {l.im};
    const struct ssg_image *in[1] = {NULL};
    CHECK_EQ(node_run_scene(&ssg_node_lightprobe, s, &FRAME, params, in, out, backend), SSG_OK);
    free(params);
    return l;
}

static struct lights run_probe(const struct ssg_scene *s, int n, const char *sampling,
                               enum ssg_backend backend)
{
    return run_probe_with(s, n, sampling, NULL, backend);
}

static const char *const GEOMETRY =
    "camera(position=[0, 1, 3], target=[0, 0, 0])\n"
    "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[2, 0, 2])\n";

/* GEOMETRY under a constant sky of radiance (0.5, 1, 2). */
static struct ssg_scene *constant_sky(void)
{
    char text[512];
    snprintf(text, sizeof text, "%senvironment(color=[0.5, 1, 2])\n", GEOMETRY);
    return scene_from_text("sky", text);
}

static void test_constant_sky(void)
{
    struct ssg_scene *s = constant_sky();
    if (!s)
        return;
    const float L[3] = {0.5f, 1, 2};
    struct lights l = run_probe(s, 128, "uniform", SSG_BACKEND_CPU);
    double total[3] = {0, 0, 0}, up[3] = {0, 0, 0}, lo = 1e30, hi = 0;
    for (int i = 0; i < l.n; i++) {
        float d[3];
        dir_of(&l, i, d);
        CHECK_NEAR(d[0] * d[0] + d[1] * d[1] + d[2] * d[2], 1.0, 1e-5);
        for (int c = 0; c < 3; c++) {
            total[c] += irr(&l, i, c);
            up[c] += irr(&l, i, c) * (d[1] > 0 ? d[1] : 0);
        }
        lo = irr(&l, i, 1) < lo ? irr(&l, i, 1) : lo;
        hi = irr(&l, i, 1) > hi ? irr(&l, i, 1) : hi;
    }
    for (int c = 0; c < 3; c++) {
        CHECK_NEAR(total[c] / (4 * M_PI * L[c]), 1.0, 1e-5);
        CHECK_NEAR(up[c] / (M_PI * L[c]), 1.0, 0.01); /* measured 0.2 % */
    }
    /* Equal-area cells: every light within 15 % of 4 pi L / N (the 256 x 128 grid's texels
       make the cells' edges ragged). */
    fprintf(stderr, "constant sky: E from %.4f to %.4f, 4 pi L / N = %.4f\n", lo, hi,
            4 * M_PI / l.n);
    CHECK(lo > 0.85 * 4 * M_PI / l.n && hi < 1.15 * 4 * M_PI / l.n);
    ssg_image_destroy(&l.im);
    ssg_scene_destroy(&s);
}

/* A 64 x 32 probe, black but texel (tx, ty) = v. */
static void write_probe(const char *name, int tx, int ty, float v)
{
    struct ssg_image *p = ssg_image_create(64, 32, 3);
    for (int c = 0; c < 3; c++)
        p->data[(c * 32 + ty) * 64 + tx] = v;
    struct ssg_exr_layer layer = {.image = p, .kind = SSG_LAYER_COLOR};
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_exr_write(scene_node_path(name), &layer, 1, &d), SSG_OK);
    ssg_image_destroy(&p);
}

static void test_one_bright_texel(void)
{
    const int tx = 40, ty = 9;
    write_probe("bright.exr", tx, ty, 1000.0f);
    char text[512];
    snprintf(text, sizeof text, "%senvironment(image=\"bright.exr\")\n", GEOMETRY);
    struct ssg_scene *s = scene_from_text("bright", text);
    if (!s)
        return;
    float texel[3];
    ssg_env_direction((tx + 0.5f) / 64, (ty + 0.5f) / 32, texel);
    double omega = 2 * M_PI / 64 * (cos(M_PI * ty / 32) - cos(M_PI * (ty + 1) / 32));
    struct lights l = run_probe(s, 128, "uniform", SSG_BACKEND_CPU);
    int carriers = 0, carrier = -1, nearest = 0;
    float best = -2;
    for (int i = 0; i < l.n; i++) {
        float d[3];
        dir_of(&l, i, d);
        float dot = d[0] * texel[0] + d[1] * texel[1] + d[2] * texel[2];
        if (dot > best)
            best = dot, nearest = i;
        if (irr(&l, i, 0) > 0)
            carriers++, carrier = i;
    }
    CHECK_EQ(carriers, 1);
    CHECK_EQ(carrier, nearest);
    CHECK_NEAR(irr(&l, carrier, 0) / (1000.0 * omega), 1.0, 1e-5);
    ssg_image_destroy(&l.im);
    ssg_scene_destroy(&s);
}

/* The probe's exact integrals over its texels: of L, and of L max(0, n.w) for n = up. */
static void probe_integrals(const struct ssg_env *env, double total[3], double up[3])
{
    for (int c = 0; c < 3; c++)
        total[c] = up[c] = 0;
    for (int y = 0; y < env->height; y++) {
        double omega = 2 * M_PI / env->width *
                       (cos(M_PI * y / env->height) - cos(M_PI * (y + 1) / env->height));
        for (int x = 0; x < env->width; x++) {
            float d[3];
            ssg_env_direction((x + 0.5f) / env->width, (y + 0.5f) / env->height, d);
            const float *L = env->radiance + 3 * ((size_t)y * env->width + x);
            for (int c = 0; c < 3; c++) {
                total[c] += L[c] * omega;
                up[c] += L[c] * omega * (d[1] > 0 ? d[1] : 0);
            }
        }
    }
}

/* Lights of a sampling against the probe's own integrals; returns the share of lights
   above the horizon. */
static double check_probe_lights(const struct ssg_scene *s, const char *sampling, double tol)
{
    double total[3], up[3], lt[3] = {0, 0, 0}, lu[3] = {0, 0, 0};
    probe_integrals(s->env, total, up);
    struct lights l = run_probe(s, 128, sampling, SSG_BACKEND_CPU);
    int above = 0;
    for (int i = 0; i < l.n; i++) {
        float d[3];
        dir_of(&l, i, d);
        above += d[1] > 0;
        for (int c = 0; c < 3; c++) {
            lt[c] += irr(&l, i, c);
            lu[c] += irr(&l, i, c) * (d[1] > 0 ? d[1] : 0);
        }
    }
    for (int c = 0; c < 3; c++) {
        fprintf(stderr, "courtyard %s ch %d: total %.6g vs %.6g, upward plane %.5g vs exact "
                "%.5g (%.2f %%)\n", sampling, c, lt[c], total[c], lu[c], up[c],
                100 * (lu[c] / up[c] - 1));
        CHECK_NEAR(lt[c] / total[c], 1.0, 1e-5);
        CHECK_NEAR(lu[c] / up[c], 1.0, tol);
    }
    ssg_image_destroy(&l.im);
    return (double)above / l.n;
}

static struct ssg_scene *courtyard(void)
{
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load("examples/courtyard.scene", 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    return s;
}

/* Two runs of N lights on scene s hold the very same floats. */
static void check_same_lights(const struct ssg_scene *s, int n, const char *sampling_a,
                              enum ssg_backend backend_a, const char *sampling_b,
                              enum ssg_backend backend_b)
{
    struct lights a = run_probe(s, n, sampling_a, backend_a);
    struct lights b = run_probe(s, n, sampling_b, backend_b);
    CHECK(memcmp(a.im->data, b.im->data, sizeof(float) * 6 * (size_t)n) == 0);
    ssg_image_destroy(&a.im);
    ssg_image_destroy(&b.im);
}

static void test_courtyard_probe(void)
{
    struct ssg_scene *s = courtyard();
    if (!s)
        return;
    /* N = 128: the upward plane's irradiance within 5 % for uniform lights (measured 3.6 %
       in red, 2.0 % green, 0.7 % blue: each light stands for a cell of ~0.1 sr whose texels'
       cosines it replaces by its own, and the courtyard's sun is one bright spot off its
       light's direction) and within 1.5 % for importance-sampled ones (measured 0.6 %:
       the bright regions get small cells). */
    double up_uniform = check_probe_lights(s, "uniform", 0.05);
    double up_importance = check_probe_lights(s, "importance", 0.015);
    fprintf(stderr, "lights above the horizon: uniform %.2f, importance %.2f\n", up_uniform,
            up_importance);
    CHECK_NEAR(up_uniform, 0.5, 0.01);
    CHECK(up_importance > up_uniform + 0.1); /* the sky outshines the ground */
    /* Both backends hold the very same floats. */
    check_same_lights(s, 64, "importance", SSG_BACKEND_CPU, "importance", SSG_BACKEND_GL);
    ssg_scene_destroy(&s);
}

/* importance warps the uniform set's Fibonacci lattice: a constant sky's luminance CDF is
   the uniform one, so it gets the uniform set bit for bit; with uniform_share = 0.25 the
   last quarter of the lights is the uniform set of N / 4 exactly (the probe's dim parts
   keep lights), and the irradiances still add up to the probe's integral. uniform_share
   without sampling=importance is refused at check. */
static void test_importance_lattice(void)
{
    struct ssg_scene *sky = constant_sky();
    if (!sky)
        return;
    check_same_lights(sky, 96, "uniform", SSG_BACKEND_CPU, "importance", SSG_BACKEND_CPU);
    ssg_scene_destroy(&sky);

    struct ssg_scene *s = courtyard();
    if (!s)
        return;
    struct lights mixed = run_probe_with(s, 128, "importance", "uniform_share=0.25",
                                         SSG_BACKEND_CPU);
    float fib[3 * 32];
    ssg_env_lights_fibonacci(32, fib);
    double total[3], up[3], lt[3] = {0, 0, 0};
    probe_integrals(s->env, total, up);
    int above = 0;
    for (int i = 0; i < 128; i++) {
        float dir[3];
        dir_of(&mixed, i, dir);
        for (int c = 0; c < 3; c++) {
            lt[c] += irr(&mixed, i, c);
            if (i >= 96)
                CHECK(dir[c] == fib[3 * (i - 96) + c]);
        }
        above += i < 96 && dir[1] > 0;
    }
    for (int c = 0; c < 3; c++)
        CHECK_NEAR(lt[c] / total[c], 1.0, 1e-5);
    CHECK(above > 0.6 * 96); /* the warped ones still follow the bright sky */
    ssg_image_destroy(&mixed.im);

    const char *bad[] = {"uniform_share=0.5"};
    void *params = node_params(&ssg_node_lightprobe, bad, 1);
    struct ssg_shape in[1] = {{0}}, out[1];
    char why[256] = "";
    CHECK(ssg_node_lightprobe.check(params, &FRAME, in, out, why, sizeof why) != SSG_OK);
    CHECK(strstr(why, "sampling=importance") != NULL);
    free(params);
    ssg_scene_destroy(&s);
}

static void test_errors(void)
{
    struct ssg_scene *s = scene_from_text("dark", GEOMETRY);
    if (!s)
        return;
    void *params = node_params(&ssg_node_lightprobe, NULL, 0);
    struct ssg_image *out[1] = {ssg_image_create(128, 2, 3)};
    const struct ssg_image *in[1] = {NULL};
    fprintf(stderr, "expected error follows:\n");
    CHECK_EQ(node_run_scene(&ssg_node_lightprobe, s, &FRAME, params, in, out, SSG_BACKEND_CPU),
             SSG_E_VALUE);
    /* missing=dark: the same scene gives 128 lights that carry nothing, so one graph
       serves scenes with and without a probe. */
    const char *dark[] = {"missing=dark"};
    void *dark_params = node_params(&ssg_node_lightprobe, dark, 1);
    out[0]->data[128] = 5.0f;
    CHECK_EQ(node_run_scene(&ssg_node_lightprobe, s, &FRAME, dark_params, in, out,
                            SSG_BACKEND_CPU),
             SSG_OK);
    struct lights l = {128, out[0]};
    double sum = 0.0;
    for (int i = 0; i < 128; i++) {
        float dir[3];
        dir_of(&l, i, dir);
        CHECK_NEAR(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2], 1.0, 1e-6);
        for (int c = 0; c < 3; c++)
            sum += fabs(irr(&l, i, c));
    }
    CHECK_NEAR(sum, 0.0, 0.0);
    free(dark_params);
    struct ssg_diags d = {0};
    for (int i = 0; i < 2; i++)
        CHECK(ssg_param_set_text(ssg_node_lightprobe.params, params,
                                 i ? "count=2049" : "count=0", "<test>", "lightprobe",
                                 &d) != SSG_OK);
    ssg_image_destroy(&out[0]);
    free(params);
    ssg_scene_destroy(&s);
}

/* The regions' irradiance sums bands of 4 probe rows, added in band order: on a 151 x 133
   probe (34 bands, the last of one row) of uneven radiance, the doubles are the same bits for
   1, 2 and 3 threads (a sum per thread instead of per band, or in finishing order, changes
   the last bits; the node's float output would mostly round that away, so the doubles are
   compared). Each count runs 3 times: one run may by chance hand every band to one thread. */
static void test_threads(void)
{
    enum { PW = 151, PH = 133, N = 96 };
    struct ssg_env env = {.has_light = 1, .has_image = 1, .width = PW, .height = PH};
    env.radiance = malloc(sizeof(float) * 3 * PW * PH);
    for (int i = 0; i < 3 * PW * PH; i++)
        env.radiance[i] = (float)(1.0 + 0.9 * sin(0.37 * i) * cos(0.011 * i));
    float dirs[3 * N];
    ssg_env_lights_fibonacci(N, dirs);
    double one[3 * N], other[3 * N];
    omp_set_num_threads(1);
    CHECK_EQ(ssg_env_lights_regions(&env, dirs, N, one), SSG_OK);
    for (int k = 0; k < 6; k++) {
        omp_set_num_threads(2 + k % 2);
        CHECK_EQ(ssg_env_lights_regions(&env, dirs, N, other), SSG_OK);
        CHECK(memcmp(one, other, sizeof one) == 0);
    }
    free(env.radiance);
}

int main(void)
{
    test_constant_sky();
    test_one_bright_texel();
    test_courtyard_probe();
    test_importance_lattice();
    test_errors();
    test_threads();
    return check_report();
}
