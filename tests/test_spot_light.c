/* test_spot_light.c - spot lights (issue 45), against closed forms worked out in
 * tests/fixtures/spot.scene: a spot 2 units above a grey floor, pointing down, 4 W/sr,
 * full within 20 degrees and dark beyond 30, and a small cube that shadows part of its
 * rim. On the CPU and on GL:
 * - the G-buffer's direct light is 0.5 / pi x 4 cone(cos a) cos a / d^2 on every floor
 *   pixel: the cone's flat top, its t^2 falloff and nothing beyond the outer angle;
 * - direct_light, through the spot's one perspective face (lightmaps), equals it away
 *   from the cube's shadow and is dark inside it; the GL image agrees with the CPU's;
 * - reference_gi's direct term (Embree's shadow rays) does the same;
 * - the light map's flux sums to what the spot sends, albedo 0.5 x 2 pi I ((1 - cos 20) +
 *   (cos 20 - cos 30) / 3): the texels' solid angles on a face wider than a cube face's,
 *   each weighted by the cone;
 * - a spot within 60 degrees takes one map face, a wider one a point light's six;
 * - a cone whose inner angle is wider than its outer one is refused at the argument's
 *   line and column, in a scene line and in a glTF file (naming the light). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "light_maps.h"
#include "scene_node.h"
#include "scratch.h"
#include "common/lightmap.h"
#include "scene/gltf.h"
#include "scene/scene.h"
#include "ssgraph.h"

enum { W = 64, H = 48, MAP = 256 };
static const double PI = 3.14159265358979323846;

struct frame {
    struct ssg_image *shadowed, *direct, *reference, *position;
    float m[16]; /* the camera's view matrix */
};

static int run(const char *backend, struct frame *f)
{
    char dir[600];
    snprintf(dir, sizeof dir, "%s", tmp_path(backend));
    CHECK_EQ(graph_run_on("tests/fixtures/spot.graph", NULL, backend, dir), SSG_OK);
    f->shadowed = exr_layer(dir, "spot.exr", NULL);
    f->direct = exr_layer(dir, "spot.exr", "gbuffer_direct");
    f->reference = exr_layer(dir, "spot.exr", "reference");
    f->position = exr_layer(dir, "spot.exr", "position");
    scene_view_matrix("tests/fixtures/spot.scene", f->m);
    return f->shadowed && f->direct && f->reference && f->position;
}

static void release(struct frame *f)
{
    ssg_image_destroy(&f->shadowed), ssg_image_destroy(&f->direct);
    ssg_image_destroy(&f->reference), ssg_image_destroy(&f->position);
}

static float px(const struct ssg_image *im, int c, size_t i)
{
    return ssg_image_plane(im, c)[i];
}

static const double COS_INNER = 0.93969262078590838, COS_OUTER = 0.86602540378443865;

/* The spot's share along a direction at cosine c to its axis (spot.scene's comment). */
static double cone(double c)
{
    double t = (c - COS_OUTER) / (COS_INNER - COS_OUTER);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return t * t;
}

/* The floor's reflected radiance at horizontal distance r from the axis. */
static double floor_radiance(double r)
{
    double d2 = 4 + r * r, c = 2 / sqrt(d2);
    return 0.5 / PI * 4 * cone(c) * c / d2;
}

/* In the cube's shadow, with a margin for the filters: behind the cube seen from the
   light (x from 0.78 to 1.1, |z| < 0.12); near it: within 0.12 of that region. */
static int shadowed(const float w[3], double margin)
{
    return w[0] > 0.78 - margin && w[0] < 1.1 + margin && fabsf(w[2]) < 0.12 + margin;
}

struct tally {
    int floor, lit, dark, beyond, top;
    double worst_direct, worst_lit, worst_dark;
};

static void check_frame(const char *backend, const struct frame *f,
                        const struct ssg_image *shadow, const char *what)
{
    struct tally t = {0};
    for (size_t i = 0; i < (size_t)W * H; i++) {
        float w[3];
        if (!pixel_world(f->position, f->m, i, w) || fabsf(w[1]) > 1e-3f)
            continue; /* the background, the cube */
        double r = hypot(w[0], w[2]), want = floor_radiance(r);
        t.floor++;
        t.beyond += r > 1.2;
        t.top += r < 0.7;
        for (int c = 0; c < 3; c++)
            t.worst_direct = fmax(t.worst_direct, fabs(px(f->direct, c, i) - want));
        double got = px(shadow, 0, i);
        if (shadowed(w, 0.0))
            t.dark++, t.worst_dark = fmax(t.worst_dark, got);
        else if (!shadowed(w, 0.12))
            t.lit++, t.worst_lit = fmax(t.worst_lit, fabs(got - want));
    }
    double top = floor_radiance(0);
    fprintf(stderr, "%s: %d floor px (%d inside 20 degrees, %d beyond 30): G-buffer direct "
            "off by %.3g at most (axis %.5f); %s: %d lit px off by %.3g, %d shadowed px at "
            "most %.3g\n", backend, t.floor, t.top, t.beyond, t.worst_direct, top, what, t.lit,
            t.worst_lit, t.dark, t.worst_dark);
    CHECK(t.floor > 1000 && t.top > 100 && t.beyond > 100 && t.dark >= 12);
    CHECK(t.worst_direct <= 1e-5 * top);
    CHECK(t.worst_lit <= 1e-4 * top);
    CHECK(t.worst_dark <= 0.02 * top);
}

