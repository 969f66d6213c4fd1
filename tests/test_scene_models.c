/* test_scene_models.c - what a model file read through Assimp (in its child process, back
 * over the model wire) brings into a scene's materials and meshes: an OBJ's map_d cutting
 * by the diffuse texture's alpha or by a file of its own, an OBJ's norm read as data (and
 * map_bump named as not read), an OBJ's map_Ke times Ke, a PLY's vertex colours as sRGB. */
#include <string.h>

#include "check.h"
#include "scratch.h"
#include "scene/scene.h"

/* A scene of one mesh line naming model (in the scratch folder), loaded with its assets;
   its messages printed and kept in *d. NULL (a failed check) when it does not load. */
static struct ssg_scene *load_model(const char *model, struct ssg_diags *d)
{
    char text[300], name[300];
    snprintf(text, sizeof text, "mesh(\"%s\")\n", model);
    snprintf(name, sizeof name, "%s.scene", model);
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load(write_file(name, text), 1, &s, d), SSG_OK);
    ssg_diags_print(d, stderr);
    return s;
}

/* An OBJ whose MTL's map_d names its map_Kd file (the usual way to cut out leaves in OBJ)
 * becomes a masked material reading that texture's alpha, through Assimp and its child
 * process. */
static void test_obj_map_d(void)
{
    write_file("leaf.mtl", "newmtl leaf\nKd 1 1 1\nmap_Kd " SSG_SOURCE_DIR
               "/tests/fixtures/alpha_half.png\nmap_d " SSG_SOURCE_DIR
               "/tests/fixtures/alpha_half.png\n");
    write_file("leaf.obj", "mtllib leaf.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\n"
               "vt 1 1\nvn 0 0 1\nusemtl leaf\nf 1/1/1 2/2/1 3/3/1\n");
    struct ssg_diags d = {0};
    struct ssg_scene *s = load_model("leaf.obj", &d);
    if (!s)
        return;
    CHECK_EQ(s->material_count, 1);
    const struct ssg_material *m = &s->materials[0];
    CHECK_EQ(m->alpha_mode, SSG_ALPHA_MASK);
    CHECK_NEAR(m->alpha_cutoff, 0.5, 0);
    CHECK(m->texture >= 0 && s->textures[m->texture].alpha != NULL);
    ssg_scene_destroy(&s);
}

/* An OBJ's norm (a tangent-space normal map) becomes the material's normal map, read as data
 * (normal_tilt.png's 204, 128, 230 exactly, not sRGB-decoded), and the mesh gets tangents;
 * a map_bump (heights) is listed as not read. */
static void test_obj_norm(void)
{
    write_file("tilt.mtl", "newmtl tilt\nKd 1 1 1\nnorm " SSG_SOURCE_DIR
               "/tests/fixtures/normal_tilt.png\nmap_bump bump.png\n");
    write_file("tilt.obj", "mtllib tilt.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\n"
               "vt 1 1\nvn 0 0 1\nusemtl tilt\nf 1/1/1 2/2/1 3/3/1\n");
    struct ssg_diags d = {0};
    struct ssg_scene *s = load_model("tilt.obj", &d);
    CHECK(d.warning_count == 1 && strstr(d.warnings[0].message, "bump maps (map_bump"));
    if (!s)
        return;
    const struct ssg_material *m = &s->materials[0];
    CHECK(m->normal_texture >= 0);
    if (m->normal_texture >= 0) {
        const float *rgb = s->textures[m->normal_texture].rgb;
        CHECK_NEAR(rgb[0], 204 / 255.0, 1e-6);
        CHECK_NEAR(rgb[1], 128 / 255.0, 1e-6);
        CHECK_NEAR(rgb[2], 230 / 255.0, 1e-6);
    }
    CHECK(s->meshes[0].tangents != NULL);
    ssg_scene_destroy(&s);
}

/* An OBJ's map_d naming its own file masks the surface: its coverage (the mask's alpha,
 * else its first channel) becomes the alpha plane of the diffuse texture, resampled onto
 * its texels (a 2 x 1 mask (1, 0) read at a 1 x 1 texture's centre: 0.5), or of a white
 * texture of the mask's size when the material has no diffuse map. */
