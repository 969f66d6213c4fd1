/* reference_gi.c - the `reference_gi` node: path-traced ground truth for SSDO, direct light
 * with true shadows plus exactly one diffuse bounce, traced through the scene with Embree
 * from every G-buffer point.
 *
 * Method: the rendering equation (Belonogov, "Global Illumination methods in simulated VR
 * environments", sec. 2.1, eq. 2.1) for a Lambertian surface, f = rho / pi, truncated
 * after one bounce: exactly the two integrals SSDO approximates in screen space
 * (Szentandrasi, "Modern Methods of Realistic Lighting in Real Time", sec. 3.2.1 eq. 1,
 * direct light with the visibility V, and sec. 3.2.2 eq. 3, the indirect radiance of the
 * surfaces a direction meets, lit by their own direct light), here with V and the
 * senders found by ray casting instead of the depth buffer. Both outputs are radiance
 * towards the camera (eq. 1 without its leading 1/pi, which the rendering equation does
 * not have). Diffuse only: the materials' Blinn-Phong specular term is ignored, in the
 * direct term and at the bounce's end, since SSDO models diffuse transport alone.
 *
 * For the G-buffer point x (world position p, unit normal n, albedo rho):
 *   direct = rho / pi * E(x), E the irradiance from
 *   - each point light: colour * intensity * max(0, n.L) / d^2 * V (one shadow ray);
 *   - each directional light: colour * intensity * max(0, n.L) * V, L = -direction;
 *   - the environment: 1/N sum L(w_i) max(0, n.w_i) V(w_i) / pdf(w_i), N = samples
 *     directions drawn by ssg_env_sample (importance sampling of the probe by luminance,
 *     uniform over the sphere for a constant colour; Pharr, Jakob and Humphreys,
 *     "Physically Based Rendering", 3rd ed., sec. 13.6.7 and 14.2.1), shadow ray to
 *     infinity. Directions under the surface weigh 0 and are not traced.
 *   bounce = rho / N sum L_out(y_i): N cosine-weighted directions w_i (pdf cos / pi, which
 *   cancels the rendering equation's cos / pi), y_i the nearest surface on each,
 *   L_out(y) = rho_y / pi * E_y with E_y y's irradiance from the same lights, each by one
 *   shadow ray, and the environment by ONE ssg_env_sample draw per path (unbiased; the
 *   paths of a pixel draw different, stratified directions). A path that escapes adds
 *   nothing: the environment seen directly is the direct term's. At y the normal is the
 *   scene's shading normal (interpolated, as the G-buffer's default), normalised and
 *   turned to face the arriving ray; albedo is material times texture (nodes/common/surface.h).
 *   out = direct + bounce. Background pixels (normal 0) are 0 in every output.
 *
 * Sampling (quasi-Monte Carlo, Szentandrasi sec. 4.2, eq. 5-7): the Hammersley set
 * (i / n, phi2(i), phi3(i), phi5(i)), i < n = samples, phi_b the radical inverse in base b.
 * The environment samples of the direct term take (i / n, phi2(i)); the bounce directions
 * take the same pair through Malley's method (PBRT sec. 13.6.3: the disk point sqrt(u)
 * (cos 2 pi v, sin 2 pi v) lifted to the hemisphere, cos^2 theta = 1 - u), and path i's
 * environment sample at its end takes (phi3(i), phi5(i)), so a pixel's bounce directions
 * and their light samples are stratified jointly in 4D. Each use gets its own per-pixel
 * Cranley-Patterson rotation (x + shift) mod 1, the shifts from a hash of (x, y, seed):
 * stratified within a pixel, decorrelated noise between pixels (for the Malley pair the
 * shift of v is a turn of the tangent frame, as in reference_ao, so the table's cos and
 * sin serve every pixel). Tangent frames: Duff et al., "Building an Orthonormal Basis,
 * Revisited" (JCGT 2017). A pixel depends only on (x, y, seed, samples) and its inputs,
 * never on the threads. The Hammersley disk, the hash, the frame and the ray origin at x
 * are nodes/common/trace.h's, shared with reference_ao.
 *
 * Geometry (as reference_ao.c): world = eye + R^T view, R the rotation of
 * ssg_camera_view_matrix. Rays from x start at o = p + e (n + v), v the unit vector to the
 * camera; rays from a bounce hit y at y + e_y (n_y - w), w the unit direction the path
 * arrived along, so each origin lies off its surface and in the free space the arriving
 * ray crossed (which keeps it off an adjacent surface at a concave edge). e = max(offset,
 * 1024 float ulps of the point's largest coordinate or distance). The light's geometry
 * (n.L, d^2) is evaluated at p and y themselves, so an unshadowed point gets exactly the
 * gbuffer node's diffuse term. A point light's shadow ray runs from the origin to the
 * light (t in [0, 1] of the unnormalised direction); others run to infinity. */
#include <stdio.h>

#include "scene/env.h"
#include "reference_gi.h"
#include "scene/scene.h"
#include "common/trace.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    (void)params, (void)frame;
    const struct ssg_shape *pos = &in[SSG_REFERENCE_GI_IN_POSITION];
    const struct ssg_shape *nrm = &in[SSG_REFERENCE_GI_IN_NORMAL];
    const struct ssg_shape *alb = &in[SSG_REFERENCE_GI_IN_ALBEDO];
    if (pos->channels != 3 || nrm->channels != 3 || alb->channels != 3 ||
        !ssg_shape_same_size(pos, nrm) || !ssg_shape_same_size(pos, alb)) {
        snprintf(why, why_len, "position, normal and albedo must be 3-channel images of one "
                 "size");
        return SSG_E_SIZE;
    }
    /* Runs at the G-buffer's resolution. */
    for (int i = 0; i < 3; i++)
        out[i] = (struct ssg_shape){pos->width, pos->height, 3, SSG_T_COLOR};
    return SSG_OK;
}