/* The flux the light map holds against what the spot sends onto grey surfaces. */
static void check_flux(const char *backend, enum ssg_backend b)
{
    static const struct ssg_frame FRAME = {W, H, 50, 0.05f, 20, 1, 0, 0, 0};
    struct ssg_scene *s = NULL;
    struct ssg_diags d = {0};
    struct ssg_image *m[3] = {0};
    CHECK_EQ(ssg_scene_load("tests/fixtures/spot.scene", 1, &s, &d), SSG_OK);
    if (!s || maps_of(s, &FRAME, MAP, b, m) != SSG_OK) {
        CHECK(!"the spot's light maps");
        ssg_scene_destroy(&s);
        return;
    }
    double sum = 0;
    for (size_t i = 0; i < (size_t)MAP * MAP; i++)
        sum += px(m[2], 0, i);
    double want = 0.5 * 2 * PI * 4 * ((1 - COS_INNER) + (COS_INNER - COS_OUTER) / 3);
    fprintf(stderr, "%s: light map flux %.5f W (closed form %.5f), %d face(s)\n", backend,
            sum, want, m[0]->channels);
    CHECK_EQ(m[0]->channels, 1);
    CHECK_NEAR(sum, want, 1e-4 * want);
    images_free(m, 3);
    ssg_scene_destroy(&s);
}

static void check_parity(const struct frame *cpu, const struct frame *gl)
{
    double worst = 0;
    for (size_t i = 0; i < (size_t)W * H; i++)
        worst = fmax(worst, fabs(px(cpu->shadowed, 0, i) - px(gl->shadowed, 0, i)));
    fprintf(stderr, "direct_light CPU against GL: largest difference %.3g\n", worst);
    CHECK(worst <= 1e-4);
}

/* One face up to 60 degrees, six beyond. */
static void check_faces(void)
{
    struct ssg_light narrow = {.kind = SSG_LIGHT_SPOT}, wide = narrow, point = {0};
    ssg_light_set_cone(&narrow, 10, 60);
    ssg_light_set_cone(&wide, 10, 61);
    ssg_light_set_cone(&point, 0, 0);
    CHECK_EQ(ssg_lightmap_light_faces(&narrow, 1), 1);
    CHECK_EQ(ssg_lightmap_light_faces(&wide, 1), 6);
    CHECK_EQ(ssg_lightmap_light_faces(&point, 1), 6);
    float w[3] = {0, 0, 1};
    CHECK_NEAR(ssg_light_cone(&point, w), 1, 0);
}

/* Bad cones: a scene line's at inner_angle's file:line:column, a glTF spot's naming it. */
static void check_bad_cones(void)
{
    const char *path = scene_node_path("bad_cone.scene");
    FILE *f = fopen(path, "w");
    if (f) {
        fputs("camera(position=[0, 2, 3], target=[0, 0, 0])\n"
              "spot_light(position=[0, 2, 0], direction=[0, -1, 0],\n"
              "           inner_angle=40, outer_angle=30)\n", f);
        fclose(f);
    }
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load(path, 0, &s, &d), SSG_E_VALUE);
    CHECK(s == NULL && d.count >= 1);
    if (d.count >= 1) {
        fprintf(stderr, "(expected) %s:%d:%d: %s\n", d.items[0].file, d.items[0].line,
                d.items[0].column, d.items[0].message);
        CHECK_EQ(d.items[0].line, 3);
        CHECK_EQ(d.items[0].column, 24);
        CHECK(strstr(d.items[0].message, "inner_angle 40 is wider than outer_angle 30"));
    }
    const char *gltf = scene_node_path("bad_cone.gltf");
    f = fopen(gltf, "w");
    if (f) {
        fputs("{\"asset\": {\"version\": \"2.0\"}, \"scene\": 0, \"scenes\": [{\"nodes\": [0]}],"
              " \"nodes\": [{\"extensions\": {\"KHR_lights_punctual\": {\"light\": 0}}}],"
              " \"extensionsUsed\": [\"KHR_lights_punctual\"], \"extensions\": "
              "{\"KHR_lights_punctual\": {\"lights\": [{\"name\": \"lamp\", \"type\": \"spot\","
              " \"spot\": {\"innerConeAngle\": 0.6, \"outerConeAngle\": 0.3}}]}}}\n", f);
        fclose(f);
    }
    struct ssg_gltf *g = NULL;
    char why[512] = "";
    CHECK_EQ(ssg_gltf_load(gltf, &g, why, sizeof why), SSG_E_GLTF);
    fprintf(stderr, "(expected) %s\n", why);
    CHECK(strstr(why, "spot light 'lamp'") && strstr(why, "innerConeAngle"));
    ssg_gltf_destroy(&g);
}

int main(void)
{
    setup_tmp("spot_light");
    check_faces();
    check_bad_cones();
    struct frame cpu = {0}, gl = {0};
    if (run("cpu", &cpu)) {
        check_frame("cpu", &cpu, cpu.shadowed, "direct_light");
        check_frame("cpu", &cpu, cpu.reference, "reference_gi");
        check_flux("cpu", SSG_BACKEND_CPU);
    }
    if (run("gl", &gl)) {
        check_frame("gl", &gl, gl.shadowed, "direct_light");
        check_flux("gl", SSG_BACKEND_GL);
        if (cpu.shadowed)
            check_parity(&cpu, &gl);
    }
    release(&cpu);
    release(&gl);
    return check_report();
}
