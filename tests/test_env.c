/* test_env.c - the environment light (core/scene/env.h) on light probes with known integrals,
 * written as EXR files and loaded through scene files like a user's:
 * - the lat-long convention (image centre looks down -z, row 0 straight up);
 * - a "sky" probe (radiance 1 above the horizon, 0 below): irradiance pi (1 + cos t) / 2
 *   for a normal at angle t from up, so pi up, pi/2 sideways, 0 down;
 * - a constant environment: irradiance pi L, uniform sampling pdf 1 / (4 pi);
 * - importance sampling is unbiased: the mean of L max(0, n.w) / pdf over a stratified
 *   set equals the irradiance, and pdf(sampled direction) agrees with ssg_env_pdf;
 * - the view-space cube sees what the lat-long sees;
 * - bad probes (not 2:1, NaN) are scene errors, not crashes; negative values (lossy
 *   compression's ringing) read as 0. */
#include <string.h>
#include <sys/stat.h>

#include "check.h"
#include "scene/env.h"
#include "graph/node.h"
#include "scene/scene.h"

static char tmp[512];

typedef void (*probe_fn)(float u, float v, float rgb[3]);

static void write_probe(const char *name, int w, int h, probe_fn fn)
{
    struct ssg_image *im = ssg_image_create(w, h, 3);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            float rgb[3];
            fn((x + 0.5f) / (float)w, (y + 0.5f) / (float)h, rgb);
            for (int c = 0; c < 3; c++)
                ssg_image_plane(im, c)[y * w + x] = rgb[c];
        }
    char path[700];
    snprintf(path, sizeof path, "%s/%s", tmp, name);
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_image_write(path, im, &d), SSG_OK);
    ssg_image_destroy(&im);
}

/* Loads a scene holding one plane and the given environment line. */
static enum ssg_err load(const char *environment, struct ssg_scene **s)
{
    char path[700];
    snprintf(path, sizeof path, "%s/env.scene", tmp);
    FILE *f = fopen(path, "w");
    if (!f)
        return SSG_E_IO;
    fprintf(f, "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[1, 0, 1])\n%s\n", environment);
    fclose(f);
    struct ssg_diags d = {0};
    enum ssg_err e = ssg_scene_load(path, 1, s, &d);
    ssg_diags_print(&d, stderr);
    return e;
}

static void sky(float u, float v, float rgb[3])
{
    (void)u;
    rgb[0] = rgb[1] = rgb[2] = v < 0.5f ? 1.0f : 0.0f;
}

/* A dim sky with one bright texel (a "sun") at u = 0.3, v = 0.3 of a 128 x 64 probe. */
static void sun(float u, float v, float rgb[3])
{
    int x = (int)(u * 128), y = (int)(v * 64);
    float s = (x == 38 && y == 19) ? 2000.0f : v < 0.5f ? 0.2f : 0.05f;
    rgb[0] = s, rgb[1] = 0.8f * s, rgb[2] = 0.6f * s;
}

static void bad_nan(float u, float v, float rgb[3])
{
    rgb[0] = rgb[1] = rgb[2] = (u > 0.5f && v > 0.5f) ? NAN : 1.0f;
}

static void bad_negative(float u, float v, float rgb[3])
{
    (void)v;
    rgb[0] = rgb[1] = 1.0f;
    rgb[2] = u > 0.9f ? -0.5f : 1.0f;
}

