/* ssilvb.c - the `ssilvb` node: screen-space indirect lighting with a visibility bitmask.
 *
 * Method: Therrien, Levesque and Gilet, "Screen Space Indirect Lighting with Visibility
 * Bitmask" (2023, arXiv 2301.11376), the successor of GTAO (Jimenez et al. 2016, our
 * nodes/gtao). The slice march is gtao's (gtao.c: slices about the view vector V, each
 * marched both ways along its screen line, samples brought back onto the slice along the
 * tangent plane, the normal's projected angle n and length |proj N|). What changes is what
 * a slice keeps: instead of two horizons, a bitmask of 32 sectors of the hemisphere
 * slice [n - pi/2, n + pi/2] (paper sec. 3.2), and a sample does not occlude everything
 * below it but only the sectors between its front point Q and its back point Q_b (sec. 3.3,
 * "thickness"): Q_b is Q's ray at the depth `back` reads at the sample's pixel (the second
 * surface behind the first), or, with `back` unconnected or not behind Q, at Q's depth
 * plus the constant `thickness`. Light passes behind a thin occluder; a solid one (back far
 * behind) is a horizon again.
 * Sectors of equal cosine-weighted measure (ours; the paper spaces them uniformly in
 * angle and leaves the cosine weighting to the integration): with theta the angle from V
 * in the slice and the cumulative slice measure
 *   C(theta) = int_0^theta cos(t - n) |sin t| dt = 1/2 (sg cos n sin^2 theta
 *              + sin n (acos(cos theta) - |sin theta| cos theta)),   sg = sign theta,
 * (gtao.c's inner integral), a direction maps to u = (C(theta) - C(n - pi/2)) / A in
 * [0, 1], A = C(n + pi/2) - C(n - pi/2) = cos n + n sin n the slice's open measure;
 * directions past the hemisphere clamp to 0 or 1. A sample marks the sectors whose centres
 * lie in [min(u_Q, u_Qb), max(u_Q, u_Qb)] (rounded to the nearest sector edge, not up as
 * the paper's ceil does: a sample of the pixel's own plane, on the tangent up to float
 * rounding, then marks none). Each set bit is 1/32 of the slice's cosine-weighted measure.
 * ao: the sum over slices of |proj N| A (32 - popcount(mask)) / 32 divided by the sum of
 *   |proj N| A: the cosine-weighted, distance-limited visibility of docs/analytic.md
 *   (1 = open), exactly 1 where no bit is set; ao = that^power, background 1.
 * bounce (sec. 3.4): a sample that newly sets bits (not set by a nearer sample of its
 *   slice) sends its `light` L_q through them when its surface faces the pixel
 *   (N_q . (P - Q) > 0; its back is not lit): the received radiance times cos over
 *   those directions is pi L_q (bits / 32) A / sum, so albedo / pi times the received
 *   irradiance is bounce = strength albedo sum_slices |proj N| A sum_q L_q bits_q / 32
 *   / sum |proj N| A, the meaning of ssdo's bounce (albedo sum F L), for `combine`'s
 *   indirect input. The paper weights a sender by its own cosine as well; a Lambertian
 *   sender's radiance does not depend on the direction, so we only test which side faces.
 * Samples count within `radius` R of P (|Q - P| <= R), off screen and on background never.
 * Per-pixel slice rotation and step jitter: Jimenez's interleaved gradient noise ("Next
 * Generation Post Processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014), for the
 * rotation at the pixel shifted by seed-derived offsets, for the jitter at the transposed
 * pixel (another linear form, so the two are not locked) shifted by two other offsets;
 * the rotation is one of 64 turns pi (j + 1/2) / (64 slices) tabulated here, the jitter u
 * in (0, 1] moves step s to (s + u) of the step length. The same float operations on both
 * backends. Evaluation in ssilvb_cpu.c; ssilvb.glsl performs the same operations. */
#include <math.h>
#include <stdio.h>

#include "common/random.h"
#include "common/sampling.h"
#include "ssilvb.h"

