/* test_param_soft.c - every number parameter of every registered node has a useful range
 * (soft_min .. soft_max, lang/params.h: what the viewer's slider spans and the docs show):
 *   - set (not empty: soft_min < soft_max) on every FLOAT and INT row;
 *   - inside the validity range min .. max (a slider never offers a value parsing refuses);
 *   - holding the row's default (the slider opens on a value it spans);
 *   - given through the public interface (ssg_node_param_info) as the row has it;
 *   - holding every value that the shipped graphs (graphs/, graphs/table1/) give a node:
 *     a range that a shipped graph leaves is not the useful one.
 * The registry is walked (ssg_node_at), so a node added later is held to it too. */
#include <glob.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "graph/node.h"
#include "lang/params.h"
#include "ssgraph_tools.h"

static int is_number(const struct ssg_param_desc *p)
{
    return p->type == SSG_P_FLOAT || p->type == SSG_P_INT;
}

/* One row's soft range against its validity range and default; 1 when it holds. */
static int row_ok(const char *node, const struct ssg_param_desc *p)
{
    int bounded = !(p->min == 0 && p->max == 0);
    double lo = bounded ? p->min : -SSG_PARAM_ABS_MAX, hi = bounded ? p->max : SSG_PARAM_ABS_MAX;
    const char *why = !ssg_param_has_soft(p)                        ? "has no useful range"
                      : p->soft_min < lo || p->soft_max > hi       ? "leaves the valid range"
                      : p->def < p->soft_min || p->def > p->soft_max ? "misses the default"
                                                                     : NULL;
    if (why)
        fprintf(stderr, "%s.%s: soft range [%g, %g] %s (valid [%g, %g], default %g)\n", node,
                p->name, p->soft_min, p->soft_max, why, lo, hi, p->def);
    return !why;
}

static void test_every_row(void)
{
    int rows = 0;
    for (int i = 0; ssg_node_at(i); i++) {
        const struct ssg_node_desc *d = ssg_node_at(i);
        for (int k = 0; k < d->params.count; k++) {
            const struct ssg_param_desc *p = &d->params.params[k];
            if (!is_number(p))
                continue;
            rows++;
            CHECK(row_ok(d->name, p));
            struct ssg_param_info info;
            CHECK_EQ(ssg_node_param_info(d->name, k, &info), SSG_OK);
            CHECK(info.soft_min == p->soft_min && info.soft_max == p->soft_max);
        }
    }
    CHECK(rows > 100); /* the walk saw the registry (112 rows when written) */
}

/* Every number a graph's node holds lies in its type's useful range. */
static void check_graph(const char *path)
{
    struct ssg_graph *g = NULL;
    struct ssg_diags diags = {0};
    if (ssg_graph_parse(path, &g, &diags) != SSG_OK)
        ssg_diags_print(&diags, stderr);
    CHECK(g && diags.count == 0);
    if (!g)
        return;
    struct ssg_graph_info gi;
    ssg_graph_inspect(g, &gi);
    for (int n = 0; n < gi.node_count; n++) {
        struct ssg_node_info ni;
        ssg_graph_node_inspect(g, n, &ni);
        for (int k = 0; ni.type && k < ni.param_count; k++) {
            struct ssg_param_info p;
            char value[128];
            ssg_node_param_info(ni.type, k, &p);
            ssg_graph_node_param(g, n, k, value, sizeof value);
            if (strcmp(p.type, "float") && strcmp(p.type, "int"))
                continue;
            double v = strtod(value, NULL);
            int inside = v >= p.soft_min && v <= p.soft_max;
            CHECK(inside);
            if (!inside)
                fprintf(stderr, "%s: %s.%s = %s outside its useful range [%g, %g]\n", path,
                        ni.name, p.name, value, p.soft_min, p.soft_max);
        }
    }
    ssg_graph_destroy(&g);
}

static void test_shipped_graphs(void)
{
    glob_t found;
    CHECK_EQ(glob("graphs/*.graph", 0, NULL, &found), 0);
    CHECK_EQ(glob("graphs/*/*.graph", GLOB_APPEND, NULL, &found), 0);
    CHECK(found.gl_pathc > 30);
    for (size_t i = 0; i < found.gl_pathc; i++)
        check_graph(found.gl_pathv[i]);
    globfree(&found);
}

int main(void)
{
    test_every_row();
    test_shipped_graphs();
    return check_report();
}
