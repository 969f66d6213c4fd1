/* io_micro.c - timing of the `write` node's files (core/io/imageio.h) on a real frame (not
 * a test: it asserts nothing about speed). Reads the layers of an EXR that
 * `ssgraph run graphs/ssao.graph` wrote (1280x720 by default: 18 channels), then writes
 * them again `runs` times as one EXR with each compression (temporary file, fsync and
 * rename included, as the node does), the PNG preview of the main image, and reads the EXR
 * back; prints the median and minimum wall milliseconds of each, the median CPU
 * milliseconds of all threads (which other processes on a shared machine move less: divided
 * by the threads, the wall time the job would take on idle cores) and the file's bytes.
 * Build: cmake -DSSGRAPH_BUILD_BENCH=ON (target io_micro). bench/io_latency.sh runs it.
 * Usage: io_micro FRAME.exr [runs=9] [threads=0 (all)] [out_dir=/tmp] [only=LABEL]
 * (only: time just the rows whose label starts with LABEL, "exr zip", "png", for perf) */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "clock.h"
#include "io/imageio.h"
#include "ssgraph.h"

/* ssao.graph's write(): the main image and its seven layers. */
static const struct {
    const char *name;
    enum ssg_layer_kind kind;
} layer_list[] = {
    {NULL, SSG_LAYER_COLOR},           {"ao", SSG_LAYER_SCALAR},
    {"ao_raw", SSG_LAYER_SCALAR},      {"depth", SSG_LAYER_SCALAR},
    {"normal", SSG_LAYER_VECTOR},      {"position", SSG_LAYER_VECTOR},
    {"albedo", SSG_LAYER_COLOR},       {"direct", SSG_LAYER_COLOR},
};
enum { LAYERS = sizeof layer_list / sizeof layer_list[0], MAX_RUNS = 101 };

static long long bytes_of(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (long long)st.st_size : -1;
}

/* What one timed thing does once; 0 on failure. */
typedef int (*job_fn)(const struct ssg_exr_layer *layers, int count, const char *path,
                      int arg);

static int write_exr(const struct ssg_exr_layer *layers, int count, const char *path, int c)
{
    struct ssg_diags d = {0};
    return ssg_exr_write_compressed(path, layers, count, (enum ssg_exr_compression)c, &d) ==
           SSG_OK;
}

static int write_png(const struct ssg_exr_layer *layers, int count, const char *path, int c)
{
    struct ssg_diags d = {0};
    (void)count, (void)c;
    return ssg_png_write(path, layers[0].image, SSG_TONEMAP_ACES, 0.0f, &d) == SSG_OK;
}

static int read_exr(const struct ssg_exr_layer *layers, int count, const char *path, int c)
{
    struct ssg_diags d = {0};
    struct ssg_image *im = NULL;
    int ok = 1;
    (void)layers, (void)c;
    for (int i = 0; i < count && ok; i++) {
        ok = ssg_image_read(path, layer_list[i].name, &im, &d) == SSG_OK;
        ssg_image_destroy(&im);
    }
    return ok;
}

static const char *only = "";

/* Times job `runs` times (after one untimed run) and prints a row. */
static void time_job(const char *label, job_fn job, const struct ssg_exr_layer *layers,
                     const char *path, int arg, int runs)
{
    double ms[MAX_RUNS], cpu[MAX_RUNS];
    if (strncmp(label, only, strlen(only)) != 0)
        return;
    if (!job(layers, LAYERS, path, arg)) {
        printf("%-12s failed\n", label);
        return;
    }
    for (int r = 0; r < runs; r++) {
        double t0 = clock_ms(CLOCK_MONOTONIC), c0 = clock_ms(CLOCK_PROCESS_CPUTIME_ID);
        job(layers, LAYERS, path, arg);
        ms[r] = clock_ms(CLOCK_MONOTONIC) - t0;
        cpu[r] = clock_ms(CLOCK_PROCESS_CPUTIME_ID) - c0;
    }
    qsort(ms, (size_t)runs, sizeof *ms, cmp_double);
    qsort(cpu, (size_t)runs, sizeof *cpu, cmp_double);
    printf("%-12s %10.1f %10.1f %10.1f %12lld\n", label, ms[runs / 2], ms[0], cpu[runs / 2],
           bytes_of(path));
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: io_micro FRAME.exr [runs] [threads] [out_dir]\n");
        return 2;
    }
    int runs = argc > 2 ? atoi(argv[2]) : 9, threads = argc > 3 ? atoi(argv[3]) : 0;
    const char *dir = argc > 4 ? argv[4] : "/tmp";
    only = argc > 5 ? argv[5] : "";
    if (runs < 1 || runs > MAX_RUNS)
        return 2;
    if (threads > 0)
        omp_set_num_threads(threads);
    struct ssg_exr_layer layers[LAYERS];
    for (int i = 0; i < LAYERS; i++) {
        struct ssg_diags d = {0};
        struct ssg_image *im = NULL;
        if (ssg_image_read(argv[1], layer_list[i].name, &im, &d) != SSG_OK) {
            fprintf(stderr, "io_micro: %s: %s\n", argv[1], d.count ? d.items[0].message : "?");
            return 1;
        }
        layers[i] = (struct ssg_exr_layer){layer_list[i].name, im, layer_list[i].kind};
    }
    char exr[4096], png[4096];
    snprintf(exr, sizeof exr, "%s/io_micro_%d.exr", dir, (int)getpid());
    snprintf(png, sizeof png, "%s/io_micro_%d.png", dir, (int)getpid());
    printf("# %d x %d, %d layers, %d threads, %d runs; wall ms\n", layers[0].image->width,
           layers[0].image->height, LAYERS, omp_get_max_threads(), runs);
    printf("%-12s %10s %10s %10s %12s\n", "file", "median", "min", "cpu", "bytes");
    static const char *const names[] = {"exr zip", "exr none", "exr rle", "exr piz"};
    for (int c = 0; c < 4; c++)
        time_job(names[c], write_exr, layers, exr, c, runs);
    time_job("png", write_png, layers, png, 0, runs);
    write_exr(layers, LAYERS, exr, SSG_EXR_ZIP);
    time_job("read exr", read_exr, layers, exr, 0, runs);
    unlink(exr);
    unlink(png);
    for (int i = 0; i < LAYERS; i++)
        ssg_image_destroy((struct ssg_image **)&layers[i].image);
    return 0;
}
