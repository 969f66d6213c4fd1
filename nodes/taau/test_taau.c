/* test_taau.c - the `taau` node on hand-made frames with known answers: the output's
 * shape and the shape errors; a restart gives this frame's samples alone; a still picture
 * sampled under the graph's jitter converges to the picture at the output's resolution; a
 * moving one is followed through its motion (and not without it); a history that leaves
 * the image, or a reset, is not used; the clamp; the same bytes for 1, 2 and 3 threads;
 * and the GL side against the CPU kernel within the descriptor's bound. */
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "scene/radical_inverse.h"
#include "gl_parity.h"
#include "scene_node.h" /* node_params, node_execute_on */
#include "taau.h"

/* One run's inputs (in's size w x h, the output's factor x that) and outputs. */
struct uframe {
    struct ssg_image *in, *motion, *hist, *weight;
    float jx, jy;
    int reset;
};

static struct ssg_image *filled(int w, int h, int ch, float v)
{
    struct ssg_image *im = ssg_image_create(w, h, ch);
    size_t n = (size_t)w * (size_t)h * (size_t)ch;
    for (size_t i = 0; i < n; i++)
        im->data[i] = v;
    return im;
}

static struct uframe uframe_make(int w, int h, int ch, int factor)
{
    return (struct uframe){.in = filled(w, h, ch, 0), .motion = filled(w, h, 3, 0),
                           .hist = filled(w * factor, h * factor, ch, 0),
                           .weight = filled(w * factor, h * factor, 1, 0), .reset = 1};
}

static void uframe_free(struct uframe *f)
{
    ssg_image_destroy(&f->in);
    ssg_image_destroy(&f->motion);
    ssg_image_destroy(&f->hist);
    ssg_image_destroy(&f->weight);
}

/* Runs the node on f with the "param=value" sets on the CPU or GL; *out and *weight are
   the caller's. As noderun.c's run_single, with the frame's jitter and the reset a graph's
   executor sets. Returns 0 on success. */
static int urun(const struct uframe *f, const char *const *sets, int n, int gl,
                struct ssg_image **out_img, struct ssg_image **weight_img)
{
    const struct ssg_node_desc *d = &ssg_node_taau;
    struct ssg_taau_params *params = node_params(d, sets, n);
    struct ssg_diags diags = {0};
    enum ssg_err e = SSG_OK;
    const struct ssg_image *in[SSG_TAAU_INPUTS] = {f->in, f->motion, f->hist, f->weight};
    struct ssg_shape ins[SSG_MAX_PORTS] = {{0}}, outs[SSG_MAX_PORTS];
    for (int i = 0; i < SSG_TAAU_INPUTS; i++)
        ins[i] = ssg_shape_of_image(in[i], d->inputs[i].types);
    struct ssg_frame frame = SSG_FRAME_DEFAULTS;
    frame.width = f->in->width, frame.height = f->in->height;
    frame.jitter_x = f->jx, frame.jitter_y = f->jy;
    char why[256] = "";
    if (!e)
        e = ssg_shapes_infer(d, params, &frame, ins, outs, why, sizeof why);
    struct ssg_image *out[SSG_TAAU_OUTPUTS] = {NULL};
    for (int i = 0; i < SSG_TAAU_OUTPUTS && !e; i++)
        out[i] = ssg_image_create(outs[i].width, outs[i].height, outs[i].channels);
    struct ssg_io io = {.in = in, .out = out};
    struct ssg_node_ctx ctx = {.desc = d, .instance = "u", .frame = &frame, .diags = &diags,
                               .in_shape = ins, .out_shape = outs,
                               .history_reset = f->reset};
    if (!e)
        e = node_execute_on(d, &ctx, params, &io, gl ? SSG_BACKEND_GL : SSG_BACKEND_CPU);
    free(params);
    if (e) {
        fprintf(stderr, "taau run failed (%s): %s\n", gl ? "gl" : "cpu", why);
        ssg_diags_print(&diags, stderr);
        ssg_image_destroy(&out[0]);
        ssg_image_destroy(&out[1]);
    }
    *out_img = out[0];
    *weight_img = out[1];
    return e != SSG_OK;
}

