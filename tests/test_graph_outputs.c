/* test_graph_outputs.c - requested outputs (ssg_overrides.outputs, ssg_run_options.outputs)
 * and ssg_graph_param: a load that asks for one port runs only what that port needs (no
 * sink, no file written), hands back the port's pixels equal to a whole run's, and names
 * what it lacks (node, port) with the code and place; with keep_sinks the sinks run too
 * (ssgraph run --show); a parameter's value and kind come
 * back after set lines and overrides, and keys the graph lacks are refused with the node's
 * line:column. Graphs are written to SSG_TMP. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "ssgraph.h"

static char tmpdir[512];

static const char *graph_path(void)
{
    static char path[1024];
    char cwd[512];
    if (!getcwd(cwd, sizeof cwd))
        exit(2);
    snprintf(path, sizeof path, "%s/g.graph", tmpdir);
    FILE *f = fopen(path, "w");
    if (!f)
        exit(2);
    fprintf(f, "scene \"%s/examples/cornell.scene\"\n"                            /* 1 */
               "size 24 16\n"                                                     /* 2 */
               "g = gbuffer()\n"                                                  /* 3 */
               "k = halton(count=8)\n"                                            /* 4 */
               "ao = ssao(g.position, g.normal, kernel=k.samples, radius=0.5)\n"  /* 5 */
               "set ao.bias = 0.03\n"                                             /* 6 */
               "out = write(ao.out, \"t\", tonemap=clamp)\n",                     /* 7 */
            cwd);
    fclose(f);
    return path;
}

/* One run of the graph asking for `port` (NULL: none), keeping its sinks or not: the
   port's image (NULL on failure or without one), and the nodes run. */
static struct ssg_image *run_with(const char *graph, const char *port, int keep_sinks,
                                  const char *dir, struct ssg_run_stats *st, int frames)
{
    const char *outs[] = {port};
    struct ssg_overrides ov = {.seed = -1, .outputs = port ? outs : NULL,
                               .output_count = port != NULL, .keep_sinks = keep_sinks};
    struct ssg_image *im[1] = {NULL};
    struct ssg_run_options ro = {.out_dir = dir, .threads = 1, .stats = st,
                                 .outputs = port ? im : NULL, .frames = frames};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    enum ssg_err e = ssg_graph_load(graph, &ov, &g, &d);
    if (!e)
        e = ssg_graph_run(g, &ro, &d);
    CHECK_EQ(e, SSG_OK);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
    return im[0];
}

static struct ssg_image *run_port_frames(const char *graph, const char *port,
                                         const char *dir, struct ssg_run_stats *st, int frames)
{
    return run_with(graph, port, 0, dir, st, frames);
}

static struct ssg_image *run_port(const char *graph, const char *port, const char *dir,
                                  struct ssg_run_stats *st)
{
    return run_port_frames(graph, port, dir, st, 1);
}

/* Several frames hand out the last frame's pixels, the one-frame image, and give every
   earlier frame's image of the port back (a leak here is what AddressSanitizer's build
   reports: bench --reference runs its cells over several frames). The port is the
   G-buffer's: at a still camera every frame has its pixels, where ao.out's samples move
   from frame to frame (halton, docs/time.md). */
static void test_frames(const char *graph)
{
    char dir[600];
    snprintf(dir, sizeof dir, "%s/frames", tmpdir);
    struct ssg_image *one = run_port_frames(graph, "g.depth", dir, NULL, 1);
    struct ssg_image *three = run_port_frames(graph, "g.depth", dir, NULL, 3);
    CHECK(one && three);
    if (one && three)
        CHECK(one->width == three->width && one->height == three->height &&
              !memcmp(one->data, three->data, (size_t)one->width * (size_t)one->height *
                                                  sizeof *one->data));
    ssg_image_destroy(&one);
    ssg_image_destroy(&three);
}

static void test_only_what_the_port_needs(const char *graph)
{
    char dir[600];
    snprintf(dir, sizeof dir, "%s/port_out", tmpdir);
    char written[700];
    snprintf(written, sizeof written, "%s/t.exr", dir);
    unlink(written); /* a previous run's */
    struct ssg_run_stats st = {0};
    struct ssg_image *depth = run_port(graph, "g.depth", dir, &st);
    CHECK(depth && depth->width == 24 && depth->height == 16 && depth->channels == 1);
    CHECK_EQ(st.node_count, 1); /* the gbuffer alone: no halton, ssao or write */
    CHECK(access(written, F_OK) != 0);
    ssg_run_stats_free(&st);

    /* The same pixels as the whole graph's: ao.out through a port equals the file. */
    struct ssg_image *ao = run_port(graph, "ao.out", dir, &st);
    CHECK_EQ(st.node_count, 3);
    ssg_run_stats_free(&st);
    struct ssg_overrides ov = {.seed = -1};
    struct ssg_run_options ro = {.out_dir = dir, .threads = 1};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_load(graph, &ov, &g, &d), SSG_OK);
    CHECK_EQ(ssg_graph_run(g, &ro, &d), SSG_OK);
    ssg_graph_destroy(&g);
    struct ssg_image *file = NULL;
    CHECK_EQ(ssg_image_read(written, NULL, &file, &d), SSG_OK);
    int same = ao && file && ao->width == file->width && ao->height == file->height;
    for (int i = 0; same && i < ao->width * ao->height; i++)
        same = ao->data[i] == file->data[i];
    CHECK(same);
    ssg_image_destroy(&ao);
    ssg_image_destroy(&file);
    ssg_image_destroy(&depth);
}