static void test_obj_separate_map_d(void)
{
    write_file("cut.mtl", "newmtl cut\nKd 1 1 1\nmap_Kd " SSG_SOURCE_DIR
               "/tests/fixtures/normal_tilt.png\nmap_d " SSG_SOURCE_DIR
               "/tests/fixtures/alpha_half.png\nnewmtl bare\nKd 0.5 0.5 0.5\nmap_d "
               SSG_SOURCE_DIR "/tests/fixtures/alpha_half.png\n");
    write_file("cut.obj", "mtllib cut.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\n"
               "vt 1 0\nvt 1 1\nvn 0 0 1\nusemtl cut\nf 1/1/1 2/2/1 3/3/1\nusemtl bare\n"
               "f 1/1/1 3/3/1 4/2/1\n");
    struct ssg_diags d = {0};
    struct ssg_scene *s = load_model("cut.obj", &d);
    CHECK_EQ(d.warning_count, 0);
    for (int i = 0; s && i < s->material_count; i++) {
        const struct ssg_material *m = &s->materials[i];
        int bare = strcmp(m->name, "bare") == 0;
        CHECK_EQ(m->alpha_mode, SSG_ALPHA_MASK);
        CHECK(m->texture >= 0 && s->textures[m->texture].alpha != NULL);
        if (m->texture < 0 || !s->textures[m->texture].alpha)
            continue;
        const struct ssg_texture *t = &s->textures[m->texture];
        CHECK_EQ(t->width, bare ? 2 : 1);
        CHECK_NEAR(t->alpha[0], bare ? 1.0 : 0.5, 1e-6);
        if (bare) {
            CHECK_NEAR(t->alpha[1], 0.0, 1e-6);
            CHECK_NEAR(t->rgb[0], 1.0, 0);
        } else {
            CHECK_NEAR(t->rgb[0], 0.6038, 1e-3); /* 204 / 255, sRGB-decoded */
        }
    }
    CHECK(s && s->material_count == 2);
    ssg_scene_destroy(&s);
}

/* A PLY's vertex colours (through Assimp, in its child process and back over the wire)
 * multiply the albedo as sRGB display colours: byte 188 is linear 0.5029, 255 is 1. */
static void test_ply_colors(void)
{
    const char *ply = write_file("colours.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"
                                 "property float x\nproperty float y\nproperty float z\n"
                                 "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                                 "element face 1\nproperty list uchar int vertex_indices\n"
                                 "end_header\n0 0 0 188 0 255\n1 0 0 188 0 255\n"
                                 "0 1 0 188 0 255\n3 0 1 2\n");
    (void)ply;
    struct ssg_diags d = {0};
    struct ssg_scene *s = load_model("colours.ply", &d);
    CHECK_EQ(d.warning_count, 0);
    if (!s)
        return;
    const float *c = s->meshes[0].colors;
    CHECK(c != NULL);
    if (c) {
        CHECK_NEAR(c[0], 0.50289, 1e-4);
        CHECK_NEAR(c[1], 0, 0);
        CHECK_NEAR(c[8], 1, 1e-6);
    }
    ssg_scene_destroy(&s);
}

/* An OBJ's map_Ke is the material's emission texture (sRGB-decoded: 204 -> 0.6038) times
 * Ke; a map_Ke without Ke glows at 1 x the map. */
static void test_obj_map_ke(void)
{
    write_file("lamp.mtl", "newmtl lamp\nKd 0 0 0\nKe 2 2 2\nmap_Ke " SSG_SOURCE_DIR
               "/tests/fixtures/normal_tilt.png\nnewmtl sign\nKd 0 0 0\nmap_Ke " SSG_SOURCE_DIR
               "/tests/fixtures/normal_tilt.png\n");
    write_file("lamp.obj", "mtllib lamp.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\n"
               "vt 1 0\nvt 1 1\nvn 0 0 1\nusemtl lamp\nf 1/1/1 2/2/1 3/3/1\nusemtl sign\n"
               "f 1/1/1 3/3/1 4/2/1\n");
    struct ssg_diags d = {0};
    struct ssg_scene *s = load_model("lamp.obj", &d);
    CHECK_EQ(d.warning_count, 0);
    for (int i = 0; s && i < s->material_count; i++) {
        const struct ssg_material *m = &s->materials[i];
        CHECK_NEAR(m->emission[0], strcmp(m->name, "lamp") == 0 ? 2.0 : 1.0, 0);
        CHECK(m->emission_texture >= 0);
        if (m->emission_texture >= 0)
            CHECK_NEAR(s->textures[m->emission_texture].rgb[0], 0.6038, 1e-3);
    }
    CHECK(s && s->material_count == 2);
    ssg_scene_destroy(&s);
}

int main(void)
{
    setup_tmp("test_scene_models");
    test_obj_map_d();
    test_obj_norm();
    test_ply_colors();
    test_obj_separate_map_d();
    test_obj_map_ke();
    return check_report();
}
