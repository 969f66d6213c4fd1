/* test_models_load.c - mesh files of every format (core/scene/model.h): an OBJ with a
 * quad and a pentagon, an ASCII PLY box and an ASCII STL load through Assimp to the
 * triangle counts and bounds they were written with, as do a COLLADA quad and a glTF 1.0
 * triangle placed by their nodes, and a PLY with a face of no vertices (which aborted
 * Assimp's triangulation) loads its triangle; diffuse colours become base colours (an OBJ's the scene
 * material's albedo) and a file without materials takes the scene's default; a mesh
 * line's scale, rotate and translate place an OBJ as they place a glTF; unknown
 * extensions, a broken OBJ, a missing .mtl or texture and a Draco glTF give SSG_E_GLTF or
 * SSG_E_IO with the file named; the scale hint fires for a model in millimetres only; each
 * reader's up axis is what its format says (none for OBJ, +Y for a glTF and for a Z_UP
 * COLLADA, which Assimp turns, the file's own for an FBX, which Assimp keeps), asked with
 * or without the model. */
#include <errno.h>
#include <string.h>

#include "check.h"
#include "scratch.h"
#include "scene/model.h"
#include "scene/scene.h"

/* A unit quad in z = 0 and a pentagon in z = 1 reaching x = 2: 2 + 3 triangles. */
static const char OBJ[] = "mtllib two.mtl\n"
                          "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                          "v 1 0 1\nv 2 0 1\nv 2 0.5 1\nv 1.5 1 1\nv 1 0.5 1\n"
                          "usemtl blue\nf 1 2 3 4\nf 5 6 7 8 9\n";
static const char MTL[] = "newmtl blue\nKd 0.2 0.4 0.6\n";

/* A box [0,1] x [0,2] x [0,3] of six quads: 12 triangles. */
static const char PLY[] = "ply\nformat ascii 1.0\nelement vertex 8\n"
                          "property float x\nproperty float y\nproperty float z\n"
                          "element face 6\nproperty list uchar int vertex_indices\nend_header\n"
                          "0 0 0\n1 0 0\n1 2 0\n0 2 0\n0 0 3\n1 0 3\n1 2 3\n0 2 3\n"
                          "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n";

/* A triangle and a face of no vertices. */
static const char PLY_EMPTY_FACE[] = "ply\nformat ascii 1.0\nelement vertex 3\n"
                                     "property float x\nproperty float y\nproperty float z\n"
                                     "element face 2\nproperty list uchar int vertex_indices\n"
                                     "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n0\n";

/* Two facets spanning [-1,1] x [0,0] x [-2,2]. */
static const char STL[] = "solid two\n"
                          "facet normal 0 1 0\nouter loop\nvertex -1 0 -2\nvertex 1 0 2\n"
                          "vertex 1 0 -2\nendloop\nendfacet\n"
                          "facet normal 0 1 0\nouter loop\nvertex -1 0 -2\nvertex -1 0 2\n"
                          "vertex 1 0 2\nendloop\nendfacet\nendsolid two\n";

/* A quad moved to z = 5 by its node, green by its lambert effect. */
static const char DAE[] =
    "<?xml version=\"1.0\"?>\n<COLLADA xmlns=\"http://www.collada.org/2005/11/"
    "COLLADASchema\" version=\"1.4.1\"><asset><up_axis>Y_UP</up_axis></asset>"
    "<library_effects><effect id=\"fx\"><profile_COMMON><technique sid=\"t\"><lambert>"
    "<diffuse><color>0.1 0.7 0.2 1</color></diffuse></lambert></technique></profile_COMMON>"
    "</effect></library_effects><library_materials><material id=\"green\" name=\"green\">"
    "<instance_effect url=\"#fx\"/></material></library_materials><library_geometries>"
    "<geometry id=\"g\"><mesh><source id=\"p\"><float_array id=\"pa\" count=\"12\">"
    "0 0 0 2 0 0 2 1 0 0 1 0</float_array><technique_common><accessor source=\"#pa\" "
    "count=\"4\" stride=\"3\"><param name=\"X\" type=\"float\"/><param name=\"Y\" "
    "type=\"float\"/><param name=\"Z\" type=\"float\"/></accessor></technique_common>"
    "</source><vertices id=\"v\"><input semantic=\"POSITION\" source=\"#p\"/></vertices>"
    "<polylist material=\"m\" count=\"1\"><input semantic=\"VERTEX\" source=\"#v\" "
    "offset=\"0\"/><vcount>4</vcount><p>0 1 2 3</p></polylist></mesh></geometry>"
    "</library_geometries><library_visual_scenes><visual_scene id=\"s\"><node id=\"n\">"
    "<translate>0 0 5</translate><instance_geometry url=\"#g\"><bind_material>"
    "<technique_common><instance_material symbol=\"m\" target=\"#green\"/>"
    "</technique_common></bind_material></instance_geometry></node></visual_scene>"
    "</library_visual_scenes><scene><instance_visual_scene url=\"#s\"/></scene></COLLADA>\n";