static int color_like(const struct ssg_shape *s, const struct ssg_shape *pos)
{
    return s->channels == 3 && ssg_shape_same_size(s, pos);
}

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    (void)params, (void)frame;
    const struct ssg_shape *pos = &in[SSG_SSILVB_IN_POSITION], *nrm = &in[SSG_SSILVB_IN_NORMAL];
    if (pos->channels != 3 || !color_like(nrm, pos)) {
        snprintf(why, why_len, "position and normal must be 3-channel images of one size");
        return SSG_E_SIZE;
    }
    if (!color_like(&in[SSG_SSILVB_IN_LIGHT], pos) ||
        !color_like(&in[SSG_SSILVB_IN_ALBEDO], pos)) {
        snprintf(why, why_len, "light and albedo must be 3-channel images the size of "
                               "position");
        return SSG_E_SIZE;
    }
    const struct ssg_shape *back = &in[SSG_SSILVB_IN_BACK];
    if (back->channels != 0 && (back->channels != 1 || !ssg_shape_same_size(back, pos))) {
        snprintf(why, why_len, "back must be a 1-channel image the size of position");
        return SSG_E_SIZE;
    }
    struct ssg_shape none = {0};
    enum ssg_err e = ssg_sampling_check_inputs(pos, NULL, &none, &in[SSG_SSILVB_IN_DEPTH],
                                               NULL, why, why_len);
    if (e)
        return e;
    out[SSG_SSILVB_OUT_AO] = (struct ssg_shape){pos->width, pos->height, 1, SSG_T_SCALAR};
    out[SSG_SSILVB_OUT_BOUNCE] = (struct ssg_shape){pos->width, pos->height, 3, SSG_T_COLOR};
    return SSG_OK;
}

/* The seed's pattern offsets (whole pixels below 1024: the noise's float arithmetic
   stays as exact as at the origin) and the turn and slice tables. */
static void prepare_tables(const struct ssg_node_ctx *ctx, struct ssg_ssilvb_consts *c)
{
    uint64_t state = (ctx->frame ? ctx->frame->seed : 1) ^ 0xA54FF53A5F1D36F1ull;
    for (int i = 0; i < 4; i++)
        c->noise_off[i] = (float)(ssg_splitmix64(&state) % 1024u);
    for (int k = 0; k < c->p.slices; k++) {
        double a = M_PI * k / c->p.slices;
        c->slice_cos[k] = (float)cos(a);
        c->slice_sin[k] = (float)sin(a);
    }
    for (int j = 0; j < SSG_SSILVB_TURNS; j++) {
        double a = M_PI * (j + 0.5) / (SSG_SSILVB_TURNS * (double)c->p.slices);
        c->turn_cos[j] = (float)cos(a);
        c->turn_sin[j] = (float)sin(a);
    }
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_ssilvb_consts *c = consts;
    c->p = *(const struct ssg_ssilvb_params *)params;
    const struct ssg_ssilvb_params *q = &c->p;
    /* prepare() may be reached without the table's range checks (a hand-built run). */
    if (!(q->radius > 0) || q->slices < 1 || q->slices > SSG_SSILVB_MAX_SLICES ||
        q->steps < 1 || q->steps > SSG_SSILVB_MAX_STEPS || !(q->thickness >= 0) ||
        !(q->power > 0) || !(q->strength >= 0) || !(q->max_screen_radius >= 0))
        return ssg_node_fail(ctx, SSG_E_VALUE, "needs radius > 0, 1..%d slices, 1..%d "
                             "steps, thickness >= 0, power > 0, strength >= 0",
                             SSG_SSILVB_MAX_SLICES, SSG_SSILVB_MAX_STEPS);
    const struct ssg_shape *pos = &ctx->in_shape[SSG_SSILVB_IN_POSITION];
    enum ssg_err e = ssg_sampling_projection(ctx, pos, &c->proj);
    if (e)
        return e;
    ssg_sampling_column_basis(&c->proj, pos->width, c->e1);
    prepare_tables(ctx, c);
    return SSG_OK;
}

static const struct ssg_param_desc params[] = {
    {.name = "slices", SSG_FIELD_INT(struct ssg_ssilvb_params, slices), .def = 4, .min = 1,
     .max = SSG_SSILVB_MAX_SLICES,
     .help = "slice directions per pixel over the half circle about the view vector, "
             "each marched both ways (turned per pixel by the noise)"},
    {.name = "steps", SSG_FIELD_INT(struct ssg_ssilvb_params, steps), .def = 12, .min = 1,
     .max = SSG_SSILVB_MAX_STEPS, .help = "depth samples on each side of a slice"},
    {.name = "radius", SSG_FIELD_FLOAT(struct ssg_ssilvb_params, radius), .def = 2,
     .min = 1e-6, .max = 1e6, .unit = "scene units",
     .help = "R: samples farther than this from the pixel neither occlude nor send light"},
    {.name = "thickness", SSG_FIELD_FLOAT(struct ssg_ssilvb_params, thickness), .def = 0.5,
     .min = 0, .max = 1e6, .unit = "scene units",
     .help = "depth of every occluder behind its front surface, where `back` is "
             "unconnected or not behind it"},
    {.name = "power", SSG_FIELD_FLOAT(struct ssg_ssilvb_params, power), .def = 2.5,
     .min = 0.1, .max = 8,
     .help = "ao = visibility^power (screen space misses what lies beyond the radius "
             "or off screen; 2.5 measured against reference_gi)"},
    {.name = "strength", SSG_FIELD_FLOAT(struct ssg_ssilvb_params, strength), .def = 1.2,
     .min = 0, .max = 16,
     .help = "scale of the bounce (1.2 measured against reference_gi: senders off "
             "screen or beyond the radius are missing)"},
    {.name = "max_screen_radius", SSG_FIELD_FLOAT(struct ssg_ssilvb_params, max_screen_radius),
     .def = 0, .min = 0, .max = 16384, .unit = "px",
     .help = "caps the projected radius f R / (depth - R) of the march; 0 = no cap"},
};

