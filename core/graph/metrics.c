/* metrics.c - collecting and writing node metrics (metrics.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "graph/metrics.h"
#include "graph/node.h"
#include "lang/diag.h"

void ssg_metric_report(const struct ssg_node_ctx *ctx, const char *name, double value)
{
    ssg_metrics_add(ctx->metrics, ctx->instance, name, value);
}

void ssg_metrics_add(struct ssg_metrics *metrics, const char *node, const char *name,
                     double value)
{
    if (!metrics || metrics->count >= SSG_METRICS_MAX)
        return;
    struct ssg_metric *m = &metrics->items[metrics->count++];
    snprintf(m->node, sizeof m->node, "%s", node);
    snprintf(m->name, sizeof m->name, "%s", name);
    m->value = value;
}

static void json_number(FILE *f, double v)
{
    if (isfinite(v))
        fprintf(f, "%.9g", v);
    else
        fputs("null", f);
}

/* Metrics arrive grouped by node (a node reports all of its own at once). */
static void write_groups(FILE *f, const void *user)
{
    const struct ssg_metrics *metrics = user;
    fputs("{", f);
    for (int i = 0; i < metrics->count; i++) {
        const struct ssg_metric *m = &metrics->items[i];
        int first_of_node = i == 0 || strcmp(metrics->items[i - 1].node, m->node) != 0;
        if (first_of_node)
            fprintf(f, "%s\n  \"%s\": {", i ? "\n  }," : "", m->node);
        fprintf(f, "%s\"%s\": ", first_of_node ? "" : ", ", m->name);
        json_number(f, m->value);
    }
    fputs(metrics->count ? "\n  }\n}\n" : "}\n", f);
}

enum ssg_err ssg_metrics_write_json(const struct ssg_metrics *metrics, const char *path,
                                    struct ssg_diags *diags)
{
    return ssg_write_text_file(path, "metrics", write_groups, metrics, diags);
}
