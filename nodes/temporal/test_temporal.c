/* test_temporal.c - the `temporal` node against its definition (README.md) on hand-made
 * inputs, on both backends, every expected value computed here from the closed form:
 * a static sequence averages with weights 1 / n up to max_length, then exponentially
 * (also for in2 beside a 1-channel in); a depth or normal mismatch restarts a pixel;
 * variance clipping pulls a stale history into mean +/- gamma sigma of the 3 x 3
 * neighbourhood; history is fetched from pixel + motion (integer: that pixel; fractional:
 * bilinearly over the taps that pass); history_reset ignores every history input.
 * CPU/GL parity and thread counts: test_temporal_parity.c. */
#include <math.h>

#include "temporal_test.h"

#define AT(im, c, x, y) ssg_image_plane(im, c)[(size_t)(y) * (size_t)(im)->width + (size_t)(x)]

/* (1) and (7): a static camera, frame f's value x_f(pixel) a hash (noise in time and
   space), fed back frame by frame (out -> history, out2 -> history2, length ->
   length_in), the first frame with history_reset. Without the clamp (gamma 0) the
   output is the running mean of x_0 .. x_f while f < max_length (weights 1 / n), then
   e_f = e_{f-1} + (x_f - e_{f-1}) / max_length; the length min(f + 1, max_length). */
static void test_convergence(int gl)
{
    enum { W = 11, H = 7, L = 8, FRAMES = 20 };
    const char *sets[] = {"gamma=0", "max_length=8"};
    struct tframe f = tframe_make(W, H, 1, 1, 0);
    double expect[4][W * H] = {{0}};
    int bad = 0, bad_len = 0;
    for (int fr = 0; fr < FRAMES; fr++) {
        for (int c = 0; c < 4; c++)
            for (int i = 0; i < W * H; i++) {
                float x = thash((uint32_t)fr, (uint32_t)i, (uint32_t)c);
                (c ? ssg_image_plane(f.in2, c - 1) : f.in->data)[i] = x;
                double n = fr < L ? fr + 1 : L;
                expect[c][i] = fr == 0 ? x : expect[c][i] + (x - expect[c][i]) / n;
            }
        struct tresult r;
        if (trun(&f, sets, 2, fr == 0, gl, &r))
            break;
        for (int i = 0; i < W * H; i++) {
            for (int c = 0; c < 4; c++) {
                float got = (c ? ssg_image_plane(r.out2, c - 1) : r.out->data)[i];
                bad += fabs(got - expect[c][i]) > 2e-6;
            }
            bad_len += r.length->data[i] != (fr < L ? fr + 1 : L);
        }
        ssg_image_destroy(&f.hist), ssg_image_destroy(&f.hist2), ssg_image_destroy(&f.len);
        f.hist = r.out, f.hist2 = r.out2, f.len = r.length;
    }
    CHECK_EQ(bad, 0);
    CHECK_EQ(bad_len, 0);
    tframe_free(&f);
}

/* Checks one pixel of a run where history h and length n were accepted (out = h +
   (x - h) / (n + 1), length n + 1) or rejected (out = x, length 1). */
static void check_pixel(const struct tresult *r, int x, int y, double xin, double h,
                        double n, int accepted)
{
    double want = accepted ? h + (xin - h) / (n + 1.0) : xin;
    CHECK_NEAR(AT(r->out, 0, x, y), want, 1e-6);
    CHECK_EQ(AT(r->length, 0, x, y), accepted ? n + 1.0 : 1.0);
}

/* (2) and (3): history 5 with length 4 everywhere, in 1, static camera. prev_depth 2.2
   at (3, 4) (10% from motion.z = 2 > 5%) and 2.12 at (1, 6) (6%) restart them, 2.08 at
   (5, 2) (4%) does not; a
   previous normal 30 degrees off at (2, 3) (cos 0.866 < 0.9) restarts it, 20 degrees at
   (6, 1) (cos 0.940) does not. Everything else accumulates. */
