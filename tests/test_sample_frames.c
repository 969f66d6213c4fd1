/* test_sample_frames.c - per-frame samples (docs/time.md, issue 32 item 5): halton's kernel
 * of frame f is the Halton points offset + f * count .. (so frames 0..3 of 8 samples are 32
 * distinct points), its rotation tile turns per frame and is reproducible; gtao's and
 * ssilvb's slices and noise move per frame, the mean of 8 frames at a still camera is
 * closer to reference_ao than frame 0 alone, and a frame's bytes do not depend on the
 * thread count. Frame 0 is the single-frame run, byte for byte. Nodes run alone
 * (ssg_node_run with "frame=N") on a small Cornell-box G-buffer. */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "ssgraph.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

enum { GW = 64, GH = 48 };

/* A node's outputs at frame `frame` (and the node's own sets); failure fails a CHECK. */
static struct ssg_outputs run_at(const char *node, const struct ssg_binding *b, int nb,
                                 const char *const *sets, int set_count, int frame,
                                 const struct ssg_frame *f)
{
    const char *all[12];
    char fr[32];
    snprintf(fr, sizeof fr, "frame=%d", frame);
    for (int i = 0; i < set_count; i++)
        all[i] = sets[i];
    all[set_count] = fr;
    struct ssg_outputs out = {0};
    struct ssg_diags d = {0};
    enum ssg_err e = ssg_node_run(node, b, nb, all, set_count + 1, f, &out, &d);
    CHECK_EQ(e, SSG_OK);
    if (e)
        ssg_diags_print(&d, stderr);
    return out;
}

static size_t image_floats(const struct ssg_image *im)
{
    return (size_t)im->width * (size_t)im->height * (size_t)im->channels;
}

static int same_bytes(const struct ssg_image *a, const struct ssg_image *b)
{
    return a && b && image_floats(a) == image_floats(b) &&
           memcmp(a->data, b->data, image_floats(a) * sizeof(float)) == 0;
}

/* Radical inverse in base b (eq. 6 of halton/README.md), written again here. */
static double phi(unsigned i, unsigned b)
{
    double r = 0, f = 1.0 / b;
    for (; i; i /= b, f /= b)
        r += f * (i % b);
    return r;
}

/* (1) Frames 0..3 of count=8: sample i of frame f is Halton point 1 + 8 f + i (offset 1):
   the cosine mapping gives z / |s| = sqrt(1 - u0) and atan2(y, x) = 2 pi u1. */
static void test_halton_kernel_frames(void)
{
    const char *sets[] = {"count=8"};
    double u0[32], u1[32];
    for (int f = 0; f < 4; f++) {
        struct ssg_outputs o = run_at("halton", NULL, 0, sets, 1, f, NULL);
        if (o.count != 2)
            return;
        const float *k = o.images[0]->data;
        for (int i = 0; i < 8; i++) {
            double x = k[i], y = k[8 + i], z = k[16 + i], len = sqrt(x * x + y * y + z * z);
            double a = atan2(y, x) / (2.0 * M_PI);
            u0[8 * f + i] = 1.0 - (z / len) * (z / len);
            u1[8 * f + i] = a < 0 ? a + 1.0 : a;
        }
        ssg_outputs_release(&o);
    }
    int off = 0;
    for (int n = 0; n < 32; n++)
        off += fabs(u0[n] - phi(1 + n, 2)) > 2e-6 || fabs(u1[n] - phi(1 + n, 3)) > 2e-6;
    CHECK_EQ(off, 0);
    /* Fixed values: indices 1, 9, 17, 25 (sample 0 of frames 0..3). */
    const double e0[4] = {0.5, 0.5625, 0.53125, 0.59375};
    const double e1[4] = {1.0 / 3, 1.0 / 27, 25.0 / 27, 17.0 / 27};
    for (int f = 0; f < 4; f++) {
        CHECK_NEAR(u0[8 * f], e0[f], 2e-6);
        CHECK_NEAR(u1[8 * f], e1[f], 2e-6);
    }
    int dup = 0; /* 32 distinct points: base-2 values 1/64 apart at least */
    for (int a = 0; a < 32; a++)
        for (int b = 0; b < a; b++)
            dup += fabs(u0[a] - u0[b]) < 1e-3 && fabs(u1[a] - u1[b]) < 1e-3;
    CHECK_EQ(dup, 0);
}

