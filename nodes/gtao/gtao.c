/* gtao.c - the `gtao` node: ground-truth ambient occlusion.
 *
 * Method: Jimenez, Wu, Pesce and Jarabo, "Practical Realtime Strategies for Accurate
 * Indirect Occlusion" (SIGGRAPH 2016 course; Activision tech. report ATVI-TR-16-01),
 * sec. 4: the cosine-weighted visibility
 *   V = (1 / pi) int_0^pi int_{h1(phi)}^{h2(phi)} cos(theta - n) |sin theta| dtheta dphi
 * is split into slices phi about the view vector V; within a slice, theta is the angle
 * from V, h1 <= 0 <= h2 the horizons on either side and n the angle of the normal
 * projected on the slice, whose length |proj N| weighs the slice. The inner integral is
 * closed form (sec. 4, "analytic inner integral"):
 *   a(h1, h2, n) = 1/4 (-cos(2 h1 - n) + cos n + 2 h1 sin n)
 *                + 1/4 (-cos(2 h2 - n) + cos n + 2 h2 sin n),
 * and the horizons are clamped to the hemisphere of the normal, h1 >= n - pi/2,
 * h2 <= n + pi/2 (sec. 4.1). Sample points come from the depth buffer (a height field);
 * sec. 4.3 "bounding the sampling area": only samples within `radius` R count, with a
 * linear fade over the last `falloff` R (XeGTAO's falloff range: the sample's horizon
 * cosine is blended towards the lowest one, cos(n -/+ pi/2), by its weight); sec. 4.3
 * "height-field assumption considerations": with `thickness` t > 0 a sample within reach
 * (weight > 0) lower than the horizon so far pulls it down, h <- h + t (sample - h) in
 * cosines (samples out of reach do not: that darkened every scene), so the horizon
 * recovers behind a thin occluder (t = 0: every depth sample is an infinitely thick
 * height field). This is the cosine-weighted, distance-limited visibility of
 * docs/analytic.md (1 = open) that reference_ao estimates by ray tracing.
 *
 * Geometry (view space, node.h) as in hbao.c: P the pixel's point, V = -P / |P|,
 * e1 = normalize(y x V) (per column, made here), e2 = V x e1; slice k has the direction
 * D = cos phi e1 + sin phi e2, phi = pi k / slices + psi (psi the rotation tile's angle
 * at (x mod n, y mod n); slices cover the half circle, each marched both ways),
 * M = V x D its plane's normal. The slice plane projects to the screen line through the
 * pixel along (su, sv) = (Dx + a_u Dz, -(Dy + a_v Dz)); step j = 0..steps-1 lies at
 * (j + u) f R / (den steps) (su, sv) px, den = max(depth - R, depth / 2), capped by
 * max_screen_radius, rounded to the nearest pixel (ties to even), both ways: hbao.c shows
 * this reaches every point of the slice within R. u in (0, 1] is the step jitter,
 * 1 - Jimenez's interleaved gradient noise at the pixel ("Next Generation Post
 * Processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014), computed by the same
 * float operations on both backends. A sample at pixel q gives Q from the depth at q
 * and H = Q - P; the rounding moves it up to half a pixel off the slice, and it is brought
 * back along the tangent plane (hbao_cpu.c place_step), so that a sample of P's own
 * plane lands exactly on the slice's tangent. Samples more off the slice than along it,
 * off screen or on background are skipped. The sample's horizon cosine is H'.V / |H'|;
 * its distance for the falloff is |H|.
 *
 * Normalisation (ours): with few slices the paper's mean of |proj N| a over slices is
 * not exactly 1 on an open tilted plane (it is 1 only in the limit of many slices). The
 * node divides the sum of |proj N| a by the sum of the same terms with the horizons at
 * the hemisphere's limits (the open value of each slice), which has the same limit, is
 * exactly 1 where nothing occludes (the same float operations on the same values) and
 * removes the per-pixel error of the slice quadrature from open regions.
 * Bent normal: the visibility-weighted mean direction of each slice (XeGTAO's closed
 * form, t0 D + t1 V weighted by |proj N|), summed and normalised; background 0.
 * out = clamp(ratio, 0, 1)^power; background pixels (depth 0 or no normal) get 1. Slices
 * within asin(0.1) of the tangent plane (|proj N|^2 < 0.01, near-grazing views) are
 * skipped, as in hbao.
 * Second depth layer (ours; `back` connected, e.g. gbuffer.back, +inf = nothing behind;
 * measured against reference_ao in docs/accuracy.md, "A second depth layer"):
 * a sample at pixel q stands for the solid segment of q's camera ray from its depth to
 * its back depth, and occludes exactly the directions from P that pass through that
 * segment: in the slice, the arc between its front point Q and its back point B (B on
 * q's ray; the cosine B.V / |B| <= Q's since angles from V grow along a ray away from the
 * eye), B taken no farther than where q's ray leaves the sphere of radius R about P
 * (occluders beyond R do not count, as in reference_ao), and +inf (a single-sided wall,
 * a floor) solid down to the hemisphere's limit, the height-field assumption. A side
 * keeps one occluded arc, the smallest that holds the arcs of all its samples that rise
 * above the tangent plane: from the highest front point (the horizon as before) down to
 * the lowest bottom, so a gap under a thin occluder (the floor under a table top) stays
 * open, while the gaps between occluders of one side are filled. Where the side's
 * previous sample (P itself for the first) lies no more than 0.3 R behind the sample's
 * back, the surface is taken to run on from it (a slanted face seen at a grazing angle,
 * whose depth changes faster between samples than its thickness) and the arc reaches
 * down to that sample. Visible = side(top) + side(lim) - side(bottom), each side's term
 * the closed form above (and its bent-normal terms alike); a bottom at the tangent plane
 * leaves exactly the horizon result, and back = +inf everywhere is gtao without back.
 * The `thickness` heuristic is the guess that back replaces: the two are refused
 * together.
 * Evaluation (both backends, gtao_cpu.c): the sample formulas are folded into per-step
 * coefficients affine in the sample's depth; acos is Abramowitz and Stegun's polynomial
 * 4.4.46 (|error| <= 2e-8), n = pi/2 - acos(sin n), and the terms in 2h - n, 3h - n,
 * h -/+ n come from cos h, sin h by the angle-sum formulas; with the defaults (no falloff,
 * no thickness) a side keeps its highest sample and takes one root per slice. */
