/* ssao.c - the `ssao` node: normal-oriented hemisphere screen-space ambient occlusion.
 *
 * Method: Szentandrasi, "Modern Methods of Realistic Lighting in Real Time", section 3.1
 * (figure 1): sample points are generated inside the hemisphere around the pixel's normal,
 * projected to the screen, and their depths compared with the depth buffer there; the
 * fraction of samples below the visible surface darkens the pixel. Belonogov, "Global
 * Illumination methods in simulated VR environments", section 3.2: the normal-oriented
 * hemisphere (figure 3.2) and a small rotation texture tiled over the screen (3.2.3), whose
 * noise a blur removes (our `bilateral` node, section 4.3.2). The range check is the one
 * of Chapman's SSAO tutorial (Belonogov's reference [18]): an occluder much nearer the
 * camera than the pixel is a different object and must not darken it. Samples come from
 * the `halton` node (Szentandrasi section 4.2).
 *
 * For pixel P with unit normal N: S = P + r * (T s.x + B s.y + N s.z) for each kernel
 * sample s, with T, B a tangent frame turned about N by the tile's angle at
 * (x mod n, y mod n). S is projected with the frame's camera (node.h); the scene depth d
 * at that pixel (nearest) occludes S when 0 < d < -S.z - bias, weighted by the range
 * check (hard: |d - depth(P)| <= r; smooth: smoothstep(0, 1, r / |depth(P) - d|)).
 * Samples outside the frame, behind the camera or over background (depth 0, infinitely
 * far) are unoccluded. out = (1 - occluded / count)^power; background pixels get 1.
 * max_screen_radius > 0 caps r per pixel at max_screen_radius * depth(P) / f (the capped
 * r is also the range-check distance), so that near pixels do not sample all over the
 * screen: their depth reads would miss the cache (see ssao_cpu.c), and section 3.1 notes
 * that the sampled area's projected size governs what SSAO can find anyway.
 * Normals are taken as unit (node.h); others are normalised. */
#include <stdio.h>

#include "ssao.h"

static int same_size(const struct ssg_shape *a, const struct ssg_shape *b)
{
    return a->width == b->width && a->height == b->height;
}

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_shape *pos = &in[SSG_SSAO_IN_POSITION], *nrm = &in[SSG_SSAO_IN_NORMAL];
    const struct ssg_shape *ker = &in[SSG_SSAO_IN_KERNEL], *rot = &in[SSG_SSAO_IN_ROTATION];
    const struct ssg_shape *dep = &in[SSG_SSAO_IN_DEPTH];
    if (pos->channels != 3 || nrm->channels != 3 || !same_size(pos, nrm)) {
        snprintf(why, why_len, "position and normal must be 3-channel images of one size");
        return SSG_E_SIZE;
    }
    if (ker->channels != 3 || ker->height != 1 || ker->width < 1) {
        snprintf(why, why_len, "kernel must be count x 1 with 3 channels, got %dx%dx%d",
                 ker->width, ker->height, ker->channels);
        return SSG_E_CHANNELS;
    }
    if (rot->channels != 0 && (rot->channels != 2 || rot->width != rot->height)) {
        snprintf(why, why_len, "rotation must be an n x n pattern with 2 channels, got "
                 "%dx%dx%d", rot->width, rot->height, rot->channels);
        return SSG_E_CHANNELS;
    }
    if (dep->channels != 0 && (dep->channels != 1 || !same_size(dep, pos))) {
        snprintf(why, why_len, "depth must be a 1-channel image the size of position");
        return SSG_E_SIZE;
    }
    /* Runs at the G-buffer's resolution, which may be a subsampled frame. */
    out[0] = (struct ssg_shape){pos->width, pos->height, 1, SSG_T_SCALAR};
    return SSG_OK;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_ssao_consts *c = consts;
    c->p = *(const struct ssg_ssao_params *)params;
    c->proj = ssg_frame_projection(ctx->frame);
    c->frame_width = ctx->frame->width;
    c->frame_height = ctx->frame->height;
    if (!(c->p.radius > 0) || c->frame_width < 1 || c->frame_height < 1 || !(c->proj.f > 0)) {
        ssg_diag_at(ctx->diags, SSG_E_VALUE, (struct ssg_loc){0},
                    "ssao '%s': needs radius > 0 and a frame with size and field of view",
                    ctx->instance ? ctx->instance : "");
        return SSG_E_VALUE;
    }
    return SSG_OK;
}

