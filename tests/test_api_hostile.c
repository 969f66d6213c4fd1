/* test_api_hostile.c - what the public API refuses rather than half-reads or crashes on
 * (issue 42), each a defect once found:
 *   - values are one line: a control character anywhere in an ssg_graph_set key or value
 *     (a newline, a tab, 0x7f, an escape) is refused whole at its column of
 *     "<ssg_graph_set>", never cut at the newline (which applied "0.3" and dropped an
 *     `include` line a viewer then saved); a raw control byte in a file's string is
 *     refused at its line and column;
 *   - a number literal is read whole however long (62 zeros then 16 is 16, not the 1 a
 *     63-character buffer left), or refused as out of range at its place;
 *   - a camera whose inputs are finite but whose view direction is not (position 2e38,
 *     target -2e38: it aborted inside Embree at the next run) is refused, and so are its
 *     kin (past +-1e9, a fov whose projection overflows); the graph keeps its camera and
 *     runs;
 *   - a single node's frame has the same fov and plane bounds (fov 1e-30 ran);
 *   - frame INT_MAX runs, and runs again, without `last + 1` overflowing (UBSan), and a
 *     sequence that would pass INT_MAX is refused before it runs. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "check.h"
#include "ssgraph.h"

static char out_dir[1024];

static struct ssg_graph *load_ssao(void)
{
    struct ssg_overrides ov = {.width = 16, .height = 12, .seed = -1, .backend = "cpu"};
    struct ssg_graph *g = NULL;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_load("graphs/ssao.graph", &ov, &g, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    return g;
}

static enum ssg_err run(struct ssg_graph *g, int frames)
{
    struct ssg_run_options opt = {.out_dir = out_dir, .threads = 1, .frames = frames,
                                  .no_files = 1};
    struct ssg_diags d = {0};
    enum ssg_err e = ssg_graph_run(g, &opt, &d);
    ssg_diags_print(&d, stderr);
    return e;
}

/* ssg_graph_set(key, value) is refused with `code` at column `column` of key=value. */
static void expect_refused(struct ssg_graph *g, const char *key, const char *value,
                           enum ssg_err code, int column)
{
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_set(g, key, value, &d), code);
    CHECK_EQ(d.count, 1);
    CHECK_EQ(d.items[0].code, code);
    CHECK(strcmp(d.items[0].file, "<ssg_graph_set>") == 0);
    CHECK_EQ(d.items[0].line, 1);
    CHECK_EQ(d.items[0].column, column);
    CHECK(strchr(d.items[0].message, '\n') == NULL); /* the value is never echoed raw */
    ssg_diags_print(&d, stderr);
}

static double param(struct ssg_graph *g, const char *key)
{
    double v = -1;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_param(g, key, &v, NULL, &d), SSG_OK);
    return v;
}

static void values_are_one_line(void)
{
    struct ssg_graph *g = load_ssao();
    expect_refused(g, "ao.radius", "0.3\ninclude \"/etc/passwd\"", SSG_E_SYNTAX, 14);
    expect_refused(g, "ao.radius", "0.3\r", SSG_E_SYNTAX, 14);
    expect_refused(g, "ao.radius", "\t0.3", SSG_E_SYNTAX, 11);
    expect_refused(g, "ao.radius", "0.3 # \n", SSG_E_SYNTAX, 17);
    expect_refused(g, "ao.radius", "0.3\x7f", SSG_E_SYNTAX, 14);
    expect_refused(g, "out.name", "\"a\x1b[2Jb\"", SSG_E_SYNTAX, 12);
    expect_refused(g, "ao.radius\n", "0.3", SSG_E_SYNTAX, 10); /* the key too */
    expect_refused(g, "ao\n.radius", "0.3", SSG_E_SYNTAX, 3);
    CHECK_NEAR(param(g, "ao.radius"), 0.5, 1e-7); /* nothing was applied */
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_set(g, "ao.radius", "0.3", &d), SSG_OK); /* one line: taken */
    CHECK_NEAR(param(g, "ao.radius"), 0.3, 1e-7);
    ssg_graph_destroy(&g);
}

/* A raw control byte inside a string of a graph file: refused at its line and column. */
static void file_strings_are_text(void)
{
    char path[1100];
    snprintf(path, sizeof path, "%s/control.graph", out_dir);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f)
        return;
    fprintf(f, "include \"%s/graphs/ssao.graph\"\nset out.name = \"ss\tao\"\n", SSG_SOURCE_DIR);
    fclose(f);
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_check(path, NULL, &d), SSG_E_SYNTAX);
    CHECK(d.count >= 1 && d.items[0].line == 2 && d.items[0].column == 19);
    ssg_diags_print(&d, stderr);
}

