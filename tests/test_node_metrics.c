/* test_node_metrics.c - the metrics a node declares (its descriptor's `metrics`, read
 * through ssg_node_metric) are exactly those it reports: `bench --error NODE.METRIC` is
 * checked against the declaration before any cell runs, so a name the node reports but
 * does not declare would be refused, and one it declares but never reports accepted for a
 * column that stays empty. compare with banding and FLIP on reports all of its metrics. */
#include <string.h>

#include "check.h"
#include "ssgraph.h"

static int declared(const char *node, const char *name)
{
    for (int k = 0; ssg_node_metric(node, k); k++)
        if (!strcmp(ssg_node_metric(node, k), name))
            return 1;
    return 0;
}

int main(void)
{
    struct ssg_image *a = ssg_image_create(24, 16, 1), *b = ssg_image_create(24, 16, 1);
    for (int i = 0; i < 24 * 16; i++) {
        a->data[i] = (float)(i % 7) / 7.0f;
        b->data[i] = (float)(i % 5) / 5.0f;
    }
    struct ssg_binding bind[] = {{"a", a}, {"b", b}};
    const char *sets[] = {"banding=2", "flip=ldr", "structure=true"};
    struct ssg_outputs out = {0};
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_node_run("compare", bind, 2, sets, 3, NULL, &out, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    int count = 0;
    while (ssg_node_metric("compare", count))
        count++;
    CHECK_EQ(out.metric_count, count);
    for (int i = 0; i < out.metric_count; i++) {
        if (!declared("compare", out.metric_names[i]))
            fprintf(stderr, "compare reports '%s', which it does not declare\n",
                    out.metric_names[i]);
        CHECK(declared("compare", out.metric_names[i]));
    }
    /* the others: none declared, none of an unknown node, none past the last */
    CHECK(ssg_node_metric("ssao", 0) == NULL);
    CHECK(ssg_node_metric("no_such_node", 0) == NULL);
    CHECK(ssg_node_metric(NULL, 0) == NULL);
    CHECK(ssg_node_metric("compare", -1) == NULL);
    CHECK(ssg_node_metric("compare", count) == NULL);
    ssg_outputs_release(&out);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
    return check_report();
}
