/* test_graph_files.c - the files a graph depends on (ssg_graph_files, ssg_scene_files;
 * ssgraph_tools.h), as a file watcher needs them: the top graph file, each include once,
 * the scene and lights files, the models, textures and environment image they name
 * (positional or named, resolved against the file naming them), each once; a graph parsed
 * with errors lists what was read so far, a missing include among it; a loaded graph with
 * its --scene override lists that scene's model; a scene's include lists the included
 * scene and what it names. */
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "scratch.h"
#include "ssgraph.h"

enum { MAX = 32 };

static struct ssg_graph_file files[MAX];

/* 1 when entry i is tmpdir/name of that kind. */
static int is(int i, const char *name, enum ssg_graph_file_kind kind)
{
    if (strcmp(files[i].path, tmp_path(name)) != 0 || files[i].kind != kind) {
        fprintf(stderr, "entry %d: %s (kind %d), expected %s (kind %d)\n", i, files[i].path,
                (int)files[i].kind, tmp_path(name), (int)kind);
        return 0;
    }
    return 1;
}

static void write_inputs(void)
{
    mkdir(tmp_path("sub"), 0777);
    write_file("inc.graph", "size 64 48\n");
    write_file("sub/s.scene",
               "clay = material(texture=\"tex/t.png\")\n"
               "mesh(\"m.obj\", material=clay)\n"
               "mesh(file=\"m.obj\")\n"             /* named twice: listed once */
               "environment([1, 1, 1], 0.3, \"probe.hdr\")\n" /* replaced by the lights */
               "set clay.texture = \"tex/u.png\"\n");
    write_file("l.scene", "environment([1, 1, 1], 0.3, \"sky.hdr\")\n");
}

/* A graph that parses: everything, in order, each once. */
static void whole(void)
{
    write_file("top.graph", "include \"inc.graph\"\ninclude \"inc.graph\"\n"
                            "scene \"sub/s.scene\"\nlights \"l.scene\"\n"
                            "g = gbuffer()\n");
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_parse(tmp_path("top.graph"), &g, &d), SSG_OK);
    int n = ssg_graph_files(g, files, MAX);
    CHECK_EQ(n, 8);
    if (n == 8) {
        CHECK(is(0, "top.graph", SSG_GRAPH_FILE_GRAPH));
        CHECK(is(1, "inc.graph", SSG_GRAPH_FILE_GRAPH));
        CHECK(is(2, "sub/s.scene", SSG_GRAPH_FILE_SCENE));
        CHECK(is(3, "l.scene", SSG_GRAPH_FILE_LIGHTS));
        CHECK(is(4, "sub/tex/t.png", SSG_GRAPH_FILE_TEXTURE));
        CHECK(is(5, "sub/m.obj", SSG_GRAPH_FILE_MODEL));
        CHECK(is(6, "sub/tex/u.png", SSG_GRAPH_FILE_TEXTURE));
        CHECK(is(7, "sky.hdr", SSG_GRAPH_FILE_ENVIRONMENT));
    }
    /* fewer than there are: the first max, and the whole count */
    memset(files, 0, sizeof files);
    CHECK_EQ(ssg_graph_files(g, files, 2), 8);
    CHECK(is(1, "inc.graph", SSG_GRAPH_FILE_GRAPH));
    CHECK_EQ(files[2].path[0], 0);
    CHECK_EQ(ssg_graph_files(g, NULL, 0), 8);
    ssg_graph_destroy(&g);
}

/* A graph with errors: what was read before and after them, the missing include too. */
static void broken(void)
{
    write_file("bad.graph", "include \"inc.graph\"\nao = nosuchnode()\n"
                            "include \"gone.graph\"\nscene \"sub/s.scene\"\n");
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    CHECK(ssg_graph_parse(tmp_path("bad.graph"), &g, &d) != SSG_OK);
    CHECK(g != NULL);
    int n = ssg_graph_files(g, files, MAX);
    CHECK_EQ(n, 8);
    if (n == 8) {
        CHECK(is(0, "bad.graph", SSG_GRAPH_FILE_GRAPH));
        CHECK(is(1, "inc.graph", SSG_GRAPH_FILE_GRAPH));
        CHECK(is(2, "gone.graph", SSG_GRAPH_FILE_GRAPH));
        CHECK(is(3, "sub/s.scene", SSG_GRAPH_FILE_SCENE));
        CHECK(is(6, "sub/probe.hdr", SSG_GRAPH_FILE_ENVIRONMENT)); /* no lights file now */
    }
    ssg_graph_destroy(&g);
    /* a top file that is missing is still the file to watch */
    CHECK(ssg_graph_parse(tmp_path("nothing.graph"), &g, &d) != SSG_OK);
    CHECK_EQ(ssg_graph_files(g, files, MAX), 1);
    CHECK(is(0, "nothing.graph", SSG_GRAPH_FILE_GRAPH));
    ssg_graph_destroy(&g);
}

/* Without a graph: a scene and lights file; none; NULL. */
static void scenes(void)
{
    CHECK_EQ(ssg_scene_files(tmp_path("sub/s.scene"), tmp_path("l.scene"), files, MAX), 6);
    CHECK(is(0, "sub/s.scene", SSG_GRAPH_FILE_SCENE));
    CHECK(is(1, "l.scene", SSG_GRAPH_FILE_LIGHTS));
    CHECK_EQ(ssg_scene_files(NULL, "", files, MAX), 0);
    CHECK_EQ(ssg_scene_files(tmp_path("no.scene"), NULL, files, MAX), 1);
    CHECK_EQ(ssg_graph_files(NULL, files, MAX), 0);
    /* a scene that includes another (the viewer's saved camera path): that file and what
       it names, resolved in its folder; a cycle ends */
    write_file("path.scene", "include \"sub/s.scene\"\ninclude \"path.scene\"\n"
                             "camera_key(time=0, position=[0, 0, 1], target=[0, 0, 0])\n");
    CHECK_EQ(ssg_scene_files(tmp_path("path.scene"), NULL, files, MAX), 6);
    CHECK(is(0, "path.scene", SSG_GRAPH_FILE_SCENE));
    CHECK(is(1, "sub/s.scene", SSG_GRAPH_FILE_SCENE));
    CHECK(is(2, "sub/tex/t.png", SSG_GRAPH_FILE_TEXTURE));
    CHECK(is(4, "sub/probe.hdr", SSG_GRAPH_FILE_ENVIRONMENT));
    CHECK(is(5, "sub/tex/u.png", SSG_GRAPH_FILE_TEXTURE));
}

/* A loaded graph with the scene overridden: the override and its model. */
static void loaded(void)
{
    struct ssg_overrides ov = {.scene = "examples/bunny.scene", .width = 32, .height = 24,
                               .seed = -1};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_load("graphs/ssao.graph", &ov, &g, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    int n = ssg_graph_files(g, files, MAX), scene = 0, model = 0;
    for (int i = 0; i < n && i < MAX; i++) {
        scene += !strcmp(files[i].path, "examples/bunny.scene") &&
                 files[i].kind == SSG_GRAPH_FILE_SCENE;
        model += !strcmp(files[i].path, "examples/bunny.gltf") &&
                 files[i].kind == SSG_GRAPH_FILE_MODEL;
    }
    CHECK(n >= 3);
    CHECK(!strcmp(files[0].path, "graphs/ssao.graph"));
    CHECK_EQ(scene, 1);
    CHECK_EQ(model, 1);
    ssg_graph_destroy(&g);
}

int main(void)
{
    setup_tmp("graph_files");
    write_inputs();
    whole();
    broken();
    scenes();
    loaded();
    return check_report();
}
