/* test_scene.c - scene files (core/scene/scene.h): every kind of mistake is reported with its
 * code at its exact line and column, all in one pass; the Cornell box loads with the
 * expected entities; primitives tessellate as documented; glTF meshes are placed and
 * their camera used; the default camera frames the scene; check mode opens no assets;
 * textures and the environment image arrive as linear RGB. */
#include <errno.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "scene/scene_build.h"
#include "scratch.h"
#include "io/imageio.h"
#include "graph/node.h"
#include "scene/rt.h"
#include "scene/scene.h"

/* ---- errors with locations ---- */

/* One expected diagnostic: on `line`, at the first occurrence of `marker` in that line. */
struct expect {
    int line;
    const char *marker;
    enum ssg_err code;
};

static const char *const bad_lines[] = {
    /*  1 */ "white = material(albedo=[1, 1, 1])",
    /*  2 */ "plane(material=whte, size=[2, 0, 2])",
    /*  3 */ "box(material=white, sise=[1, 1, 1])",
    /*  4 */ "sphere(radius=\"big\")",
    /*  5 */ "mesh(material=white)",
    /*  6 */ "mesh(\"no_such_file.gltf\")",
    /*  7 */ "teapot(size=1)",
    /*  8 */ "camera(fov=500)",
    /*  9 */ "point_light(color=[1, 1, 1])",
    /* 10 */ "floor = plane(material=white)",
    /* 11 */ "floor = box()",
    /* 12 */ "plane(material=floor)",
    /* 13 */ "set whte.albedo = 1",
    /* 14 */ "camera(position=[0, 0, 1], target=[0, 0, 1])",
    /* 15 */ "box(size=[1, 1])",
    /* 16 */ "material(texture=\"missing.png\", shininess=-1)",
    /* 17 */ "plane(normal=[0, 0, 0], size=[1, 0, 0])",
    /* 18 */ "sphere(material=white, 3)",
    /* 19 */ "size 640 480",
    /* 20 */ "set white.colour = [1, 0, 0]",
};

static const struct expect bad_expect[] = {
    {2, "whte", SSG_E_UNKNOWN_NAME},
    {3, "sise", SSG_E_UNKNOWN_PARAM},
    {4, "\"big\"", SSG_E_TYPE},
    {5, "mesh", SSG_E_MISSING_INPUT},
    {6, "\"no_such_file.gltf\"", SSG_E_IO},
    {7, "teapot", SSG_E_UNKNOWN_NODE},
    {8, "500", SSG_E_RANGE},
    {9, "point_light", SSG_E_MISSING_INPUT},
    {11, "floor", SSG_E_DUPLICATE},
    {12, "floor", SSG_E_TYPE},
    {13, "whte", SSG_E_UNKNOWN_NAME},
    {14, "camera", SSG_E_DUPLICATE},
    {14, "[0, 0, 1])", SSG_E_VALUE},
    {15, "[1, 1]", SSG_E_TYPE},
    {16, "-1", SSG_E_RANGE},
    {16, "\"missing.png\"", SSG_E_IO},
    {17, "[0, 0, 0]", SSG_E_VALUE},
    {17, "[1, 0, 0]", SSG_E_RANGE},
    {18, "3", SSG_E_SYNTAX},
    {19, "size", SSG_E_SYNTAX},
    {20, "colour", SSG_E_UNKNOWN_PARAM},
};

static int column_of(int line, const char *marker)
{
    const char *at = strstr(bad_lines[line - 1], marker);
    return at ? (int)(at - bad_lines[line - 1]) + 1 : -1;
}

static void test_errors(void)
{
    char text[4096] = "";
    for (int i = 0; i < SSG_COUNT(bad_lines); i++) {
        strcat(text, bad_lines[i]);
        strcat(text, "\n");
    }
    const char *path = write_file("bad.scene", text);
    struct ssg_diags d = {0};
    struct ssg_scene *s = (struct ssg_scene *)1;
    CHECK(ssg_scene_load(path, 0, &s, &d) != SSG_OK);
    CHECK(s == NULL);
    CHECK_EQ(d.total, SSG_COUNT(bad_expect));
    for (int i = 0; i < SSG_COUNT(bad_expect); i++) {
        const struct expect *e = &bad_expect[i];
        int col = column_of(e->line, e->marker), found = 0;
        for (int k = 0; k < d.count; k++)
            found |= d.items[k].line == e->line && d.items[k].column == col &&
                     d.items[k].code == e->code && strcmp(d.items[k].file, path) == 0;
        if (!found)
            fprintf(stderr, "missing: line %d column %d %s\n", e->line, col,
                    ssg_err_name(e->code));
        CHECK(found);
    }
    ssg_diags_print(&d, stderr);
}

