/* gbuffer.c - the `gbuffer` node: the geometry buffer of deferred shading, made by ray
 * casting instead of rasterisation.
 *
 * Method: the G-buffer of deferred shading (Deering et al. 1988, as used by Knuth and
 * Kohlhammer, "A Hybrid Ambient Occlusion Technique for Dynamic Scenes", section 4,
 * Architecture, figure 10; Belonogov, "Global Illumination methods in simulated VR
 * environments", section 4.5, geometry pass): per pixel the view-space position, normal
 * and linear depth of the nearest surface, its albedo, and direct light. Visibility: one
 * primary ray per pixel centre through Embree (core/scene/rt.h). Direct light: Lambert diffuse
 * plus the Blinn-Phong specular term (Blinn, "Models of light reflection for computer
 * synthesized pictures", SIGGRAPH 1977, the half-vector form N.H), without shadows:
 *   direct = sum over lights of (albedo / pi + specular * max(0, N.H)^shininess) * E,
 *   E = color * intensity * max(0, N.L) / d^2   (point light at distance d)
 *   E = color * intensity * max(0, N.L)         (directional light, L = -direction)
 * with N the shading normal turned towards the camera and H = normalize(L + V).
 * Environment light (a separate output, so occlusion methods can darken it alone): the
 * unoccluded diffuse reflection of the scene's environment, albedo / pi * E_env(N), with
 * E_env the cosine convolution of the light probe (core/scene/env.h), the term SSDO's
 * modulation factor darkens (Szentandrasi sec. 4.1: "equation (1) without the
 * visibility function").
 *
 * Conventions (node.h): view space looks down -z; ray directions are built with view
 * z = -1 so the ray parameter of a hit is its depth, and position = t * direction
 * reprojects exactly to the pixel centre through ssg_frame_projection. Background
 * pixels are 0 in every output. The camera pose comes from ctx->scene, the intrinsics
 * (fov, near, far, size) from ctx->frame. On GL (gbuffer_gl.c) the rasteriser finds each
 * pixel's triangle and the ray is cast at that triangle alone, with the same formulas. */
#include "gbuffer.h"

#include "common/trace.h"

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_gbuffer_consts *c = consts;
    c->p = *(const struct ssg_gbuffer_params *)params;
    enum ssg_err e = ssg_trace_camera(ctx, c->rot, c->eye);
    if (e)
        return e;
    c->proj = ssg_frame_projection(ctx->frame);
    if (ctx->frame->width < 1 || ctx->frame->height < 1 || !(c->proj.f > 0) ||
        !(ctx->frame->near_z > 0) || !(ctx->frame->far_z > ctx->frame->near_z)) {
        return ssg_node_fail(ctx, SSG_E_VALUE, "the frame "
                    "needs a size, a field of view and 0 < near < far");
    }
    c->near_z = ctx->frame->near_z;
    c->far_z = ctx->frame->far_z;
    return SSG_OK;
}

static const char *const normals_choices[] = {"smooth", "face", NULL};

static const struct ssg_param_desc params[] = {
    {.name = "normals", SSG_FIELD_ENUM(struct ssg_gbuffer_params, normals),
     .def = SSG_GBUFFER_NORMALS_SMOOTH, .choices = normals_choices,
     .help = "smooth: interpolated vertex normals; face: the triangle's own normal (no "
             "self-occlusion of flat-shaded meshes in SSAO)"},
};