/* (2) Frame 0 is the single-frame run; frame 1's tile differs, each entry turned by 2 pi /
   phi; frame 3 twice is the same bytes, on the CPU and on GL. */
static void test_halton_rotation_frames(void)
{
    const char *sets[] = {"pattern=8"}, *gl[] = {"pattern=8", "backend=gl"};
    struct ssg_outputs one = {0}, f0, f1, f3a, f3b, f3gl;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_node_run("halton", NULL, 0, sets, 1, NULL, &one, &d), SSG_OK);
    f0 = run_at("halton", NULL, 0, sets, 1, 0, NULL);
    f1 = run_at("halton", NULL, 0, sets, 1, 1, NULL);
    f3a = run_at("halton", NULL, 0, sets, 1, 3, NULL);
    f3b = run_at("halton", NULL, 0, sets, 1, 3, NULL);
    f3gl = run_at("halton", NULL, 0, gl, 2, 3, NULL);
    if (one.count == 2 && f0.count == 2 && f1.count == 2 && f3a.count == 2 &&
        f3b.count == 2 && f3gl.count == 2) {
        CHECK(same_bytes(one.images[0], f0.images[0]) && same_bytes(one.images[1], f0.images[1]));
        CHECK(!same_bytes(f0.images[1], f1.images[1]));
        CHECK(!same_bytes(f0.images[0], f1.images[0]));
        CHECK(same_bytes(f3a.images[0], f3b.images[0]) && same_bytes(f3a.images[1], f3b.images[1]));
        CHECK(same_bytes(f3a.images[0], f3gl.images[0]) &&
              same_bytes(f3a.images[1], f3gl.images[1]));
        double turn = 0.61803398874989484820 * 2.0 * M_PI, worst = 0;
        const float *a = f0.images[1]->data, *b = f1.images[1]->data;
        for (int i = 0; i < 64; i++) {
            double da = atan2(b[64 + i], b[i]) - atan2(a[64 + i], a[i]) - turn;
            da -= 2.0 * M_PI * floor(da / (2.0 * M_PI) + 0.5);
            worst = fmax(worst, fabs(da));
        }
        CHECK(worst < 1e-5);
    }
    struct ssg_outputs *all[] = {&one, &f0, &f1, &f3a, &f3b, &f3gl};
    for (int i = 0; i < 6; i++)
        ssg_outputs_release(all[i]);
}

/* The Cornell box's G-buffer, halton's tile and reference_ao (4096 rays) at GW x GH. */
enum { POS, NRM, DEP, ALB, DIR, ROT, REF, NIN };
static struct ssg_image *in[NIN];
static struct ssg_frame gframe;

static int load_scene(void)
{
    char dir[600], path[700], cwd[400];
    const char *t = getenv("SSG_TMP");
    snprintf(dir, sizeof dir, "%s", t ? t : CHECK_TMP_ROOT "/ssg_test_sample_frames");
    mkdir(dir, 0777);
    snprintf(path, sizeof path, "%s/g.graph", dir);
    FILE *f = fopen(path, "w");
    if (!f || !getcwd(cwd, sizeof cwd))
        return 0;
    fprintf(f, "scene \"%s/examples/cornell.scene\"\nsize %d %d\nseed 1\ng = gbuffer()\n"
               "k = halton(count=16)\n"
               "ref = reference_ao(g.position, g.normal, rays=4096, max_distance=0.5)\n",
            cwd, GW, GH);
    fclose(f);
    const char *outs[NIN] = {"g.position", "g.normal", "g.depth", "g.albedo", "g.direct",
                             "k.rotation", "ref.out"};
    struct ssg_overrides ov = {.seed = -1, .outputs = outs, .output_count = NIN};
    struct ssg_run_options ro = {.out_dir = dir, .threads = 2, .outputs = in};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    struct ssg_view v;
    enum ssg_err e = ssg_graph_load(path, &ov, &g, &d);
    if (!e)
        e = ssg_graph_run(g, &ro, &d);
    if (!e)
        e = ssg_graph_view(g, &v, &d);
    CHECK_EQ(e, SSG_OK);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
    gframe = (struct ssg_frame)SSG_FRAME_DEFAULTS;
    gframe.width = GW, gframe.height = GH, gframe.fov_y = v.fov_y;
    return e == SSG_OK;
}