/* Feeds a run's outputs back as the next frame's history (prev(), as a graph does). */
static void feed_back(struct uframe *f, struct ssg_image *out, struct ssg_image *weight)
{
    ssg_image_destroy(&f->hist);
    ssg_image_destroy(&f->weight);
    f->hist = out, f->weight = weight;
    f->reset = 0;
}

/* The graph's jitter of frame k under `jitter 8` (graph_time.c). */
static void jitter_of(int k, float *jx, float *jy)
{
    uint64_t i = (uint64_t)(k % 8) + 1;
    *jx = (float)(ssg_halton_radical_inverse(i, 2) - 0.5);
    *jy = (float)(ssg_halton_radical_inverse(i, 3) - 0.5);
}

/* A picture in output coordinates (pixels of the factor x image): smooth bands of about
   9 output pixels, moving right by `shift` output pixels. */
static float picture(double x, double y, double shift)
{
    return (float)(0.5 + 0.4 * sin((x - shift) * 0.7) * cos(y * 0.45));
}

/* in sampled from the picture at this frame's jittered sample positions. */
static void render(struct uframe *f, int factor, double shift)
{
    for (int j = 0; j < f->in->height; j++)
        for (int i = 0; i < f->in->width; i++) {
            double x = ((double)i + 0.5 + f->jx) * factor, y = ((double)j + 0.5 + f->jy) * factor;
            f->in->data[(size_t)j * f->in->width + i] = picture(x, y, shift);
        }
}

/* RMSE of an output against the picture at its pixel centres, a border of 4 left out. */
static double error(const struct ssg_image *out, double shift)
{
    double s = 0;
    long n = 0;
    for (int y = 4; y < out->height - 4; y++)
        for (int x = 4; x < out->width - 4; x++) {
            double e = out->data[(size_t)y * out->width + x] - picture(x + 0.5, y + 0.5, shift);
            s += e * e, n++;
        }
    return sqrt(s / (double)n);
}

static void test_shapes(void)
{
    struct uframe f = uframe_make(10, 7, 3, 3);
    const char *sets[] = {"factor=3"};
    struct ssg_image *out, *wt;
    if (!urun(&f, sets, 1, 0, &out, &wt)) {
        CHECK(out->width == 30 && out->height == 21 && out->channels == 3);
        CHECK(wt->width == 30 && wt->height == 21 && wt->channels == 1);
        ssg_image_destroy(&out);
        ssg_image_destroy(&wt);
    }
    /* a history of the input's size, not the output's, is refused before anything runs */
    const struct ssg_node_desc *d = &ssg_node_taau;
    struct ssg_taau_params params;
    ssg_params_defaults(d->params, &params);
    struct ssg_shape ins[SSG_MAX_PORTS] = {{0}}, outs[SSG_MAX_PORTS];
    ins[SSG_TAAU_IN_IN] = ssg_shape_of_image(f.in, SSG_T_COLOR);
    ins[SSG_TAAU_IN_MOTION] = ssg_shape_of_image(f.motion, SSG_T_VECTOR);
    ins[SSG_TAAU_IN_HISTORY] = ssg_shape_of_image(f.in, SSG_T_COLOR);
    ins[SSG_TAAU_IN_WEIGHT_IN] = ssg_shape_of_image(f.weight, SSG_T_SCALAR);
    struct ssg_frame frame = SSG_FRAME_DEFAULTS;
    char why[256] = "";
    CHECK_EQ(ssg_shapes_infer(d, &params, &frame, ins, outs, why, sizeof why), SSG_E_SIZE);
    CHECK(strstr(why, "history must have") != NULL);
    /* a guard band would stay in the output (write crops only frame-sized images) */
    ins[SSG_TAAU_IN_HISTORY] = ssg_shape_of_image(f.hist, SSG_T_COLOR);
    params.factor = 3; /* f's history is 3 x its input */
    frame.guard = 4;
    CHECK_EQ(ssg_shapes_infer(d, &params, &frame, ins, outs, why, sizeof why), SSG_E_SIZE);
    CHECK(strstr(why, "guard band") != NULL);
    frame.guard = 0;
    CHECK_EQ(ssg_shapes_infer(d, &params, &frame, ins, outs, why, sizeof why), SSG_OK);
    uframe_free(&f);
}