/* glTF 1.0 (named dictionaries, version "1.0"): one triangle, its node 1 down -z, red. */
static const char GLTF1[] =
    "{\"asset\": {\"version\": \"1.0\"}, \"scene\": \"s\", \"scenes\": {\"s\": "
    "{\"nodes\": [\"n\"]}}, \"nodes\": {\"n\": {\"meshes\": [\"m\"], \"translation\": "
    "[0, 0, -1]}}, \"meshes\": {\"m\": {\"primitives\": [{\"attributes\": {\"POSITION\": "
    "\"p\"}, \"indices\": \"i\", \"mode\": 4, \"material\": \"red\"}]}}, \"materials\": "
    "{\"red\": {\"values\": {\"diffuse\": [0.8, 0.1, 0.1, 1]}}}, \"accessors\": {\"p\": "
    "{\"bufferView\": \"vp\", \"byteOffset\": 0, \"byteStride\": 12, \"componentType\": "
    "5126, \"count\": 3, \"type\": \"VEC3\", \"min\": [0, 0, 0], \"max\": [1, 1, 0]}, "
    "\"i\": {\"bufferView\": \"vi\", \"byteOffset\": 0, \"byteStride\": 0, "
    "\"componentType\": 5123, \"count\": 3, \"type\": \"SCALAR\"}}, \"bufferViews\": "
    "{\"vp\": {\"buffer\": \"b\", \"byteOffset\": 0, \"byteLength\": 36, \"target\": "
    "34962}, \"vi\": {\"buffer\": \"b\", \"byteOffset\": 36, \"byteLength\": 6, "
    "\"target\": 34963}}, \"buffers\": {\"b\": {\"uri\": \"data:application/octet-stream;"
    "base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIA\", \"byteLength\": 42, "
    "\"type\": \"arraybuffer\"}}}";

/* A box 1 x 2 x 3 standing on z = 0, in an ASCII FBX 7.5 that says it is Z-up. */
static const char FBX_Z_UP[] =
    "; FBX 7.5.0 project file\n"
    "FBXHeaderExtension:  {\n  FBXHeaderVersion: 1003\n  FBXVersion: 7500\n}\n"
    "GlobalSettings:  {\n  Version: 1000\n  Properties70:  {\n"
    "    P: \"UpAxis\", \"int\", \"Integer\", \"\",2\n"
    "    P: \"UpAxisSign\", \"int\", \"Integer\", \"\",1\n  }\n}\n"
    "Objects:  {\n  Geometry: 1, \"Geometry::box\", \"Mesh\" {\n"
    "    Vertices: *24 {\n      a: 0,0,0,1,0,0,0,2,0,1,2,0,0,0,3,1,0,3,0,2,3,1,2,3\n    }\n"
    "    PolygonVertexIndex: *24 {\n"
    "      a: 0,2,3,-2,4,5,7,-7,0,1,5,-5,2,6,7,-4,0,4,6,-3,1,3,7,-6\n    }\n"
    "    GeometryVersion: 124\n  }\n"
    "  Model: 2, \"Model::box\", \"Mesh\" {\n    Version: 232\n  }\n}\n"
    "Connections:  {\n  C: \"OO\",2,0\n  C: \"OO\",1,2\n}\n";

static void bounds_of(const struct ssg_gltf *g, float lo[3], float hi[3], long long *tris)
{
    *tris = 0;
    for (int i = 0; i < 3; i++)
        lo[i] = HUGE_VALF, hi[i] = -HUGE_VALF;
    for (int m = 0; m < g->mesh_count; m++) {
        *tris += g->meshes[m].triangle_count;
        for (int v = 0; v < 3 * g->meshes[m].vertex_count; v++) {
            float p = g->meshes[m].positions[v];
            lo[v % 3] = fminf(lo[v % 3], p);
            hi[v % 3] = fmaxf(hi[v % 3], p);
        }
    }
}

/* Loads path and checks its triangle count and bounds; returns the model (caller frees). */
static struct ssg_gltf *expect_model(const char *path, long long tris, const float lo[3],
                                     const float hi[3])
{
    struct ssg_gltf *g = NULL;
    char why[1024] = "";
    CHECK_EQ(ssg_model_load(path, &g, why, sizeof why), SSG_OK);
    if (!g) {
        fprintf(stderr, "%s\n", why);
        return NULL;
    }
    float l[3], h[3];
    long long n;
    bounds_of(g, l, h, &n);
    CHECK_EQ(n, tris);
    for (int i = 0; i < 3; i++) {
        CHECK_NEAR(l[i], lo[i], 1e-6);
        CHECK_NEAR(h[i], hi[i], 1e-6);
    }
    for (int m = 0; m < g->mesh_count; m++) /* every normal is unit length */
        for (int v = 0; v < g->meshes[m].vertex_count; v++) {
            const float *nv = &g->meshes[m].normals[3 * v];
            CHECK_NEAR(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2], 1.0, 1e-4);
        }
    return g;
}

