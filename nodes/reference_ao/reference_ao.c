/* reference_ao.c - the `reference_ao` node: ground-truth ambient occlusion (obscurance) by
 * tracing rays through the scene with Embree from every G-buffer point.
 *
 * Method: Belonogov, "Global Illumination methods in simulated VR environments", section
 * 2.2.3: AO as the cosine-weighted visibility of the normal's hemisphere, eq. 2.5,
 * V = 1/pi * integral of Visibility(x, w) cos(theta) dw, in its distance-limited form
 * ("ambient obscurance", eq. 2.6-2.7) with the hard step as distance test: a direction is
 * occluded when a surface lies on it within max_distance, and an occluder farther away
 * does not count. So 1 = unoccluded, and the result is directly comparable with the
 * screen-space nodes at the same radius (ssao's radius, hbao's radius). Estimated by
 * Monte Carlo ray casting as that section and Szentandrasi, "Modern Methods of Realistic
 * Lighting in Real Time", section 3.1, describe: V = 1 - occluded rays / rays.
 *
 * Sampling (quasi-Monte Carlo, Szentandrasi section 4.2, eq. 5-7): the 2D Hammersley set
 * (i / n, radical inverse in base 2 of i), i < n = rays, is mapped to the cosine-weighted
 * hemisphere by Malley's method (Pharr, Jakob and Humphreys, "Physically Based Rendering",
 * 3rd ed., section 13.6.3): a point (u, v) becomes the disk point sqrt(u) (cos 2 pi v,
 * sin 2 pi v) lifted to the hemisphere, so cos^2 theta = 1 - u. Each pixel applies its own
 * Cranley-Patterson rotation (Cranley and Patterson 1976), (u + a, v + b) mod 1, with (a,
 * b) from a hash of (x, y, seed): the set stays stratified within a pixel while neighbours
 * decorrelate into noise. Shifting v by b is turning the tangent frame by 2 pi b, so the
 * table of cos and sin made here once serves every pixel and no ray needs a sine. The
 * tangent frame comes from the normal by Duff et al., "Building an Orthonormal Basis,
 * Revisited" (JCGT 2017). Everything depends only on (x, y, seed, rays), never on the
 * threads. The table, the hash, the frame and the ray origin below are nodes/common/trace.h's,
 * shared with reference_gi.
 *
 * Geometry: G-buffer positions and normals are in view space (node.h); world = eye +
 * R^T view, normal_world = R^T normal_view, R the rotation of ssg_camera_view_matrix.
 * Rays start at o = p + e (n + v), v the unit vector from p to the camera, and count
 * occluders with 0 <= t <= max_distance along unit directions, so the result is exactly
 * the obscurance of the moved point o. The G-buffer point lies on its surface only to
 * float precision, and a ray starting under a surface is occluded at once: the n term
 * lifts o off its own surface, the v term moves it into the free space the primary ray
 * crossed, which keeps it off a neighbouring surface too (a point on a concave edge lies
 * on both: the Cornell box's symmetric view puts a pixel centre exactly on each of its
 * receding edges, and without v those pixels came out 0). e = max(offset, 1024 float
 * ulps of the point's largest world coordinate or depth), as precision falls with the
 * scene's scale. Background pixels (normal 0) are 1. Normals that are not unit are
 * normalised.
 *
 * Horizon: the G-buffer's normal is the interpolated (shading) normal; on a smooth-shaded
 * mesh seen at a grazing angle it can lean past the triangle's own plane, and directions
 * of its hemisphere then leave below the surface, into the object. A path tracer counts
 * those as blocked; so does this node: each pixel traces its primary ray once more for the
 * triangle's face normal (nodes/common/trace.h), weights directions by the shading normal's cosine
 * and counts every direction below the face's plane as occluded. */
#include <stdio.h>

