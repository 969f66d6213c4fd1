/* test_lightmaps.c - the `lightmaps` node against what nodes/common/lightmap.h defines:
 * - a cube's six faces' texel solid angles sum to 4 pi;
 * - a plane under a directional light: its depth on the map is exact, its normal faces the
 *   light whichever way the plane's own normal points, and the flux of all its texels is
 *   albedo x E x its area;
 * - a point light in a closed box: every texel of the six faces sees a wall at the right
 *   depth (no cracks along the faces' edges or where the near plane clips), and the flux
 *   sums to albedo x I x 4 pi;
 * - a scene without point or directional lights has one empty face; a light of zero
 *   intensity gives black flux and no NaN;
 * - resolution 0 and 65536 are refused, so are more faces than the images hold and maps
 *   over the memory limit (check_scene);
 * - the environment as N directional lights (own=false): a plane under a white sky
 *   reflects albedo x sum E_i |cos| x its area (both sides), which tends to albedo x 2 pi x
 *   area; the faces follow the own lights' and carry lightprobe's uniform directions; a
 *   scene without environment light leaves them empty; own=false with no environment
 *   lights is refused;
 * - under a probe (an image) the environment lights are drawn through its brightness, a
 *   quarter of them the uniform set: a small bright patch gets most of them, the dim rest
 *   still its own, and their irradiances still add up to the probe's integral;
 * - the maps do not depend on the thread count. */
#include <math.h>
#include <omp.h>
#include <string.h>

#include "check.h"
#include "light_maps.h"
#include "common/env_lights.h"
#include "io/imageio.h"
#include "scene/env.h"
#include "scene_node.h"

static const struct ssg_frame FRAME = {32, 24, 45, 0.05f, 100, 1, 0, 0, 0};

static void test_solid_angles(void)
{
    const int res[] = {16, 64, 256};
    for (int k = 0; k < 3; k++) {
        double sum = 0;
        for (int y = 0; y < res[k]; y++)
            for (int x = 0; x < res[k]; x++)
                sum += 6.0 * ssg_lightmap_texel_solid_angle(1.0f, res[k], x, y);
        fprintf(stderr, "cube %d: texel solid angles sum to 4 pi x %.6f\n", res[k],
                sum / (4 * M_PI));
        CHECK_NEAR(sum / (4 * M_PI), 1.0, k == 0 ? 2e-3 : 1e-4);
    }
}

/* A 2 x 2 plane at y = 0.25 (normal up or down), the sun straight down on it. */
static void plane_under_sun(const char *normal)
{
    char text[600];
    snprintf(text, sizeof text,
             "camera(position=[0, 2, 3], target=[0, 0, 0])\n"
             "m = material(albedo=[0.5, 0.25, 0.8])\n"
             "plane(material=m, center=[0, 0.25, 0], normal=%s, size=[2, 0, 2])\n"
             "directional_light(direction=[0, -1, 0], color=[1, 0.5, 2], intensity=3)\n",
             normal);
    struct ssg_scene *s = scene_from_text("lightmaps_sun", text);
    if (!s)
        return;
    const int res = 256;
    struct ssg_image *m[3];
    CHECK_EQ(maps_of(s, &FRAME, res, SSG_BACKEND_CPU, m), SSG_OK);
    CHECK_EQ(m[0]->channels, 1);
    float radius = ssg_scene_bounding_sphere(s).radius;
    double flux[3] = {0, 0, 0};
    int covered = 0;
    for (int y = 0; y < res; y++)
        for (int x = 0; x < res; x++) {
            if (px_at(m[0], 0, x, y) >= SSG_SHADOW_EMPTY)
                continue;
            covered++;
            CHECK_NEAR(px_at(m[0], 0, x, y), radius, 1e-5);
            CHECK_EQ(px_at(m[1], 1, x, y), 1.0f); /* faces the light */
            for (int c = 0; c < 3; c++)
                flux[c] += px_at(m[2], c, x, y);
        }
    const double albedo[3] = {0.5, 0.25, 0.8}, e[3] = {3, 1.5, 6};
    float texel = 2 * radius / res;
    fprintf(stderr, "plane (normal %s) under the sun: %d texels (area %.4f), flux %.4f %.4f "
            "%.4f, albedo E area %.4f %.4f %.4f\n", normal, covered,
            covered * texel * texel, flux[0], flux[1], flux[2], albedo[0] * e[0] * 4,
            albedo[1] * e[1] * 4, albedo[2] * e[2] * 4);
    for (int c = 0; c < 3; c++) /* the texel centres quantise the edge: 8 / 2 texel / 4 */
        CHECK_NEAR(flux[c] / (albedo[c] * e[c] * 4.0), 1.0, 8.0 * texel / 2.0 / 4.0);
    images_free(m, 3);
    ssg_scene_destroy(&s);
}

