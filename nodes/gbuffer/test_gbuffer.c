/* test_gbuffer.c - the `gbuffer` node on a scene with known answers: a camera at the origin
 * looking down -z, a 4x4 plane facing it at distance 5 and a sphere in front of it, lit by
 * a point light and a directional light. Checked per pixel against ray-casting by hand:
 * depth, normals, background zeros, the reprojection of position onto its own pixel,
 * albedo, direct light against the closed form of gbuffer.c, and the constant
 * environment's diffuse light. Also: face normals,
 * the same result on 1 and 2 threads, and the error without a scene. */
#include <omp.h>
#include <string.h>
#include <unistd.h>
#include <sys/stat.h>

#include "check.h"
#include "gbuffer/gbuffer.h"
#include "scene/scene.h"

extern const struct ssg_node_desc ssg_node_gbuffer;

enum { W = 64, H = 48 };

static const char *scene_text =
    "camera(position=[0, 0, 0], target=[0, 0, -1], up=[0, 1, 0], fov=60, near=0.1, far=100)\n"
    "wall = material(albedo=[0.5, 0.4, 0.3], specular=[0.25, 0.25, 0.25], shininess=8)\n"
    "ball = material(albedo=[0.2, 0.6, 0.9])\n"
    "plane(material=wall, center=[0, 0, -5], normal=[0, 0, 1], size=[4, 0, 4])\n"
    "sphere(material=ball, center=[1.2, 0.9, -3], radius=0.6, subdivisions=64)\n"
    "point_light(position=[0.5, -0.7, -3], color=[1, 0.8, 0.6], intensity=2)\n"
    "directional_light(direction=[0.3, 0, -1], color=[0.2, 0.3, 0.4], intensity=0.5)\n"
    "environment(color=[0.2, 0.4, 0.5], intensity=0.5)\n";

/* A constant environment of radiance L has irradiance pi L about any normal, so its
   diffuse light is albedo * L on every surface (gbuffer.c). */
static const float env_radiance[3] = {0.1f, 0.2f, 0.25f};

static const float sphere_c[3] = {1.2f, 0.9f, -3.0f}, sphere_r = 0.6f;

struct gbuf {
    struct ssg_image *out[SSG_GBUFFER_OUTPUTS]; /* back, motion: NULL, not read */
};

static enum ssg_err render(const struct ssg_scene *s, int normals, struct gbuf *g,
                           struct ssg_diags *d)
{
    static const int channels[6] = {3, 3, 1, 3, 3, 3};
    struct ssg_frame frame = {W, H, s ? s->camera.fov_y : 60, s ? s->camera.near_z : 0.1f,
                              s ? s->camera.far_z : 100, 1, 0, 0, 0};
    struct ssg_node_ctx ctx = {.desc = &ssg_node_gbuffer, .instance = "g", .frame = &frame,
                               .scene = s, .out_dir = ".", .diags = d};
    struct ssg_gbuffer_params p;
    struct ssg_gbuffer_consts c;
    ssg_params_defaults(ssg_node_gbuffer.params, &p);
    p.normals = normals;
    for (int i = 0; i < 6; i++) {
        g->out[i] = ssg_image_create(W, H, channels[i]);
        for (size_t k = 0; k < (size_t)W * H * (size_t)channels[i]; k++)
            g->out[i]->data[k] = -123.0f; /* outputs arrive with undefined contents */
    }
    g->out[SSG_GBUFFER_OUT_BACK] = NULL; /* on-demand outputs nobody reads */
    g->out[SSG_GBUFFER_OUT_MOTION] = NULL;
    struct ssg_io io = {.out = g->out};
    enum ssg_err e = ssg_node_gbuffer.prepare(&ctx, &p, &c);
    return e ? e : ssg_node_gbuffer.run_cpu(&ctx, &c, &io);
}

static void release(struct gbuf *g)
{
    for (int i = 0; i < 6; i++)
        ssg_image_destroy(&g->out[i]);
}

static float at(const struct ssg_image *im, int c, int x, int y)
{
    return ssg_image_plane(im, c)[y * W + x];
}

/* The view direction of pixel (x, y) with z = -1 (camera at the origin, no rotation). */
static void pixel_dir(const struct ssg_projection *p, int x, int y, float d[3])
{
    d[0] = ((float)x + 0.5f - p->cx) / p->f;
    d[1] = -((float)y + 0.5f - p->cy) / p->f;
    d[2] = -1.0f;
}

/* Distance from the sphere's centre to the ray's line, relative to the radius. */
static float sphere_miss(const float d[3])
{
    float dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    float cd = sphere_c[0] * d[0] + sphere_c[1] * d[1] + sphere_c[2] * d[2];
    float cc =
        sphere_c[0] * sphere_c[0] + sphere_c[1] * sphere_c[1] + sphere_c[2] * sphere_c[2];
    return sqrtf(fmaxf(cc - cd * cd / dd, 0.0f)) / sphere_r;
}

