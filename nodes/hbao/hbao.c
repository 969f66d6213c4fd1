/* hbao.c - the `hbao` node: horizon-based screen-space ambient occlusion.
 *
 * Method: Bavoil, Sainz and Dimitrov, "Image-Space Horizon-Based Ambient Occlusion"
 * (SIGGRAPH 2008 talk), as described by Belonogov, "Global Illumination methods in
 * simulated VR environments", section 3.3.1, eq. 3.1 and 3.2:
 *   A = 1 - 1/(2 pi) int_{-pi}^{pi} (sin h(theta) - sin t(theta)) W(theta) dtheta,
 * theta the azimuth about the view vector, t the signed elevation of the surface tangent,
 * h the elevation of the horizon (the highest point of the depth buffer, seen as a height
 * field, within R), W = max(0, 1 - r / R), r the distance from P to the horizon point.
 * The integral is estimated with `directions` azimuths per pixel, each ray-marched with
 * `steps` depth samples: as section 3.3.1 describes, a sample higher than the highest so
 * far raises the horizon and adds its own term, "every individual ambient occlusion
 * factors for each sample are accumulated": (sin h_j - sin h_{j-1}) W(r_j), from
 * h_0 = t + bias; lower samples are skipped. With falloff = none (W = 1 within R) the
 * terms telescope to eq. 3.2's sin h - sin t for the highest sample within R.
 * The azimuths are turned per pixel by the tiled rotation pattern (section 3.3.1: HBAO
 * inherits SSAO's rotation noise, removed by a blur afterwards).
 *
 * Geometry (view space, node.h). P is the pixel's point, V = -P / |P| the unit vector to
 * the eye. Azimuths are uniform about V: D(theta) = cos theta e1 + sin theta e2 with
 * e1 = normalize(y x V) (horizontal) and e2 = V x e1, theta_k = 2 pi k / directions + psi,
 * psi the pattern's angle at (x mod n, y mod n) (0 without a pattern). The plane through
 * the eye spanned by V and D projects to one screen line through the pixel, along
 * J D (J the projection's Jacobian at P), so marching that line visits exactly the
 * points of the slice: the sampled occluders and the angles of eq. 3.2 live in one plane.
 * A sample at pixel q gives Q, reconstructed from the depth at q and the camera (as HBAO
 * reconstructs from the depth buffer; P likewise, so a sample on P's own pixel gives
 * Q = P exactly), and H = Q - P. Rounding to pixel centres moves samples off the line by
 * up to half a pixel; H is brought back onto the slice along the tangent plane (not
 * orthogonally, see hbao_cpu.c place_step), giving H', and sin h = H'.V / r,
 * r = |H'| = sqrt((H'.V)^2 + (H'.D)^2). The tangent of the slice is the direction in it
 * perpendicular to the normal N: sin t = -(D.N) / sqrt((V.N)^2 + (D.N)^2). Any sample of
 * the tangent plane thus has h = t up to float rounding, whatever the rounding to
 * pixels: a flat plane gives exactly 1 once bias exceeds float rounding. Samples the
 * rounding moved more off the slice than along it are skipped, and so are slices within
 * 6 degrees of the tangent plane (V.N < 0.1, near-grazing views), where the tangent line
 * is ill-conditioned.
 * Because the slices are uniform in azimuth about V and cos(alpha) dalpha dtheta in
 * eq. 3.1 is the solid angle, with falloff = none and many directions and steps the node
 * tends to 1 - (solid angle above the tangent plane occluded within R) / (2 pi) when the
 * occluders are height fields: uniform weighting, not cosine weighting. For a floor at
 * distance a from an infinite wall that is (1 + a/R) / 2 for a < R (tests/test_hbao.c
 * derives it), where the cosine-weighted docs/analytic.md case 3 gives
 * 1 - (acos c - c sqrt(1 - c^2)) / pi, c = a/R: both 1/2 at the edge, both 1 at a >= R,
 * the uniform weighting darker in between (0.8 against 0.858 at c = 0.6).
 *
 * March: step j = 0..steps-1 lies at (j + u) step (su, sv) px from P's pixel, rounded to
 * the nearest pixel (ties to even), where (su, sv) = (Dx + a_u Dz, -(Dy + a_v Dz)) is the
 * screen direction of D scaled so that a displacement beta D at depth d' moves the image
 * by f beta |(su, sv)| / (d' - beta Dz) px, and step = f R / (den steps),
 * den = max(depth - R, depth / 2). A point of the slice within R of P has depth at least
 * depth - R, so it lies within f R |(su, sv)| / (depth - R) px of P's pixel: the march
 * covers every point of the slice within R unless the camera is nearly inside the
 * sphere (depth < 2 R, where den is floored); max_screen_radius > 0 caps f R / den.
 * u in (0, 1] is the step jitter: 1 without a pattern, else 1 - frac(phi / 2 pi), phi
 * the pattern's angle half a tile away ((x + n/2) mod n, (y + n/2) mod n), so direction
 * and step jitter come from different cells. Samples off screen, on background
 * (depth 0) or beyond R (r > R) are skipped. The horizon starts at t + bias (Bavoil's
 * angle bias against the self-occlusion of tessellated or noisy surfaces; 0.1 rad ~
 * 5.7 degrees; t + bias beyond pi/2 means no occlusion in that slice).
 * out = clamp(1 - strength * mean over directions of the accumulated terms, 0, 1);
 * background pixels (depth 0 or no normal) get 1.
 *
 * Per-pixel counts (optional `count` input; Szentandrasi section 4.3, the `complexity`
 * node): hbao has no sample kernel, so the count is the number of DIRECTIONS pixel i uses:
 * n_i = round(count_i) (half up) clamped to [1, directions] (NaN = all), and the mean is
 * over those n_i. The directions are taken in an order whose prefixes spread round the
 * circle: with an even number the opposite pairs (k, k + directions/2) stay together
 * (ranks 2r, 2r + 1) and the pairs are ordered by farthest-point insertion on the half
 * circle (each next pair the one farthest in angle from those before, ties to the
 * lowest k); with an odd number the directions themselves are ordered so on the full
 * circle. For directions = 2^m every prefix of 2^j directions is exactly the set of
 * directions = 2^j (angles 2 pi k / 2^j, summed in the same order): counts 1, 2, 4, 8 of
 * 8 directions give the bits of directions = 1, 2, 4, 8. Other counts use a prefix that is
 * as even as the order allows (3 of 8: 0, 180 and 90 degrees). Unconnected: all. */