static const struct ssg_port_desc outputs[] = {
    [SSG_GBUFFER_OUT_POSITION] = {.name = "position", .types = SSG_T_VECTOR,
     .doc = "view-space position, 0 = background"},
    [SSG_GBUFFER_OUT_NORMAL] = {.name = "normal", .types = SSG_T_VECTOR,
     .doc = "unit view-space normal facing the camera"},
    [SSG_GBUFFER_OUT_DEPTH] = {.name = "depth", .types = SSG_T_SCALAR,
     .doc = "linear depth along -z, 0 = background"},
    [SSG_GBUFFER_OUT_ALBEDO] = {.name = "albedo", .types = SSG_T_COLOR,
     .doc = "material albedo times texture, linear RGB"},
    [SSG_GBUFFER_OUT_DIRECT] = {.name = "direct", .types = SSG_T_COLOR, .lit = 1,
     .doc = "diffuse + Blinn-Phong light of the scene's lights, no shadows, linear RGB"},
    [SSG_GBUFFER_OUT_ENVIRONMENT] = {.name = "environment", .types = SSG_T_COLOR, .lit = 1,
     .doc = "diffuse light of the scene's environment, no occlusion: albedo / pi * "
            "irradiance, linear RGB"},
    [SSG_GBUFFER_OUT_BACK] = {.name = "back", .types = SSG_T_SCALAR, .on_demand = 1,
     .doc = "linear depth along -z of the next surface behind the first on the pixel's "
            "ray (depth * (1 + 1e-4) < back <= far); +inf where there is none, 0 = "
            "background"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_GBUFFER_OUTPUTS, "one entry a port enumerator");

/* Flops per pixel (node.h), by reading gbuffer_cpu.c, for one light: about 10 for the
   ray, 35 for the normal, frame and hit point, 35 a light (Lambert and Blinn-Phong), 25
   for the environment and the stores' products. Embree's traversal is not counted. */
static double gbuffer_flops(const void *consts, const struct ssg_shape *in)
{
    (void)consts, (void)in;
    return 105.0;
}

const struct ssg_node_desc ssg_node_gbuffer = {
    .name = "gbuffer",
    .summary = "view-space G-buffer and direct light by ray casting the scene (Embree)",
    .method = "deferred-shading G-buffer (Knuth and Kohlhammer, sec. 4, fig. 10; Belonogov, "
              "sec. 4.5) by primary ray casting; Lambert + Blinn-Phong direct light (Blinn "
              "1977), no shadows",
    .doc = "Casts one ray per pixel centre from the scene camera (pose from the scene, fov, "
           "near and far from the frame) and writes the nearest surface's view-space "
           "position, normal (turned to face the camera) and linear depth, its albedo "
           "(material albedo times texture) and `direct` = sum over lights of (albedo/pi + "
           "specular * (N.H)^shininess) * E, with E = color * intensity * max(0, N.L) / d^2 "
           "for point lights (no 1/d^2 for directional lights). Surfaces outside [near, "
           "far] and background pixels are 0 in every output. `back` (a second depth "
           "layer, computed only when a node reads it) continues the pixel's ray past the "
           "first surface and gives the depth, in `depth`'s convention, of the nearest "
           "surface beyond depth + 1e-4 depth (so the first surface and triangles at its "
           "very depth are never found again) up to far: for a closed mesh the ray's exit "
           "point, so back - depth is the object's thickness along the ray; for a single "
           "sheet the next surface behind it. Where the ray meets nothing more it is +inf: "
           "a consumer that takes [depth, back] as the space the pixel's surface fills then "
           "gets exactly the height-field assumption (infinitely thick) of screen-space "
           "methods without a second layer, the safe answer for the single-sided walls, "
           "floors and terrain that have nothing behind them (0 there would make them "
           "infinitely thin and invisible to a sector-based consumer). 0 on background. "
           "CPU: a second Embree ray; GL: a depth peel (a raster pass discarding fragments "
           "at or before that depth), then the ray cast at the triangle found.",
    SSG_NODE_OUTPUTS(outputs),
    SSG_NODE_PARAMS(params, struct ssg_gbuffer_params),
    .consts_size = sizeof(struct ssg_gbuffer_consts),
    .needs_scene = 1,
    .prepare = prepare,
    .flops_per_pixel = gbuffer_flops,
    .run_cpu = ssg_gbuffer_run_cpu,
    .run_gl = ssg_gbuffer_run_gl,
};
