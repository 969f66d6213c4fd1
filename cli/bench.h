/* bench.h - `ssgraph bench` (bench.c): a graph run over the cross product of parameter
 * sweeps, each cell timed over several frames, written as CSV, Markdown and JSON. */
#ifndef SSG_CLI_BENCH_H
#define SSG_CLI_BENCH_H

#include "ssgraph.h"

#define SSG_BENCH_MAX_SWEEPS 4

struct ssg_bench_request {
    const char *graph;                /* the graph file */
    const struct ssg_overrides *ov;   /* --scene, --size, --set, --seed, --backend */
    const char *const *scenes;        /* two or more --scene: a sweep of its own, "scene",
                                         the outermost; one is an override (in ov) */
    int scene_count;
    const char *const *sweeps;        /* "node.param=v1,v2,..." */
    int sweep_count;
    int frames;                       /* per cell; 0 = 5 */
    int threads;
    const char *out_dir;              /* bench.csv, bench.md, bench.json, cells/ */
    const char *time_node;            /* the node whose ms bench.md shows; NULL = frame */
    const char *error_metric;         /* "node.metric" the Pareto plot uses; NULL = first */
    int plot;                         /* 1 = bench_ms.png and bench_pareto.png (gnuplot) */
    const char *reference;            /* NODE.PORT every cell's image is compared with */
    const char *image;                /* NODE.PORT: that image (with --reference) */
    const char *mask;                 /* NODE.PORT: only pixels where it is over 0.5 are
                                         compared (with --reference); NULL = all */
    int stereo;                       /* 1 = each cell renders both eyes; times add up */
    float ipd;                        /* eye distance, scene units */
    const char *shard;                /* "I/N": only the cells whose index % N is I; NULL =
                                         every cell (0/1) */
    const char *const *merge_dirs;    /* bench --merge: the shard folders to join (then
                                         graph and sweeps are unused) */
    int merge_count;
    int quiet;                        /* 1 = no progress, no summary, no wrote lines */
    int verbose;                      /* 1 = each cell's line also gives every node's ms */
};

/* Runs every cell (of its shard); returns the process exit code (0: all cells ran, 1: some
 * failed, a bad --shard, or the files could not be written, 2: a malformed sweep). */
int ssg_bench_main(const struct ssg_bench_request *req);

/* bench --merge (bench_merge.c): reads every folder's bench.json, checks that they are
 * shards of one sweep definition that together hold every cell exactly once, and writes
 * bench.csv, bench.json, bench.md (and the plots with req->plot) into req->out_dir as an
 * unsharded run would; 0, or 1 with what is wrong (nothing written). */
int ssg_bench_merge(const struct ssg_bench_request *req);

#endif