#include <math.h>

#include "common/sampling.h"
#include "hbao.h"

/* Farthest-point order of m positions on a circle of m (distance min(|a - b|,
   m - |a - b|)), starting at 0, ties to the lowest index: order[r] is the r-th. */
static void spread_order(int m, int *order)
{
    int used[SSG_HBAO_MAX_DIRECTIONS] = {0};
    order[0] = 0;
    used[0] = 1;
    for (int r = 1; r < m; r++) {
        int best = -1, best_dist = -1;
        for (int k = 0; k < m; k++) {
            int dist = m;
            for (int q = 0; !used[k] && q < r; q++) {
                int d = k > order[q] ? k - order[q] : order[q] - k;
                d = d < m - d ? d : m - d;
                dist = d < dist ? d : dist;
            }
            if (!used[k] && dist > best_dist)
                best = k, best_dist = dist;
        }
        order[r] = best;
        used[best] = 1;
    }
}

/* dir_rank of the consts (file header): pairs ranked on the half circle, or directions
   on the whole circle when their number is odd. */
static void rank_directions(int nd, int *rank)
{
    int order[SSG_HBAO_MAX_DIRECTIONS];
    if (nd % 2 == 0) {
        spread_order(nd / 2, order);
        for (int r = 0; r < nd / 2; r++) {
            rank[order[r]] = 2 * r;
            rank[order[r] + nd / 2] = 2 * r + 1;
        }
    } else {
        spread_order(nd, order);
        for (int r = 0; r < nd; r++)
            rank[order[r]] = r;
    }
}

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    return ssg_sampling_check_ao(&in[SSG_HBAO_IN_POSITION], &in[SSG_HBAO_IN_NORMAL], NULL,
                                 &in[SSG_HBAO_IN_ROTATION], &in[SSG_HBAO_IN_DEPTH],
                                 &in[SSG_HBAO_IN_COUNT], out, why, why_len);
}