/* Nearest t along d (z = -1, so t is the depth) on the analytic sphere. */
static float sphere_t(const float d[3])
{
    float a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    float b = sphere_c[0] * d[0] + sphere_c[1] * d[1] + sphere_c[2] * d[2];
    float c = sphere_c[0] * sphere_c[0] + sphere_c[1] * sphere_c[1] +
              sphere_c[2] * sphere_c[2] - sphere_r * sphere_r;
    return (b - sqrtf(b * b - a * c)) / a;
}

/* The closed form of gbuffer.c for a point of the wall (normal +z, camera at the origin). */
static void wall_direct(const float p[3], float out[3])
{
    const float albedo[3] = {0.5f, 0.4f, 0.3f}, spec = 0.25f, shin = 8;
    const float lp[3] = {0.5f, -0.7f, -3}, lc[3] = {1, 0.8f, 0.6f}, li = 2;
    const float dl[3] = {0.3f, 0, -1}, dc[3] = {0.2f, 0.3f, 0.4f}, di = 0.5f;
    float v[3] = {-p[0], -p[1], -p[2]}, vl = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int a = 0; a < 3; a++)
        v[a] /= vl;
    float l1[3] = {lp[0] - p[0], lp[1] - p[1], lp[2] - p[2]};
    float d2 = l1[0] * l1[0] + l1[1] * l1[1] + l1[2] * l1[2], dist = sqrtf(d2);
    float dll = sqrtf(dl[0] * dl[0] + dl[2] * dl[2]);
    float lights[2][3] = {{l1[0] / dist, l1[1] / dist, l1[2] / dist},
                          {-dl[0] / dll, -dl[1] / dll, -dl[2] / dll}};
    float e[2] = {li * lights[0][2] / d2, di * lights[1][2]}; /* N = +z: N.L = L.z */
    const float *color[2] = {lc, dc};
    out[0] = out[1] = out[2] = 0;
    for (int k = 0; k < 2; k++) {
        float h[3] = {lights[k][0] + v[0], lights[k][1] + v[1], lights[k][2] + v[2]};
        float hl = sqrtf(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
        float s = powf(h[2] / hl, shin);
        for (int a = 0; a < 3; a++)
            out[a] += (albedo[a] / (float)M_PI + spec * s) * color[k][a] * e[k];
    }
}

struct tally {
    int wall, ball, background, direct_checked;
};

static void check_wall_pixel(const struct gbuf *g, int x, int y, const float d[3],
                             struct tally *t)
{
    float depth = at(g->out[2], 0, x, y), want[3];
    CHECK_NEAR(depth, 5, 2e-5);
    CHECK_NEAR(at(g->out[1], 0, x, y), 0, 1e-6);
    CHECK_NEAR(at(g->out[1], 1, x, y), 0, 1e-6);
    CHECK_NEAR(at(g->out[1], 2, x, y), 1, 1e-6);
    CHECK_NEAR(at(g->out[3], 1, x, y), 0.4, 1e-6);
    for (int a = 0; a < 3; a++)
        CHECK_NEAR(at(g->out[5], a, x, y), at(g->out[3], a, x, y) * env_radiance[a], 1e-6);
    if ((x + y) % 7 == 0) { /* a sample of the wall's pixels for the lighting */
        const float p[3] = {5 * d[0], 5 * d[1], -5};
        wall_direct(p, want);
        for (int a = 0; a < 3; a++)
            CHECK_NEAR(at(g->out[4], a, x, y), want[a], 1e-5 * (1 + want[a]));
        t->direct_checked++;
    }
    t->wall++;
}

static void check_ball_pixel(const struct gbuf *g, int x, int y, const float d[3],
                             struct tally *t)
{
    float depth = at(g->out[2], 0, x, y), want = sphere_t(d);
    CHECK_NEAR(depth, want, 2e-3); /* 64 bands: the facets lie within 5e-4 of the sphere */
    for (int a = 0; a < 3; a++) /* the analytic normal (P - C) / r */
        CHECK_NEAR(at(g->out[1], a, x, y), (want * d[a] - sphere_c[a]) / sphere_r, 2e-2);
    CHECK_NEAR(at(g->out[3], 2, x, y), 0.9, 1e-6);
    CHECK_NEAR(at(g->out[5], 2, x, y), 0.9 * env_radiance[2], 1e-6);
    CHECK(at(g->out[4], 0, x, y) >= 0);
    t->ball++;
}

static void check_background_pixel(const struct gbuf *g, int x, int y, struct tally *t)
{
    int nonzero = 0;
    for (int o = 0; o < 6; o++)
        for (int c = 0; c < g->out[o]->channels; c++)
            nonzero += at(g->out[o], c, x, y) != 0.0f;
    CHECK_EQ(nonzero, 0);
    t->background++;
}