/* A point light inside a closed 2 x 2 x 2 box (a box primitive: both faces of its walls
   count), off centre so the faces see walls at different depths. */
static void test_closed_box(void)
{
    struct ssg_scene *s = scene_from_text(
        "lightmaps_box", "camera(position=[0, 0, 5], target=[0, 0, 0])\n"
                         "m = material(albedo=[0.6, 0.6, 0.6])\n"
                         "box(material=m, center=[0, 0, 0], size=[2, 2, 2])\n"
                         "point_light(position=[0.2, -0.3, 0.1], color=[1, 1, 1], "
                         "intensity=2)\n");
    if (!s)
        return;
    const int res = 64;
    struct ssg_image *m[3];
    CHECK_EQ(maps_of(s, &FRAME, res, SSG_BACKEND_CPU, m), SSG_OK);
    CHECK_EQ(m[0]->channels, 6);
    struct ssg_lightmap_face faces[6];
    CHECK_EQ(ssg_lightmap_faces(s, SSG_LIGHTMAP_OWN_ONLY, faces, 6), 6);
    double flux = 0, worst = 0;
    int holes = 0;
    for (int f = 0; f < 6; f++)
        for (int y = 0; y < res; y++)
            for (int x = 0; x < res; x++) {
                float z = px_at(m[0], f, x, y), p[3];
                holes += z >= SSG_SHADOW_EMPTY;
                ssg_lightmap_texel_point(&faces[f], res, x, y, z, p);
                /* the point is on a wall: one coordinate at +-1, the others inside */
                float out = fmaxf(fabsf(p[0]), fmaxf(fabsf(p[1]), fabsf(p[2])));
                worst = fmax(worst, fabs(out - 1.0));
                flux += px_at(m[2], 3 * f, x, y);
            }
    fprintf(stderr, "point light in a closed box: %d empty texels, texel points off the walls "
            "by %.2g at most, flux %.5f = albedo I 4 pi x %.6f\n", holes, worst, flux,
            flux / (0.6 * 2 * 4 * M_PI));
    CHECK_EQ(holes, 0);
    CHECK(worst < 1e-4);
    CHECK_NEAR(flux / (0.6 * 2 * 4 * M_PI), 1.0, 1e-3);
    images_free(m, 3);
    ssg_scene_destroy(&s);
}

static void test_no_lights_and_dark_light(void)
{
    struct ssg_scene *s = scene_from_text(
        "lightmaps_none", "camera(position=[0, 2, 3], target=[0, 0, 0])\n"
                          "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[2, 0, 2])\n");
    struct ssg_scene *d = scene_from_text(
        "lightmaps_dark", "camera(position=[0, 2, 3], target=[0, 0, 0])\n"
                          "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[2, 0, 2])\n"
                          "point_light(position=[0, 1, 0], color=[1, 1, 1], intensity=0)\n");
    if (!s || !d)
        return;
    struct ssg_image *m[3];
    CHECK_EQ(maps_of(s, &FRAME, 16, SSG_BACKEND_CPU, m), SSG_OK);
    int bad = 0;
    for (size_t i = 0; i < 16 * 16; i++)
        bad += m[0]->data[i] != SSG_SHADOW_EMPTY;
    for (size_t i = 0; i < 3 * 16 * 16; i++)
        bad += m[1]->data[i] != 0.0f || m[2]->data[i] != 0.0f;
    CHECK_EQ(bad, 0);
    images_free(m, 3);
    CHECK_EQ(maps_of(d, &FRAME, 32, SSG_BACKEND_CPU, m), SSG_OK);
    int floor = 0;
    for (size_t i = 0; i < 18 * 32 * 32; i++) {
        bad += m[2]->data[i] != 0.0f || isnan(m[1]->data[i]);
        floor += i < 6 * 32 * 32 && m[0]->data[i] < SSG_SHADOW_EMPTY;
    }
    CHECK_EQ(bad, 0);
    CHECK(floor > 900); /* the floor fills the -y face: it still casts shadows */
    images_free(m, 3);
    ssg_scene_destroy(&s);
    ssg_scene_destroy(&d);
}