/* The consts with e1 for the G-buffer's columns. */
static size_t consts_size_of(const void *params, const struct ssg_shape *in)
{
    return sizeof(struct ssg_hbao_consts) + 2 * (size_t)in[SSG_HBAO_IN_POSITION].width *
                                                sizeof(float);
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_hbao_consts *c = consts;
    const struct ssg_hbao_params *q = &c->p;
    c->p = *(const struct ssg_hbao_params *)params;
    const struct ssg_shape *pos = &ctx->in_shape[SSG_HBAO_IN_POSITION];
    enum ssg_err e = ssg_sampling_projection(ctx, pos, &c->proj);
    ssg_sampling_column_basis(&c->proj, pos->width, c->e1);
    c->invf = 1.0f / c->proj.f;
    c->rf = c->proj.f * q->radius;
    c->r2 = q->radius * q->radius;
    c->inv_radius = 1.0f / q->radius;
    c->inv_steps = 1.0f / (float)q->steps;
    c->scale = q->strength / (float)q->directions;
    c->cos_bias = (float)cos(q->bias);
    c->sin_bias = (float)sin(q->bias);
    for (int k = 0; k < q->directions; k++) {
        double a = 2.0 * M_PI * k / q->directions;
        c->dir_cos[k] = (float)cos(a);
        c->dir_sin[k] = (float)sin(a);
    }
    rank_directions(q->directions, c->dir_rank);
    return e;
}

static const char *const ssg_hbao_falloff_choices[] = {"linear", "none", NULL};
SSG_PARAMS_TABLE(params, ssg_hbao_params, SSG_HBAO_PARAMS);

SSG_PORT_TABLE(inputs, SSG_HBAO_IN);
SSG_PORT_TABLE(outputs, SSG_HBAO_OUT);

/* Flops per pixel (node.h), by reading hbao_cpu.c: per direction about 20 for its step
   and tangent, per step about 25 (place, index, the horizon's tangent, falloff, max),
   about 40 per pixel for its frame and the finish. */
static double hbao_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_hbao_consts *c = consts;
    (void)in;
    return 40.0 + c->p.directions * (20.0 + 25.0 * c->p.steps);
}

const struct ssg_node_desc ssg_node_hbao = {
    .name = "hbao",
    .summary = "horizon-based screen-space ambient occlusion",
    .method = "Bavoil, Sainz and Dimitrov, Image-Space Horizon-Based Ambient Occlusion "
              "(SIGGRAPH 2008), as in Belonogov, Global Illumination methods in simulated "
              "VR environments, sec. 3.3.1, eq. 3.1-3.2 (W = max(0, 1 - r/R), per-sample "
              "horizon terms, angle bias, rotated directions)",
    .doc = "For each pixel, `directions` slices uniform in azimuth about the view vector "
           "(turned by the rotation tile) are marched on screen with `steps` depth samples "
           "each, far enough to reach every point of the slice within `radius`. Each "
           "sample within `radius` that rises above the horizon so far (at first the "
           "tangent's elevation t + `bias`) adds (sin h_j - sin h_{j-1}) W(r_j), W = "
           "1 - r/R (falloff linear) or 1 (none: the slice adds sin h - sin(t + bias)). "
           "out = clamp(1 - strength * mean over slices, 0, 1); background pixels are 1. "
           "A flat open plane gives exactly 1. With the count input a pixel uses only its "
           "first round(count) directions (clamped to [1, directions]) in an order whose "
           "prefixes spread round the circle (for 8: 0, 180, 90, 270, 45, ... degrees) and "
           "averages over those.",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_hbao_params),
    .consts_size_of = consts_size_of,
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = hbao_flops,
    .run_cpu = ssg_hbao_run_cpu,
    .run_gl = ssg_hbao_run_gl,
};
