/* test_gltf.c - the glTF adapter (core/scene/gltf.h): the bundled bunny loads with the OBJ's
 * vertex and triangle counts; a small fixture checks transforms, computed normals,
 * materials, sRGB texture decoding and the camera; broken files give SSG_E_GLTF (or
 * SSG_E_IO) with the file name in the message, and never crash. */
#include <string.h>

#include "check.h"
#include "scene/scene.h"
#include "scratch.h"
#include "scene/gltf.h"

#define OBJ_PATH "/usr/share/glmark2/models/bunny.obj"

/* Counts `v ` and `f ` lines of the OBJ the bunny was converted from (tools/obj2gltf.py
 * keeps one vertex per OBJ position and one triangle per triangular face). */
static int count_obj(int *vertices, int *faces)
{
    FILE *f = fopen(OBJ_PATH, "r");
    char line[256];
    if (!f)
        return 0;
    *vertices = *faces = 0;
    while (fgets(line, sizeof line, f)) {
        *vertices += line[0] == 'v' && line[1] == ' ';
        *faces += line[0] == 'f' && line[1] == ' ';
    }
    fclose(f);
    return 1;
}

static void test_bunny(void)
{
    struct ssg_gltf *g = NULL;
    char why[512] = "";
    CHECK_EQ(ssg_gltf_load("examples/bunny.gltf", &g, why, sizeof why), SSG_OK);
    if (!g) {
        fprintf(stderr, "%s\n", why);
        return;
    }
    int vertices = 34835, faces = 69666; /* the glmark2-data copy, when it is not installed */
    count_obj(&vertices, &faces);
    CHECK_EQ(g->mesh_count, 1);
    CHECK_EQ(g->meshes[0].vertex_count, vertices);
    CHECK_EQ(g->meshes[0].triangle_count, faces);
    CHECK_EQ(g->meshes[0].material, -1);
    CHECK(g->meshes[0].uvs == NULL);
    CHECK_EQ(g->has_camera, 0);
    /* every normal is unit length and every index in range */
    int bad = 0;
    for (int v = 0; v < g->meshes[0].vertex_count; v++) {
        const float *n = &g->meshes[0].normals[3 * v];
        bad += fabsf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1.0f) > 1e-4f;
    }
    for (int i = 0; i < 3 * g->meshes[0].triangle_count; i++)
        bad += g->meshes[0].indices[i] >= (uint32_t)vertices;
    CHECK_EQ(bad, 0);
    ssg_gltf_destroy(&g);
    CHECK(g == NULL);
}

static void test_triangle(void)
{
    struct ssg_gltf *g = NULL;
    char why[512] = "";
    CHECK_EQ(ssg_gltf_load("tests/fixtures/gltf/triangle.gltf", &g, why, sizeof why), SSG_OK);
    if (!g) {
        fprintf(stderr, "%s\n", why);
        return;
    }
    CHECK_EQ(g->mesh_count, 1);
    const struct ssg_mesh *m = &g->meshes[0];
    CHECK_EQ(m->vertex_count, 3);
    CHECK_EQ(m->triangle_count, 1);
    /* node: translation (1,2,3), scale 2 -> (1,2,3), (3,2,3), (1,4,3) */
    const float want[9] = {1, 2, 3, 3, 2, 3, 1, 4, 3};
    for (int i = 0; i < 9; i++)
        CHECK_NEAR(m->positions[i], want[i], 1e-6);
    for (int v = 0; v < 3; v++) { /* computed: the face normal, +z */
        CHECK_NEAR(m->normals[3 * v], 0, 1e-6);
        CHECK_NEAR(m->normals[3 * v + 1], 0, 1e-6);
        CHECK_NEAR(m->normals[3 * v + 2], 1, 1e-6);
    }
    CHECK(m->uvs != NULL);
    if (m->uvs)
        CHECK_NEAR(m->uvs[2], 1.0, 1e-6);
    CHECK_EQ(m->material, 0);
    CHECK_EQ(g->material_count, 1);
    CHECK(strcmp(g->materials[0].name, "tinted") == 0);
    CHECK_NEAR(g->materials[0].base_color[1], 0.25, 1e-6);
    CHECK_EQ(g->materials[0].texture, 0);
    CHECK_EQ(g->texture_count, 1);
    if (g->texture_count == 1) { /* sRGB (255,128,0), (0,0,188) decoded to linear */
        const struct ssg_texture *t = &g->textures[0];
        CHECK_EQ(t->width, 2);
        CHECK_EQ(t->height, 1);
        CHECK_NEAR(t->rgb[0], 1.0, 1e-6);
        CHECK_NEAR(t->rgb[1], 0.2158605, 1e-5);
        CHECK_NEAR(t->rgb[2], 0.0, 1e-6);
        CHECK_NEAR(t->rgb[5], 0.5028865, 1e-5);
    }
    CHECK_EQ(g->has_camera, 1);
    CHECK_NEAR(g->camera.position[2], 5, 1e-6);
    CHECK_NEAR(g->camera.target[2], 4, 1e-6); /* looks down -z */
    CHECK_NEAR(g->camera.up[1], 1, 1e-6);
    CHECK_NEAR(g->camera.fov_y, 0.8 * 180.0 / 3.14159265358979, 1e-4);
    CHECK_NEAR(g->camera.near_z, 0.1, 1e-6);
    CHECK_NEAR(g->camera.far_z, 50, 1e-6);
    ssg_gltf_destroy(&g);
}