#include <math.h>
#include <stdio.h>

#include "common/sampling.h"
#include "gtao.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_shape *pos = &in[SSG_GTAO_IN_POSITION], *back = &in[SSG_GTAO_IN_BACK];
    enum ssg_err e = ssg_sampling_check_ao(pos, &in[SSG_GTAO_IN_NORMAL], NULL,
                                           &in[SSG_GTAO_IN_ROTATION], &in[SSG_GTAO_IN_DEPTH],
                                           NULL, out, why, why_len);
    if (e)
        return e;
    if (back->channels != 0 && (back->channels != 1 || !ssg_shape_same_size(back, pos))) {
        snprintf(why, why_len, "back must be a 1-channel image the size of position");
        return SSG_E_SIZE;
    }
    if (back->channels != 0 && ((const struct ssg_gtao_params *)params)->thickness > 0) {
        snprintf(why, why_len, "thickness (a guess at how thick occluders are) and back "
                 "(how thick they are) answer one question: give one");
        return SSG_E_VALUE;
    }
    out[SSG_GTAO_OUT_BENT_NORMAL] =
        (struct ssg_shape){pos->width, pos->height, 3, SSG_T_VECTOR};
    return SSG_OK;
}

/* The consts with e1 for the G-buffer's columns. */
static size_t consts_size_of(const void *params, const struct ssg_shape *in)
{
    return sizeof(struct ssg_gtao_consts) + 2 * (size_t)in[SSG_GTAO_IN_POSITION].width *
                                                sizeof(float);
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_gtao_consts *c = consts;
    const struct ssg_gtao_params *q = &c->p;
    c->p = *(const struct ssg_gtao_params *)params;
    const struct ssg_shape *pos = &ctx->in_shape[SSG_GTAO_IN_POSITION];
    enum ssg_err e = ssg_sampling_projection(ctx, pos, &c->proj);
    ssg_sampling_column_basis(&c->proj, pos->width, c->e1);
    c->invf = 1.0f / c->proj.f;
    /* XeGTAO's fade: w = 1 up to (1 - falloff) R, 0 at R: w = r mul + add. */
    float range = q->falloff * q->radius;
    c->fall_mul = q->falloff > 0 ? -1.0f / range : 0.0f;
    c->fall_add = q->falloff > 0 ? q->radius / range : 1.0f;
    c->link = SSG_GTAO_BACK_LINK * q->radius;
    for (int k = 0; k < q->slices; k++) {
        double a = M_PI * k / q->slices;
        c->slice_cos[k] = (float)cos(a);
        c->slice_sin[k] = (float)sin(a);
    }
    return e;
}

