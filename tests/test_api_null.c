/* test_api_null.c - every function of the public header (ssgraph.h) given NULL where it
 * takes a pointer: a function that returns a code answers SSG_E_USAGE and names the
 * function and the argument in diags (or records nothing when diags itself is NULL); one
 * that returns nothing does nothing; none crashes. A library user's mistake is reported,
 * not a segmentation fault. */
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "ssgraph.h"

/* SSG_E_USAGE with a message naming function and argument. */
static void expect_usage(enum ssg_err e, const struct ssg_diags *d, const char *function,
                         const char *argument)
{
    CHECK_EQ(e, SSG_E_USAGE);
    CHECK(d->count >= 1);
    if (d->count < 1)
        return;
    CHECK_EQ(d->items[0].code, SSG_E_USAGE);
    CHECK(strstr(d->items[0].message, function) != NULL);
    CHECK(strstr(d->items[0].message, argument) != NULL);
}

static void graphs(void)
{
    struct ssg_diags d = {0};
    struct ssg_graph *g = (struct ssg_graph *)&d; /* must be set to NULL, never read */
    expect_usage(ssg_graph_load(NULL, NULL, &g, &d), &d, "ssg_graph_load", "path");
    CHECK(g == NULL);
    d = (struct ssg_diags){0};
    expect_usage(ssg_graph_load("graphs/ssao.graph", NULL, NULL, &d), &d, "ssg_graph_load",
                 "out");
    CHECK_EQ(ssg_graph_load(NULL, NULL, &g, NULL), SSG_E_USAGE); /* NULL diags: no record */
    d = (struct ssg_diags){0};
    expect_usage(ssg_graph_check(NULL, NULL, &d), &d, "ssg_graph_check", "path");
    d = (struct ssg_diags){0};
    expect_usage(ssg_graph_run(NULL, NULL, &d), &d, "ssg_graph_run", "graph");
    d = (struct ssg_diags){0};
    double v;
    expect_usage(ssg_graph_param(NULL, "a.b", &v, NULL, &d), &d, "ssg_graph_param", "graph");
    d = (struct ssg_diags){0};
    struct ssg_view view;
    expect_usage(ssg_graph_camera_at(NULL, 0, &view, &d), &d, "ssg_graph_camera_at", "graph");
    d = (struct ssg_diags){0};
    float jitter[2];
    expect_usage(ssg_graph_jitter_at(NULL, 0, jitter, &d), &d, "ssg_graph_jitter_at", "graph");
    d = (struct ssg_diags){0};
    expect_usage(ssg_graph_set_frame(NULL, 0, &d), &d, "ssg_graph_set_frame", "graph");
    d = (struct ssg_diags){0};
    expect_usage(ssg_scene_check(NULL, &d), &d, "ssg_scene_check", "path");
    d = (struct ssg_diags){0};
    g = (struct ssg_graph *)&d;
    expect_usage(ssg_graph_load_text("x.graph", NULL, NULL, &g, &d), &d,
                 "ssg_graph_load_text", "text");
    CHECK(g == NULL);
    char *text = (char *)&d; /* must be set to NULL, never read */
    d = (struct ssg_diags){0};
    expect_usage(ssg_graph_text_edit("x.graph", "g = gbuffer()", NULL, &text, &d), &d,
                 "ssg_graph_text_edit", "edits");
    CHECK(text == NULL);
    CHECK_EQ(ssg_node_port_count(NULL), 0);
    CHECK_EQ(ssg_node_port_info(NULL, 0, NULL), SSG_E_USAGE);
    ssg_graph_destroy(NULL);
    g = NULL;
    ssg_graph_destroy(&g);
}

/* ssg_graph_param's key and value, on a loaded graph. */
static void graph_param(void)
{
    struct ssg_diags d = {0};
    struct ssg_overrides ov = {.seed = -1, .width = 8, .height = 8};
    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_check("graphs/ssao.graph", &ov, &d), SSG_OK);
    if (ssg_graph_load("graphs/ssao.graph", &ov, &g, &d) != SSG_OK)
        return;
    double v;
    d = (struct ssg_diags){0};
    expect_usage(ssg_graph_param(g, NULL, &v, NULL, &d), &d, "ssg_graph_param", "key");
    d = (struct ssg_diags){0};
    expect_usage(ssg_graph_param(g, "ao.radius", NULL, NULL, &d), &d, "ssg_graph_param",
                 "value");
    ssg_graph_destroy(&g);
}