/* A broken file: the expected code, no struct, and the file named in the message. */
static void expect_failure(const char *path, enum ssg_err code, const char *words)
{
    struct ssg_gltf *g = (struct ssg_gltf *)1;
    char why[512] = "";
    CHECK_EQ(ssg_gltf_load(path, &g, why, sizeof why), code);
    CHECK(g == NULL);
    CHECK(strstr(why, path) != NULL);
    CHECK(strstr(why, words) != NULL);
    fprintf(stderr, "  (expected) %s\n", why);
}

/* tests/fixtures/gltf/triangle.gltf with `from` replaced by `to` (and `from2` by `to2`
   when given), written to the scratch folder; NULL when that fails. */
static const char *triangle_with(const char *from, const char *to, const char *from2,
                                 const char *to2)
{
    static char text[8400], out[8400];
    FILE *f = fopen("tests/fixtures/gltf/triangle.gltf", "r");
    size_t n = f ? fread(text, 1, sizeof text - 1, f) : 0;
    if (f)
        fclose(f);
    text[n] = 0;
    for (int k = 0; k < 2 && (k ? from2 : from); k++) {
        const char *a = k ? from2 : from, *b = k ? to2 : to, *at = strstr(text, a);
        CHECK(at != NULL);
        if (!at)
            return NULL;
        snprintf(out, sizeof out, "%.*s%s%s", (int)(at - text), text, b, at + strlen(a));
        snprintf(text, sizeof text, "%s", out);
    }
    return write_file("camera.gltf", text);
}

/* The file triangle_with wrote, loaded; NULL (a failed check, the reason printed) when it
   was not written or does not load. */
static struct ssg_gltf *load_written(const char *path)
{
    struct ssg_gltf *g = NULL;
    char why[512] = "";
    CHECK_EQ(path ? ssg_gltf_load(path, &g, why, sizeof why) : SSG_E_IO, SSG_OK);
    if (!g)
        fprintf(stderr, "%s\n", why);
    return g;
}

/* A camera glTF forbids is refused, naming the file and the camera, never dropped: yfov
   at or below 0 or 179 degrees and more (1e999, no JSON number, is the parser's to refuse),
   znear at or below 0, zfar before znear. */
