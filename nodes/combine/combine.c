/* combine.c - the `combine` node: final shading of the frame from the G-buffer's direct
 * light and albedo, the (filtered) ambient occlusion and optional indirect light.
 *
 *   out = direct + ambient * ambient_color * albedo * ao + indirect      (per channel)
 *
 * The ambient term is the constant ambient light of a perfectly diffuse surface
 * (Belonogov, "Global Illumination methods in simulated VR environments", section 2.2.2),
 * darkened by ambient occlusion as its visibility factor: Szentandrasi, "Modern Methods of
 * Realistic Lighting in Real Time", section 3.1 ("this visibility property is used as a
 * darkening factor"), with AO in [0, 1] as defined by Belonogov section 2.2.3, eq. 2.5,
 * and applied to the ambient component only (Belonogov section 3.2). Direct light is not
 * darkened: it carries its own visibility. Background pixels (albedo 0, direct 0) stay 0. */
#include <stddef.h>

#include "combine.h"

static const struct ssg_port_desc inputs[] = {
    {.name = "direct", .types = SSG_T_COLOR,
     .doc = "direct light (diffuse + specular) of the visible surface, linear RGB"},
    {.name = "albedo", .types = SSG_T_COLOR, .doc = "diffuse reflectance, linear RGB"},
    {.name = "ambient_occlusion", .types = SSG_T_SCALAR, .optional = 1,
     .doc = "ambient occlusion, 1 = unoccluded; unconnected = 1 everywhere"},
    {.name = "indirect", .types = SSG_T_COLOR, .optional = 1,
     .doc = "indirect light added as is, linear RGB; unconnected = 0"},
};

static const struct ssg_port_desc outputs[] = {
    {.name = "out", .types = SSG_T_COLOR, .same_as = "direct",
     .doc = "shaded frame, linear RGB (unbounded; write tone-maps its PNG)"},
};

static const struct ssg_param_desc param_table[] = {
    {.name = "ambient", .type = SSG_P_FLOAT, .offset = offsetof(struct ssg_combine_params, ambient),
     .def = 0.3, .min = 0, .max = 10,
     .help = "strength of the uniform ambient light that AO darkens (linear, like direct)"},
    {.name = "ambient_color", .type = SSG_P_VEC3,
     .offset = offsetof(struct ssg_combine_params, ambient_color), .min = 0, .max = 100,
     .def3 = {1, 1, 1}, .unit = "linear RGB", .help = "tint of the ambient light"},
};

const struct ssg_node_desc ssg_node_combine = {
    .name = "combine",
    .summary = "final shading: direct + ambient * albedo * AO + indirect",
    .method = "out = direct + ambient * ambient_color * albedo * ao + indirect; AO darkens the "
              "ambient term only (Szentandrasi, Modern Methods of Realistic Lighting in Real "
              "Time, sec. 3.1; AO as in Belonogov, Global Illumination methods in simulated VR "
              "environments, sec. 2.2.3 eq. 2.5 and sec. 3.2)",
    .doc = "Combines the G-buffer's direct light with a uniform ambient light scaled by the "
           "surface albedo and darkened by ambient occlusion, plus optional indirect light "
           "(added as is). Without ambient_occlusion the ambient light is unoccluded; "
           "background pixels (albedo 0, direct 0) stay black. Output is linear and may "
           "exceed 1.",
    .inputs = inputs,
    .input_count = SSG_COUNT(inputs),
    .outputs = outputs,
    .output_count = SSG_COUNT(outputs),
    .params = SSG_TABLE(param_table),
    .params_size = sizeof(struct ssg_combine_params),
    .run_cpu = ssg_combine_run_cpu,
};