static void images(void)
{
    struct ssg_diags d = {0};
    struct ssg_image *im = NULL;
    expect_usage(ssg_image_read(NULL, NULL, &im, &d), &d, "ssg_image_read", "path");
    d = (struct ssg_diags){0};
    expect_usage(ssg_image_read("x.exr", NULL, NULL, &d), &d, "ssg_image_read", "out");
    d = (struct ssg_diags){0};
    expect_usage(ssg_image_write(NULL, NULL, &d), &d, "ssg_image_write", "path");
    d = (struct ssg_diags){0};
    expect_usage(ssg_image_write("x.exr", NULL, &d), &d, "ssg_image_write", "image");
    d = (struct ssg_diags){0};
    expect_usage(ssg_make_dirs(NULL, &d), &d, "ssg_make_dirs", "dir");
    d = (struct ssg_diags){0};
    expect_usage(ssg_output_check(NULL, "x", 0, &d), &d, "ssg_output_check", "path");
    d = (struct ssg_diags){0};
    expect_usage(ssg_output_check("x", NULL, 0, &d), &d, "ssg_output_check", "what");
    ssg_image_destroy(NULL);
    ssg_image_destroy(&im);
    CHECK(ssg_image_create(0, 0, 1) == NULL);
}

/* ssgraph.h's "Looking at images" section. */
static void looking(void)
{
    struct ssg_diags d = {0};
    struct ssg_image *im = ssg_image_create(2, 2, 1), *copy = im;
    expect_usage(ssg_image_write_png(NULL, im, NULL, 0, &d), &d, "ssg_image_write_png",
                 "path");
    d = (struct ssg_diags){0};
    expect_usage(ssg_image_write_png("x.png", NULL, NULL, 0, &d), &d, "ssg_image_write_png",
                 "image");
    struct ssg_layer_info info[1];
    int count = 7;
    d = (struct ssg_diags){0};
    expect_usage(ssg_image_layers(NULL, info, 1, &count, &d), &d, "ssg_image_layers", "path");
    CHECK_EQ(count, 0);
    d = (struct ssg_diags){0};
    expect_usage(ssg_image_layers("x.exr", info, 1, NULL, &d), &d, "ssg_image_layers",
                 "count");
    d = (struct ssg_diags){0};
    expect_usage(ssg_image_layers("x.exr", NULL, 1, &count, &d), &d, "ssg_image_layers",
                 "layers");
    CHECK(ssg_image_framed(NULL, NULL, &copy) == NULL);
    CHECK(ssg_image_framed(NULL, im, NULL) == NULL);
    CHECK(ssg_image_framed(NULL, im, &copy) == im && copy == NULL);
    struct ssg_frame f = {0};
    ssg_graph_frame(NULL, &f);
    CHECK(f.fov_y == SSG_DEFAULT_FOV_Y && f.seed == 1);
    ssg_graph_frame(NULL, NULL);
    ssg_image_destroy(&im);
}

static void nodes(void)
{
    struct ssg_diags d = {0};
    struct ssg_outputs out;
    expect_usage(ssg_node_run(NULL, NULL, 0, NULL, 0, NULL, &out, &d), &d, "ssg_node_run",
                 "node");
    CHECK_EQ(out.count, 0);
    d = (struct ssg_diags){0};
    expect_usage(ssg_node_run("gaussian", NULL, 0, NULL, 0, NULL, NULL, &d), &d,
                 "ssg_node_run", "outputs");
    d = (struct ssg_diags){0};
    expect_usage(ssg_node_run("gaussian", NULL, 2, NULL, 0, NULL, &out, &d), &d,
                 "ssg_node_run", "inputs");
    d = (struct ssg_diags){0};
    expect_usage(ssg_node_run("gaussian", NULL, 0, NULL, 1, NULL, &out, &d), &d,
                 "ssg_node_run", "sets");
    const char *sets[] = {NULL, "sigma=1"};
    d = (struct ssg_diags){0};
    expect_usage(ssg_node_run("gaussian", NULL, 0, sets, 2, NULL, &out, &d), &d,
                 "ssg_node_run", "sets[0]");
    struct ssg_binding bind = {NULL, NULL};
    d = (struct ssg_diags){0};
    expect_usage(ssg_node_run("gaussian", &bind, 1, NULL, 0, NULL, &out, &d), &d,
                 "ssg_node_run", "inputs[0].port");
    ssg_outputs_release(NULL);
    CHECK_EQ(ssg_node_describe(NULL, stdout), SSG_E_USAGE);
    CHECK_EQ(ssg_node_describe("ssao", NULL), SSG_E_USAGE);
    CHECK(ssg_node_name(-1) == NULL);
    CHECK(ssg_node_summary(ssg_node_count()) == NULL);
    ssg_nodes_markdown(NULL, NULL);
    ssg_scenes_markdown(NULL);
}

static void diagnostics(void)
{
    struct ssg_diags d = {0};
    ssg_diags_print(NULL, stderr);
    ssg_diags_print(&d, NULL);
    CHECK_EQ(ssg_diags_first(NULL), SSG_OK);
    ssg_run_stats_free(NULL);
    CHECK(ssg_err_name((enum ssg_err)-1) != NULL);
    CHECK(ssg_err_text(SSG_ERR_COUNT) != NULL);
}

int main(void)
{
    graphs();
    graph_param();
    images();
    looking();
    nodes();
    diagnostics();
    return check_report();
}