/* keep_sinks: the requested port is handed out and the graph's sinks still run (every
   node, the file written); without outputs it changes nothing. */
static void test_keep_sinks(const char *graph)
{
    char dir[600], written[700];
    snprintf(dir, sizeof dir, "%s/keep", tmpdir);
    snprintf(written, sizeof written, "%s/t.exr", dir);
    for (int with_outputs = 0; with_outputs < 2; with_outputs++) {
        unlink(written); /* the previous pass's */
        struct ssg_run_stats st = {0};
        struct ssg_image *im = run_with(graph, with_outputs ? "g.depth" : NULL, 1, dir, &st, 1);
        CHECK_EQ(st.node_count, 4); /* gbuffer, halton, ssao, write */
        CHECK(access(written, F_OK) == 0);
        CHECK(!with_outputs || (im && im->width == 24 && im->channels == 1));
        ssg_image_destroy(&im);
        ssg_run_stats_free(&st);
    }
}

/* A requested output the graph lacks: the code, in the file "<output>", at the column of
   the name that is wrong. */
static void expect_output_error(const char *graph, const char *port, enum ssg_err code,
                                int column)
{
    const char *outs[] = {port};
    struct ssg_overrides ov = {.seed = -1, .outputs = outs, .output_count = 1};
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_check(graph, &ov, &d), code);
    CHECK(d.count >= 1 && !strcmp(d.items[0].file, "<output>"));
    CHECK_EQ(d.count ? d.items[0].column : -1, column);
}

static void expect_param(const struct ssg_graph *g, const char *key, enum ssg_err code,
                         int line, double value, int integer)
{
    struct ssg_diags d = {0};
    double v = -1;
    int is_int = -1;
    CHECK_EQ(ssg_graph_param(g, key, &v, &is_int, &d), code);
    if (code == SSG_OK) {
        CHECK_NEAR(v, value, 1e-7);
        CHECK_EQ(is_int, integer);
    } else {
        CHECK_EQ(d.count, 1);
        CHECK_EQ(d.items[0].code, code);
        CHECK_EQ(d.items[0].line, line);
    }
}

static void test_param(const char *graph)
{
    const char *sets[] = {"k.count=16"};
    struct ssg_overrides ov = {.seed = -1, .sets = sets, .set_count = 1};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_load(graph, &ov, &g, &d), SSG_OK);
    if (!g)
        return;
    expect_param(g, "ao.radius", SSG_OK, 0, 0.5, 0);
    expect_param(g, "ao.bias", SSG_OK, 0, 0.03, 0);   /* the set line */
    expect_param(g, "k.count", SSG_OK, 0, 16, 1);     /* the override */
    expect_param(g, "ao.radus", SSG_E_UNKNOWN_PARAM, 5, 0, 0);
    expect_param(g, "k.bases", SSG_E_TYPE, 4, 0, 0);  /* a list, not a number */
    expect_param(g, "out.name", SSG_E_TYPE, 7, 0, 0); /* a string */
    expect_param(g, "a.radius", SSG_E_UNKNOWN_NAME, 0, 0, 0);
    expect_param(g, "radius", SSG_E_USAGE, 0, 0, 0);
    ssg_graph_destroy(&g);
}

int main(void)
{
    const char *t = getenv("SSG_TMP");
    snprintf(tmpdir, sizeof tmpdir, "%s", t ? t : CHECK_TMP_ROOT "/ssg_test_graph_outputs");
    mkdir(tmpdir, 0777);
    const char *graph = graph_path();
    test_only_what_the_port_needs(graph);
    test_frames(graph);
    test_keep_sinks(graph);
    expect_output_error(graph, "a.out", SSG_E_UNKNOWN_NAME, 1);
    expect_output_error(graph, "ao.diff", SSG_E_UNKNOWN_PORT, 4);
    expect_output_error(graph, "3", SSG_E_USAGE, 1);
    test_param(graph);
    return check_report();
}