/* An unknown material lists the materials that exist. */
static void test_unknown_material_message(void)
{
    const char *path = write_file("unknown_material.scene",
                                  "red = material(albedo=[1, 0, 0])\n"
                                  "blue = material(albedo=[0, 0, 1])\n"
                                  "  box(material=green)\n");
    struct ssg_diags d = {0};
    struct ssg_scene *s;
    CHECK_EQ(ssg_scene_load(path, 1, &s, &d), SSG_E_UNKNOWN_NAME);
    CHECK_EQ(d.count, 1);
    CHECK_EQ(d.items[0].line, 3);
    CHECK_EQ(d.items[0].column, 16);
    CHECK(strstr(d.items[0].message, "red, blue") != NULL);
}

static void test_missing_scene(void)
{
    struct ssg_diags d = {0};
    struct ssg_scene *s;
    CHECK_EQ(ssg_scene_load("tests/fixtures/no_such.scene", 0, &s, &d), SSG_E_IO);
    CHECK(s == NULL);
    CHECK_EQ(d.count, 1);
}

/* A lights file replaces the scene's lights and environment; its image paths are its own
   (examples/lights/courtyard.scene names ../probes/courtyard.exr). */
static void test_lights_file(void)
{
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load_lit("examples/bunny.scene", "examples/lights/sky.scene", 1, &s, &d),
             SSG_OK);
    ssg_diags_print(&d, stderr);
    if (s) {
        CHECK_EQ(s->light_count, 0); /* bunny's point and directional lights are gone */
        CHECK_NEAR(s->environment.color[0], 1, 0);
        CHECK_NEAR(s->environment.color[2], 1, 0); /* bunny's own sky is bluish */
        CHECK(s->mesh_count > 1);                  /* the geometry stays */
        ssg_scene_destroy(&s);
    }
    CHECK_EQ(ssg_scene_load_lit("examples/cornell.scene", "examples/lights/courtyard.scene", 1,
                                &s, &d), SSG_OK);
    if (s) {
        CHECK_EQ(s->light_count, 0);
        CHECK(s->environment.image >= 0);
        ssg_scene_destroy(&s);
    }
    CHECK_EQ(ssg_scene_load_lit("examples/cornell.scene", "examples/lights/sun.scene", 1, &s,
                                &d), SSG_OK);
    if (s) {
        CHECK_EQ(s->light_count, 1);
        CHECK_EQ(s->lights[0].kind, SSG_LIGHT_DIRECTIONAL);
        CHECK_NEAR(s->environment.color[1], 0, 0); /* no environment in the sun file */
        ssg_scene_destroy(&s);
    }
}

/* A lights file with geometry in it is refused at the statement, with what it may hold. */
static void test_lights_file_errors(void)
{
    const char *path = write_file("bad.lights", "environment(color=[1, 1, 1])\n"
                                                "  box(size=[1, 1, 1])\n");
    struct ssg_diags d = {0};
    struct ssg_scene *s = (struct ssg_scene *)1;
    CHECK_EQ(ssg_scene_load_lit("examples/cornell.scene", path, 0, &s, &d), SSG_E_SYNTAX);
    CHECK(s == NULL);
    CHECK_EQ(d.count, 1);
    CHECK_EQ(d.items[0].line, 2);
    CHECK_EQ(d.items[0].column, 3);
    CHECK(strcmp(d.items[0].file, path) == 0);
    CHECK(strstr(d.items[0].message, "point_light, directional_light, spot_light and environment") != NULL);
    d = (struct ssg_diags){0};
    path = write_file("two_skies.lights", "environment(color=[1, 1, 1])\n"
                                          "environment(color=[0, 0, 1])\n");
    CHECK_EQ(ssg_scene_load_lit("examples/cornell.scene", path, 0, &s, &d), SSG_E_DUPLICATE);
    d = (struct ssg_diags){0};
    path = write_file("no_probe.lights", "environment(image=\"missing.exr\")\n");
    CHECK_EQ(ssg_scene_load_lit("examples/cornell.scene", path, 0, &s, &d), SSG_E_IO);
    CHECK_EQ(d.count, 1);
    CHECK(strcmp(d.items[0].file, path) == 0); /* resolved beside the lights file */
    d = (struct ssg_diags){0};
    CHECK_EQ(ssg_scene_load_lit("examples/cornell.scene", "tests/fixtures/no_such.lights", 0,
                                &s, &d), SSG_E_IO);
}