static const struct ssg_port_desc inputs[] = {
    [SSG_SSILVB_IN_POSITION] = {.name = "position", .types = SSG_T_VECTOR,
     .doc = "view-space position (its -z is the depth unless depth is given)"},
    [SSG_SSILVB_IN_NORMAL] = {.name = "normal", .types = SSG_T_VECTOR,
     .doc = "unit view-space normal"},
    [SSG_SSILVB_IN_DEPTH] = {.name = "depth", .types = SSG_T_SCALAR, .optional = 1,
     .doc = "linear depth the points are reconstructed from; none = -position.z"},
    [SSG_SSILVB_IN_LIGHT] = {.name = "light", .types = SSG_T_COLOR,
     .doc = "outgoing radiance of each pixel, the bounce's senders (as ssdo's light)"},
    [SSG_SSILVB_IN_ALBEDO] = {.name = "albedo", .types = SSG_T_COLOR,
     .doc = "diffuse albedo of the receiver"},
    [SSG_SSILVB_IN_BACK] = {.name = "back", .types = SSG_T_SCALAR, .optional = 1,
     .doc = "linear depth of the second surface behind the first along the pixel's ray; "
            "none (or not behind) = depth + thickness"},
};
_Static_assert(SSG_COUNT(inputs) == SSG_SSILVB_INPUTS, "one entry a port enumerator");

static const struct ssg_port_desc outputs[] = {
    [SSG_SSILVB_OUT_AO] = {.name = "ao", .types = SSG_T_SCALAR,
     .doc = "cosine-weighted visibility within radius from the sector bitmasks, "
            "1 = unoccluded"},
    [SSG_SSILVB_OUT_BOUNCE] = {.name = "bounce", .types = SSG_T_COLOR,
     .doc = "one indirect bounce from the on-screen senders, albedo / pi x received "
            "irradiance (as ssdo's bounce)"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_SSILVB_OUTPUTS, "one entry a port enumerator");

/* Flops per pixel (node.h), by reading ssilvb_cpu.c: per slice about 60 (its frame, the
   open measure), per step of each side about 75 (two points, two arc measures with their
   acos polynomials, the bits, the sender), about 50 per pixel. */
static double ssilvb_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_ssilvb_consts *c = consts;
    (void)in;
    return 50.0 + c->p.slices * (60.0 + 2.0 * 75.0 * c->p.steps);
}

const struct ssg_node_desc ssg_node_ssilvb = {
    .name = "ssilvb",
    .summary = "screen-space indirect lighting and ambient occlusion with visibility "
               "bitmasks (GTAO slices, thick occluders)",
    .method = "Therrien, Levesque and Gilet, Screen Space Indirect Lighting with Visibility "
              "Bitmask (2023, arXiv 2301.11376), sec. 3: GTAO's slices with a 32-sector "
              "bitmask per slice, occluders of finite thickness, one bounce through the "
              "sectors a sample newly occludes; sectors of equal cosine-weighted measure",
    .doc = "For each pixel, `slices` slice directions over the half circle about the view "
           "vector (turned per pixel by interleaved gradient noise shifted by the seed) are "
           "marched on screen both ways with `steps` jittered depth samples, as gtao does. "
           "Each sample within `radius` is an occluder from its depth to its back (the "
           "`back` input, or depth + `thickness`) and marks the sectors of its slice's "
           "32-bit mask between its front and back directions; sectors have equal "
           "cosine-weighted measure, so ao = sum of |proj N| A (unset bits / 32) over the "
           "sum of |proj N| A (A the slice's open measure), ^power; exactly 1 when nothing "
           "occludes, background 1. A sample's newly set bits receive its `light` when its "
           "surface faces the pixel: bounce = strength albedo sum |proj N| A sum L bits / "
           "32 / sum |proj N| A (background 0). CPU and GL evaluate the same operations in "
           "the same order and agree within 2e-6 (tests/test_gl_ssilvb.c, llvmpipe: "
           "identical but where pow rounds; a GL whose sqrt or division rounds "
           "differently could move a sector boundary, 1/32 of a slice).",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_ssilvb_params),
    .consts_size = sizeof(struct ssg_ssilvb_consts),
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = ssilvb_flops,
    .run_cpu = ssg_ssilvb_run_cpu,
    .run_gl = ssg_ssilvb_run_gl,
};
