/* ssdo_micro.c - timing of the `ssdo` node's CPU kernel (Ritschel et al. 2009 SSDO, as in
 * Szentandrasi sec. 3.2 / 4.1) on a synthetic G-buffer (not a test: it asserts nothing
 * about speed). For each frame size (1280x720, 1920x1080), kernel size K (12, 16, 24, 36,
 * 64) and bounce off / on, prints the median wall time of several runs of run_cpu alone
 * (prepare and allocation excluded), the median CPU time of all threads (on a shared
 * machine wall time also counts other processes), and a hash of the output bits, to
 * compare builds (the AVX2 and SSE paths must give the same hash).
 *
 * Scene: the corner of ssao_micro.c (bench/micro.h) with a relief on the floor; albedo
 * and light are smooth colour ramps. No scene: the constant white environment of ssdo.c
 * (the one-step graph's modulation with channels=1). Kernel: halton mapping=uniform with
 * its rotation tile, as ssdo wants.
 * Usage: ssdo_micro [runs=9] [threads=0 (all)] [only_k=0 (all)] [ssdo param=value ...] */
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

/* One frame size's inputs. */
struct inputs {
    int w, h;
    struct ssg_image *pos, *nrm, *alb, *light;
};

/* micro.h's make_gbuffer casts W x H (1080p); smaller frames take its nearest pixels: the
   same scene through the same field of view (positions off the pixel centres by under a
   pixel, which does not matter for timing). */
static void make_inputs(struct inputs *in, int w, int h)
{
    struct ssg_frame full = {W, H, 45.0f, 0.05f, 100.0f, 1, 0, 0, 0};
    struct ssg_image *pos = ssg_image_create(W, H, 3), *nrm = ssg_image_create(W, H, 3);
    make_gbuffer(&full, pos, nrm);
    in->w = w, in->h = h;
    in->pos = ssg_image_create(w, h, 3);
    in->nrm = ssg_image_create(w, h, 3);
    in->alb = ssg_image_create(w, h, 3);
    in->light = ssg_image_create(w, h, 3);
    size_t n = (size_t)w * h, nf = (size_t)W * H;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t o = (size_t)y * w + x, of = (size_t)(y * H / h) * W + (size_t)(x * W / w);
            for (int c = 0; c < 3; c++) {
                in->pos->data[c * n + o] = pos->data[c * nf + of];
                in->nrm->data[c * n + o] = nrm->data[c * nf + of];
                in->alb->data[c * n + o] = 0.3f + 0.2f * (float)c + 0.1f * (float)x / w;
                in->light->data[c * n + o] = 0.5f + 0.4f * (float)y / h - 0.1f * (float)c;
            }
        }
    ssg_image_destroy(&pos);
    ssg_image_destroy(&nrm);
}

static void free_inputs(struct inputs *in)
{
    ssg_image_destroy(&in->pos);
    ssg_image_destroy(&in->nrm);
    ssg_image_destroy(&in->alb);
    ssg_image_destroy(&in->light);
}

