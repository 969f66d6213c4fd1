/* bench_shard.c - what makes a bench's shards belong together: `--shard I/N` and the
 * sweep's definition.
 *
 * The definition is every input that decides which cells there are and what each one
 * computes: the graph as given and a hash of its bytes, the sweeps, the overrides (size,
 * seed, --set, scene, lights, backend, guard), frames, the --reference/--image/--mask
 * comparison, --time, --error and stereo. It is written into bench.json as text (one
 * `key: value` a line) with its FNV-1a 64-bit hash; `bench --merge` joins only shards whose
 * hashes agree, so shards of an edited graph or of other values can never be mixed.
 * Threads are left out: they never change a result. */
#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_cells.h"
#include "ssgraph.h"

uint64_t ssg_bench_fnv1a(const void *data, size_t len)
{
    const unsigned char *p = data;
    uint64_t h = 0xcbf29ce484222325ULL;
    for (size_t i = 0; i < len; i++)
        h = (h ^ p[i]) * 0x100000001b3ULL;
    return h;
}

int ssg_bench_file_fnv1a(const char *path, uint64_t *hash, char *why, size_t why_len)
{
    char *data = NULL;
    size_t len = 0;
    if (ssg_input_read(path, 1LL << 30, &data, &len, why, why_len))
        return 0;
    *hash = ssg_bench_fnv1a(data, len);
    free(data);
    return 1;
}

/* Appends one `key: value` line (printf style) to the definition; 0 once it is full. */
static int define(struct bench *b, const char *fmt, ...)
{
    size_t used = strlen(b->definition);
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(b->definition + used, sizeof b->definition - used, fmt, ap);
    va_end(ap);
    return n >= 0 && (size_t)n < sizeof b->definition - used;
}

static const char *or_none(const char *s)
{
    return s ? s : "";
}

/* The graph file's bytes as a hash: an edited graph is another sweep. */
static int graph_hash(const char *path, uint64_t *hash)
{
    char why[256];
    if (ssg_bench_file_fnv1a(path, hash, why, sizeof why))
        return 1;
    fprintf(stderr, "ssgraph: error: %s: %s\n", path, why);
    return 0;
}

static int define_overrides(struct bench *b, const struct ssg_overrides *ov)
{
    const char *scene = b->scene_axis ? NULL : ov->scene; /* else the sweep "scene" says */
    int ok = define(b, "size: %dx%d\nseed: %" PRId64 "\nscene: %s\nlights: %s\nbackend: %s\n",
                    ov->width, ov->height, ov->seed, or_none(scene), or_none(ov->lights),
                    or_none(ov->backend));
    ok = ok && define(b, "guard: %d\n", ov->guard_given ? ov->guard : -1);
    for (int i = 0; ok && i < ov->set_count; i++)
        ok = define(b, "set: %s\n", ov->sets[i]);
    return ok;
}

int ssg_bench_define(struct bench *b)
{
    const struct ssg_bench_request *q = b->req;
    uint64_t graph = 0;
    if (!graph_hash(q->graph, &graph))
        return 0;
    b->definition[0] = '\0';
    int ok = define(b, "graph: %s\ngraph_fnv1a64: %016" PRIx64 "\n", q->graph, graph) &&
             define_overrides(b, q->ov);
    for (int k = 0; ok && k < b->n; k++) {
        ok = define(b, "sweep: %s=", b->sweeps[k].key);
        for (int v = 0; ok && v < b->sweeps[k].count; v++)
            ok = define(b, "%s%s", v ? "," : "", b->sweeps[k].values[v]);
        ok = ok && define(b, "\n");
    }
    ok = ok && define(b, "frames: %d\nreference: %s\nimage: %s\nmask: %s\ntime: %s\n"
                         "error: %s\nstereo: %d %g\n", q->frames > 0 ? q->frames : 5,
                      or_none(q->reference), or_none(q->image), or_none(q->mask),
                      or_none(q->time_node), or_none(q->error_metric), q->stereo,
                      q->stereo ? (double)q->ipd : 0.0);
    if (!ok) {
        fprintf(stderr, "ssgraph: error: the sweep's definition is longer than %zu bytes "
                "(fewer --set or sweep values)\n", sizeof b->definition);
        return 0;
    }
    snprintf(b->definition_hash, sizeof b->definition_hash, "%016" PRIx64,
             ssg_bench_fnv1a(b->definition, strlen(b->definition)));
    return 1;
}

int ssg_bench_parse_shard(struct bench *b, const char *text)
{
    b->shard_index = 0;
    b->shard_count = 1;
    if (!text)
        return 1;
    long i, n;
    char slash, extra;
    if (sscanf(text, "%ld%c%ld%c", &i, &slash, &n, &extra) != 3 || slash != '/') {
        fprintf(stderr, "ssgraph: error: --shard expects I/N (shard I of N, 0 <= I < N), got "
                "'%s'\n", text);
        return 0;
    }
    if (n < 1 || n > 100000) {
        fprintf(stderr, "ssgraph: error: --shard '%s': N, the number of shards, must be 1 to "
                "100000\n", text);
        return 0;
    }
    if (i < 0 || i >= n) {
        fprintf(stderr, "ssgraph: error: --shard '%s': I must be one of 0 to %ld (shards are "
                "numbered from 0)\n", text, n - 1);
        return 0;
    }
    /* A shard with no cell would write empty tables that look like a lost run: a cluster
       job asking for more tasks than there are cells is a mistake to name at once. */
    if (n > b->cell_count) {
        fprintf(stderr, "ssgraph: error: --shard '%s': %ld shards for %d cells (at most %d "
                "shards: each must hold a cell)\n", text, n, b->cell_count, b->cell_count);
        return 0;
    }
    b->shard_index = (int)i;
    b->shard_count = (int)n;
    return 1;
}
