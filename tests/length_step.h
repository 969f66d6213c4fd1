/* length_step.h - the scene of the length-shift tests of ssao and ssdo (halton
 * lengths=shifted: the rotation tile's planes 3 and 4 give each pixel an offset dl and an
 * index shift k; its sample i takes the length of kernel sample (i + k) mod K plus dl).
 * A 64 x 16 frame (vertical field of view 45 degrees, f = 8 / tan(22.5 deg) = 19.31 px)
 * sees a wall facing the camera (normal +z) at depth 5 left of column STEP_X and at depth
 * 4.5 from it on: a step towards the camera. Two kernel samples in the tangent frame of
 * N = +z (T = +x, B = +y, Duff et al.) with no turn, sin a = 0.04:
 *     s_0 = 0.5 (cos a, 0, sin a),   s_1 = 0.75 (-cos a, 0, sin a).
 * At radius r and length l a pixel P of the far wall places s_0 at
 * S = P + r l (cos a, 0, sin a), which lands at column
 *     u = cx + f S.x / -S.z,  -S.z = 5 - r l sin a,
 * and is occluded (depth 4.5 < -S.z - bias, the pixel there being on the near wall)
 * exactly when STEP_X <= u < 64. With r = 3 it reaches about f r l cos a / -S.z px to
 * the right: 4.4 px at l = 0.375, 5.9 at 0.5, 7.4 at 0.625, 10.4 at 0.875, so per row
 * the pixels 36..39, 34..39, 33..39 and 30..39 of the far wall are occluded (the landing
 * column at least 0.0015 px from a pixel border). s_1 goes left, over the far
 * wall (depth 5, not nearer than -S.z - bias) or off screen: never occluded. So a far-wall
 * pixel reads 1 - V_0 / 2 of one sample of two (ssao's 1 - occluded / 2, ssdo's modulation
 * with two equal weights N.w), V_0 at its cell's length of sample 0: 0.5 without a
 * shift, else the length of s_k plus dl. step_occluded() evaluates the formula per pixel
 * in double. Header-only, for node tests that include planes.h and ssao_planes.h first. */
#ifndef SSG_TEST_LENGTH_STEP_H
#define SSG_TEST_LENGTH_STEP_H

enum { STEP_W = 64, STEP_H = 16, STEP_X = 40 };
#define STEP_RADIUS 3.0
#define STEP_SIN 0.04

static double step_depth(int x, int y, int arg)
{
    (void)y, (void)arg;
    return x < STEP_X ? 5.0 : 4.5;
}

/* The two-sample kernel, owned. */
static inline struct ssg_image *step_kernel(void)
{
    struct ssg_image *k = ssg_image_create(2, 1, 3);
    double c = sqrt(1.0 - STEP_SIN * STEP_SIN);
    k->data[0] = (float)(0.5 * c), k->data[1] = (float)(-0.75 * c);
    k->data[2] = k->data[3] = 0.0f;
    k->data[4] = (float)(0.5 * STEP_SIN), k->data[5] = (float)(0.75 * STEP_SIN);
    return k;
}

/* An n x n tile without a turn (cos 1, sin 0) and, with dl, the length shift planes:
   offsets dl[y * n + x] and index shifts k[y * n + x]; owned. */
static inline struct ssg_image *step_tile(int n, const float *dl, const float *k)
{
    struct ssg_image *t = ssg_image_create(n, n, dl ? 4 : 2);
    for (int i = 0; i < n * n; i++) {
        t->data[i] = 1.0f;
        t->data[n * n + i] = 0.0f;
        if (dl) {
            t->data[2 * n * n + i] = dl[i];
            t->data[3 * n * n + i] = k[i];
        }
    }
    return t;
}

/* 1 when the far-wall pixel x (< STEP_X) of any row has s_0 occluded at length l (file
   header); *margin gets the landing column's distance to the nearest pixel border, so a
   caller can see that float rounding cannot move it. */
static inline int step_occluded(int x, double l, double *margin)
{
    struct ssg_frame f = frame();
    struct ssg_projection p = ssg_frame_projection(&f);
    double px = 5.0 * (x + 0.5 - p.cx) / p.f;
    double c = sqrt(1.0 - STEP_SIN * STEP_SIN);
    double z = 5.0 - STEP_RADIUS * l * STEP_SIN;
    double u = p.cx + p.f * (px + STEP_RADIUS * l * c) / z;
    *margin = fabs(u - floor(u + 0.5));
    return u >= STEP_X && u < STEP_W;
}

/* Checks out (one channel) on the far wall: 1 - V_0 / 2 with s_0 at length len[cell] of
   each pixel's cell of an n x n tile (file header). */
static inline void step_check(const struct ssg_image *out, int n, const double *len)
{
    int occluded = 0;
    for (int y = 0; y < STEP_H; y++)
        for (int x = 0; x < STEP_X; x++) {
            double margin;
            int occ = step_occluded(x, len[(y % n) * n + x % n], &margin);
            CHECK(margin > 1e-3);
            CHECK_EQ(out->data[(size_t)y * STEP_W + (size_t)x], occ ? 0.5f : 1.0f);
            occluded += occ;
        }
    CHECK(occluded > 0);
}

#endif