static void long_literals_read_whole(void)
{
    struct ssg_graph *g = load_ssao();
    char count[80], radius[120], huge[420];
    snprintf(count, sizeof count, "%062d16", 0); /* 64 characters */
    snprintf(radius, sizeof radius, "0.%070d5e70", 0); /* 0.5, written in 76 */
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_set(g, "k.count", count, &d), SSG_OK);
    CHECK_EQ(param(g, "k.count"), 16);
    CHECK_EQ(ssg_graph_set(g, "ao.radius", radius, &d), SSG_OK);
    CHECK_NEAR(param(g, "ao.radius"), 0.5, 1e-7);
    CHECK_EQ(d.count, 0);
    memset(huge, '9', 400); /* 1e400: past a double, refused (at node k, as any value) */
    huge[400] = 0;
    CHECK_EQ(ssg_graph_set(g, "k.count", huge, &d), SSG_E_SYNTAX);
    CHECK(d.count == 1 && d.items[0].code == SSG_E_SYNTAX && d.items[0].line == 12);
    CHECK_EQ(param(g, "k.count"), 16);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

static void cameras_past_float(void)
{
    struct ssg_graph *g = load_ssao();
    struct ssg_view home, bad;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_view(g, &home, &d), SSG_OK);
    const struct ssg_view overflows = {{0, 0, 2e38f}, {0, 0, -2e38f}, {0, 1, 0}, 45};
    CHECK_EQ(ssg_graph_set_view(g, &overflows, &d), SSG_E_VALUE);
    bad = home, bad.position[0] = 3e9f; /* past the scene format's +-1e9 */
    CHECK_EQ(ssg_graph_set_view(g, &bad, &d), SSG_E_VALUE);
    bad = home, bad.fov_y = 1e-30f; /* 1 / tan(fov / 2) is no float */
    CHECK_EQ(ssg_graph_set_view(g, &bad, &d), SSG_E_VALUE);
    bad = home, memcpy(bad.target, bad.position, sizeof bad.target);
    CHECK_EQ(ssg_graph_set_view(g, &bad, &d), SSG_E_VALUE);
    CHECK_EQ(d.count, 4);
    ssg_diags_print(&d, stderr);
    struct ssg_view now;
    CHECK_EQ(ssg_graph_view(g, &now, &d), SSG_OK);
    CHECK(memcmp(&now, &home, sizeof now) == 0);
    CHECK_EQ(run(g, 1), SSG_OK); /* the old camera: before the fix, Embree aborted */
    ssg_graph_destroy(&g);
}

/* A single node's frame has the camera's bounds too: fov 1e-30 (an infinite focal length),
   fov 180 and far at infinity are refused, fov 45 runs. */
static void node_frames_in_range(void)
{
    const float fovs[] = {1e-30f, 180.0f, 45.0f};
    for (int i = 0; i < 3; i++) {
        struct ssg_frame f = SSG_FRAME_DEFAULTS;
        struct ssg_outputs out = {0};
        struct ssg_diags d = {0};
        f.fov_y = fovs[i];
        CHECK_EQ(ssg_node_run("halton", NULL, 0, NULL, 0, &f, &out, &d),
                 i < 2 ? SSG_E_VALUE : SSG_OK);
        ssg_outputs_release(&out);
    }
    struct ssg_frame f = SSG_FRAME_DEFAULTS;
    struct ssg_outputs out = {0};
    struct ssg_diags d = {0};
    f.far_z = 1.0f / 0.0f;
    CHECK_EQ(ssg_node_run("halton", NULL, 0, NULL, 0, &f, &out, &d), SSG_E_VALUE);
    ssg_outputs_release(&out);
}

static void last_frame_index(void)
{
    struct ssg_graph *g = load_ssao();
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_keep(g, 0, &d), SSG_OK);
    CHECK_EQ(ssg_graph_set_frame(g, INT_MAX, &d), SSG_OK);
    CHECK_EQ(run(g, 1), SSG_OK);
    CHECK_EQ(run(g, 1), SSG_OK); /* follows on from INT_MAX? (last + 1 overflowed) */
    CHECK_EQ(run(g, 2), SSG_E_VALUE); /* frames INT_MAX and INT_MAX + 1: refused */
    CHECK_EQ(ssg_graph_set_frame(g, INT_MAX - 1, &d), SSG_OK);
    CHECK_EQ(run(g, 2), SSG_OK); /* ends on INT_MAX exactly */
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

int main(void)
{
    const char *tmp = getenv("SSG_TMP");
    snprintf(out_dir, sizeof out_dir, "%s", tmp ? tmp : CHECK_TMP_ROOT "/ssg_test_api_hostile");
    mkdir(out_dir, 0755);
    values_are_one_line();
    file_strings_are_text();
    long_literals_read_whole();
    cameras_past_float();
    node_frames_in_range();
    last_frame_index();
    return check_report();
}