static void test_disocclusion(int gl)
{
    struct tframe f = tframe_make(8, 8, 1, 0, 1);
    for (int i = 0; i < 64; i++)
        f.hist->data[i] = 5.0f, f.len->data[i] = 4.0f, f.in->data[i] = 1.0f;
    AT(f.pdepth, 0, 3, 4) = 2.2f;
    AT(f.pdepth, 0, 5, 2) = 2.08f;
    AT(f.pdepth, 0, 1, 6) = 2.12f;
    const double deg = M_PI / 180.0;
    AT(f.pnormal, 1, 2, 3) = (float)sin(30 * deg), AT(f.pnormal, 2, 2, 3) = (float)cos(30 * deg);
    AT(f.pnormal, 1, 6, 1) = (float)sin(20 * deg), AT(f.pnormal, 2, 6, 1) = (float)cos(20 * deg);
    const char *sets[] = {"gamma=0"};
    struct tresult r;
    if (!trun(&f, sets, 1, 0, gl, &r)) {
        for (int y = 0; y < 8; y++)
            for (int x = 0; x < 8; x++)
                check_pixel(&r, x, y, 1.0, 5.0, 4.0,
                            !(x == 3 && y == 4) && !(x == 1 && y == 6) && !(x == 2 && y == 3));
        tresult_free(&r);
    }
    /* depth_tolerance 0.15 takes (3, 4) back; normal_tolerance 0.8 takes (2, 3) back */
    const char *loose[] = {"gamma=0", "depth_tolerance=0.15", "normal_tolerance=0.8"};
    if (!trun(&f, loose, 3, 0, gl, &r)) {
        check_pixel(&r, 3, 4, 1.0, 5.0, 4.0, 1);
        check_pixel(&r, 2, 3, 1.0, 5.0, 4.0, 1);
        tresult_free(&r);
    }
    tframe_free(&f);
}

/* (4): in(x, y) = ((7x + 3y) mod 5) / 4 (a pattern with spread), history 10 (stale, far
   above), -10 (far below) or the window's mean (inside: kept), length 3. The expected
   clamp bounds are the mean and standard deviation of the in-image taps of each 3 x 3
   window, computed here in double. */
static void test_clamp(int gl)
{
    enum { W = 9, H = 6 };
    struct tframe f = tframe_make(W, H, 1, 0, 0);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            AT(f.in, 0, x, y) = (float)((7 * x + 3 * y) % 5) / 4.0f, AT(f.len, 0, x, y) = 3;
    static const char *gammas[] = {"gamma=1", "gamma=0.5"};
    for (int g = 0; g < 2; g++)
        for (int stale = -1; stale <= 1; stale++) {
            double gamma = g ? 0.5 : 1.0, mean[W * H], sd[W * H];
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++) {
                    double s1 = 0, s2 = 0, n = 0;
                    for (int qy = y - 1; qy <= y + 1; qy++)
                        for (int qx = x - 1; qx <= x + 1; qx++)
                            if (qx >= 0 && qx < W && qy >= 0 && qy < H) {
                                double v = AT(f.in, 0, qx, qy);
                                s1 += v, s2 += v * v, n++;
                            }
                    mean[y * W + x] = s1 / n;
                    sd[y * W + x] = sqrt(fmax(s2 / n - (s1 / n) * (s1 / n), 0.0));
                    f.hist->data[y * W + x] = stale ? 10.0f * (float)stale
                                                    : (float)mean[y * W + x];
                }
            struct tresult r;
            if (trun(&f, &gammas[g], 1, 0, gl, &r))
                continue;
            int bad = 0;
            for (int i = 0; i < W * H; i++) {
                double h = stale ? mean[i] + stale * gamma * sd[i] : mean[i];
                double want = h + (f.in->data[i] - h) / 4.0;
                bad += fabs(r.out->data[i] - want) > 2e-6;
                bad += stale && !(sd[i] > 0.1); /* the pattern has spread in every window */
            }
            CHECK_EQ(bad, 0);
            tresult_free(&r);
        }
    tframe_free(&f);
}

/* The history value the README's reprojection gives at pixel (x, y) for motion (mx, my):
   the bilinear taps around (x + mx, y + my) inside the image and with prev_depth within
   tolerance (here: not the marked pixel), their weights renormalised; NAN = restart. */
static double expected_fetch(const struct ssg_image *hist, int x, int y, double mx, double my,
                             int skip_x, int skip_y)
{
    double px = x + mx, py = y + my, fx = px - floor(px), fy = py - floor(py);
    int ix = (int)floor(px), iy = (int)floor(py);
    double s = 0, wsum = 0;
    for (int t = 0; t < 4; t++) {
        int tx = ix + (t & 1), ty = iy + (t >> 1);
        double w = ((t & 1) ? fx : 1 - fx) * ((t >> 1) ? fy : 1 - fy);
        if (tx < 0 || ty < 0 || tx >= hist->width || ty >= hist->height ||
            (tx == skip_x && ty == skip_y) || w == 0)
            continue;
        s += w * AT(hist, 0, tx, ty), wsum += w;
    }
    return wsum >= 0.01 ? s / wsum : NAN;
}

/* (5): history a hash (so a wrong place shows), length 1, in 0, so out = h / 2 where the
   history is found and 0 (restart) where it is not. Motion (3, -2): the pixel 3 right and
   2 up; (0.5, 0): half of two neighbours; (0.5, 0.5): a quarter of four; (-1.25, 0.75).
   prev_depth 3 at (5, 5) rejects that tap wherever it is used. */