/* A 2 x 2 plane at y = 0 under a white sky (radiance 1), no own lights, as 64 environment
   lights at 128 texels. */
static void test_environment(void)
{
    const char *sky = "camera(position=[0, 2, 3], target=[0, 0, 0])\n"
                      "m = material(albedo=[0.5, 0.5, 0.5])\n"
                      "plane(material=m, center=[0, 0, 0], normal=[0, 1, 0], size=[2, 0, 2])\n"
                      "directional_light(direction=[0, -1, 0], intensity=1)\n";
    char text[400];
    snprintf(text, sizeof text, "%senvironment(color=[1, 1, 1])\n", sky);
    struct ssg_scene *s = scene_from_text("lightmaps_sky", text);
    struct ssg_scene *dark = scene_from_text("lightmaps_nosky", sky);
    if (!s || !dark)
        return;
    enum { N = 64, RES = 128 };
    const struct ssg_lightmap_sources env = {0, N, 1}, both = {1, N, 1};
    struct ssg_lightmap_face faces[N + 1];
    CHECK_EQ(ssg_lightmap_face_count(s, both), N + 1);
    CHECK_EQ(ssg_lightmap_faces(s, both, faces, N + 1), N + 1);
    float dirs[3 * N];
    ssg_lightmap_env_directions(s, N, dirs);
    CHECK_EQ(faces[0].light, 0);
    int bad = 0;
    for (int k = 0; k < N; k++) { /* face k + 1 looks along -d_k, light k */
        const struct ssg_lightmap_face *f = &faces[k + 1];
        bad += ssg_lightmap_face_env(f) != k || !f->ortho;
        for (int c = 0; c < 3; c++)
            bad += fabsf(f->axis[c] + dirs[3 * k + c]) > 1e-6f;
    }
    CHECK_EQ(bad, 0);
    double e[3 * N];
    CHECK_EQ(ssg_env_lights_regions(s->env, dirs, N, e), SSG_OK);
    double want = 0, total = 0;
    for (int k = 0; k < N; k++) /* the plane's area 4, both sides, albedo 0.5 */
        want += 0.5 * 4.0 * e[3 * k] * fabs(dirs[3 * k + 1]), total += e[3 * k];
    struct ssg_image *m[3];
    CHECK_EQ(maps_with(s, &FRAME, RES, env, SSG_BACKEND_CPU, m), SSG_OK);
    CHECK_EQ(m[0]->channels, N);
    double flux = 0;
    for (size_t i = 0; i < (size_t)N * RES * RES; i++)
        flux += m[2]->data[3 * (i / ((size_t)RES * RES)) * RES * RES + i % ((size_t)RES * RES)];
    fprintf(stderr, "plane under a white sky as %d lights: flux %.4f, sum albedo E |cos| area "
            "%.4f (x %.4f), albedo 2 pi area %.4f; the E_i sum to 4 pi x %.5f\n", N, flux,
            want, flux / want, 0.5 * 2 * M_PI * 4, total / (4 * M_PI));
    CHECK_NEAR(total / (4 * M_PI), 1.0, 1e-3);
    CHECK_NEAR(flux / want, 1.0, 0.02); /* the texel centres quantise the plane's edges */
    CHECK_NEAR(flux / (0.5 * 2 * M_PI * 4), 1.0, 0.05);
    images_free(m, 3);
    /* without environment light the environment's faces stay empty */
    CHECK_EQ(maps_with(dark, &FRAME, 32, both, SSG_BACKEND_CPU, m), SSG_OK);
    for (size_t i = 32 * 32; i < (size_t)(N + 1) * 32 * 32; i++)
        bad += m[0]->data[i] != SSG_SHADOW_EMPTY;
    for (size_t i = 3 * 32 * 32; i < 3 * (size_t)(N + 1) * 32 * 32; i++)
        bad += m[2]->data[i] != 0.0f;
    CHECK_EQ(bad, 0);
    images_free(m, 3);
    /* own=false, environment=0: nothing to map */
    const char *none[] = {"own=false"};
    void *params = node_params(&ssg_node_lightmaps, none, 1);
    struct ssg_shape out[3];
    char why[200];
    CHECK_EQ(ssg_node_lightmaps.check(params, &FRAME, NULL, out, why, sizeof why), SSG_E_VALUE);
    fprintf(stderr, "own=false environment=0: %s\n", why);
    free(params);
    ssg_scene_destroy(&s);
    ssg_scene_destroy(&dark);
}

