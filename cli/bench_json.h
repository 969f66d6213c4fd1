/* bench_json.h - reading a bench.json back (bench_json_adapter.cc, nlohmann::json behind a
 * C interface), for `bench --merge`: the sweep's definition, its shard and its cells. */
#ifndef SSG_CLI_BENCH_JSON_H
#define SSG_CLI_BENCH_JSON_H

#include <stddef.h>

#include "bench.h"

/* One cell as bench.json records it; stats holds frames, frame times (median, min, max,
   average), the metrics in their order and every node's name and median, min, max and
   average ms (a bench.json of an older ssgraph has only averages: they stand for the
   median, min and max it lacks) (ownership: ssg_run_stats_free). */
struct ssg_bench_json_cell {
    int index;
    int ok;
    char error[512];
    struct ssg_run_stats stats;
};

struct ssg_bench_json {
    char graph[1024], time_node[128], error_metric[128], reference[128];
    char definition[16384], definition_hash[17];
    int shard_index, shard_count, cells_total;
    int sweep_count;
    char sweep_keys[SSG_BENCH_MAX_SWEEPS][128];
    int value_count[SSG_BENCH_MAX_SWEEPS];
    char values[SSG_BENCH_MAX_SWEEPS][64][256];
    int cell_count;
    struct ssg_bench_json_cell *cells; /* malloc'd; ssg_bench_json_free */
};

/* Parses the bench.json text (len bytes) into *out (zeroed first); 0 on success, else 1
   with what is wrong or missing in why. Only files that ssgraph bench wrote are
   understood: every field must be there with its type. */
int ssg_bench_json_parse(const char *text, size_t len, struct ssg_bench_json *out, char *why,
                         size_t why_len);
void ssg_bench_json_free(struct ssg_bench_json *j);

#endif
