/* gtao_micro.c - timing of the `gtao` node's CPU kernel on the synthetic 1920x1080 corner
 * G-buffer of micro.h (not a test: it asserts nothing about speed), as hbao_micro.c does
 * for hbao. Prints the median wall time of several runs of run_cpu alone (prepare and
 * allocation excluded), the median CPU time of all threads (on a shared machine wall time
 * also counts other processes), and hashes of both outputs' bits, to compare builds (the
 * AVX2 and SSE paths, and any thread count, must give the same hashes). The rotation tile
 * comes from halton, as in graphs/gtao.graph.
 * Usage: gtao_micro [runs=15] [slices=8] [steps=12] [threads=0 (all)]
 *                   [gtao param=value ...] */
#include <omp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "graph/exec.h"
#include "graph/node.h"
#include "ssgraph.h"

#include "micro.h"

/* The node's parameters: defaults, slices and steps, then argv[5..]. */
static int set_params(const struct ssg_node_desc *d, void *params, int slices, int steps,
                      int argc, char **argv, struct ssg_diags *diags)
{
    char sl[32], st[32];
    snprintf(sl, sizeof sl, "slices=%d", slices);
    snprintf(st, sizeof st, "steps=%d", steps);
    ssg_params_defaults(d->params, params);
    int n = 2 + (argc > 5 ? argc - 5 : 0);
    for (int a = 0; a < n; a++) {
        const char *text = a == 0 ? sl : a == 1 ? st : argv[a + 3];
        if (ssg_param_set_text(d->params, params, text, "<argv>", "gtao", diags))
            return 1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    int runs = argc > 1 ? atoi(argv[1]) : 15;
    int slices = argc > 2 ? atoi(argv[2]) : 8, steps = argc > 3 ? atoi(argv[3]) : 12;
    int threads = argc > 4 ? atoi(argv[4]) : 0;
    if (runs < 1 || runs > 1000)
        return 2;
    if (threads > 0)
        omp_set_num_threads(threads);
    struct ssg_frame frame = {W, H, 45.0f, 0.05f, 100.0f, 1, 0, 0, 0};
    struct ssg_diags diags = {0};
    struct ssg_outputs hal;
    if (ssg_node_run("halton", NULL, 0, NULL, 0, &frame, &hal, &diags) != SSG_OK) {
        ssg_diags_print(&diags, stderr);
        return 1;
    }
    struct ssg_image *pos = ssg_image_create(W, H, 3), *nrm = ssg_image_create(W, H, 3);
    struct ssg_image *out = ssg_image_create(W, H, 1), *bent = ssg_image_create(W, H, 3);
    const struct ssg_node_desc *d = ssg_node_find("gtao", 4);
    if (!pos || !nrm || !out || !bent || !d)
        return 1;
    make_gbuffer(&frame, pos, nrm);
    void *params = calloc(1, d->params_size), *consts = NULL;
    if (set_params(d, params, slices, steps, argc, argv, &diags)) {
        ssg_diags_print(&diags, stderr);
        return 2;
    }
    struct ssg_node_ctx ctx = {.desc = d, .instance = "t", .frame = &frame, .out_dir = "out",
                               .diags = &diags};
    const struct ssg_image *in[5] = {pos, nrm, hal.images[1], NULL, NULL};
    struct ssg_image *outs[2] = {out, bent};
    struct ssg_io io = {.in = in, .out = outs};
    struct ssg_io_shapes shapes;
    ssg_io_shapes_of(d, &io, &shapes);
    ssg_node_ctx_set_shapes(&ctx, &shapes);
    if (ssg_node_prepare(d, &ctx, params, &consts) != SSG_OK) {
        ssg_diags_print(&diags, stderr);
        return 1;
    }
    double *ms = calloc((size_t)runs, sizeof *ms), *cpu = calloc((size_t)runs, sizeof *cpu);
    micro_time(d, &ctx, consts, &io, runs, ms, cpu);
    double mean_ao, mean_bent;
    uint64_t h_ao = micro_hash(out->data, (size_t)W * H, &mean_ao);
    uint64_t h_bent = micro_hash(bent->data, (size_t)W * H * 3, &mean_bent);
    printf("gtao %dx%d, %d slices x %d steps, %d threads: median %.2f ms (min %.2f, max "
           "%.2f) over %d runs, cpu time median %.2f ms (min %.2f); mean ao %.4f, hash "
           "%016llx, bent hash %016llx\n", W, H, slices, steps, omp_get_max_threads(),
           ms[runs / 2], ms[0], ms[runs - 1], runs, cpu[runs / 2], cpu[0], mean_ao,
           (unsigned long long)h_ao, (unsigned long long)h_bent);
    free(ms);
    free(cpu);
    free(params);
    free(consts);
    ssg_image_destroy(&pos);
    ssg_image_destroy(&nrm);
    ssg_image_destroy(&out);
    ssg_image_destroy(&bent);
    ssg_outputs_release(&hal);
    return 0;
}