static void test_reprojection(int gl)
{
    enum { W = 10, H = 8 };
    static const double motions[][2] = {{3, -2}, {0.5, 0}, {0.5, 0.5}, {-1.25, 0.75}};
    struct tframe f = tframe_make(W, H, 1, 0, 0);
    for (int i = 0; i < W * H; i++)
        f.hist->data[i] = thash(7u, (uint32_t)i, 0u), f.len->data[i] = 1.0f;
    AT(f.pdepth, 0, 5, 5) = 3.0f;
    const char *sets[] = {"gamma=0"};
    for (int m = 0; m < 4; m++) {
        for (int i = 0; i < W * H; i++) {
            ssg_image_plane(f.motion, 0)[i] = (float)motions[m][0];
            ssg_image_plane(f.motion, 1)[i] = (float)motions[m][1];
        }
        struct tresult r;
        if (trun(&f, sets, 1, 0, gl, &r))
            continue;
        int bad = 0, found = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                double h = expected_fetch(f.hist, x, y, motions[m][0], motions[m][1], 5, 5);
                found += !isnan(h);
                bad += fabs(AT(r.out, 0, x, y) - (isnan(h) ? 0.0 : h / 2)) > 1e-6;
                bad += AT(r.length, 0, x, y) != (isnan(h) ? 1.0f : 2.0f);
            }
        CHECK_EQ(bad, 0);
        CHECK(found > W * H / 2);
        tresult_free(&r);
    }
    tframe_free(&f);
}

/* (6): history_reset: whatever history, history2, length_in and the tests say, out = in,
   out2 = in2 and length 1, bit for bit. */
static void test_reset(int gl)
{
    enum { W = 6, H = 5, N = W * H };
    struct tframe f = tframe_make(W, H, 1, 1, 1);
    for (int i = 0; i < N; i++) {
        f.in->data[i] = thash(1u, (uint32_t)i, 0u), f.hist->data[i] = 9.0f;
        f.len->data[i] = 7.0f;
        for (int c = 0; c < 3; c++)
            ssg_image_plane(f.in2, c)[i] = thash(2u, (uint32_t)i, (uint32_t)c),
            ssg_image_plane(f.hist2, c)[i] = -3.0f;
    }
    struct tresult r;
    if (trun(&f, NULL, 0, 1, gl, &r))
        return;
    int bad = 0;
    for (int i = 0; i < N; i++) {
        bad += r.out->data[i] != f.in->data[i] || r.length->data[i] != 1.0f;
        for (int c = 0; c < 3; c++)
            bad += ssg_image_plane(r.out2, c)[i] != ssg_image_plane(f.in2, c)[i];
    }
    CHECK_EQ(bad, 0);
    tresult_free(&r);
    /* the same frame without the reset does use the history */
    if (!trun(&f, NULL, 0, 0, gl, &r)) {
        CHECK(r.length->data[0] == 8.0f && r.out->data[0] != f.in->data[0]);
        tresult_free(&r);
    }
    tframe_free(&f);
}

/* Shapes: history must match in, in2 and history2 go together, normal and prev_normal
   too (check() refuses the graph). */
static void test_shapes(void)
{
    struct tframe f = tframe_make(4, 4, 1, 1, 0);
    ssg_image_destroy(&f.hist2);
    struct ssg_shape ins[SSG_MAX_PORTS] = {{0}}, outs[SSG_MAX_PORTS];
    const struct ssg_image *in[] = {f.in, f.in2, f.hist, NULL, f.len, f.motion, f.depth, NULL,
                                    f.pdepth, NULL};
    for (int i = 0; i < SSG_TEMPORAL_INPUTS; i++)
        if (in[i])
            ins[i] = ssg_shape_of_image(in[i], ssg_node_temporal.inputs[i].types);
    struct ssg_temporal_params p;
    ssg_params_defaults(ssg_node_temporal.params, &p);
    struct ssg_frame frame = {.width = 4, .height = 4};
    char why[200];
    CHECK_EQ(ssg_shapes_infer(&ssg_node_temporal, &p, &frame, ins, outs, why, sizeof why),
             SSG_E_SIZE);
    ins[SSG_TEMPORAL_IN_IN2].channels = 0; /* without in2: fine, out2 shaped like out */
    CHECK_EQ(ssg_shapes_infer(&ssg_node_temporal, &p, &frame, ins, outs, why, sizeof why),
             SSG_OK);
    CHECK_EQ(outs[SSG_TEMPORAL_OUT_OUT2].channels, 1);
    ins[SSG_TEMPORAL_IN_NORMAL] = ins[SSG_TEMPORAL_IN_MOTION]; /* normal, no prev_normal */
    CHECK_EQ(ssg_shapes_infer(&ssg_node_temporal, &p, &frame, ins, outs, why, sizeof why),
             SSG_E_SIZE);
    tframe_free(&f);
}

int main(void)
{
    test_shapes();
    for (int gl = 0; gl < 2; gl++) {
        test_convergence(gl);
        test_disocclusion(gl);
        test_clamp(gl);
        test_reprojection(gl);
        test_reset(gl);
    }
    return check_report();
}