/* After a reset a constant picture comes out as itself, whatever the jitter. */
static void test_reset_constant(void)
{
    struct uframe f = uframe_make(12, 9, 3, 2);
    for (size_t i = 0; i < 12 * 9 * 3; i++)
        f.in->data[i] = 0.25f;
    f.jx = 0.3f, f.jy = -0.45f;
    struct ssg_image *out, *wt;
    if (!urun(&f, NULL, 0, 0, &out, &wt)) {
        double worst = 0, wmin = 1e9;
        for (size_t i = 0; i < 24 * 18 * 3; i++)
            worst = fmax(worst, fabs(out->data[i] - 0.25));
        for (size_t i = 0; i < 24 * 18; i++)
            wmin = fmin(wmin, wt->data[i]);
        CHECK(worst < 1e-6);
        CHECK(wmin > 0.0 && wmin <= 4.0);
        ssg_image_destroy(&out);
        ssg_image_destroy(&wt);
    }
    uframe_free(&f);
}

/* A still picture under 16 frames of jitter: the output approaches the picture at the
   output's resolution, well below the first frame's error (one sample per 2 x 2). */
static void test_still_converges(void)
{
    struct uframe f = uframe_make(40, 30, 1, 2);
    double first = 0, last = 0;
    for (int k = 0; k < 16; k++) {
        jitter_of(k, &f.jx, &f.jy);
        render(&f, 2, 0.0);
        struct ssg_image *out, *wt;
        if (urun(&f, NULL, 0, 0, &out, &wt))
            break;
        last = error(out, 0.0);
        if (k == 0)
            first = last;
        feed_back(&f, out, wt);
    }
    printf("still picture: RMSE %.4f after the first frame, %.4f after 16\n", first, last);
    CHECK(first > 0.02);
    CHECK(last < 0.5 * first);
    uframe_free(&f);
}

/* A picture moving right by 1 output pixel a frame: with the motion (previous pixel minus
   this one: -1 output pixel = -0.5 of in's) the output follows it; without, the history
   lags and the error is larger. */
static double moving(int with_motion)
{
    struct uframe f = uframe_make(40, 30, 1, 2);
    for (size_t i = 0; i < 40 * 30; i++)
        f.motion->data[i] = with_motion ? -0.5f : 0.0f;
    double e = 0;
    for (int k = 0; k < 12; k++) {
        jitter_of(k, &f.jx, &f.jy);
        render(&f, 2, (double)k);
        struct ssg_image *out, *wt;
        if (urun(&f, NULL, 0, 0, &out, &wt))
            break;
        e = error(out, (double)k);
        feed_back(&f, out, wt);
    }
    uframe_free(&f);
    return e;
}

static void test_motion(void)
{
    double followed = moving(1), lagging = moving(0);
    printf("moving picture: RMSE %.4f with its motion, %.4f without\n", followed, lagging);
    CHECK(followed < 0.7 * lagging);
}