/* ---- loading ---- */

static int count_triangles(const struct ssg_scene *s)
{
    int n = 0;
    for (int i = 0; i < s->mesh_count; i++)
        n += s->meshes[i].triangle_count;
    return n;
}

static void test_cornell(void)
{
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load("examples/cornell.scene", 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    if (!s)
        return;
    CHECK_EQ(s->has_camera, 1);
    CHECK_EQ(s->mesh_count, 7);          /* 5 walls, 2 boxes */
    CHECK_EQ(count_triangles(s), 5 * 2 + 2 * 12);
    CHECK_EQ(s->material_count, 3);      /* white, red, green: no default needed */
    CHECK_EQ(s->light_count, 1);
    CHECK_EQ(s->texture_count, 0);
    CHECK(s->rt != NULL);
    CHECK_EQ(s->lights[0].kind, SSG_LIGHT_POINT);
    CHECK_NEAR(s->lights[0].position[1], 1.9, 1e-6);
    CHECK(strcmp(s->materials[s->meshes[3].material].name, "red") == 0);
    CHECK(strcmp(s->materials[s->meshes[4].material].name, "green") == 0);
    CHECK_NEAR(s->camera.fov_y, 40, 1e-6);
    /* the floor faces up and spans [-1, 1]^2 */
    const struct ssg_mesh *floor = &s->meshes[0];
    for (int v = 0; v < floor->vertex_count; v++) {
        CHECK_NEAR(floor->normals[3 * v + 1], 1, 1e-6);
        CHECK_NEAR(fabsf(floor->positions[3 * v]), 1, 1e-6);
        CHECK_NEAR(floor->positions[3 * v + 1], 0, 1e-6);
    }
    /* a ray down the middle hits the floor at y = 0: t = 1 from y = 1 */
    struct ssg_hit h;
    const float org[3] = {0.8f, 1, 0.8f}, down[3] = {0, -1, 0};
    ssg_rt_intersect(s->rt, org, down, 0, 100, &h);
    CHECK_EQ(h.mesh, 0);
    CHECK_NEAR(h.t, 1, 1e-5);
    CHECK_EQ(ssg_rt_occluded(s->rt, org, down, 0, 0.9f), 0);
    CHECK_EQ(ssg_rt_occluded(s->rt, org, down, 0, 1.1f), 1);
    ssg_scene_destroy(&s);
    CHECK(s == NULL);
}

/* Geometric normal of triangle t agrees with its vertex normals (outward winding). */
static int winding_ok(const struct ssg_mesh *m, int t)
{
    const uint32_t *i = &m->indices[3 * t];
    const float *a = &m->positions[3 * i[0]], *b = &m->positions[3 * i[1]];
    const float *c = &m->positions[3 * i[2]];
    float e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    float e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    float g[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                  e1[0] * e2[1] - e1[1] * e2[0]};
    const float *n = &m->normals[3 * i[0]];
    return g[0] * n[0] + g[1] * n[1] + g[2] * n[2] > 0.0f;
}

static void test_shapes(void)
{
    const char *path = write_file("shapes.scene",
                                  "plane(center=[0, 1, 0], normal=[1, 0, 0], size=[2, 0, 4])\n"
                                  "box(center=[5, 0, 0], size=[2, 1, 1], rotate=[0, 90, 0])\n"
                                  "sphere(center=[0, 0, -4], radius=2, subdivisions=8)\n");
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load(path, 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    if (!s)
        return;
    CHECK_EQ(s->mesh_count, 3);
    CHECK_EQ(s->material_count, 1); /* the default one */
    CHECK_NEAR(s->materials[0].albedo[0], 0.8, 1e-6);
    CHECK_EQ(s->has_camera, 0);
    int bad = 0;
    for (int m = 0; m < 3; m++)
        for (int t = 0; t < s->meshes[m].triangle_count; t++)
            bad += !winding_ok(&s->meshes[m], t);
    CHECK_EQ(bad, 0);
    /* plane turned from +y to +x: x spans y in [0, 2] (width 2), z in [-2, 2] (depth 4) */
    const struct ssg_mesh *p = &s->meshes[0];
    for (int v = 0; v < 4; v++) {
        CHECK_NEAR(p->positions[3 * v], 0, 1e-6);
        CHECK_NEAR(fabsf(p->positions[3 * v + 1] - 1), 1, 1e-6);
        CHECK_NEAR(fabsf(p->positions[3 * v + 2]), 2, 1e-6);
        CHECK_NEAR(p->normals[3 * v], 1, 1e-6);
    }
    /* box 2 long in x, turned 90 degrees about y: now 2 long in z */
    float lo[3] = {1e9f, 1e9f, 1e9f}, hi[3] = {-1e9f, -1e9f, -1e9f};
    const struct ssg_mesh *b = &s->meshes[1];
    for (int v = 0; v < b->vertex_count; v++)
        for (int a = 0; a < 3; a++) {
            lo[a] = fminf(lo[a], b->positions[3 * v + a]);
            hi[a] = fmaxf(hi[a], b->positions[3 * v + a]);
        }
    CHECK_NEAR(hi[0] - lo[0], 1, 1e-5);
    CHECK_NEAR(hi[2] - lo[2], 2, 1e-5);
    CHECK_NEAR(0.5f * (hi[0] + lo[0]), 5, 1e-5);
    /* sphere: 8 bands, 16 segments, fans at the poles; vertices on the sphere */
    const struct ssg_mesh *sp = &s->meshes[2];
    CHECK_EQ(sp->triangle_count, 2 * 16 * 7);
    for (int v = 0; v < sp->vertex_count; v++) {
        const float *q = &sp->positions[3 * v];
        bad += fabsf(sqrtf(q[0] * q[0] + q[1] * q[1] + (q[2] + 4) * (q[2] + 4)) - 2) > 1e-5f;
    }
    CHECK_EQ(bad, 0);
    /* default camera: looks at the middle of the bounds, everything in front of it */
    CHECK_NEAR(s->camera.target[0], 1.75, 1e-4); /* x bounds [-2, 5.5] */
    CHECK(s->camera.position[2] > 4);
    CHECK(s->camera.near_z > 0 && s->camera.far_z > s->camera.near_z);
    ssg_scene_destroy(&s);
}

/* A glTF file next to the scene, placed by translate/rotate/scale; its camera is used. */
static void test_mesh_and_gltf_camera(void)
{
    FILE *in = fopen("tests/fixtures/gltf/triangle.gltf", "r");
    char gltf[8192];
    size_t n = in ? fread(gltf, 1, sizeof gltf - 1, in) : 0;
    if (in)
        fclose(in);
    gltf[n] = 0;
    char sub[600];
    snprintf(sub, sizeof sub, "%s/sub", tmpdir);
    mkdir(sub, 0755);
    write_file("sub/tri.gltf", gltf);
    const char *path = write_file(
        "mesh.scene", "mesh(\"sub/tri.gltf\", translate=[10, 0, 0], rotate=[0, 0, 90], "
                      "scale=0.5)\n");
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load(path, 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    if (!s)
        return;
    CHECK_EQ(s->mesh_count, 1);
    CHECK_EQ(s->material_count, 1);
    CHECK(strcmp(s->materials[0].name, "tinted") == 0);
    CHECK_EQ(s->materials[0].texture, 0);
    CHECK_EQ(s->texture_count, 1);
    /* glTF world (1,2,3) -> scale 0.5 -> (0.5,1,1.5) -> 90 deg about z -> (-1,0.5,1.5) -> +10 x */
    const float *p = s->meshes[0].positions;
    CHECK_NEAR(p[0], 9, 1e-5);
    CHECK_NEAR(p[1], 0.5, 1e-5);
    CHECK_NEAR(p[2], 1.5, 1e-5);
    CHECK_NEAR(s->meshes[0].normals[2], 1, 1e-5);
    CHECK_EQ(s->has_camera, 1);
    CHECK_NEAR(s->camera.position[0], 10, 1e-5); /* (0,0,5) -> (0,0,2.5) -> +10 x */
    CHECK_NEAR(s->camera.position[2], 2.5, 1e-5);
    CHECK_NEAR(s->camera.up[0], -1, 1e-5);       /* +y turned 90 degrees about z */
    ssg_scene_destroy(&s);
}

/* Check mode reads nothing but the scene; loading reports a broken glTF at its mention. */
static void test_check_mode_and_broken_gltf(void)
{
    char broken[1024], text[1200];
    snprintf(broken, sizeof broken, "%s/tests/fixtures/broken.gltf", getcwd(text, 600));
    snprintf(text, sizeof text, "box()\n  mesh(\"%s\")\n", broken);
    const char *path = write_file("broken_mesh.scene", text);
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load(path, 0, &s, &d), SSG_OK);
    CHECK_EQ(d.count, 0);
    CHECK(s && s->mesh_count == 0 && s->rt == NULL);
    ssg_scene_destroy(&s);
    CHECK_EQ(ssg_scene_load(path, 1, &s, &d), SSG_E_GLTF);
    CHECK(s == NULL);
    CHECK_EQ(d.count, 1);
    CHECK_EQ(d.items[0].line, 2);
    CHECK_EQ(d.items[0].column, 8);
    CHECK(strstr(d.items[0].message, "broken.gltf") != NULL);
}

/* Writes a 2x1 RGB image with pixels (a, b, c) and (d, e, f) as EXR or PNG. */
static void write_image(const char *name, const float rgb[6], int png)
{
    char path[1024];
    struct ssg_diags d = {0};
    struct ssg_image *im = ssg_image_create(2, 1, 3);
    for (int c = 0; c < 3; c++)
        for (int x = 0; x < 2; x++)
            ssg_image_plane(im, c)[x] = rgb[3 * x + c];
    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    struct ssg_exr_layer layer = {NULL, im, SSG_LAYER_COLOR};
    CHECK_EQ(png ? ssg_png_write(path, im, SSG_TONEMAP_CLAMP, 0, &d)
                 : ssg_exr_write(path, &layer, 1, &d), SSG_OK);
    ssg_image_destroy(&im);
}

/* A material texture (8-bit sRGB PNG, linear once loaded) and an HDR environment (EXR,
 * linear as stored) end up as interleaved linear RGB textures. */
static void test_textures(void)
{
    const float albedo[6] = {1, 0.5f, 0.2f, 0, 0.05f, 0.9f};
    const float sky[6] = {4, 2, 1, 0.25f, 0.5f, 8};
    write_image("albedo.png", albedo, 1);
    write_image("sky.exr", sky, 0);
    const char *path = write_file(
        "textured.scene", "tex = material(albedo=[1, 1, 1], texture=\"albedo.png\")\n"
                          "environment(color=[1, 1, 1], intensity=0.5, image=\"sky.exr\")\n"
                          "box(material=tex)\n");
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load(path, 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    if (!s)
        return;
    CHECK_EQ(s->texture_count, 2);
    CHECK_EQ(s->materials[0].texture, 0);
    CHECK_EQ(s->environment.image, 1);
    CHECK_NEAR(s->environment.intensity, 0.5, 1e-6);
    if (s->texture_count == 2) {
        const struct ssg_texture *t = &s->textures[0], *e = &s->textures[1];
        CHECK(t->width == 2 && t->height == 1 && e->width == 2 && e->height == 1);
        for (int i = 0; i < 6; i++) { /* 8-bit sRGB steps are at most 1.4% near 1 */
            CHECK_NEAR(t->rgb[i], albedo[i], 0.015 * albedo[i] + 0.002);
            CHECK_NEAR(e->rgb[i], sky[i], 1e-6);
        }
    }
    ssg_scene_destroy(&s);
}

/* A scene material's alpha: mask keeps its texture's alpha channel as the coverage plane
 * (alpha_half.png: 255 then 0) with the cutoff and opacity written; opaque decodes none;
 * blend warns at the argument and reads as mask at 0.5. */
static void test_alpha_materials(void)
{
    const char *path = write_file(
        "alpha.scene",
        "leaf = material(texture=\"" SSG_SOURCE_DIR "/tests/fixtures/alpha_half.png\", "
        "alpha_mode=mask, alpha_cutoff=0.25, opacity=0.75)\n"
        "wall = material(texture=\"" SSG_SOURCE_DIR "/tests/fixtures/alpha_half.png\")\n"
        "glass = material(alpha_mode=blend, alpha_cutoff=0.9)\n"
        "box(material=leaf)\nbox(material=wall)\nbox(material=glass)\n");
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load(path, 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    CHECK_EQ(d.warning_count, 1);
    CHECK(d.warning_count == 1 && strstr(d.warnings[0].message, "material 'glass': alpha_mode=blend") &&
          d.warnings[0].line == 3);
    if (!s)
        return;
    const struct ssg_material *leaf = &s->materials[0], *wall = &s->materials[1];
    const struct ssg_material *glass = &s->materials[2];
    CHECK_EQ(leaf->alpha_mode, SSG_ALPHA_MASK);
    CHECK_NEAR(leaf->alpha_cutoff, 0.25, 0);
    CHECK_NEAR(leaf->opacity, 0.75, 0);
    const struct ssg_texture *t = &s->textures[leaf->texture];
    CHECK(t->alpha != NULL);
    if (t->alpha) {
        CHECK_NEAR(t->alpha[0], 1.0, 0);
        CHECK_NEAR(t->alpha[1], 0.0, 0);
    }
    CHECK_EQ(wall->alpha_mode, SSG_ALPHA_OPAQUE);
    CHECK(s->textures[wall->texture].alpha == NULL);
    CHECK_EQ(glass->alpha_mode, SSG_ALPHA_BLEND);
    CHECK_NEAR(glass->alpha_cutoff, 0.5, 0);
    ssg_scene_destroy(&s);
}

/* Every entity kind's parameters fit the places an entity keeps for their locations. */
static void test_kinds_fit(void)
{
    for (int k = 0; k < SK_COUNT; k++)
        CHECK(ssg_scene_kinds[k].table.count <= SCENE_MAX_ARGS);
}

static void test_view_matrix(void)
{
    struct ssg_camera c = {{1, 2, 3}, {1, 2, -1}, {0, 1, 0}, 45, 0.1f, 100};
    float m[16];
    ssg_camera_view_matrix(&c, m);
    /* eye -> origin; target -> 4 units down -z; world +x stays view +x */
    const float eye[3] = {1, 2, 3}, target[3] = {1, 2, -1};
    for (int r = 0; r < 3; r++) {
        float e = m[r] * eye[0] + m[4 + r] * eye[1] + m[8 + r] * eye[2] + m[12 + r];
        float t = m[r] * target[0] + m[4 + r] * target[1] + m[8 + r] * target[2] + m[12 + r];
        CHECK_NEAR(e, 0, 1e-6);
        CHECK_NEAR(t, r == 2 ? -4 : 0, 1e-6);
    }
    CHECK_NEAR(m[0], 1, 1e-6);
    CHECK_NEAR(m[5], 1, 1e-6);
    CHECK_NEAR(m[15], 1, 1e-6);
}

int main(void)
{
    setup_tmp("test_scene");
    test_errors();
    test_unknown_material_message();
    test_missing_scene();
    test_lights_file();
    test_lights_file_errors();
    test_cornell();
    test_shapes();
    test_mesh_and_gltf_camera();
    test_check_mode_and_broken_gltf();
    test_textures();
    test_alpha_materials();
    test_kinds_fit();
    test_view_matrix();
    return check_report();
}