/* A 64 x 32 probe of radiance 0.1 with a patch of 100 over texels [px, px + 8) x [py, py
   + 4) (about 1.3 % of the sphere, 93 % of its light). */
enum { PROBE_W = 64, PROBE_H = 32, PATCH_X = 16, PATCH_Y = 13 };

static int in_patch(const float d[3])
{
    float u, v;
    ssg_env_latlong(d, &u, &v);
    int x = (int)(u * PROBE_W), y = (int)(v * PROBE_H);
    return x >= PATCH_X && x < PATCH_X + 8 && y >= PATCH_Y && y < PATCH_Y + 4;
}

static void test_environment_probe(void)
{
    struct ssg_image *p = ssg_image_create(PROBE_W, PROBE_H, 3);
    for (int c = 0; c < 3; c++)
        for (int y = 0; y < PROBE_H; y++)
            for (int x = 0; x < PROBE_W; x++)
                p->data[(c * PROBE_H + y) * PROBE_W + x] =
                    x >= PATCH_X && x < PATCH_X + 8 && y >= PATCH_Y && y < PATCH_Y + 4 ? 100.0f
                                                                                      : 0.1f;
    struct ssg_exr_layer layer = {.image = p, .kind = SSG_LAYER_COLOR};
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_exr_write(scene_node_path("lightmaps_patch.exr"), &layer, 1, &d), SSG_OK);
    ssg_image_destroy(&p);
    struct ssg_scene *s = scene_from_text(
        "lightmaps_probe", "camera(position=[0, 2, 3], target=[0, 0, 0])\n"
                           "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[2, 0, 2])\n"
                           "environment(image=\"lightmaps_patch.exr\")\n");
    if (!s)
        return;
    enum { N = 48 };
    const struct ssg_lightmap_sources env = {0, N, 1};
    struct ssg_lightmap_face faces[N];
    CHECK_EQ(ssg_lightmap_faces(s, env, faces, N), N);
    float dirs[3 * N], fib[3 * N];
    ssg_lightmap_env_directions(s, N, dirs);
    ssg_env_lights_fibonacci(N, fib);
    int bad = 0, patch = 0, uniform_patch = 0;
    for (int k = 0; k < N; k++) {
        for (int c = 0; c < 3; c++) /* the faces look along the same directions */
            bad += fabsf(faces[k].axis[c] + dirs[3 * k + c]) > 1e-6f;
        patch += in_patch(dirs + 3 * k);
        uniform_patch += in_patch(fib + 3 * k);
    }
    CHECK_EQ(bad, 0);
    /* the last 12 (a quarter) are the uniform set of 12: the dim sky keeps lights */
    float twelve[3 * 12];
    ssg_env_lights_fibonacci(12, twelve);
    for (int k = 0; k < 12 * 3; k++)
        bad += fabsf(dirs[3 * (N - 12) + k] - twelve[k]) > 1e-6f;
    CHECK_EQ(bad, 0);
    double e[3 * N], total = 0, integral = 0;
    CHECK_EQ(ssg_env_lights_regions(s->env, dirs, N, e), SSG_OK);
    for (int k = 0; k < N; k++)
        total += e[3 * k];
    for (int y = 0; y < PROBE_H; y++) /* the probe's integral: radiance x texel solid angle */
        integral += (2 * M_PI / PROBE_W) * (cos(M_PI * y / PROBE_H) - cos(M_PI * (y + 1) / PROBE_H)) *
                    (PROBE_W * 0.1 + (y >= PATCH_Y && y < PATCH_Y + 4 ? 8 * (100 - 0.1) : 0));
    fprintf(stderr, "a bright patch under 48 environment lights: %d in it (uniform: %d); "
            "the E_i sum to %.4f of the probe's integral\n", patch, uniform_patch,
            total / integral);
    CHECK(patch >= 24); /* 36 drawn through the probe, 93 % of whose light is the patch's */
    CHECK(uniform_patch <= 2);
    CHECK_NEAR(total / integral, 1.0, 1e-3);
    ssg_scene_destroy(&s);
}