static int bind_for(const char *node, struct ssg_binding *b)
{
    int n = 0;
    b[n++] = (struct ssg_binding){"position", in[POS]};
    b[n++] = (struct ssg_binding){"normal", in[NRM]};
    b[n++] = (struct ssg_binding){"depth", in[DEP]};
    if (strcmp(node, "gtao") == 0) {
        b[n++] = (struct ssg_binding){"rotation", in[ROT]};
    } else {
        b[n++] = (struct ssg_binding){"light", in[DIR]};
        b[n++] = (struct ssg_binding){"albedo", in[ALB]};
    }
    return n;
}

/* rmse of ao against the reference over surface pixels (depth > 0). */
static double rmse(const float *ao)
{
    double s = 0;
    long n = 0;
    for (int i = 0; i < GW * GH; i++)
        if (in[DEP]->data[i] > 0) {
            double e = ao[i] - in[REF]->data[i];
            s += e * e, n++;
        }
    return sqrt(s / (double)(n ? n : 1));
}

/* (3) and (4) for one node: frame 1 differs from frame 0; the mean of frames 0..7 lowers
   the error against reference_ao by the stated factor at least; frame 3 on 1 and on 2
   threads gives the same bytes. */
static void test_horizon_frames(const char *node, const char *const *sets, int nsets,
                                double factor)
{
    struct ssg_binding b[6];
    int nb = bind_for(node, b);
    float *mean = calloc((size_t)GW * GH, sizeof *mean);
    double first = 0;
    struct ssg_outputs f0 = {0};
    for (int f = 0; f < 8; f++) {
        struct ssg_outputs o = run_at(node, b, nb, sets, nsets, f, &gframe);
        if (o.count < 1)
            break;
        for (int i = 0; i < GW * GH; i++)
            mean[i] += o.images[0]->data[i] / 8.0f;
        if (f == 0)
            first = rmse(o.images[0]->data), f0 = o;
        else if (f == 1)
            CHECK(!same_bytes(f0.images[0], o.images[0]));
        if (f > 0)
            ssg_outputs_release(&o);
    }
    double avg = rmse(mean);
    printf("%s: rmse vs reference_ao frame 0 %.5f, mean of 8 frames %.5f (ratio %.3f)\n",
           node, first, avg, avg / first);
    CHECK(avg < factor * first);
    omp_set_num_threads(1);
    struct ssg_outputs t1 = run_at(node, b, nb, sets, nsets, 3, &gframe);
    omp_set_num_threads(2);
    struct ssg_outputs t2 = run_at(node, b, nb, sets, nsets, 3, &gframe);
    for (int i = 0; i < t1.count && i < t2.count; i++)
        CHECK(same_bytes(t1.images[i], t2.images[i]));
    ssg_outputs_release(&t1);
    ssg_outputs_release(&t2);
    ssg_outputs_release(&f0);
    free(mean);
}

int main(void)
{
    test_halton_kernel_frames();
    test_halton_rotation_frames();
    if (load_scene()) {
        /* Few slices, so one frame's error is mostly the slices' quadrature, which the
           frames' turns average out. Measured (64x48, 4096 reference rays): rmse 0.136 ->
           0.090 for gtao (ratio 0.66), 0.133 -> 0.089 for ssilvb (0.67); repeating frame
           0 eight times, as before per-frame samples, gives ratio 1. Required: 0.8. */
        const char *gtao[] = {"slices=2", "steps=6", "radius=0.5"};
        test_horizon_frames("gtao", gtao, 3, 0.8);
        const char *ssilvb[] = {"slices=2", "steps=6", "radius=0.5", "power=1"};
        test_horizon_frames("ssilvb", ssilvb, 4, 0.8);
    }
    for (int i = 0; i < NIN; i++)
        ssg_image_destroy(&in[i]);
    return check_report();
}