SSG_PARAMS_TABLE(params, ssg_gtao_params, SSG_GTAO_PARAMS);

SSG_PORT_TABLE(inputs, SSG_GTAO_IN);
SSG_PORT_TABLE(outputs, SSG_GTAO_OUT);

/* Flops per pixel (node.h), by reading gtao_cpu.c: per slice about 70 (its frame and the
   arc integral's polynomials), per step of each side about 22, about 40 per pixel. */
static double gtao_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_gtao_consts *c = consts;
    (void)in;
    return 40.0 + c->p.slices * (70.0 + 2.0 * 22.0 * c->p.steps);
}

const struct ssg_node_desc ssg_node_gtao = {
    .name = "gtao",
    .summary = "ground-truth (horizon-based, cosine-weighted) ambient occlusion",
    .method = "Jimenez, Wu, Pesce and Jarabo, Practical Realtime Strategies for Accurate "
              "Indirect Occlusion (SIGGRAPH 2016), sec. 4: slices about the view vector, "
              "two horizons per slice clamped to the normal's hemisphere, the analytic "
              "cosine-weighted inner integral weighted by the projected normal's length; "
              "sec. 4.3 distance falloff and thickness heuristic",
    .doc = "For each pixel, `slices` slice directions over the half circle about the view "
           "vector (turned by the rotation tile) are marched on screen both ways with "
           "`steps` depth samples each, far enough to reach every point of the slice "
           "within `radius`. Each side keeps its horizon (the highest sample within "
           "`radius`, faded over the last `falloff` of it; with `thickness` > 0 a lower "
           "sample pulls the horizon down), clamped to the normal's hemisphere. The "
           "closed-form cosine-weighted integral between the two horizons, weighted by "
           "the length of the normal projected on the slice, is summed over slices and "
           "divided by the same sum with open horizons, so an open surface is exactly 1. "
           "out = clamp(that, 0, 1)^power; background pixels are 1. With `back` (the depth "
           "of the next surface behind each pixel, gbuffer.back) a sample occludes only "
           "the directions through its real thickness, between its front and its back "
           "point (the back clipped to `radius`; +inf = solid, the height-field "
           "assumption): a side keeps the arc from its highest front point down to the "
           "lowest back point of the samples that rise above the tangent plane (down to "
           "the previous sample where the surface runs on from it), and the visible part "
           "is the rest of the side, so the floor under a thin table top sees past it "
           "(thickness must then be 0). bent_normal is the "
           "normalised visibility-weighted mean direction (background 0). CPU and GL "
           "agree within 2e-4 on both outputs (tests/test_gl_gtao.c; both evaluate the "
           "same operations, acos as a polynomial, so only sqrt, division and pow may "
           "round differently).",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_gtao_params),
    .consts_size_of = consts_size_of,
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = gtao_flops,
    .run_cpu = ssg_gtao_run_cpu,
    .run_gl = ssg_gtao_run_gl,
};