static void test_formats(void)
{
    write_file("two.mtl", MTL);
    struct ssg_gltf *g = expect_model(write_file("two.obj", OBJ), 5, (float[]){0, 0, 0},
                                      (float[]){2, 1, 1});
    if (g) {
        CHECK_EQ(g->material_count, 1);
        CHECK(g->material_count == 1 && !strcmp(g->materials[0].name, "blue"));
        CHECK_NEAR(g->materials[0].base_color[2], 0.6, 1e-6);
        CHECK_EQ(g->meshes[0].material, 0);
        ssg_gltf_destroy(&g);
    }
    g = expect_model(write_file("box.ply", PLY), 12, (float[]){0, 0, 0}, (float[]){1, 2, 3});
    if (g) {
        CHECK_EQ(g->meshes[0].material, -1); /* none in the file: the scene's default */
        ssg_gltf_destroy(&g);
    }
    g = expect_model(write_file("two.stl", STL), 2, (float[]){-1, 0, -2}, (float[]){1, 0, 2});
    ssg_gltf_destroy(&g);
    /* a face without indices: Assimp's triangulation aborted on it (found by fuzz_model) */
    g = expect_model(write_file("empty_face.ply", PLY_EMPTY_FACE), 1, (float[]){0, 0, 0},
                     (float[]){1, 1, 0});
    ssg_gltf_destroy(&g);
    g = expect_model(write_file("quad.dae", DAE), 2, (float[]){0, 0, 5}, (float[]){2, 1, 5});
    if (g) {
        CHECK(g->material_count == 1 && !strcmp(g->materials[0].name, "green"));
        CHECK_NEAR(g->materials[0].base_color[1], 0.7, 1e-6);
        ssg_gltf_destroy(&g);
    }
    g = expect_model(write_file("tri1.gltf", GLTF1), 1, (float[]){0, 0, -1}, (float[]){1, 1, -1});
    if (g) {
        CHECK(g->material_count == 1 && g->meshes[0].material == 0);
        CHECK_NEAR(g->materials[0].base_color[0], 0.8, 1e-6);
        ssg_gltf_destroy(&g);
    }
}

/* Every failure: the code, *out NULL, and the file's name and `what` in the message. */
static void expect_fail(const char *path, enum ssg_err code, const char *what)
{
    struct ssg_gltf *g = NULL;
    char why[1024] = "";
    CHECK_EQ(ssg_model_load(path, &g, why, sizeof why), code);
    CHECK(g == NULL);
    const char *slash = strrchr(path, '/');
    CHECK(strstr(why, slash ? slash + 1 : path) != NULL);
    if (!strstr(why, what)) {
        fprintf(stderr, "message '%s' lacks '%s'\n", why, what);
        CHECK(0);
    }
    ssg_gltf_destroy(&g);
}

