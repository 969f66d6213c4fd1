/* test_ao_samples.c - every kernel sample of `ssao` and every march step of `hbao` counts:
 * per node a tiny synthetic G-buffer where exactly one sample (one step) meets what
 * decides the answer, worked out by hand, so a loop that drops a sample or a step moves
 * the result far beyond the tolerance. The other ssao and hbao tests average over many
 * samples (test_ssao.c's 4096-sample bracket moves by 1/1024 at most when one sample of
 * each kernel is lost), so only the CPU/GL parity tests saw such a slip before, and the
 * same slip in both backends would pass them.
 *
 * Both scenes: a 63 x 63 frame (planes.h's 45 degree camera, f = 31.5 / tan(22.5 deg)
 * = 76.05 px) and the point P seen by the centre pixel (31, 31), whose ray is the view
 * axis: P = (0, 0, -5) on a plane facing the camera, normal +z, so the sample frame is
 * T = x, B = y, N = z (ssg_sampling_basis) and V = N. G-buffers are written from a depth
 * per pixel (gbuf_from_depth, ssao_planes.h); only P's value is checked. */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "graph/node.h"
#include "ssgraph.h"

#include "planes.h"
#include "ssao_planes.h"

enum { SIDE = 63, CENTRE = 31, KERNEL = 4, STEPS = 3 };

/* ssao's kernel: s_k = (0.7 cos a_k, 0.7 sin a_k, 0.5), a_k = k 45 degrees, so that the
   2 KERNEL places of the normal-free modes (each sample and its opposite) lie 45 degrees
   apart around P and none shares a pixel with another. */
static const double SSAO_SPREAD = M_PI / 4, SSAO_XY = 0.7, SSAO_Z = 0.5;

/* Where sample k lands, in pixels from P's centre (+v down the screen), radius 1: the
   hemisphere's (and the sphere's) sample S = P + s_k at depth 5 - 0.5 lands
   f 0.7 / 4.5 = 11.83 px away; the disc's offset is rounded f 0.7 / 5 = 10.65 px. Their
   midpoint 11.2 px is within 0.7 px of both, and a pixel centre within 0.71 px more. */
static void ssao_gap(int k, double *du, double *dv)
{
    *du = 11.2 * cos(k * SSAO_SPREAD);
    *dv = -11.2 * sin(k * SSAO_SPREAD);
}

/* Depth 2 everywhere (a near occluder in front of every sample), except 5 (the open
   plane) within 2.5 px of P and within 2.5 px of where sample k lands: 4.5 px of room
   for the rounding above, 9 px short of the nearest other place (45 degrees at 11 px). */
static double ssao_depth(int x, int y, int k)
{
    double du, dv, cu = x - CENTRE, cv = y - CENTRE;
    ssao_gap(k, &du, &dv);
    int near_p = cu * cu + cv * cv <= 2.5 * 2.5;
    int in_gap = (cu - du) * (cu - du) + (cv - dv) * (cv - dv) <= 2.5 * 2.5;
    return near_p || in_gap ? 5.0 : 2.0;
}

/* Every place but one is occluded: a sample that reaches the depth-2 occluder lies at
   depth 4.5 (forward) or 5.5 (the sphere's opposite), far behind it, and range_check none
   counts it fully; sample k alone lands on the open plane in front of it (depth 4.5 < 5
   - bias; the disc's place reads 5, not below 5 - bias). So
     hemisphere: 1 - (KERNEL - 1) / KERNEL = 1/4;
     sphere, disc: clamp(2 - (2 KERNEL - 1) / KERNEL, 0, 1) = 1/4 (ssao/README's
     rescale);
   while one sample fewer leaves one occluded place fewer: 1/2 (hemisphere), 3/4 (the
   others), or where k itself is dropped, as many left as divided by. Every k in turn,
   so each sample is the one left open once and counted as occluded in the others. */
static void test_ssao_each_sample(void)
{
    struct ssg_image *kernel = ssg_image_create(KERNEL, 1, 3);
    for (int k = 0; k < KERNEL; k++) {
        kernel->data[k] = (float)(SSAO_XY * cos(k * SSAO_SPREAD));
        kernel->data[KERNEL + k] = (float)(SSAO_XY * sin(k * SSAO_SPREAD));
        kernel->data[2 * KERNEL + k] = (float)SSAO_Z;
    }
    static const char *const modes[] = {"mode=hemisphere", "mode=sphere", "mode=disc"};
    for (int k = 0; k < KERNEL; k++) {
        struct gbuf g = gbuf_from_depth(ssao_depth, k);
        for (int m = 0; m < 3; m++) {
            const char *sets[] = {modes[m], "radius=1", "bias=0.02", "range_check=none",
                                  "power=1"};
            struct ssg_image *ao = ssao(&g, kernel, NULL, 0, sets, 5);
            if (!ao)
                continue;
            float v = ao->data[(size_t)CENTRE * W + CENTRE];
            CHECK_NEAR(v, 0.25, 1e-6);
            if (!(fabs(v - 0.25) <= 1e-6))
                fprintf(stderr, "  ssao %s, sample %d open: %.6f, expected 0.25\n", modes[m],
                        k, v);
            ssg_image_destroy(&ao);
        }
        release(&g);
    }
    ssg_image_destroy(&kernel);
}

