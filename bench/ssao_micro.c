/* ssao_micro.c - timing of the `ssao` node's CPU kernel on a synthetic 1920x1080 G-buffer
 * (not a test: it asserts nothing about speed). Prints the median wall time of several
 * runs of run_cpu alone (prepare and allocation excluded), the median CPU time of all
 * threads (on a shared machine wall time also counts other processes), and a hash of the
 * output bits, to compare builds (the AVX2 and SSE paths must give the same hash).
 *
 * Scene: an inner corner (a floor and a wall at 45 degrees to the view, 5 units away) with
 * a sinusoidal relief on the floor, so normals vary and samples land all over the depth
 * plane as in a real frame. Default kernel: halton count=16 with its rotation tile.
 * Build against a Release libssgraph, e.g. in CMake:
 *   add_executable(ssao_micro bench/ssao_micro.c)
 *   target_link_libraries(ssao_micro PRIVATE ssgraph)
 * Usage: ssao_micro [runs=15] [samples=16] [threads=0 (all)] [ssao param=value ...] */
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "graph/exec.h"
#include "graph/node.h"
#include "ssgraph.h"

#include "micro.h"

int main(int argc, char **argv)
{
    int runs = argc > 1 ? atoi(argv[1]) : 15;
    int samples = argc > 2 ? atoi(argv[2]) : 16;
    int threads = argc > 3 ? atoi(argv[3]) : 0;
    if (runs < 1 || runs > 1000 || samples < 1 || samples > 1024)
        return 2;
    if (threads > 0)
        omp_set_num_threads(threads);
    struct ssg_frame frame = {W, H, 45.0f, 0.05f, 100.0f, 1, 0, 0, 0};
    struct ssg_diags diags = {0};

    /* Kernel and rotation from the halton node. */
    char count_set[32];
    snprintf(count_set, sizeof count_set, "count=%d", samples);
    const char *hsets[] = {count_set};
    struct ssg_outputs hal;
    if (ssg_node_run("halton", NULL, 0, hsets, 1, &frame, &hal, &diags) != SSG_OK) {
        ssg_diags_print(&diags, stderr);
        return 1;
    }
    struct ssg_image *pos = ssg_image_create(W, H, 3), *nrm = ssg_image_create(W, H, 3);
    struct ssg_image *out = ssg_image_create(W, H, 1);
    if (!pos || !nrm || !out)
        return 1;
    make_gbuffer(&frame, pos, nrm);

    const struct ssg_node_desc *d = ssg_node_find("ssao", 4);
    if (!d)
        return 1;
    void *params = calloc(1, d->params_size), *consts = calloc(1, d->consts_size);
    ssg_params_defaults(d->params, params);
    for (int a = 4; a < argc; a++)
        if (ssg_param_set_text(d->params, params, argv[a], "<argv>", "ssao", &diags)) {
            ssg_diags_print(&diags, stderr);
            return 2;
        }
    struct ssg_node_ctx ctx = {.desc = d, .instance = "ao", .frame = &frame, .out_dir = "out",
                               .diags = &diags};
    const struct ssg_image *in[6] = {pos, nrm, hal.images[0], hal.images[1], NULL, NULL};
    struct ssg_image *outs[1] = {out};
    struct ssg_io io = {.in = in, .out = outs};
    struct ssg_io_shapes shapes;
    ssg_io_shapes_of(d, &io, &shapes);
    ssg_node_ctx_set_shapes(&ctx, &shapes);
    if (d->prepare(&ctx, params, consts) != SSG_OK)
        return 1;

    /* Wall time, and the CPU time of all threads (on a shared machine, wall time also
       counts time other processes held the cores). */
    double *ms = calloc((size_t)runs, sizeof *ms), *cpu = calloc((size_t)runs, sizeof *cpu);
    d->run_cpu(&ctx, consts, &io); /* warm caches and threads */
    for (int r = 0; r < runs; r++) {
        double t0 = clock_ms(CLOCK_MONOTONIC), c0 = clock_ms(CLOCK_PROCESS_CPUTIME_ID);
        d->run_cpu(&ctx, consts, &io);
        ms[r] = clock_ms(CLOCK_MONOTONIC) - t0;
        cpu[r] = clock_ms(CLOCK_PROCESS_CPUTIME_ID) - c0;
    }
    qsort(ms, (size_t)runs, sizeof *ms, cmp_double);
    qsort(cpu, (size_t)runs, sizeof *cpu, cmp_double);
    /* Mean, and an FNV-1a hash of the bits, to compare builds and variants. */
    double mean_ao = 0;
    uint64_t hash = 1469598103934665603ull;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        uint32_t bits;
        memcpy(&bits, &out->data[i], sizeof bits);
        hash = (hash ^ bits) * 1099511628211ull;
        mean_ao += out->data[i];
    }
    printf("ssao %dx%d, %d samples, %d threads: median %.2f ms (min %.2f, max %.2f) over %d "
           "runs, cpu time median %.2f ms; mean ao %.4f, hash %016llx\n", W, H, samples,
           omp_get_max_threads(), ms[runs / 2], ms[0], ms[runs - 1], runs, cpu[runs / 2],
           mean_ao / ((double)W * H), (unsigned long long)hash);
    free(ms);
    free(cpu);
    free(params);
    free(consts);
    ssg_image_destroy(&pos);
    ssg_image_destroy(&nrm);
    ssg_image_destroy(&out);
    ssg_outputs_release(&hal);
    return 0;
}
