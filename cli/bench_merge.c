/* bench_merge.c - `ssgraph bench --merge DIR... --out DIR`: the shards of one sweep
 * (`--shard I/N` runs, each folder holding its bench.json) joined into the files an
 * unsharded run writes.
 *
 * Everything is checked before anything is written: every folder's bench.json must read,
 * all must carry one definition (bench_shard.c) and one shard count, no shard may come
 * twice, no cell may be in two folders, and together they must hold every cell. A
 * problem is reported naming the folder (and the cells or shards concerned), exit 1, and
 * --out is left as it was. The joined cells then go through the same writers as a run's
 * (bench_out.c), so the tables, the JSON and the plots are an unsharded run's, values and
 * metrics exactly; timings are the shards' own. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bench_cells.h"
#include "bench_json.h"
#include "ssgraph.h"

#define SHARD_JSON_MAX (256LL << 20)

struct shards {
    int count;
    const char *const *dirs;
    struct ssg_bench_json **files;
};

static int read_shard(const char *dir, struct ssg_bench_json *j)
{
    char path[4200], why[512], *text = NULL;
    size_t len = 0;
    snprintf(path, sizeof path, "%s/bench.json", dir);
    if (ssg_input_read(path, SHARD_JSON_MAX, &text, &len, why, sizeof why) ||
        ssg_bench_json_parse(text, len, j, why, sizeof why)) {
        fprintf(stderr, "ssgraph: error: bench --merge: %s: %s\n", path, why);
        free(text);
        return 0;
    }
    free(text);
    return 1;
}

static void free_shards(struct shards *s)
{
    for (int i = 0; s->files && i < s->count; i++)
        if (s->files[i]) {
            ssg_bench_json_free(s->files[i]);
            free(s->files[i]);
        }
    free(s->files);
}

/* The cells a file's sweeps make must be its cells_total: the tables index the cells by
   the sweeps' values (a forged or damaged file could say otherwise). */
static int sweeps_fit(const char *dir, const struct ssg_bench_json *j)
{
    long long cells = 1;
    for (int k = 0; k < j->sweep_count; k++)
        cells *= j->value_count[k];
    if (cells == j->cells_total)
        return 1;
    fprintf(stderr, "ssgraph: error: bench --merge: %s/bench.json: its sweeps make %lld cells, "
            "not its cells_total %d\n", dir, cells, j->cells_total);
    return 0;
}

/* Same definition, shard count and cell count as the first; no shard index twice. */
static int same_sweep(const struct shards *s)
{
    const struct ssg_bench_json *first = s->files[0];
    for (int i = 1; i < s->count; i++) {
        const struct ssg_bench_json *j = s->files[i];
        if (strcmp(j->definition_hash, first->definition_hash) ||
            strcmp(j->definition, first->definition)) {
            fprintf(stderr, "ssgraph: error: bench --merge: %s is a shard of another sweep than "
                    "%s (definition %s, not %s): a different graph, sweep or option\n",
                    s->dirs[i], s->dirs[0], j->definition_hash, first->definition_hash);
            return 0;
        }
        if (j->shard_count != first->shard_count || j->cells_total != first->cells_total) {
            fprintf(stderr, "ssgraph: error: bench --merge: %s is shard %d of %d, %s of %d: "
                    "shards of one run of the sweep share N\n", s->dirs[i], j->shard_index,
                    j->shard_count, s->dirs[0], first->shard_count);
            return 0;
        }
        for (int k = 0; k < i; k++)
            if (s->files[k]->shard_index == j->shard_index) {
                fprintf(stderr, "ssgraph: error: bench --merge: %s and %s are both shard %d/%d "
                        "(overlapping shards: give each once)\n", s->dirs[k], s->dirs[i],
                        j->shard_index, j->shard_count);
                return 0;
            }
    }
    return 1;
}

/* Every cell exactly once, each in the shard its index says; owner[c] = its folder. */
static int covers_once(const struct shards *s, int *owner)
{
    const int total = s->files[0]->cells_total, n = s->files[0]->shard_count;
    for (int c = 0; c < total; c++)
        owner[c] = -1;
    for (int i = 0; i < s->count; i++)
        for (int k = 0; k < s->files[i]->cell_count; k++) {
            int c = s->files[i]->cells[k].index;
            if (c % n != s->files[i]->shard_index || owner[c] >= 0) {
                fprintf(stderr, "ssgraph: error: bench --merge: cell %d %s %s\n", c,
                        owner[c] >= 0 ? "is in both" : "does not belong to its shard in",
                        s->dirs[i]);
                if (owner[c] >= 0)
                    fprintf(stderr, "  and %s (overlapping shards)\n", s->dirs[owner[c]]);
                return 0;
            }
            owner[c] = i;
        }
    int missing = 0;
    for (int c = 0; c < total; c++)
        if (owner[c] < 0 && missing++ < 8)
            fprintf(stderr, "%s%d (shard %d/%d)", missing == 1 ? "ssgraph: error: bench "
                    "--merge: cells missing: " : ", ", c, c % n, n);
    if (!missing)
        return 1;
    fprintf(stderr, "%s\n  run shard", missing > 8 ? ", ..." : "");
    for (int shard = 0, listed = 0; shard < n && shard < total; shard++)
        for (int c = shard; c < total; c += n)
            if (owner[c] < 0) {
                fprintf(stderr, "%s%d/%d", listed++ ? ", " : " ", shard, n);
                break;
            }
    fprintf(stderr, " (--shard I/N) and merge again\n");
    return 0;
}