static void test_convention(void)
{
    float d[3], u, v;
    ssg_env_direction(0.5f, 0.5f, d);
    CHECK_NEAR(d[0], 0, 1e-6);
    CHECK_NEAR(d[1], 0, 1e-6);
    CHECK_NEAR(d[2], -1, 1e-6);
    ssg_env_direction(0.3f, 0.0f, d);
    CHECK_NEAR(d[1], 1, 1e-6);
    ssg_env_direction(0.75f, 0.5f, d); /* a quarter turn from -z towards +x */
    CHECK_NEAR(d[0], 1, 1e-6);
    CHECK_NEAR(d[2], 0, 1e-6);
    for (int i = 0; i < 50; i++) {
        float uu = (i * 0.618034f) - floorf(i * 0.618034f), vv = 0.02f + 0.96f * (i / 50.0f);
        ssg_env_direction(uu, vv, d);
        ssg_env_latlong(d, &u, &v);
        CHECK_NEAR(fmodf(u - uu + 1.5f, 1.0f) - 0.5f, 0, 1e-5);
        CHECK_NEAR(v, vv, 1e-5);
    }
}

/* Sky probe: E(t) = pi (1 + cos t) / 2. 1 % covers the 5.6 degree coarse texels. */
static void test_sky(void)
{
    write_probe("sky.exr", 256, 128, sky);
    struct ssg_scene *s = NULL;
    CHECK_EQ(load("environment(image=\"sky.exr\", intensity=2, color=[1, 0.5, 0.25])", &s),
             SSG_OK);
    if (!s)
        return;
    const struct ssg_env *env = s->env;
    CHECK(env && env->has_image && env->has_light);
    const float up[3] = {0, 1, 0}, side[3] = {0.6f, 0, 0.8f}, down[3] = {0, -1, 0};
    const float tilt[3] = {0, 0.5f, -0.8660254f}; /* 60 degrees from up */
    const float tint[3] = {2, 1, 0.5f};
    float e[3];
    for (int c = 0; c < 3; c++) {
        ssg_env_irradiance(env, up, e);
        CHECK_NEAR(e[c], M_PI * tint[c], 0.01 * M_PI * tint[c]);
        ssg_env_irradiance(env, side, e);
        CHECK_NEAR(e[c], M_PI / 2 * tint[c], 0.01 * M_PI * tint[c]);
        ssg_env_irradiance(env, tilt, e);
        CHECK_NEAR(e[c], M_PI * 0.75 * tint[c], 0.01 * M_PI * tint[c]);
        ssg_env_irradiance(env, down, e);
        CHECK_NEAR(e[c], 0, 0.01 * M_PI * tint[c]);
    }
    float l[3];
    ssg_env_radiance(env, up, l);
    CHECK_NEAR(l[1], 1, 1e-6);
    ssg_env_radiance(env, down, l);
    CHECK_NEAR(l[1], 0, 1e-6);
    /* The cube, in a frame turned 90 degrees about x (frame +z = world +y). */
    static struct ssg_env_cube cube;
    const float to_world[9] = {1, 0, 0, 0, 0, 1, 0, -1, 0};
    ssg_env_cube_build(env, to_world, &cube);
    CHECK_NEAR(ssg_env_cube_texel(&cube, 0, 0, 1)[0], 2, 1e-5);  /* world up */
    CHECK_NEAR(ssg_env_cube_texel(&cube, 0, 0, -1)[0], 0, 1e-5); /* world down */
    ssg_scene_destroy(&s);
}

static void test_constant(void)
{
    struct ssg_scene *s = NULL;
    CHECK_EQ(load("environment(color=[0.5, 1, 2], intensity=0.5)", &s), SSG_OK);
    if (!s)
        return;
    const float n[3] = {0.48f, 0.6f, 0.64f};
    float e[3], d[3], rgb[3];
    ssg_env_irradiance(s->env, n, e);
    CHECK_NEAR(e[0], M_PI * 0.25, 1e-5);
    CHECK_NEAR(e[2], M_PI, 1e-5);
    float pdf = ssg_env_sample(s->env, 0.3f, 0.7f, d, rgb);
    CHECK_NEAR(pdf, 1 / (4 * M_PI), 1e-7);
    CHECK_NEAR(d[0] * d[0] + d[1] * d[1] + d[2] * d[2], 1, 1e-5);
    CHECK_NEAR(rgb[1], 0.5, 1e-7);
    ssg_scene_destroy(&s);
    /* No environment line: black, nothing to sample. */
    CHECK_EQ(load("", &s), SSG_OK);
    if (s) {
        CHECK(s->env && !s->env->has_light);
        CHECK_EQ(ssg_env_sample(s->env, 0.5f, 0.5f, d, rgb), 0.0f);
    }
    ssg_scene_destroy(&s);
}