#include "reference_ao.h"
#include "common/trace.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_shape *pos = &in[SSG_REFERENCE_AO_IN_POSITION];
    const struct ssg_shape *nrm = &in[SSG_REFERENCE_AO_IN_NORMAL];
    if (pos->channels != 3 || nrm->channels != 3 || pos->width != nrm->width ||
        pos->height != nrm->height) {
        snprintf(why, why_len, "position and normal must be 3-channel images of one size");
        return SSG_E_SIZE;
    }
    /* Runs at the G-buffer's resolution. */
    out[0] = (struct ssg_shape){pos->width, pos->height, 1, SSG_T_SCALAR};
    return SSG_OK;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_reference_ao_consts *c = consts;
    c->p = *(const struct ssg_reference_ao_params *)params;
    enum ssg_err e = ssg_trace_camera(ctx, c->rot, c->eye);
    if (e)
        return e;
    if (c->p.rays < 1 || c->p.rays > SSG_REFERENCE_AO_MAX_RAYS || !(c->p.max_distance > 0) ||
        !(c->p.offset >= 0)) {
        return ssg_node_fail(ctx, SSG_E_VALUE, "needs "
                    "1 <= rays <= %d, max_distance > 0 and offset >= 0",
                    SSG_REFERENCE_AO_MAX_RAYS);
    }
    c->seed = ctx->frame->seed;
    ssg_hammersley_disk(c->p.rays, c->u, c->c, c->s);
    return SSG_OK;
}

static const struct ssg_param_desc params[] = {
    {.name = "rays", SSG_FIELD_INT(struct ssg_reference_ao_params, rays), .def = 256, .min = 1,
     .max = SSG_REFERENCE_AO_MAX_RAYS,
     .help = "cosine-weighted rays per pixel; the standard error is sqrt(V (1 - V) / rays) "
             "or less (stratified)"},
    {.name = "max_distance", SSG_FIELD_FLOAT(struct ssg_reference_ao_params, max_distance),
     .def = 0.5, .min = 1e-6, .max = 1e30, .unit = "scene units",
     .help = "occluders farther along a ray do not count (the meaning of ssao's radius)"},
    {.name = "offset", SSG_FIELD_FLOAT(struct ssg_reference_ao_params, offset), .def = 1e-3,
     .min = 0, .max = 1e6, .unit = "scene units",
     .help = "ray origins move this far along the normal and this far towards the camera, "
             "against self-intersection (at least 1024 float ulps of the point's "
             "coordinates)"},
};

static const struct ssg_port_desc inputs[] = {
    [SSG_REFERENCE_AO_IN_POSITION] = {.name = "position", .types = SSG_T_VECTOR,
     .doc = "view-space position (gbuffer)"},
    [SSG_REFERENCE_AO_IN_NORMAL] = {.name = "normal", .types = SSG_T_VECTOR,
     .doc = "unit view-space normal facing the camera, 0 = background (gbuffer)"},
};
_Static_assert(SSG_COUNT(inputs) == SSG_REFERENCE_AO_INPUTS, "one entry a port enumerator");

static const struct ssg_port_desc outputs[] = {
    [SSG_REFERENCE_AO_OUT_OUT] = {.name = "out", .types = SSG_T_SCALAR,
     .doc = "visibility, 1 = unoccluded (cosine-weighted, distance-limited)"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_REFERENCE_AO_OUTPUTS, "one entry a port enumerator");

const struct ssg_node_desc ssg_node_reference_ao = {
    .name = "reference_ao",
    .summary = "ground-truth ambient obscurance by ray casting the scene (Embree)",
    .method = "Belonogov, Global Illumination methods in simulated VR environments, sec. "
              "2.2.3, eq. 2.5-2.7 (cosine-weighted, distance-limited visibility), by Monte "
              "Carlo ray casting with a Hammersley set (Szentandrasi sec. 4.2, eq. 5-7), "
              "Malley's method and per-pixel Cranley-Patterson rotation",
    .doc = "Per pixel, `rays` cosine-weighted directions over the normal's hemisphere (a "
           "Hammersley set mapped by Malley's method, shifted per pixel by a hash of x, y "
           "and the seed) are traced from the world-space point moved by `offset` along "
           "the normal and towards the camera; a ray is occluded when any surface lies within "
           "`max_distance` on "
           "it, or when it leaves below the plane of the hit triangle itself (its face normal "
           "is the horizon, the shading normal only weights). out = 1 - occluded / rays: "
           "1 = unoccluded, comparable with ssao and hbao "
           "at radius = max_distance. Deterministic for a seed, whatever the threads. "
           "Background pixels (normal 0) are 1. Shows a progress bar when stderr is a "
           "terminal.",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_reference_ao_params),
    .consts_size = sizeof(struct ssg_reference_ao_consts),
    .needs_scene = 1,
    .check = check,
    .prepare = prepare,
    .run_cpu = ssg_reference_ao_run_cpu,
};