static void test_bad_cameras(void)
{
    static const char *const cases[][3] = {
        {"\"yfov\": 0.8", "\"yfov\": 0", "camera 0: yfov 0"},
        {"\"yfov\": 0.8", "\"yfov\": -0.8", "camera 0: yfov -0.8"},
        {"\"yfov\": 0.8", "\"yfov\": 3.2", "camera 0: yfov 3.2"},
        {"\"yfov\": 0.8", "\"yfov\": 1e999", ""}, /* JSON holds no infinity: the parser's */
        {"\"znear\": 0.1", "\"znear\": 0", "camera 0: znear 0"},
        {"\"znear\": 0.1", "\"znear\": -1", "camera 0: znear -1"},
        {"\"zfar\": 50", "\"zfar\": 0.05", "camera 0: zfar 0.05"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *path = triangle_with(cases[i][0], cases[i][1], NULL, NULL);
        if (path)
            expect_failure(path, SSG_E_GLTF, cases[i][2]);
    }
    const char *named = triangle_with("\"yfov\": 0.8", "\"yfov\": -1", "\"type\": \"perspective\"",
                                      "\"name\": \"eye\", \"type\": \"perspective\"");
    if (named)
        expect_failure(named, SSG_E_GLTF, "camera 0 ('eye'): yfov -1");
}

/* alphaMode: MASK keeps the texture's alpha channel (a 2 x 1 RGBA PNG, alpha 255 then 0:
   linear, not sRGB) and alphaCutoff; BLEND is kept as such (scene_build.c warns and draws
   it as MASK at 0.5); OPAQUE, the default, decodes no alpha plane; a cutoff outside 0 to 1
   is refused naming the material. */
static void test_alpha(void)
{
    static const char rgba_png[] = "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAIAAAABCAYAAA"
                                   "D0In+KAAAAEUlEQVR4nGP8////fwYGBkYAGfkD/3ZDTbIAAAAASUVORK5CYII=";
    static const char old_png[] = "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAIAAAABCAIAAA"
                                  "B7QOjdAAAAD0lEQVR4nGP438DAwLAHAAk9AjyeXEGtAAAAAElFTkSuQmCC";
    static const struct {
        const char *mode;
        int want;
        double cutoff;
    } cases[] = {{"\"alphaMode\": \"MASK\", \"alphaCutoff\": 0.3,", SSG_ALPHA_MASK, 0.3},
                 {"\"alphaMode\": \"BLEND\",", SSG_ALPHA_BLEND, 0.5},
                 {"", SSG_ALPHA_OPAQUE, 0.5}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char to[160];
        snprintf(to, sizeof to, "\"name\": \"tinted\", %s", cases[k].mode);
        const char *path = triangle_with("\"name\": \"tinted\",", to, old_png, rgba_png);
        struct ssg_gltf *g = load_written(path);
        if (!g)
            continue;
        CHECK_EQ(g->materials[0].alpha_mode, cases[k].want);
        CHECK_NEAR(g->materials[0].alpha_cutoff, cases[k].cutoff, 1e-6);
        CHECK_NEAR(g->materials[0].base_color[3], 1.0, 0);
        const struct ssg_texture *t = &g->textures[0];
        CHECK_EQ(t->alpha != NULL, cases[k].want != SSG_ALPHA_OPAQUE);
        if (t->alpha) {
            CHECK_NEAR(t->alpha[0], 1.0, 0);
            CHECK_NEAR(t->alpha[1], 0.0, 0);
        }
        ssg_gltf_destroy(&g);
    }
    const char *bad = triangle_with("\"name\": \"tinted\",",
                                    "\"name\": \"tinted\", \"alphaMode\": \"MASK\", "
                                    "\"alphaCutoff\": 1.5,", NULL, NULL);
    if (bad)
        expect_failure(bad, SSG_E_GLTF, "'tinted': alphaCutoff 1.5 is outside 0 to 1");
}

/* KHR_texture_transform on the base colour is baked into the mesh's uvs: offset (0.25,
 * 0.5), rotation pi/2 and scale (2, 3) give uv' = (3 v + 0.25, -2 u + 0.5), so the
 * triangle's uvs (0, 0), (1, 0), (0, 1) become (0.25, 0.5), (0.25, -1.5), (3.25, 0.5);
 * a normal map with another transform on the same material keeps the base colour's and
 * is named as not read. */
static void test_texture_transform(void)
{
    static const char from[] = "\"baseColorTexture\": {\n     \"index\": 0\n    }";
    static const char to[] = "\"baseColorTexture\": {\"index\": 0, \"extensions\": "
                             "{\"KHR_texture_transform\": {\"offset\": [0.25, 0.5], "
                             "\"rotation\": 1.5707963267948966, \"scale\": [2, 3]}}}";
    static const char normal[] = "\"name\": \"tinted\", \"normalTexture\": {\"index\": 0, "
                                 "\"extensions\": {\"KHR_texture_transform\": {\"scale\": [4, 4]}}},";
    static const float want[6] = {0.25f, 0.5f, 0.25f, -1.5f, 3.25f, 0.5f};
    for (int differ = 0; differ < 2; differ++) {
        const char *path = triangle_with(from, to, differ ? "\"name\": \"tinted\"," : NULL,
                                         differ ? normal : NULL);
        struct ssg_gltf *g = load_written(path);
        if (!g)
            continue;
        const float *uv = g->meshes[0].uvs;
        CHECK(uv != NULL);
        for (int k = 0; uv && k < 6; k++)
            CHECK_NEAR(uv[k], want[k], 1e-6);
        CHECK_EQ(strstr(g->ignored, "texture transforms (KHR_texture_transform) that differ") !=
                     NULL, differ);
        ssg_gltf_destroy(&g);
    }
}

/* What a file uses and no path reads is named, not dropped in silence: a normal map on a
 * second uv set on material 'tinted' and an unknown extension, each a line of
 * g->ignored; a scene naming the file warns once at its mesh line with the features, and
 * check's summary lists them with the material. */
static void test_ignored(void)
{
    const char *path = triangle_with("\"name\": \"tinted\",",
                                     "\"name\": \"tinted\", \"normalTexture\": {\"index\": 0, "
                                     "\"texCoord\": 1}, \"emissiveFactor\": [1, 0.5, 0],",
                                     "\"asset\": {", "\"extensionsUsed\": [\"KHR_lights_punctual\", "
                                     "\"KHR_materials_clearcoat\"], \"asset\": {");
    struct ssg_gltf *g = NULL;
    char why[512] = "";
    CHECK_EQ(path ? ssg_gltf_load(path, &g, why, sizeof why) : SSG_E_IO, SSG_OK);
    if (!g) {
        fprintf(stderr, "%s\n", why);
        return;
    }
    fprintf(stderr, "ignored:\n%s", g->ignored);
    CHECK(strstr(g->ignored, "normal maps on another texture coordinate set than the base "
                 "colour's: 1 use: 'tinted'\n") != NULL);
    CHECK(strstr(g->ignored, "KHR_lights_punctual") == NULL); /* read: no light here */
    CHECK(strstr(g->ignored, "emission") == NULL); /* read now */
    CHECK_NEAR(g->materials[0].emission[1], 0.5, 0);
    CHECK(strstr(g->ignored, "extension KHR_materials_clearcoat\n") != NULL);
    ssg_gltf_destroy(&g);
    const char *scene = write_file("ignored.scene", "mesh(\"camera.gltf\")\n");
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load(scene, 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    CHECK_EQ(d.warning_count, 1);
    CHECK(d.warning_count == 1 && d.warnings[0].line == 1 &&
          strstr(d.warnings[0].message, "camera.gltf uses what ssgraph does not read yet, and "
                 "the picture leaves it out: normal maps on another texture coordinate set "
                 "than the base colour's; extension KHR_materials_clearcoat"));
    if (s) {
        CHECK_EQ(s->model_count, 1);
        CHECK(strstr(s->models[0].ignored, "'tinted'") != NULL);
    }
    ssg_scene_destroy(&s);
    /* the plain file uses nothing ssgraph leaves out */
    CHECK_EQ(ssg_gltf_load("tests/fixtures/gltf/triangle.gltf", &g, why, sizeof why), SSG_OK);
    CHECK(g && g->ignored[0] == 0);
    ssg_gltf_destroy(&g);
}

int main(void)
{
    setup_tmp("gltf");
    test_ignored();
    test_alpha();
    test_texture_transform();
    test_bunny();
    test_triangle();
    test_bad_cameras();
    expect_failure("tests/fixtures/broken.gltf", SSG_E_GLTF, "");
    expect_failure("tests/fixtures/gltf/index_out_of_range.gltf", SSG_E_GLTF, "out of range");
    expect_failure("tests/fixtures/gltf/lines.gltf", SSG_E_GLTF, "not a triangle mode");
    expect_failure("tests/fixtures/gltf/missing_bin.gltf", SSG_E_GLTF, "missing.bin");
    expect_failure("tests/fixtures/gltf/no_such_file.gltf", SSG_E_IO, "cannot open");
    expect_failure("tests/fixtures/garbage.png", SSG_E_GLTF, "");
    return check_report();
}