/* A history that left the image is not used: the same bytes as a reset. */
static void test_outside(void)
{
    struct uframe f = uframe_make(16, 12, 3, 2);
    for (size_t i = 0; i < 16 * 12 * 3; i++)
        f.in->data[i] = (float)(i % 7) * 0.1f;
    for (size_t i = 0; i < 32 * 24 * 3; i++)
        f.hist->data[i] = 5.0f;
    for (size_t i = 0; i < 32 * 24; i++)
        f.weight->data[i] = 4.0f;
    for (size_t i = 0; i < 16 * 12; i++)
        f.motion->data[i] = 100.0f; /* x: far to the right */
    struct ssg_image *a, *aw, *b, *bw;
    f.reset = 0;
    if (urun(&f, NULL, 0, 0, &a, &aw))
        return;
    f.reset = 1;
    if (!urun(&f, NULL, 0, 0, &b, &bw)) {
        CHECK(memcmp(a->data, b->data, sizeof(float) * 32 * 24 * 3) == 0);
        CHECK(memcmp(aw->data, bw->data, sizeof(float) * 32 * 24) == 0);
        ssg_image_destroy(&b);
        ssg_image_destroy(&bw);
    }
    ssg_image_destroy(&a);
    ssg_image_destroy(&aw);
    uframe_free(&f);
}

/* A history far outside this frame's samples (a constant 1: deviation 0) is clamped to
   them; with gamma 0 it is not, and pulls the output up. */
static void test_clamp(void)
{
    struct uframe f = uframe_make(16, 12, 1, 2);
    for (size_t i = 0; i < 16 * 12; i++)
        f.in->data[i] = 1.0f;
    for (size_t i = 0; i < 32 * 24; i++)
        f.hist->data[i] = 10.0f, f.weight->data[i] = 4.0f;
    f.reset = 0;
    const char *off[] = {"gamma=0"};
    struct ssg_image *a, *aw, *b, *bw;
    if (urun(&f, NULL, 0, 0, &a, &aw) || urun(&f, off, 1, 0, &b, &bw))
        return;
    double worst = 0, lowest = 1e9;
    for (size_t i = 0; i < 32 * 24; i++) {
        worst = fmax(worst, fabs(a->data[i] - 1.0));
        lowest = fmin(lowest, b->data[i]);
    }
    CHECK(worst < 1e-6);
    CHECK(lowest > 5.0);
    CHECK(aw->data[100] == 1.0f); /* the weight stays capped at max_weight (1) */
    ssg_image_destroy(&a);
    ssg_image_destroy(&aw);
    ssg_image_destroy(&b);
    ssg_image_destroy(&bw);
    uframe_free(&f);
}

/* Weights that underflow to subnormals (a small sigma at factor 4) count as none: every
   output of a constant picture stays that constant, over all eight jitter phases. */
static void test_tiny_weights(void)
{
    struct uframe f = uframe_make(20, 15, 1, 4);
    for (size_t i = 0; i < 20 * 15; i++)
        f.in->data[i] = 0.5f;
    const char *sets[] = {"factor=4", "sigma=0.2"};
    double worst = 0;
    for (int k = 0; k < 8; k++) {
        jitter_of(k, &f.jx, &f.jy);
        struct ssg_image *out, *wt;
        if (urun(&f, sets, 2, 0, &out, &wt))
            break;
        for (size_t i = 0; i < 80 * 60; i++)
            worst = isfinite(out->data[i]) ? fmax(worst, fabs(out->data[i] - 0.5)) : INFINITY;
        feed_back(&f, out, wt);
    }
    CHECK(worst < 1e-6);
    uframe_free(&f);
}

/* A history that is not finite (NaN with weight 0, an infinity with max_weight 0) gives a
   finite output, the same as this frame's estimate, and does not spread; on both sides. */
