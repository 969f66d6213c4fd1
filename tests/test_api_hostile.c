/* test_api_hostile.c - what the public API refuses rather than half-reads or crashes on
 * (issue 42), each a defect once found:
 *   - values are one line: a control character anywhere in an ssg_graph_set key or value
 *     (a newline, a tab, 0x7f, an escape) is refused whole at its column of
 *     "<ssg_graph_set>", never cut at the newline (which applied "0.3" and dropped an
 *     `include` line a viewer then saved); a raw control byte in a file's string is
 *     refused at its line and column. */
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

int main(void)
{
    const char *tmp = getenv("SSG_TMP");
    snprintf(out_dir, sizeof out_dir, "%s", tmp ? tmp : CHECK_TMP_ROOT "/ssg_test_api_hostile");
    mkdir(out_dir, 0755);
    values_are_one_line();
    file_strings_are_text();
    return check_report();
}