/* Times one configuration; returns 0 on success. */
static int time_one(const struct inputs *in, int k, int bounce, int runs, int argc,
                    char **argv)
{
    struct ssg_frame frame = {in->w, in->h, 45.0f, 0.05f, 100.0f, 1, 0, 0, 0};
    struct ssg_diags diags = {0};
    char count_set[32];
    snprintf(count_set, sizeof count_set, "count=%d", k);
    const char *hsets[] = {count_set, "mapping=uniform"};
    struct ssg_outputs hal;
    if (ssg_node_run("halton", NULL, 0, hsets, 2, &frame, &hal, &diags) != SSG_OK) {
        ssg_diags_print(&diags, stderr);
        return 1;
    }
    const struct ssg_node_desc *d = ssg_node_find("ssdo", 4);
    if (!d)
        return 1;
    void *params = calloc(1, d->params_size), *consts = calloc(1, d->consts_size);
    ssg_params_defaults(d->params, params);
    ssg_param_set_text(d->params, params, bounce ? "bounce=true" : "bounce=false", "<argv>",
                       "ssdo", &diags);
    for (int a = 4; a < argc; a++)
        if (ssg_param_set_text(d->params, params, argv[a], "<argv>", "ssdo", &diags)) {
            ssg_diags_print(&diags, stderr);
            return 2;
        }
    struct ssg_image *out = ssg_image_create(in->w, in->h, 1);
    struct ssg_image *bo = ssg_image_create(in->w, in->h, 3);
    struct ssg_node_ctx ctx = {.desc = d, .instance = "ssdo", .frame = &frame, .out_dir = "out",
                               .diags = &diags};
    const struct ssg_image *ins[8] = {in->pos, in->nrm, hal.images[0], hal.images[1], NULL,
                                      in->alb, in->light};
    struct ssg_image *outs[2] = {out, bo};
    struct ssg_io io = {.in = ins, .out = outs};
    struct ssg_io_shapes shapes;
    ssg_io_shapes_of(d, &io, &shapes);
    ssg_node_ctx_set_shapes(&ctx, &shapes);
    if (d->prepare(&ctx, params, consts) != SSG_OK || d->run_cpu(&ctx, consts, &io)) {
        ssg_diags_print(&diags, stderr);
        return 1;
    }
    double *ms = calloc((size_t)runs, sizeof *ms), *cpu = calloc((size_t)runs, sizeof *cpu);
    for (int r = 0; r < runs; r++) {
        double t0 = clock_ms(CLOCK_MONOTONIC), c0 = clock_ms(CLOCK_PROCESS_CPUTIME_ID);
        d->run_cpu(&ctx, consts, &io);
        ms[r] = clock_ms(CLOCK_MONOTONIC) - t0;
        cpu[r] = clock_ms(CLOCK_PROCESS_CPUTIME_ID) - c0;
    }
    qsort(ms, (size_t)runs, sizeof *ms, cmp_double);
    qsort(cpu, (size_t)runs, sizeof *cpu, cmp_double);
    double mean = 0, mean_b = 0;
    uint64_t hash = 1469598103934665603ull;
    size_t n = (size_t)in->w * in->h;
    for (size_t i = 0; i < n; i++) {
        uint32_t bits[4];
        memcpy(&bits[0], &out->data[i], 4);
        for (int c = 0; c < 3; c++)
            memcpy(&bits[1 + c], &bo->data[c * n + i], 4);
        for (int b = 0; b < 4; b++)
            hash = (hash ^ bits[b]) * 1099511628211ull;
        mean += out->data[i];
        mean_b += bo->data[n + i];
    }
    printf("ssdo %4dx%-4d K=%2d bounce=%d %d threads: median %7.2f ms (min %7.2f, max %7.2f), "
           "cpu median %7.2f ms; mean out %.4f, mean bounce.g %.4f, hash %016llx\n", in->w,
           in->h, k, bounce, omp_get_max_threads(), ms[runs / 2], ms[0], ms[runs - 1],
           cpu[runs / 2], mean / n, mean_b / n, (unsigned long long)hash);
    fflush(stdout);
    free(ms);
    free(cpu);
    free(params);
    free(consts);
    ssg_image_destroy(&out);
    ssg_image_destroy(&bo);
    ssg_outputs_release(&hal);
    return 0;
}

int main(int argc, char **argv)
{
    int runs = argc > 1 ? atoi(argv[1]) : 9;
    int threads = argc > 2 ? atoi(argv[2]) : 0;
    int only_k = argc > 3 ? atoi(argv[3]) : 0;
    if (runs < 1 || runs > 1000)
        return 2;
    if (threads > 0)
        omp_set_num_threads(threads);
    static const int sizes[2][2] = {{1280, 720}, {W, H}};
    static const int ks[] = {12, 16, 24, 36, 64};
    for (int s = 0; s < 2; s++) {
        struct inputs in;
        make_inputs(&in, sizes[s][0], sizes[s][1]);
        for (int ki = 0; ki < 5; ki++)
            for (int b = 0; b < 2; b++)
                if (!only_k || only_k == ks[ki])
                    if (time_one(&in, ks[ki], b, runs, argc, argv))
                        return 1;
        free_inputs(&in);
    }
    return 0;
}