static void test_bad_history(int gl)
{
    struct uframe f = uframe_make(16, 12, 1, 2);
    for (size_t i = 0; i < 16 * 12; i++)
        f.in->data[i] = 0.25f;
    for (size_t i = 0; i < 32 * 24; i++)
        f.hist->data[i] = 0.25f, f.weight->data[i] = 1.0f;
    f.hist->data[10 * 32 + 10] = NAN, f.weight->data[10 * 32 + 10] = 0.0f;
    f.hist->data[5 * 32 + 20] = INFINITY;
    f.reset = 0;
    const char *none[] = {"max_weight=0"};
    for (int k = 0; k < 4; k++) {
        struct ssg_image *out, *wt;
        if (urun(&f, k == 3 ? none : NULL, k == 3, gl, &out, &wt))
            break;
        int bad = 0;
        for (size_t i = 0; i < 32 * 24; i++)
            bad += !isfinite(out->data[i]) || fabs(out->data[i] - 0.25) > 1e-6;
        CHECK_EQ(bad, 0);
        if (k < 2) { /* the bad texels again, into the next frame's history */
            out->data[10 * 32 + 10] = NAN;
            out->data[5 * 32 + 20] = -INFINITY;
        }
        feed_back(&f, out, wt);
    }
    uframe_free(&f);
}

/* A frame that exercises every branch: random values, a stale history on a tenth of the
   pixels, motion up to +-40 output pixels (some outside), 1 or 3 channels. */
static struct uframe random_frame(int w, int h, int ch)
{
    struct uframe f = uframe_make(w, h, ch, 2);
    srand(7);
    for (size_t i = 0; i < (size_t)w * h * ch; i++)
        f.in->data[i] = (float)rand() / (float)RAND_MAX;
    for (size_t i = 0; i < (size_t)4 * w * h * ch; i++)
        f.hist->data[i] = (float)rand() / (float)RAND_MAX * (rand() % 10 == 0 ? 6.0f : 1.0f);
    for (size_t i = 0; i < (size_t)4 * w * h; i++)
        f.weight->data[i] = 6.0f * (float)rand() / (float)RAND_MAX;
    for (size_t i = 0; i < (size_t)2 * w * h; i++)
        f.motion->data[i] = 40.0f * (float)rand() / (float)RAND_MAX - 20.0f;
    f.jx = 0.3125f, f.jy = -0.2f;
    f.reset = 0;
    return f;
}

static void test_threads(void)
{
    struct uframe f = random_frame(83, 71, 3); /* more rows than a band, odd sizes */
    struct ssg_image *ref, *refw, *o, *ow;
    omp_set_num_threads(1);
    if (urun(&f, NULL, 0, 0, &ref, &refw))
        return;
    for (int t = 2; t <= 3; t++) {
        omp_set_num_threads(t);
        if (urun(&f, NULL, 0, 0, &o, &ow))
            continue;
        CHECK(memcmp(ref->data, o->data, sizeof(float) * 166 * 142 * 3) == 0);
        CHECK(memcmp(refw->data, ow->data, sizeof(float) * 166 * 142) == 0);
        ssg_image_destroy(&o);
        ssg_image_destroy(&ow);
    }
    omp_set_num_threads(2);
    ssg_image_destroy(&ref);
    ssg_image_destroy(&refw);
    uframe_free(&f);
}

static void parity(const char *label, int ch, int reset)
{
    struct uframe f = random_frame(37, 29, ch);
    f.reset = reset;
    struct ssg_image *c, *cw, *g, *gw;
    if (urun(&f, NULL, 0, 0, &c, &cw))
        return;
    if (!urun(&f, NULL, 0, 1, &g, &gw)) {
        struct parity_tol tol = parity_tol_of("taau");
        parity_check_output("taau", label, "out", c, g, tol);
        parity_check_output("taau", label, "weight", cw, gw, tol);
        ssg_image_destroy(&g);
        ssg_image_destroy(&gw);
    }
    ssg_image_destroy(&c);
    ssg_image_destroy(&cw);
    uframe_free(&f);
}

int main(void)
{
    test_shapes();
    test_reset_constant();
    test_still_converges();
    test_motion();
    test_outside();
    test_clamp();
    test_tiny_weights();
    test_bad_history(0);
    test_bad_history(1);
    test_threads();
    parity("3 channels", 3, 0);
    parity("1 channel", 1, 0);
    parity("history_reset", 3, 1);
    return check_report();
}
