/* ssao.c - the `ssao` node: screen-space ambient occlusion in three classic variants
 * (`mode`): the normal-oriented hemisphere (default), the normal-free sphere, and the
 * screen-space disc.
 *
 * hemisphere. Szentandrasi, "Modern Methods of Realistic Lighting in Real Time", section
 * 3.1 (figure 1): sample points are generated inside the hemisphere around the pixel's
 * normal, projected to the screen, and their depths compared with the depth buffer
 * there; the fraction of samples below the visible surface darkens the pixel. Belonogov,
 * "Global Illumination methods in simulated VR environments", section 3.2: the
 * normal-oriented hemisphere (figure 3.2) and a small rotation texture tiled over the
 * screen (3.2.3), whose noise a blur removes (our `bilateral` node, section 4.3.2). The
 * range check is the one of Chapman's SSAO tutorial (Belonogov's reference [18]): an
 * occluder much nearer the camera than the pixel is a different object and must not
 * darken it. Samples come from the `halton` node (Szentandrasi section 4.2).
 * For pixel P with unit normal N: S = P + r * (T s.x + B s.y + N s.z) for each kernel
 * sample s, with T, B a tangent frame turned about N by the tile's angle at
 * (x mod n, y mod n). S is projected with the frame's camera (node.h); the scene depth d
 * at that pixel (nearest) occludes S when 0 < d < -S.z - bias, weighted by the range
 * check (hard: |d - depth(P)| <= r; smooth: smoothstep(0, 1, r / |depth(P) - d|)).
 * Samples outside the frame, behind the camera or over background (depth 0, infinitely
 * far) are unoccluded. out = (1 - occluded / count)^power; background pixels get 1.
 *
 * sphere. Knuth and Kohlhammer, "A Hybrid Ambient Occlusion Technique for Dynamic
 * Scenes", section 4 (local part, figure 9): samples in the spherical region around the
 * pixel, denser towards its centre (the kernel's lengths), without the normal; the
 * result is the average of the depth tests, and "objects occluding less than half of
 * the sphere would appear brighter than usual ... we clamp the attenuation factor to
 * [0..1]": half the sphere occluded is the normal, unoccluded state of a surface point.
 * So out = clamp(2 (1 - occluded / samples), 0, 1)^power: an open plane (half the
 * sphere behind it) gives 1, convex surfaces saturate at 1, concave ones darken. The
 * sphere is the kernel's hemisphere about the view axis (+z, towards the camera, turned
 * by the tile's angle) and its point reflection: each kernel sample s gives the two
 * points P + r R s and P - r R s. The pair is the documented equivalent of "mirroring
 * every other sample": same density (a uniform hemisphere kernel, halton
 * mapping = uniform, becomes a uniform sphere), and a plane through P has at most one of
 * the two behind it, so an open plane gives exactly 1 (same depth tests, bias and range
 * check as the hemisphere mode; the normal input is not read).
 *
 * disc. Mittring, "Finding Next Gen - CryEngine 2" (SIGGRAPH 2007 course; the first
 * SSAO), in the two-dimensional form Belonogov section 3.2.1 describes ("SSAO eventually
 * deals ... with its disc-shaped projection on the image space"): depth samples at
 * screen offsets in the disc of radius f r / depth(P) px around the pixel, each sample
 * occluding when its depth d is nearer than the pixel's by more than bias
 * (0 < d < depth(P) - bias), with the range check on depth(P) - d. The offsets are the
 * kernel samples' (s.x, s.y) (a cosine kernel's are uniform over the unit disc, Malley),
 * turned by the tile's angle, rounded to whole pixels (ties to even), and used in
 * opposite pairs +-o. Since 1 / depth is affine in screen position on a plane, of two
 * opposite samples of a plane at most one is nearer than the pixel: as in the sphere
 * mode, out = clamp(2 (1 - occluded / samples), 0, 1)^power is exactly 1 on any open
 * plane (where the raw fraction would leave tilted planes half grey, Crytek's known
 * artefact) and darkens creases. The normal input is not read.
 *
 * All modes, per-pixel sample count (Szentandrasi section 4.3, the `complexity` node):
 * with the optional `count` input, pixel i uses only the first n_i = round(count_i)
 * kernel samples (rounded half up, clamped to [1, kernel width]; NaN = all), and every
 * "count" above is n_i: out = (1 - occluded / n_i)^power, or clamp(2 - occluded / n_i,
 * 0, 1)^power in the normal-free modes. With a kernel of whole Halton periods (halton
 * period=N_g) and counts multiple of N_g, each pixel's samples are still quasi-uniform
 * (eq. 8). Unconnected, every pixel uses the whole kernel.
 *
 * All modes: max_screen_radius > 0 caps r per pixel at max_screen_radius * depth(P) / f
 * (the capped r is also the range-check distance), so that near pixels do not sample
 * all over the screen: their depth reads would miss the cache (see ssao_cpu.c), and
 * Szentandrasi section 3.1 notes that the sampled area's projected size governs what
 * SSAO can find anyway. Normals are taken as unit (node.h); others are normalised. */
