/* metrics.h - named scalar results that nodes report while running (compare's RMSE, PSNR,
 * SSIM, ...). The executor collects them, returns them in the run's statistics and writes
 * them to <out>/metrics.json; ssg_node_run returns them in struct ssg_outputs. One store per
 * run; ssg_metric_report may be called from the node's own thread only (not inside
 * ssg_parallel_rows bands). */
#ifndef SSG_METRICS_H
#define SSG_METRICS_H

#include "ssgraph.h"

/* Room for 40 compare nodes of 12 metrics (banding and flip on) and more; 128 was full at
   graphs/banding.graph (12 compare nodes), where the last node lost its last metric. */
#define SSG_METRICS_MAX 512

struct ssg_metric {
    char node[64];  /* node instance that reported it */
    char name[32];  /* metric name, e.g. "rmse" */
    double value;
};

struct ssg_metrics {
    int count;
    struct ssg_metric items[SSG_METRICS_MAX];
};

/* Adds one metric; silently ignores reports past SSG_METRICS_MAX or without a store. */
void ssg_metrics_add(struct ssg_metrics *metrics, const char *node, const char *name,
                     double value);
/* Writes {"node": {"name": value, ...}, ...} atomically (temporary file, then rename).
 * Non-finite values are written as null. */
enum ssg_err ssg_metrics_write_json(const struct ssg_metrics *metrics, const char *path,
                                    struct ssg_diags *diags);

#endif
