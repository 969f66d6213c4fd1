/* bench_cells.h - what the two halves of `ssgraph bench` share (private to cli/): the
 * sweeps and cells that bench.c parses, checks and runs, and that bench_out.c writes
 * (bench.csv, bench.json, bench.md) and plots. */
#ifndef SSG_CLI_BENCH_CELLS_H
#define SSG_CLI_BENCH_CELLS_H

#include <stdint.h>

#include "bench.h"

/* At most 64 values a sweep, and at most MAX_CELLS cells in one bench: each finished cell
   rewrites bench.json and bench.md whole, and a sweep that big is hours of work that is
   better split (checked before anything is allocated). */
enum { MAX_VALUES = 64, MAX_CELLS = 10000 };

struct sweep {
    char key[128];                    /* node.param */
    char text[1024];                  /* the values, split in place */
    const char *values[MAX_VALUES];
    int count;
};

struct cell {
    int index[SSG_BENCH_MAX_SWEEPS];  /* value index per sweep */
    int ran;                          /* 1 = run (or merged): its row is written */
    int ok;
    char error[512];
    struct ssg_run_stats stats;
};

struct bench {
    const struct ssg_bench_request *req;
    const char *graph;                /* what runs: the graph */
    struct sweep sweeps[SSG_BENCH_MAX_SWEEPS];
    int n;                            /* sweeps */
    int scene_axis;                   /* 1 = sweeps[0] is the --scene list, key "scene" */
    struct cell *cells;
    int cell_count, done;             /* cells of the cross product; cells run so far */
    int shard_index, shard_count;     /* --shard I/N: the cells with index % N == I; 0/1 */
    char definition[16384];           /* everything that decides the cells' results, one
                                         `key: value` a line (bench_shard.c) */
    char definition_hash[17];         /* FNV-1a 64 of definition, hex: what --merge compares */
};

/* FNV-1a, 64 bits, of len bytes: the fingerprint of definitions, cache keys and pixels
   (bench_shard.c), not a defence against forgery. */
uint64_t ssg_bench_fnv1a(const void *data, size_t len);
/* The fingerprint of a whole file's bytes; 0 with the reason in why when it cannot be
   read. */
int ssg_bench_file_fnv1a(const char *path, uint64_t *hash, char *why, size_t why_len);

/* The sweep's definition and its hash from the request and the parsed sweeps (the graph
   file's bytes are hashed too, so an edited graph is another sweep); 0 with a message
   when the graph cannot be read. */
int ssg_bench_define(struct bench *b);
/* "I/N" into b->shard_index and b->shard_count; 0 with a message naming what is wrong,
   also when N is more than b->cell_count (set first): such a shard would hold no cell. */
int ssg_bench_parse_shard(struct bench *b, const char *text);

static inline const char *ssg_bench_value(const struct bench *b, const struct cell *c, int k)
{
    return b->sweeps[k].values[c->index[k]];
}

/* The cells of the cross product (first sweep outermost), b->cell_count of them; 0 with a
   message when out of memory. ssg_bench_free_cells releases them and their statistics
   (nothing allocated: nothing done). */
int ssg_bench_make_cells(struct bench *b);
void ssg_bench_free_cells(struct bench *b);

/* With --reference (bench_reference.c): the cell's --image (and --mask) run `frames` times
   into *stats, only the nodes they need, and scored by a compare with the reference
   (cached per machine, rendered when missing or untrusted): its metrics are appended to
   stats as node bench_reference. */
enum ssg_err ssg_bench_run_compared(const struct bench *b, const struct ssg_overrides *cell,
                                    int frames, struct ssg_run_stats *stats,
                                    struct ssg_diags *d);

/* A time as the tables and plots show it, ms: the median of a cell's runs (its steady
   rate: the mean carries the first run's one-off costs), the fastest and the slowest. */
struct ssg_bench_ms {
    double median, min, max;
};

/* The time shown for a cell: the --time node's, else the frame's. */
struct ssg_bench_ms ssg_bench_shown_ms(const struct bench *b, const struct cell *c);
/* A cell whose median frame took more than this times its fastest ran on a busy machine
   (or its frames differ in work, as on a camera path): its median may mislead by as much;
   two identical cells were seen 10-15x apart on a busy machine (issue 46). The median
   against the fastest, not the slowest: a first frame's one-off costs (fresh memory) make
   the slowest slow on any machine. bench.md lists such cells, and the run warns. */
#define SSG_BENCH_SPREAD 2.0
/* Whether cell c (run, ok) is such a cell; how many of the bench's cells are. */
int ssg_bench_noisy(const struct bench *b, const struct cell *c);
int ssg_bench_noisy_count(const struct bench *b);

/* After each cell: bench.csv, bench.json and bench.md rewritten whole, each through a
 * temporary and a rename (files.h), so an interrupted bench keeps every finished cell and
 * no file is ever half-written or written through a planted link. */
enum ssg_err ssg_bench_save(const struct bench *b, struct ssg_diags *d);
/* Before the first cell: the three tables' names in out_dir can take them (a FIFO or a
 * folder planted at bench.md is refused then, not after the first cell), ssg_output_check. */
enum ssg_err ssg_bench_check_tables(const char *out_dir, struct ssg_diags *d);
/* The `wrote OUT/bench.csv` lines of the three tables, to stdout. */
void ssg_bench_print_tables(const char *out_dir);

/* bench_ms.png and bench_pareto.png from the finished cells; 0 on success, else 1 with
 * the reason on stderr. */
int ssg_bench_draw_plots(const struct bench *b);

#endif