/* Every foreground pixel's position projects back onto its own pixel centre. */
static void check_reprojection(const struct gbuf *g, const struct ssg_projection *p)
{
    double worst = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float z = at(g->out[0], 2, x, y);
            if (at(g->out[2], 0, x, y) == 0.0f)
                continue;
            CHECK_NEAR(-z, at(g->out[2], 0, x, y), 1e-6);
            double px = p->cx + p->f * at(g->out[0], 0, x, y) / -z;
            double py = p->cy - p->f * at(g->out[0], 1, x, y) / -z;
            worst = fmax(worst, fmax(fabs(px - (x + 0.5)), fabs(py - (y + 0.5))));
        }
    CHECK_NEAR(worst, 0, 1e-3);
}

static void test_known_scene(const struct ssg_scene *s)
{
    struct ssg_diags d = {0};
    struct gbuf g;
    CHECK_EQ(render(s, SSG_GBUFFER_NORMALS_SMOOTH, &g, &d), SSG_OK);
    struct ssg_frame frame = {W, H, 60, 0.1f, 100, 1, 0, 0, 0};
    struct ssg_projection p = ssg_frame_projection(&frame);
    struct tally t = {0};
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float dir[3];
            pixel_dir(&p, x, y, dir);
            float miss = sphere_miss(dir), wx = 5 * dir[0], wy = 5 * dir[1];
            int on_wall = fabsf(wx) < 1.99f && fabsf(wy) < 1.99f;
            int off_wall = fabsf(wx) > 2.01f || fabsf(wy) > 2.01f;
            if (miss < 0.95f)
                check_ball_pixel(&g, x, y, dir, &t);
            else if (miss > 1.05f && on_wall)
                check_wall_pixel(&g, x, y, dir, &t);
            else if (miss > 1.05f && off_wall)
                check_background_pixel(&g, x, y, &t);
        }
    /* the picture really has all three */
    CHECK(t.wall > 500);
    CHECK(t.ball > 30);
    CHECK(t.background > 200);
    CHECK(t.direct_checked > 50);
    check_reprojection(&g, &p);
    release(&g);
}

/* Face normals: the plane is unchanged; the sphere's normals stay unit and near smooth. */
static void test_face_normals(const struct ssg_scene *s)
{
    struct ssg_diags d = {0};
    struct gbuf smooth, face;
    CHECK_EQ(render(s, SSG_GBUFFER_NORMALS_SMOOTH, &smooth, &d), SSG_OK);
    CHECK_EQ(render(s, SSG_GBUFFER_NORMALS_FACE, &face, &d), SSG_OK);
    int differ = 0, bad = 0;
    for (int i = 0; i < W * H; i++) {
        float n[3] = {face.out[1]->data[i], face.out[1]->data[W * H + i],
                      face.out[1]->data[2 * W * H + i]};
        float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (face.out[2]->data[i] > 0)
            bad += fabsf(len - 1) > 1e-5f;
        for (int c = 0; c < 3; c++)
            differ += fabsf(face.out[1]->data[c * W * H + i] -
                            smooth.out[1]->data[c * W * H + i]) > 1e-6f;
    }
    CHECK_EQ(bad, 0);
    CHECK(differ > 0);
    CHECK_EQ(memcmp(face.out[2]->data, smooth.out[2]->data, sizeof(float) * W * H), 0);
    release(&smooth);
    release(&face);
}

static void test_threads(const struct ssg_scene *s)
{
    struct ssg_diags d = {0};
    struct gbuf one, two;
    int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    CHECK_EQ(render(s, 0, &one, &d), SSG_OK);
    omp_set_num_threads(2);
    CHECK_EQ(render(s, 0, &two, &d), SSG_OK);
    omp_set_num_threads(threads);
    for (int o = 0; o < 6; o++)
        CHECK_EQ(memcmp(one.out[o]->data, two.out[o]->data,
                        sizeof(float) * W * H * (size_t)one.out[o]->channels), 0);
    release(&one);
    release(&two);
}

static void test_no_scene(void)
{
    struct ssg_diags d = {0};
    struct gbuf g;
    CHECK_EQ(render(NULL, 0, &g, &d), SSG_E_SCENE);
    CHECK_EQ(d.count, 1);
    release(&g);
}

int main(void)
{
    const char *dir = getenv("SSG_TMP");
    char path[600];
    snprintf(path, sizeof path, "%s/gbuffer.scene", dir && dir[0] ? dir : "/tmp");
    if (dir && dir[0])
        mkdir(dir, 0755);
    FILE *f = fopen(path, "w");
    if (!f)
        return 1;
    fputs(scene_text, f);
    fclose(f);
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load(path, 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    if (s) {
        test_known_scene(s);
        test_face_normals(s);
        test_threads(s);
    }
    test_no_scene();
    ssg_scene_destroy(&s);
    return check_report();
}
