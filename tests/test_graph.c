/* test_graph.c - the graph format and its validation: every error the runtime promises to
 * find, with its code and exact line:column, plus includes, set lines, command-line
 * overrides, forward references and the run order. Graphs are written to SSG_TMP. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "graph/graph.h"

static char tmpdir[512];
static char scene[1024];

static const char *write_file(const char *name, const char *text)
{
    static char path[1024];
    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    FILE *f = fopen(path, "w");
    if (!f) {
        perror(path);
        exit(2);
    }
    fputs(text, f);
    fclose(f);
    return path;
}

/* A graph text with the Cornell scene line prepended (so line numbers start at 2). */
static const char *graph_file(const char *name, const char *body)
{
    char text[8192];
    snprintf(text, sizeof text, "scene \"%s\"\n%s", scene, body);
    return write_file(name, text);
}

static const char *base =
    "g = gbuffer()\n"                                                        /* 2 */
    "k = halton(count=8)\n"                                                  /* 3 */
    "ao = ssao(g.position, g.normal, kernel=k.samples, radius=0.5)\n"        /* 4 */
    "out = write(ao.out, \"t\")\n";                                          /* 5 */

/* Checks the graph and expects one diagnostic with this code at line:column. */
static void expect_error(const char *name, const char *body, enum ssg_err code, int line,
                         int column)
{
    struct ssg_diags d = {0};
    enum ssg_err e = ssg_graph_check(graph_file(name, body), NULL, &d);
    CHECK_EQ(e, code);
    CHECK(d.count >= 1);
    if (d.count >= 1) {
        CHECK_EQ(d.items[0].code, code);
        CHECK_EQ(d.items[0].line, line);
        CHECK_EQ(d.items[0].column, column);
    }
    if (e != code || d.count < 1 || d.items[0].line != line || d.items[0].column != column) {
        fprintf(stderr, "  in case '%s':\n", name);
        ssg_diags_print(&d, stderr);
    }
}