/* hbao's march (hbao/README): no falloff, bias 0, strength 1, 2 directions, radius
   R = 1, STEPS steps. Its length is f R / den px along the unnormalised screen direction,
   den = max(depth - R, depth / 2) = 4, unit here (V = N, D in the image plane): 19.01 px,
   a step 6.34 px. A 1 x 1 rotation tile of angle -pi/2 (cos 0, sin -1) turns direction 0
   from e1 = x to -e2 = -y, straight down the screen, and gives the steps the jitter
   u = 1 - frac(-1/4) = 1/4 (the angle of the cell half a tile away, here itself): step
   j lands (j + 1/4) 6.34 px down, on rows 2, 8 and 14 below P (1.58, 7.92, 14.26 rounded,
   none near a tie); direction 1 goes up. The last step lands inside the sphere of radius
   R about P (whose image reaches 76.05 / sqrt(24) = 15.5 px), so each step can count. */
static double hbao_row(int j)
{
    struct ssg_frame f = frame();
    double fpx = ssg_frame_projection(&f).f;
    return fpx * 1.0 / (4.0 * STEPS) * (j + 0.25);
}

/* A ramp through P rising towards the camera, elevation e, sin e = 0.2: the points
   P + l (0, -cos e, sin e) + m (1, 0, 0), plane normal (0, sin e, cos e), its depth along
   a pixel's ray 5 cos e / (cos e - a_v sin e), a_v = -(y + 0.5 - cy) / f. It fills the
   three rows about step k's row (its rounding cannot leave them, and no other step's
   row is in them); elsewhere the open plane at depth 5. */
static const double RAMP_SIN = 0.2;
static double hbao_depth(int x, int y, int k)
{
    int row = CENTRE + (int)lround(hbao_row(k));
    if (abs(y - row) > 1)
        return 5.0;
    struct ssg_frame f = frame();
    struct ssg_projection pr = ssg_frame_projection(&f);
    double av = -(y + 0.5 - pr.cy) / pr.f, ce = sqrt(1 - RAMP_SIN * RAMP_SIN);
    return 5.0 * ce / (ce - av * RAMP_SIN);
}

/* Step k's sample is a ramp point Q = P + l (0, -cos e, sin e): H = Q - P has elevation
   e over the plane perpendicular to V (sin h = H.V / |H| = sin e) and l <= 0.97 < R
   (checked below from the row); every other sample is a point of the open plane, on
   the tangent (elevation 0 = the starting horizon sin(t + bias), t = 0), which raises
   nothing, as does the whole upward direction. So the slice term of direction 0 is
   sin e - 0 and hbao = 1 - strength (sin e) / directions = 1 - 0.2 / 2 = 0.9; with that
   step not marched, 1. Every k in turn (the last step is the one `steps - 1` drops). */
static void test_hbao_each_step(void)
{
    struct ssg_image *rot = ssg_image_create(1, 1, 2);
    rot->data[0] = 0.0f;
    rot->data[1] = -1.0f;
    struct ssg_frame f = frame();
    double fpx = ssg_frame_projection(&f).f, ce = sqrt(1 - RAMP_SIN * RAMP_SIN);
    for (int k = 0; k < STEPS; k++) {
        /* Within R at the far edge of the band: l = depth a_v / -cos e. */
        double ov = lround(hbao_row(k)) + 1, dq = 5.0 * ce / (ce + ov / fpx * RAMP_SIN);
        CHECK(dq * ov / fpx / ce < 0.98);
        struct gbuf g = gbuf_from_depth(hbao_depth, k);
        struct ssg_binding b[3] = {{"position", g.pos}, {"normal", g.nrm}, {"rotation", rot}};
        char steps[16];
        snprintf(steps, sizeof steps, "steps=%d", STEPS);
        const char *sets[] = {"directions=2", steps, "radius=1", "bias=0", "strength=1",
                              "falloff=none"};
        struct ssg_diags diags = {0};
        struct ssg_outputs out;
        CHECK_EQ(ssg_node_run("hbao", b, 3, sets, 6, &f, &out, &diags), SSG_OK);
        if (out.count == 1) {
            float v = out.images[0]->data[(size_t)CENTRE * W + CENTRE];
            CHECK_NEAR(v, 1 - RAMP_SIN / 2, 1e-4);
            if (!(fabs(v - (1 - RAMP_SIN / 2)) <= 1e-4))
                fprintf(stderr, "  hbao, occluder at step %d: %.6f, expected %.6f\n", k, v,
                        1 - RAMP_SIN / 2);
        }
        ssg_outputs_release(&out);
        release(&g);
    }
    ssg_image_destroy(&rot);
}

int main(void)
{
    W = H = SIDE;
    test_ssao_each_sample();
    test_hbao_each_step();
    return check_report();
}
