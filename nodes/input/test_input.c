/* test_input.c - the `input` node: a pipeline fed through input nodes with a G-buffer's own
 * images gives the bytes of the same pipeline reading the gbuffer node (ssao on CPU and
 * GL); a wrong shape, a node that is not an input, and a run with nothing supplied are
 * refused with messages that say what was expected; on a kept graph a new image re-runs
 * the node and its readers. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "ssgraph.h"

static char graph[1200];

/* Two ssao nodes, one on the gbuffer, one on input nodes, on the cornell scene. */
static void write_graph(void)
{
    char cwd[900], dir[1024];
    const char *tmp = getenv("SSG_TMP");
    snprintf(dir, sizeof dir, "%s", tmp ? tmp : CHECK_TMP_ROOT "/ssg_test_input");
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_make_dirs(dir, &d), SSG_OK);
    CHECK(getcwd(cwd, sizeof cwd) != NULL);
    snprintf(graph, sizeof graph, "%s/input.graph", dir);
    FILE *f = fopen(graph, "w");
    CHECK(f != NULL);
    fprintf(f, "scene \"%s/examples/cornell.scene\"\nsize 40 28\n"
               "g = gbuffer()\npos = input(type=vector)\nnrm = input(type=vector)\n"
               "k = halton(count=8)\n"
               "a = ssao(g.position, g.normal, kernel=k.samples, rotation=k.rotation)\n"
               "b = ssao(pos.out, nrm.out, kernel=k.samples, rotation=k.rotation)\n"
               "w = write(a.out, \"a\", b=b.out)\n", cwd);
    fclose(f);
}

static struct ssg_graph *load(const char *backend, const char *const *outputs, int count)
{
    struct ssg_overrides ov = {.seed = -1, .backend = backend, .outputs = outputs,
                               .output_count = count};
    struct ssg_graph *g = NULL;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_load(graph, &ov, &g, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    return g;
}

static int same(const struct ssg_image *a, const struct ssg_image *b)
{
    return a && b && a->width == b->width && a->height == b->height &&
           a->channels == b->channels &&
           !memcmp(a->data, b->data, (size_t)a->width * a->height * a->channels * 4);
}

static void fed_equals_gbuffer(const char *backend)
{
    const char *first[] = {"g.position", "g.normal", "a.out"};
    struct ssg_image *im[3] = {0};
    struct ssg_graph *g = load(backend, first, 3);
    struct ssg_diags d = {0};
    struct ssg_run_options opt = {.threads = 2, .outputs = im};
    CHECK_EQ(ssg_graph_run(g, &opt, &d), SSG_OK);
    ssg_graph_destroy(&g);

    const char *second[] = {"b.out"};
    struct ssg_image *fed = NULL;
    g = load(backend, second, 1);
    CHECK_EQ(ssg_graph_supply(g, "pos", im[0], &d), SSG_OK);
    CHECK_EQ(ssg_graph_supply(g, "nrm", im[1], &d), SSG_OK);
    opt.outputs = &fed;
    CHECK_EQ(ssg_graph_run(g, &opt, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    CHECK(same(fed, im[2]));

    /* kept: a new normal image re-runs nrm and b, not pos */
    struct ssg_run_stats st = {0};
    ssg_image_destroy(&fed);
    CHECK_EQ(ssg_graph_keep(g, 0, &d), SSG_OK);
    CHECK_EQ(ssg_graph_run(g, &opt, &d), SSG_OK);
    ssg_image_destroy(&fed);
    for (size_t i = 0; i < (size_t)im[1]->width * im[1]->height * 3; i++)
        im[1]->data[i] = -im[1]->data[i]; /* flipped normals: a different answer */
    CHECK_EQ(ssg_graph_supply(g, "nrm", im[1], &d), SSG_OK);
    opt.stats = &st;
    CHECK_EQ(ssg_graph_run(g, &opt, &d), SSG_OK);
    for (int i = 0; i < st.node_count; i++)
        if (!strcmp(st.nodes[i].name, "pos") || !strcmp(st.nodes[i].name, "nrm") ||
            !strcmp(st.nodes[i].name, "b"))
            CHECK_EQ(st.nodes[i].calls, strcmp(st.nodes[i].name, "pos") ? 1 : 0);
    CHECK(fed && !same(fed, im[2]));
    ssg_run_stats_free(&st);
    ssg_image_destroy(&fed);
    for (int k = 0; k < 3; k++)
        ssg_image_destroy(&im[k]);
    ssg_graph_destroy(&g);
}

static void refusals(void)
{
    const char *outs[] = {"b.out"};
    struct ssg_graph *g = load("cpu", outs, 1);
    struct ssg_diags d = {0};
    struct ssg_image *small = ssg_image_create(8, 8, 3), *fed = NULL;
    CHECK_EQ(ssg_graph_supply(g, "pos", small, &d), SSG_E_SIZE);
    CHECK_EQ(ssg_graph_supply(g, "k", small, &d), SSG_E_TYPE);
    CHECK_EQ(ssg_graph_supply(g, "nosuch", small, &d), SSG_E_UNKNOWN_NAME);
    struct ssg_run_options opt = {.threads = 2, .outputs = &fed};
    CHECK_EQ(ssg_graph_run(g, &opt, &d), SSG_E_MISSING_INPUT);
    ssg_diags_print(&d, stderr);
    int said = 0;
    for (int i = 0; i < d.count; i++)
        said |= strstr(d.items[i].message, "expected 40x28 with 3") != NULL ||
                strstr(d.items[i].message, "ssg_graph_supply(graph, \"pos\"") != NULL;
    CHECK(said);
    ssg_image_destroy(&small);
    ssg_graph_destroy(&g);
}

int main(void)
{
    write_graph();
    fed_equals_gbuffer("cpu");
    fed_equals_gbuffer("gl");
    refusals();
    return check_report();
}