static void test_valid(void)
{
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_check(graph_file("ok.graph", base), NULL, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
}

static void test_errors(void)
{
    expect_error("unknown_node.graph", "g = gbufer()\n", SSG_E_UNKNOWN_NODE, 2, 5);
    expect_error("unknown_param.graph",
                 "g = gbuffer()\nk = halton(count=8)\n"
                 "ao = ssao(g.position, g.normal, kernel=k.samples, radus=0.5)\n"
                 "out = write(ao.out, \"t\")\n",
                 SSG_E_UNKNOWN_PARAM, 4, 51);
    expect_error("unknown_port.graph",
                 "g = gbuffer()\nk = halton(count=8)\n"
                 "ao = ssao(g.positon, g.normal, kernel=k.samples)\n"
                 "out = write(ao.out, \"t\")\n",
                 SSG_E_UNKNOWN_PORT, 4, 13);
    expect_error("unknown_name.graph",
                 "g = gbuffer()\nk = halton(count=8)\n"
                 "ao = ssao(g.position, gg.normal, kernel=k.samples)\n"
                 "out = write(ao.out, \"t\")\n",
                 SSG_E_UNKNOWN_NAME, 4, 23);
    expect_error("type.graph",
                 "g = gbuffer()\nk = halton(count=8)\n"
                 "ao = ssao(g.position, g.albedo, kernel=k.samples)\n"
                 "out = write(ao.out, \"t\")\n",
                 SSG_E_TYPE, 4, 23);
    expect_error("missing.graph",
                 "g = gbuffer()\n"
                 "ao = ssao(g.position, g.normal)\n"
                 "out = write(ao.out, \"t\")\n",
                 SSG_E_MISSING_INPUT, 3, 6);
    expect_error("range.graph",
                 "g = gbuffer()\nk = halton(count=8)\n"
                 "ao = ssao(g.position, g.normal, kernel=k.samples, radius=-2)\n"
                 "out = write(ao.out, \"t\")\n",
                 SSG_E_RANGE, 4, 58);
    expect_error("param_type.graph",
                 "g = gbuffer()\nk = halton(count=\"many\")\n"
                 "ao = ssao(g.position, g.normal, kernel=k.samples)\n"
                 "out = write(ao.out, \"t\")\n",
                 SSG_E_TYPE, 3, 18);
    expect_error("duplicate.graph",
                 "g = gbuffer()\ng = gbuffer()\nk = halton()\n"
                 "ao = ssao(g.position, g.normal, kernel=k.samples)\n"
                 "out = write(ao.out, \"t\")\n",
                 SSG_E_DUPLICATE, 3, 1);
    expect_error("cycle.graph",
                 "g = gbuffer()\nk = halton()\n"
                 "a = bilateral(b.out, depth=g.depth)\n"
                 "b = bilateral(a.out, depth=g.depth)\n"
                 "out = write(b.out, \"t\")\n",
                 SSG_E_CYCLE, 4, 5);
    expect_error("syntax.graph", "g = gbuffer(\nout = write(g.depth \"t\")\n", SSG_E_SYNTAX,
                 3, 12);
    expect_error("bad_char.graph", "g = gbuffer() $\n", SSG_E_SYNTAX, 2, 15);
    expect_error("size.graph", "size 0 480\n", SSG_E_SIZE, 2, 6);
    expect_error("jitter_range.graph", "jitter 5000\n", SSG_E_SIZE, 2, 8);
    expect_error("jitter_negative.graph", "jitter -1\n", SSG_E_SIZE, 2, 8);
    expect_error("jitter_fraction.graph", "jitter 1.5\n", SSG_E_TYPE, 2, 8);
    expect_error("jitter_two.graph", "jitter 8 2\n", SSG_E_SYNTAX, 2, 10);
    expect_error("jitter_none.graph", "jitter\n", SSG_E_TYPE, 2, 1);
    expect_error("include_missing.graph", "include \"nope.graph\"\n", SSG_E_IO, 2, 9);
    expect_error("unknown_directive.graph", "sise 640 480\n", SSG_E_SYNTAX, 2, 1);
    expect_error("set_unknown.graph",
                 "g = gbuffer()\nk = halton()\n"
                 "ao = ssao(g.position, g.normal, kernel=k.samples)\n"
                 "out = write(ao.out, \"t\")\nset a.radius = 1\n",
                 SSG_E_UNKNOWN_NAME, 6, 5);
    expect_error("bad_enum.graph",
                 "g = gbuffer()\nk = halton(mapping=conical)\n"
                 "ao = ssao(g.position, g.normal, kernel=k.samples)\n"
                 "out = write(ao.out, \"t\")\n",
                 SSG_E_VALUE, 3, 20);
}

static void test_every_error_reported(void)
{
    struct ssg_diags d = {0};
    const char *body = "g = gbuffer()\nk = halton(count=0)\n"
                       "ao = ssao(g.position, g.normal, kernel=k.samples, radus=1)\n"
                       "x = nonsense()\nout = write(ao.out, \"t\")\n";
    CHECK(ssg_graph_check(graph_file("many.graph", body), NULL, &d) != SSG_OK);
    CHECK_EQ(d.count, 3);
    if (d.count == 3) {
        CHECK_EQ(d.items[0].code, SSG_E_UNKNOWN_NODE); /* found while reading */
        CHECK_EQ(d.items[1].code, SSG_E_RANGE);        /* then while binding */
        CHECK_EQ(d.items[2].code, SSG_E_UNKNOWN_PARAM);
    }
}

static void test_include_cycle(void)
{
    write_file("loop_b.graph", "include \"loop_a.graph\"\n");
    const char *a = write_file("loop_a.graph", "include \"loop_b.graph\"\n");
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_check(a, NULL, &d), SSG_E_INCLUDE);
    CHECK_EQ(d.items[0].line, 1);
    CHECK_EQ(d.items[0].column, 9);
}