/* The first shard's sweeps as bench.c parses them (the same strings, in one buffer). */
static void fill_sweeps(struct bench *b, const struct ssg_bench_json *j)
{
    b->n = j->sweep_count;
    for (int k = 0; k < b->n; k++) {
        struct sweep *s = &b->sweeps[k];
        snprintf(s->key, sizeof s->key, "%s", j->sweep_keys[k]);
        size_t used = 0;
        s->count = j->value_count[k];
        for (int v = 0; v < s->count; v++) {
            size_t len = strlen(j->values[k][v]) + 1;
            if (used + len > sizeof s->text) { /* no longer than the run's own --sweep */
                s->count = v;
                break;
            }
            memcpy(s->text + used, j->values[k][v], len);
            s->values[v] = s->text + used;
            used += len;
        }
    }
}

static const char *or_null(const char *s)
{
    return s[0] ? s : NULL;
}

/* The joined sweep: the first shard's definition, every shard's cells in place. */
static int join(struct bench *b, struct ssg_bench_request *req, const struct shards *s)
{
    const struct ssg_bench_json *first = s->files[0];
    req->graph = first->graph;
    req->time_node = or_null(first->time_node);
    req->error_metric = or_null(first->error_metric);
    req->reference = or_null(first->reference);
    b->req = req;
    b->graph = req->graph;
    fill_sweeps(b, first);
    /* several --scene: the outermost sweep, "scene" (no --sweep key lacks a dot) */
    b->scene_axis = b->n > 0 && !strcmp(b->sweeps[0].key, "scene");
    b->cell_count = first->cells_total;
    b->shard_index = 0;
    b->shard_count = 1;
    snprintf(b->definition, sizeof b->definition, "%s", first->definition);
    snprintf(b->definition_hash, sizeof b->definition_hash, "%s", first->definition_hash);
    if (!ssg_bench_make_cells(b))
        return 0;
    for (int i = 0; i < s->count; i++)
        for (int k = 0; k < s->files[i]->cell_count; k++) {
            struct ssg_bench_json_cell *from = &s->files[i]->cells[k];
            struct cell *c = &b->cells[from->index];
            c->ran = 1;
            c->ok = from->ok;
            snprintf(c->error, sizeof c->error, "%s", from->error);
            c->stats = from->stats; /* moved: the shard's copy is emptied */
            from->stats = (struct ssg_run_stats){0};
        }
    b->done = b->cell_count;
    return 1;
}

static int write_merged(struct bench *b, const struct ssg_bench_request *req, int shards)
{
    struct ssg_diags d = {0};
    enum ssg_err e = ssg_make_dirs(req->out_dir, &d);
    if (!e)
        e = ssg_bench_save(b, &d);
    ssg_diags_print(&d, stderr);
    if (e)
        return 1;
    int failed = 0;
    for (int c = 0; c < b->cell_count; c++)
        failed += !b->cells[c].ok;
    if (!req->quiet) {
        printf("bench: merged %d shards: %d cells, %d failed\n", shards, b->cell_count,
               failed);
        ssg_bench_print_tables(req->out_dir);
        fflush(stdout);
    }
    if (req->plot && ssg_bench_draw_plots(b))
        return 1;
    return failed ? 1 : 0;
}

/* --out must not be one of the shards: writing the joined tables there replaced that
   shard's bench.json (and with it the only copy of its cells). Compared as files (device
   and inode), so another spelling of the folder (a/../a, a link to it) is caught too. */
static int out_is_input(const struct ssg_bench_request *q)
{
    struct stat out, in;
    if (stat(q->out_dir, &out) != 0)
        return 0; /* not there yet: no shard */
    for (int i = 0; i < q->merge_count; i++)
        if (stat(q->merge_dirs[i], &in) == 0 && in.st_dev == out.st_dev &&
            in.st_ino == out.st_ino) {
            fprintf(stderr, "ssgraph: error: bench --merge: --out %s is the shard folder %s: "
                    "the joined tables would replace that shard's files (expected another "
                    "folder)\n", q->out_dir, q->merge_dirs[i]);
            return 1;
        }
    return 0;
}

int ssg_bench_merge(const struct ssg_bench_request *given)
{
    struct ssg_bench_request req = *given;
    struct shards s = {.count = given->merge_count, .dirs = given->merge_dirs};
    if (s.count < 1) {
        fprintf(stderr, "ssgraph: error: bench --merge expects the shard folders to join\n");
        return 2;
    }
    if (out_is_input(given))
        return 1;
    s.files = calloc((size_t)s.count, sizeof *s.files);
    int ok = s.files != NULL;
    for (int i = 0; ok && i < s.count; i++)
        ok = (s.files[i] = calloc(1, sizeof *s.files[i])) && read_shard(s.dirs[i], s.files[i]) &&
             sweeps_fit(s.dirs[i], s.files[i]);
    int *owner = ok ? malloc((size_t)s.files[0]->cells_total * sizeof *owner) : NULL;
    ok = ok && owner && same_sweep(&s) && covers_once(&s, owner);
    struct bench b = {0};
    int rc = 1;
    if (ok && join(&b, &req, &s))
        rc = write_merged(&b, &req, s.count);
    ssg_bench_free_cells(&b);
    free(owner);
    free_shards(&s);
    return rc;
}