static void test_bounds(void)
{
    void *params = node_params(&ssg_node_lightmaps, NULL, 0);
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_param_set_text(ssg_node_lightmaps.params, params, "resolution=0", "<test>",
                                "lightmaps", &d), SSG_E_RANGE);
    CHECK_EQ(ssg_param_set_text(ssg_node_lightmaps.params, params, "resolution=65536",
                                "<test>", "lightmaps", &d), SSG_E_RANGE);
    ssg_diags_print(&d, stderr);
    /* 114 point lights: 684 faces, 2 more than the normal image's 2048 channels hold */
    char *text = malloc(114 * 80 + 200);
    strcpy(text, "camera(position=[0, 2, 3], target=[0, 0, 0])\n"
                 "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[2, 0, 2])\n");
    for (int i = 0; i < 114; i++)
        sprintf(text + strlen(text), "point_light(position=[0, %d, 0], intensity=1)\n", i + 1);
    struct ssg_scene *s = scene_from_text("lightmaps_many", text);
    free(text);
    struct ssg_lightmaps_params *p = params;
    struct ssg_shape out[3];
    char why[300];
    p->resolution = 16;
    CHECK_EQ(ssg_node_lightmaps.check_scene(p, s, NULL, out, why, sizeof why), SSG_E_SIZE);
    fprintf(stderr, "114 point lights: %s\n", why);
    ssg_scene_destroy(&s);
    s = scene_from_text("lightmaps_one", "camera(position=[0, 2, 3], target=[0, 0, 0])\n"
                                         "point_light(position=[0, 1, 0], intensity=1)\n");
    CHECK_EQ(ssg_node_lightmaps.check_scene(p, s, NULL, out, why, sizeof why), SSG_OK);
    CHECK_EQ(out[0].channels * 100 + out[2].channels, 618);
    p->resolution = 8192; /* 3 x 6 x 8192^2 floats: over 512 Mi */
    CHECK_EQ(ssg_node_lightmaps.check_scene(p, s, NULL, out, why, sizeof why), SSG_E_SIZE);
    fprintf(stderr, "a point light at 8192: %s\n", why);
    ssg_scene_destroy(&s);
    free(params);
}

static void test_threads(void)
{
    struct ssg_scene *s = scene_from_text(
        "lightmaps_threads", "camera(position=[0, 1, 3.9], target=[0, 1, 0])\n"
                             "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[2, 0, 2])\n"
                             "box(center=[0.2, 0.3, 0], size=[0.5, 0.6, 0.5], "
                             "rotate=[0, 20, 0])\n"
                             "point_light(position=[0, 1.5, 0.2], intensity=2)\n"
                             "directional_light(direction=[-0.3, -1, -0.2], intensity=1)\n");
    if (!s)
        return;
    struct ssg_image *a[3], *b[3];
    omp_set_num_threads(1);
    CHECK_EQ(maps_of(s, &FRAME, 48, SSG_BACKEND_CPU, a), SSG_OK);
    omp_set_num_threads(3);
    CHECK_EQ(maps_of(s, &FRAME, 48, SSG_BACKEND_CPU, b), SSG_OK);
    for (int i = 0; i < 3; i++)
        CHECK(memcmp(a[i]->data, b[i]->data,
                     sizeof(float) * 48 * 48 * (size_t)a[i]->channels) == 0);
    images_free(a, 3);
    images_free(b, 3);
    ssg_scene_destroy(&s);
}

int main(void)
{
    test_solid_angles();
    plane_under_sun("[0, 1, 0]");
    plane_under_sun("[0, -1, 0]");
    test_closed_box();
    test_no_lights_and_dark_light();
    test_environment();
    test_environment_probe();
    test_bounds();
    test_threads();
    return check_report();
}