/* Loads a graph for real and returns it, so parameters and order can be inspected. */
static struct ssg_graph *load(const char *path, const struct ssg_overrides *ov)
{
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_load(path, ov, &g, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    return g;
}

static float param_float(const struct ssg_graph *g, const char *node, const char *param)
{
    int i = ssg_graph_find(g, node, strlen(node));
    const struct gnode *n = &g->nodes[i];
    int p = ssg_param_find(n->desc->params, param, strlen(param));
    return *(const float *)((const char *)n->params + n->desc->params.params[p].offset);
}

static void test_include_set_and_overrides(void)
{
    graph_file("base.graph", base);
    const char *variant = write_file("variant.graph", "include \"base.graph\"\n"
                                                      "set ao.radius = 0.25\nsize 320 200\n");
    struct ssg_graph *g = load(variant, NULL);
    if (g) {
        CHECK_NEAR(param_float(g, "ao", "radius"), 0.25, 0);
        CHECK_EQ(g->width, 320);
        CHECK_EQ(g->height, 200);
        /* run order follows dependencies: gbuffer and halton before ssao before write */
        CHECK_EQ(g->order_count, 4);
        CHECK(strcmp(g->nodes[g->order[3]].name, "out") == 0);
    }
    ssg_graph_destroy(&g);
    CHECK(g == NULL);

    const char *sets[] = {"ao.radius=0.75"};
    struct ssg_overrides ov = {.width = 64, .height = 48, .sets = sets, .set_count = 1,
                               .seed = 9};
    g = load(variant, &ov);
    if (g) {
        CHECK_NEAR(param_float(g, "ao", "radius"), 0.75, 0);
        CHECK_EQ(g->width, 64);
        CHECK_EQ(g->frame.seed, 9);
    }
    ssg_graph_destroy(&g);

    struct ssg_diags d = {0};
    const char *bad[] = {"ao.radius=abc"};
    ov.sets = bad;
    CHECK(ssg_graph_check(variant, &ov, &d) != SSG_OK);
    CHECK_EQ(d.items[0].code, SSG_E_TYPE);
    CHECK_EQ(d.items[0].column, 11);
    CHECK(strcmp(d.items[0].file, "<command line --set>") == 0);
}

static void test_forward_reference_and_pruning(void)
{
    const char *body = "out = write(ao.out, \"t\")\n"
                       "ao = ssao(g.position, g.normal, kernel=k.samples)\n"
                       "unused = bilateral(ao.out, depth=g.depth)\n"
                       "k = halton()\ng = gbuffer()\n";
    struct ssg_graph *g = load(graph_file("forward.graph", body), NULL);
    if (g) {
        CHECK_EQ(g->order_count, 4); /* `unused` feeds no sink: it is not run */
        CHECK(strcmp(g->nodes[g->order[0]].name, "k") == 0 ||
              strcmp(g->nodes[g->order[0]].name, "g") == 0);
        CHECK(strcmp(g->nodes[g->order[3]].name, "out") == 0);
    }
    ssg_graph_destroy(&g);
}

static void test_no_sink(void)
{
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_check(graph_file("nosink.graph", "g = gbuffer()\n"), NULL, &d),
             SSG_E_VALUE);
}

int main(void)
{
    const char *t = getenv("SSG_TMP");
    snprintf(tmpdir, sizeof tmpdir, "%s", t ? t : CHECK_TMP_ROOT "/ssg_test_graph");
    mkdir(tmpdir, 0777);
    char cwd[512];
    if (!getcwd(cwd, sizeof cwd))
        return 2;
    snprintf(scene, sizeof scene, "%s/examples/cornell.scene", cwd);
    test_valid();
    test_errors();
    test_every_error_reported();
    test_include_cycle();
    test_include_set_and_overrides();
    test_forward_reference_and_pruning();
    test_no_sink();
    return check_report();
}
