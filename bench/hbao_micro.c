/* hbao_micro.c - timing of the `hbao` node's CPU kernel on a synthetic 1920x1080 G-buffer
 * (not a test: it asserts nothing about speed). Prints the median wall time of several
 * runs of run_cpu alone (prepare and allocation excluded), the median CPU time of all
 * threads (on a shared machine wall time also counts other processes), and a hash of the
 * output bits, to compare builds (the AVX2 and SSE paths must give the same hash).
 *
 * Scene: the one of ssao_micro.c, an inner corner (a floor and a wall at 45 degrees to the
 * view, 5 units away) with a sinusoidal relief on the floor, so normals and depths vary
 * and the marches land all over the depth plane as in a real frame. The rotation tile
 * comes from halton (pattern 4), as in graphs/hbao.graph.
 * Build against a Release libssgraph, e.g. in CMake:
 *   add_executable(hbao_micro bench/hbao_micro.c)
 *   target_link_libraries(hbao_micro PRIVATE ssgraph)
 * Usage: hbao_micro [runs=15] [directions=8] [steps=4] [threads=0 (all)]
 *                   [hbao param=value ...] */
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
    int directions = argc > 2 ? atoi(argv[2]) : 8;
    int steps = argc > 3 ? atoi(argv[3]) : 4;
    int threads = argc > 4 ? atoi(argv[4]) : 0;
    if (runs < 1 || runs > 1000)
        return 2;
    if (threads > 0)
        omp_set_num_threads(threads);
    struct ssg_frame frame = {W, H, 45.0f, 0.05f, 100.0f, 1, 0, 0, 0};
    struct ssg_diags diags = {0};

    /* The rotation tile from the halton node. */
    struct ssg_outputs hal;
    if (ssg_node_run("halton", NULL, 0, NULL, 0, &frame, &hal, &diags) != SSG_OK) {
        ssg_diags_print(&diags, stderr);
        return 1;
    }
    struct ssg_image *pos = ssg_image_create(W, H, 3), *nrm = ssg_image_create(W, H, 3);
    struct ssg_image *out = ssg_image_create(W, H, 1);
    if (!pos || !nrm || !out)
        return 1;
    make_gbuffer(&frame, pos, nrm);

    const struct ssg_node_desc *d = ssg_node_find("hbao", 4);
    if (!d)
        return 1;
    void *params = calloc(1, d->params_size), *consts = NULL;
    ssg_params_defaults(d->params, params);
    char dir_set[32], step_set[32];
    snprintf(dir_set, sizeof dir_set, "directions=%d", directions);
    snprintf(step_set, sizeof step_set, "steps=%d", steps);
    const char *sets[2] = {dir_set, step_set};
    for (int a = 0; a < 2 + (argc > 5 ? argc - 5 : 0); a++) {
        const char *text = a < 2 ? sets[a] : argv[a + 3];
        if (ssg_param_set_text(d->params, params, text, "<argv>", "hbao", &diags)) {
            ssg_diags_print(&diags, stderr);
            return 2;
        }
    }
    struct ssg_node_ctx ctx = {.desc = d, .instance = "h", .frame = &frame, .out_dir = "out",
                               .diags = &diags};
    const struct ssg_image *in[5] = {pos, nrm, hal.images[1], NULL, NULL};
    struct ssg_image *outs[1] = {out};
    struct ssg_io io = {.in = in, .out = outs};
    struct ssg_io_shapes shapes;
    ssg_io_shapes_of(d, &io, &shapes);
    ssg_node_ctx_set_shapes(&ctx, &shapes);
    if (ssg_node_prepare(d, &ctx, params, &consts) != SSG_OK) {
        ssg_diags_print(&diags, stderr);
        return 1;
    }

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
    printf("hbao %dx%d, %d directions x %d steps, %d threads: median %.2f ms (min %.2f, max "
           "%.2f) over %d runs, cpu time median %.2f ms (min %.2f); mean ao %.4f, hash "
           "%016llx\n", W, H, directions, steps, omp_get_max_threads(), ms[runs / 2], ms[0],
           ms[runs - 1], runs, cpu[runs / 2], cpu[0], mean_ao / ((double)W * H),
           (unsigned long long)hash);
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