static void test_failures(void)
{
    expect_fail(write_file("model.xyz", "solid\n"), SSG_E_GLTF, "'.xyz'");
    expect_fail(write_file("noext", "v 0 0 0\n"), SSG_E_GLTF, "extension");
    expect_fail(write_file("broken.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n"), SSG_E_GLTF, "OBJ");
    expect_fail(write_file("empty.obj", "# nothing\n"), SSG_E_GLTF, "OBJ");
    expect_fail(write_file("nomtl.obj", "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
                SSG_E_GLTF, "gone.mtl");
    expect_fail(tmp_path("missing.stl"), SSG_E_IO, "missing.stl");
    expect_fail(write_file("draco.gltf", "{\"asset\":{\"version\":\"2.0\"},\"extensionsRequired\":"
                                         "[\"KHR_draco_mesh_compression\"],\"meshes\":[]}"),
                SSG_E_GLTF, "Draco");
}

/* A scene around an OBJ: its diffuse colour is the albedo, the mesh line places it as
   scale, then rotate, then translate, and a missing texture is named at the mesh line. */
static void test_scene(void)
{
    write_file("two.mtl", MTL);
    write_file("two.obj", OBJ);
    const char *path = write_file("two.scene", "camera(position=[0, 0, 9])\n"
                                  "mesh(\"two.obj\", scale=[2, 2, 2], rotate=[0, 0, 90], "
                                  "translate=[10, 0, 0])\n");
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load(path, 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    if (s) {
        float lo[3], hi[3], diagonal;
        ssg_scene_bounds(s, lo, hi); /* (x, y) -> (-2y, 2x) + 10 x */
        CHECK_NEAR(lo[0], 8, 1e-5);
        CHECK_NEAR(hi[0], 10, 1e-5);
        CHECK_NEAR(lo[1], 0, 1e-5);
        CHECK_NEAR(hi[1], 4, 1e-5);
        CHECK_NEAR(hi[2], 2, 1e-5);
        CHECK_EQ(s->model_count, 1);
        CHECK_EQ(s->models[0].triangles, 5);
        CHECK_EQ(s->models[0].line, 2);
        CHECK_NEAR(s->materials[s->meshes[0].material].albedo[1], 0.4, 1e-6);
        CHECK_EQ(ssg_scene_scale_hint(s, 0.5f, &diagonal), 0); /* 5 units: fits */
        ssg_scene_destroy(&s);
    }
    d = (struct ssg_diags){0};
    write_file("tex.mtl", "newmtl t\nKd 1 1 1\nmap_Kd gone.png\n");
    write_file("tex.obj", "mtllib tex.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\n"
                          "vt 0 1\nusemtl t\nf 1/1 2/2 3/3\n");
    path = write_file("tex.scene", "mesh(\"tex.obj\")\n");
    CHECK_EQ(ssg_scene_load(path, 1, &s, &d), SSG_E_IO);
    CHECK(s == NULL);
    CHECK(d.count == 1 && d.items[0].line == 1 && d.items[0].column == 6 &&
          strstr(d.items[0].message, "gone.png"));
}

/* 300 mm across in millimetres: 0.01 brings it to 3 units, about 6 AO radii. */
static void test_scale_hint(void)
{
    write_file("mm.stl", "solid mm\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                         "vertex 300 0 0\nvertex 0 200 0\nendloop\nendfacet\nendsolid mm\n");
    const char *path = write_file("mm.scene", "camera(position=[0, 0, 900], far=2000)\n"
                                  "mesh(\"mm.stl\")\n");
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load(path, 1, &s, &d), SSG_OK);
    if (s) {
        float diagonal;
        CHECK_NEAR(ssg_scene_scale_hint(s, 0.5f, &diagonal), 0.01, 1e-9);
        CHECK_NEAR(diagonal, sqrtf(300 * 300 + 200 * 200), 1e-2);
        ssg_scene_destroy(&s);
    }
}

/* Loads path for its up axis, with the model and without; the model's box into lo, hi. */
static void expect_up(const char *path, int axis, int sign, const char *basis, float lo[3],
                      float hi[3])
{
    struct ssg_gltf *g = NULL;
    struct ssg_model_up up = {.axis = 9, .sign = 9}, alone = {.axis = 9, .sign = 9};
    char why[1024] = "";
    long long tris;
    CHECK_EQ(ssg_model_load_up(path, &g, &up, why, sizeof why), SSG_OK);
    CHECK_EQ(ssg_model_load_up(path, NULL, &alone, why, sizeof why), SSG_OK);
    CHECK(up.axis == axis && up.sign == sign && alone.axis == axis && alone.sign == sign);
    if (!strstr(up.basis, basis) || strcmp(up.basis, alone.basis)) {
        fprintf(stderr, "%s: up basis '%s' / '%s' lacks '%s'\n", path, up.basis, alone.basis,
                basis);
        CHECK(0);
    }
    if (g)
        bounds_of(g, lo, hi, &tris);
    ssg_gltf_destroy(&g);
}

static void test_up(void)
{
    float lo[3], hi[3];
    char z_up[sizeof DAE];
    snprintf(z_up, sizeof z_up, "%s", DAE);
    memcpy(strstr(z_up, "Y_UP"), "Z", 1);
    expect_up(write_file("two.obj", OBJ), -1, 1, "OBJ files do not say", lo, hi);
    expect_up(write_file("tri1.gltf", GLTF1), 1, 1, "glTF 1.0", lo, hi);
    expect_up(write_file("zup.dae", z_up), 1, 1, "Collada", lo, hi);
    CHECK_NEAR(lo[1], 5, 1e-6); /* the node's z = 5 is now y */
    CHECK_NEAR(hi[1], 5, 1e-6);
    expect_up(write_file("zup.fbx", FBX_Z_UP), 2, 1, "UpAxis", lo, hi);
    CHECK_NEAR(hi[2], 3, 1e-6); /* kept as written: 3 tall along z */
}

int main(void)
{
    setup_tmp("test_models_load");
    test_formats();
    test_failures();
    test_scene();
    test_scale_hint();
    test_up();
    return check_report();
}