static const char *const range_choices[] = {"none", "hard", "smooth", NULL};

static const struct ssg_param_desc params[] = {
    {.name = "radius", .type = SSG_P_FLOAT, .offset = offsetof(struct ssg_ssao_params, radius),
     .def = 0.5, .min = 1e-6, .max = 1e6, .unit = "scene units",
     .help = "hemisphere radius around the pixel"},
    {.name = "bias", .type = SSG_P_FLOAT, .offset = offsetof(struct ssg_ssao_params, bias),
     .def = 0.02, .min = 0, .max = 1e6, .unit = "scene units",
     .help = "a sample is occluded only when the surface is this much in front of it"},
    {.name = "power", .type = SSG_P_FLOAT, .offset = offsetof(struct ssg_ssao_params, power),
     .def = 1, .min = 0, .max = 64, .help = "intensity: out = visibility^power"},
    {.name = "range_check", .type = SSG_P_ENUM,
     .offset = offsetof(struct ssg_ssao_params, range_check), .def = SSG_SSAO_RANGE_SMOOTH,
     .choices = range_choices,
     .help = "how occluders far in depth from the pixel are discounted"},
    {.name = "max_screen_radius", .type = SSG_P_FLOAT,
     .offset = offsetof(struct ssg_ssao_params, max_screen_radius), .def = 0, .min = 0,
     .max = 16384, .unit = "px", .help = "caps the projected radius; 0 = no cap"},
};

static const struct ssg_port_desc inputs[] = {
    {.name = "position", .types = SSG_T_VECTOR, .doc = "view-space position"},
    {.name = "normal", .types = SSG_T_VECTOR, .doc = "unit view-space normal"},
    {.name = "kernel", .types = SSG_T_KERNEL, .doc = "hemisphere samples (halton.samples)"},
    {.name = "rotation", .types = SSG_T_PATTERN, .optional = 1,
     .doc = "per-pixel rotation tile (halton.rotation); none = no rotation"},
    {.name = "depth", .types = SSG_T_SCALAR, .optional = 1,
     .doc = "linear depth for the occluder lookup; none = -position.z"},
};

static const struct ssg_port_desc outputs[] = {
    {.name = "out", .types = SSG_T_SCALAR, .doc = "visibility, 1 = unoccluded"},
};

const struct ssg_node_desc ssg_node_ssao = {
    .name = "ssao",
    .summary = "normal-oriented hemisphere screen-space ambient occlusion",
    .method = "Szentandrasi, Modern Methods of Realistic Lighting in Real Time, sec. 3.1 "
              "and fig. 1; Belonogov, Global Illumination methods in simulated VR "
              "environments, sec. 3.2 (normal-oriented hemisphere, tiled rotation)",
    .doc = "For each pixel, kernel samples are placed in the hemisphere of radius `radius` "
           "around the normal (turned by the rotation tile), projected, and compared with "
           "the scene depth there: a sample is occluded when the surface is more than "
           "`bias` in front of it, weighted by the range check. Samples off screen, "
           "behind the camera or over background are unoccluded. out = (1 - occluded / "
           "count)^power; background pixels are 1.",
    .inputs = inputs,
    .input_count = SSG_COUNT(inputs),
    .outputs = outputs,
    .output_count = SSG_COUNT(outputs),
    .params = SSG_TABLE(params),
    .params_size = sizeof(struct ssg_ssao_params),
    .consts_size = sizeof(struct ssg_ssao_consts),
    .check = check,
    .prepare = prepare,
    .run_cpu = ssg_ssao_run_cpu,
};