/* The Hammersley tables of n points (header comment). */
static void make_table(struct ssg_reference_gi_table *t, int n)
{
    ssg_hammersley_disk(n, t->u, t->c, t->s);
    for (int i = 0; i < n; i++) {
        t->v[i] = (float)ssg_radical_inverse((uint32_t)i, 2);
        t->e1[i] = (float)ssg_radical_inverse((uint32_t)i, 3);
        t->e2[i] = (float)ssg_radical_inverse((uint32_t)i, 5);
    }
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_reference_gi_consts *c = consts;
    const struct ssg_scene *s = ctx->scene;
    c->p = *(const struct ssg_reference_gi_params *)params;
    enum ssg_err e = ssg_trace_camera(ctx, c->rot, c->eye);
    if (e)
        return e;
    if (c->p.samples < 1 || c->p.samples > SSG_REFERENCE_GI_MAX_SAMPLES ||
        !(c->p.offset >= 0)) {
        return ssg_node_fail(ctx, SSG_E_VALUE, "needs "
                    "1 <= samples <= %d and offset >= 0", SSG_REFERENCE_GI_MAX_SAMPLES);
    }
    c->seed = ctx->frame->seed;
    c->use_env = c->p.environment && s->env && s->env->has_light;
    make_table(&c->t, c->p.samples);
    return SSG_OK;
}

static const struct ssg_param_desc params[] = {
    {.name = "samples", SSG_FIELD_INT(struct ssg_reference_gi_params, samples), .def = 64,
     .min = 1, .max = SSG_REFERENCE_GI_MAX_SAMPLES,
     .help = "environment samples (direct term) and bounce paths per pixel; the noise falls "
             "as 1 / sqrt(samples) or faster (stratified)"},
    {.name = "bounce", SSG_FIELD_BOOL(struct ssg_reference_gi_params, bounce), .def = 1,
     .help = "trace one diffuse bounce; false: the bounce output is 0 and no bounce rays "
             "are cast"},
    {.name = "offset", SSG_FIELD_FLOAT(struct ssg_reference_gi_params, offset), .def = 1e-3,
     .min = 0, .max = 1e6, .unit = "scene units",
     .help = "ray origins move this far along the normal and this far back along the "
             "arriving ray, against self-intersection (at least 1024 float ulps of the "
             "point's coordinates)"},
    {.name = "environment", SSG_FIELD_BOOL(struct ssg_reference_gi_params, environment),
     .def = 1,
     .help = "include the scene's environment light (directly and at the bounce's end)"},
};

static const struct ssg_port_desc inputs[] = {
    [SSG_REFERENCE_GI_IN_POSITION] = {.name = "position", .types = SSG_T_VECTOR,
     .doc = "view-space position (gbuffer)"},
    [SSG_REFERENCE_GI_IN_NORMAL] = {.name = "normal", .types = SSG_T_VECTOR,
     .doc = "unit view-space normal facing the camera, 0 = background (gbuffer)"},
    [SSG_REFERENCE_GI_IN_ALBEDO] = {.name = "albedo", .types = SSG_T_COLOR,
     .doc = "diffuse albedo, linear RGB (gbuffer)"},
};
_Static_assert(SSG_COUNT(inputs) == SSG_REFERENCE_GI_INPUTS, "one entry a port enumerator");

static const struct ssg_port_desc outputs[] = {
    [SSG_REFERENCE_GI_OUT_DIRECT] = {.name = "direct", .types = SSG_T_COLOR,
     .doc = "diffuse light of the lights and the environment with true shadows, linear RGB"},
    [SSG_REFERENCE_GI_OUT_BOUNCE] = {.name = "bounce", .types = SSG_T_COLOR,
     .doc = "one diffuse bounce of that light off the scene's surfaces, linear RGB"},
    [SSG_REFERENCE_GI_OUT_OUT] = {.name = "out", .types = SSG_T_COLOR,
     .doc = "direct + bounce"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_REFERENCE_GI_OUTPUTS, "one entry a port enumerator");

const struct ssg_node_desc ssg_node_reference_gi = {
    .name = "reference_gi",
    .summary = "ground-truth direct light with shadows plus one diffuse bounce (Embree)",
    .method = "the rendering equation (Belonogov sec. 2.1, eq. 2.1) for Lambertian surfaces "
              "after one bounce: the integrals SSDO approximates (Szentandrasi sec. 3.2.1 "
              "eq. 1 and sec. 3.2.2 eq. 3) by ray casting, with environment importance "
              "sampling, cosine-weighted bounce paths (Malley) and a Hammersley set with "
              "per-pixel Cranley-Patterson rotation",
    .doc = "Per pixel, the G-buffer point's diffuse direct light with true shadows: one "
           "shadow ray per point and directional light, and `samples` environment "
           "directions drawn by importance sampling of the probe. Then `samples` "
           "cosine-weighted bounce paths find the nearest surface and add its diffuse "
           "direct light (every light by a shadow ray, the environment by one sample per "
           "path) times the pixel's albedo. Specular terms are ignored (SSDO is diffuse). "
           "out = direct + bounce, all radiance in linear RGB, comparable with the SSDO "
           "nodes by `compare`. Deterministic for a seed, whatever the threads. "
           "Background pixels (normal 0) are 0. Shows a progress bar when stderr is a "
           "terminal.",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_reference_gi_params),
    .consts_size = sizeof(struct ssg_reference_gi_consts),
    .needs_scene = 1,
    .check = check,
    .prepare = prepare,
    .run_cpu = ssg_reference_gi_run_cpu,
};