#include <stdio.h>

#include "common/sampling.h"
#include "ssao.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_ssao_params *p = params;
    if (p->mode == SSG_SSAO_MODE_HEMISPHERE && in[SSG_SSAO_IN_NORMAL].channels == 0) {
        snprintf(why, why_len, "needs input 'normal' (mode hemisphere orients its samples "
                 "by it; modes sphere and disc do not)");
        return SSG_E_MISSING_INPUT;
    }
    return ssg_sampling_check_ao(&in[SSG_SSAO_IN_POSITION], &in[SSG_SSAO_IN_NORMAL],
                                 &in[SSG_SSAO_IN_KERNEL], &in[SSG_SSAO_IN_ROTATION],
                                 &in[SSG_SSAO_IN_DEPTH], &in[SSG_SSAO_IN_COUNT], out, why,
                                 why_len);
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_ssao_consts *c = consts;
    c->p = *(const struct ssg_ssao_params *)params;
    enum ssg_err e =
        ssg_sampling_projection(ctx, &ctx->in_shape[SSG_SSAO_IN_POSITION], &c->proj);
    c->cap = c->p.max_screen_radius / c->proj.f;
    c->capped = c->p.max_screen_radius > 0.0f;
    c->inv_samples = 1.0f / (float)ctx->in_shape[SSG_SSAO_IN_KERNEL].width;
    return e;
}

static const char *const ssg_ssao_range_choices[] = {"none", "hard", "smooth", NULL};
static const char *const ssg_ssao_mode_choices[] = {"hemisphere", "sphere", "disc", NULL};
SSG_PARAMS_TABLE(params, ssg_ssao_params, SSG_SSAO_PARAMS);

SSG_PORT_TABLE(inputs, SSG_SSAO_IN);
SSG_PORT_TABLE(outputs, SSG_SSAO_OUT);

/* Flops per pixel (node.h), by reading ssao_cpu.c: per kernel sample about 38 (placing
   and projecting it: three 4-term affine forms, a division, rounding and bounds; the
   depth test, range check and sum), about 60 per pixel for its frame and the finish. */
static double ssao_flops(const void *consts, const struct ssg_shape *in)
{
    (void)consts;
    return 60.0 + 38.0 * in[SSG_SSAO_IN_KERNEL].width;
}

const struct ssg_node_desc ssg_node_ssao = {
    .name = "ssao",
    .summary = "screen-space ambient occlusion: normal hemisphere, normal-free sphere or "
               "screen-space disc",
    .method = "hemisphere: Szentandrasi, Modern Methods of Realistic Lighting in Real Time, "
              "sec. 3.1 and fig. 1; Belonogov, Global Illumination methods in simulated VR "
              "environments, sec. 3.2 (normal-oriented hemisphere, tiled rotation). "
              "sphere: Knuth and Kohlhammer, A Hybrid Ambient Occlusion Technique for "
              "Dynamic Scenes, sec. 4 local part, fig. 9 (normal-free sphere, denser "
              "towards the centre, averaged, clamped to [0,1]). disc: Mittring, Finding "
              "Next Gen - CryEngine 2 (SIGGRAPH 2007), in the screen-space disc form of "
              "Belonogov sec. 3.2.1",
    .doc = "mode hemisphere: kernel samples are placed in the hemisphere of radius `radius` "
           "around the normal (turned by the rotation tile), projected, and compared with "
           "the scene depth there: a sample is occluded when the surface is more than "
           "`bias` in front of it, weighted by the range check. Samples off screen, "
           "behind the camera or over background are unoccluded. out = (1 - occluded / "
           "count)^power. mode sphere: the same test on each kernel sample and its point "
           "reflection about the pixel (a sphere about the view axis, no normal); mode "
           "disc: depth samples at the kernel's (x, y) offsets and their opposites in a "
           "screen disc of radius f radius / depth, occluding when nearer than the pixel "
           "by more than `bias`. Both normal-free modes report clamp(2 (1 - occluded / "
           "samples), 0, 1)^power, so that half the sphere (an open plane) is 1 (Knuth "
           "and Kohlhammer's clamp). Background pixels are 1. With the count input a pixel "
           "uses only the first round(count) kernel samples (clamped to [1, kernel "
           "width]) and divides by that number.",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_ssao_params),
    .consts_size = sizeof(struct ssg_ssao_consts),
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = ssao_flops,
    .run_cpu = ssg_ssao_run_cpu,
    .run_gl = ssg_ssao_run_gl,
};