/* Unbiased importance sampling on the sun probe: a 128 x 128 stratified estimate of the
   irradiance about several normals agrees with the cosine convolution within 3 %, and
   (almost) every estimate sample's pdf is the probe pixel's share. */
static void test_sampling(void)
{
    write_probe("sun.exr", 128, 64, sun);
    struct ssg_scene *s = NULL;
    CHECK_EQ(load("environment(image=\"sun.exr\")", &s), SSG_OK);
    if (!s)
        return;
    /* Normals that see the sun well inside their hemisphere (at grazing angles the cosine
       of a one-texel sun swings with sub-texel shifts, which the coarse table makes). */
    const float normals[3][3] = {{0, 1, 0}, {-0.7694f, 0.5878f, -0.25f}, {0, 0.6f, -0.8f}};
    int mismatched = 0, sun_hits = 0;
    for (int k = 0; k < 3; k++) {
        double sum[3] = {0, 0, 0};
        const int n = 128;
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                float d[3], rgb[3];
                float pdf = ssg_env_sample(s->env, (i + 0.5f) / n, (j + 0.5f) / n, d, rgb);
                float c = d[0] * normals[k][0] + d[1] * normals[k][1] + d[2] * normals[k][2];
                mismatched += fabsf(pdf - ssg_env_pdf(s->env, d)) > 1e-3f * pdf;
                sun_hits += rgb[0] > 1000.0f;
                for (int ch = 0; ch < 3; ch++)
                    sum[ch] += c > 0 ? rgb[ch] * c / pdf : 0.0;
            }
        float e[3];
        ssg_env_irradiance(s->env, normals[k], e);
        for (int ch = 0; ch < 3; ch++)
            CHECK_NEAR(sum[ch] / (n * n), e[ch], 0.03 * e[ch]);
    }
    CHECK(mismatched < 3 * 128 * 128 / 1000); /* only texel-border round-off */
    CHECK(sun_hits > 3 * 128 * 128 / 4);      /* the sun holds most of the power */
    ssg_scene_destroy(&s);
}

static void expect_bad(const char *name, int w, int h, probe_fn fn)
{
    write_probe(name, w, h, fn);
    char line[256];
    snprintf(line, sizeof line, "environment(image=\"%s\")", name);
    struct ssg_scene *s = NULL;
    CHECK_EQ(load(line, &s), SSG_E_VALUE);
    CHECK(s == NULL);
    ssg_scene_destroy(&s);
}

int main(void)
{
    const char *dir = getenv("SSG_TMP");
    snprintf(tmp, sizeof tmp, "%s", dir && dir[0] ? dir : "/tmp");
    mkdir(tmp, 0755);
    test_convention();
    test_sky();
    test_constant();
    test_sampling();
    expect_bad("square.exr", 32, 32, sky);
    expect_bad("nan.exr", 64, 32, bad_nan);
    write_probe("negative.exr", 64, 32, bad_negative);
    struct ssg_scene *s = NULL;
    CHECK_EQ(load("environment(image=\"negative.exr\")", &s), SSG_OK);
    if (s) {
        const float d[3] = {0.309017f, 0, 0.951057f}; /* u = 0.95: a negative texel */
        float rgb[3];
        ssg_env_radiance(s->env, d, rgb);
        CHECK_EQ(rgb[2], 0.0f);
        CHECK_EQ(rgb[0], 1.0f);
    }
    ssg_scene_destroy(&s);
    return check_report();
}
