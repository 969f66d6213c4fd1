/* combine.c - the `combine` node: final shading of the frame from the G-buffer's light and
 * albedo, ambient occlusion or SSDO's modulation factor, and indirect light:
 *
 *   out = M * direct + M * ao * (environment + ambient * ambient_color * albedo)
 *         + (darken_indirect ? M : 1) * indirect                       (per channel)
 *
 * with M the modulation factor (1 or 3 channels, 1 when unconnected) and ao the ambient
 * occlusion (1 when unconnected). With indirect_albedo, indirect stands for albedo x
 * indirect: a white receiver's bounce made at low resolution (rsm without albedo) takes
 * the full-resolution albedo here, after upsampling.
 * - SSAO: the ambient term is the ambient light of a diffuse surface (Belonogov, "Global
 *   Illumination methods in simulated VR environments", section 2.2.2) or the scene's
 *   environment light, darkened by AO as its visibility factor (Szentandrasi, "Modern
 *   Methods of Realistic Lighting in Real Time", section 3.1: "this visibility property is
 *   used as a darkening factor"; AO in [0, 1] by Belonogov eq. 2.5, applied to the ambient
 *   component only, Belonogov section 3.2). Direct light is not darkened by AO.
 * - SSDO one step (Szentandrasi section 4.1): the modulation factor, the ratio of light with
 *   and without visibility, darkens the light it was computed for (direct and environment)
 *   and, "in order to avoid pixels being too bright in darkened corners", the bounce too.
 * - SSDO two steps: direct = SSDO's radiance, indirect = the bounce pass: a plain sum.
 * - Near and far field together (graphs/hybrid_ssdo.graph): `environment` is light that is
 *   already shadowed at every distance (probe_light.out, shadow maps) and `far_visibility`
 *   its visibility V (probe_light.visibility); M is SSDO's near-field modulation. A near
 *   occluder is seen by both, so their product would count it twice: the pixel's
 *   visibility is the smaller, min(V, M), and the environment is scaled by
 *   q = min(1, M / V) (1 where V = 0: nothing reaches the pixel then). The directions the
 *   far field blocks but SSDO's radius does not reach, max(0, M - V) of the hemisphere,
 *   bounce light SSDO's bounce does not gather; with far_bounce they send back the
 *   receiver's own radiance times its albedo (one bounce from surroundings that look like
 *   the receiver: the assumption of Jimenez et al., "Practical Real-Time Strategies for
 *   Accurate Indirect Occlusion", 2016, sec. 5, taken for one bounce):
 *     own = M direct + q ao (environment + ambient ambient_color albedo)
 *     out = own + (darken_indirect ? M : 1) indirect + far_bounce albedo max(0, M - V) own
 *   On the example scenes under a sky this far bounce is most of what the shadow-mapped
 *   probe light misses against one-bounce truth (docs/accuracy.md).
 * Background pixels (albedo 0, light 0) stay 0. */
#include <stddef.h>

#include <stdio.h>

#include "combine.h"

/* Every connected input must have the output's size (the frame's): combine reads them
   pixel by pixel. Channels follow from the ports' types. */
static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len);

static const struct ssg_port_desc inputs[] = {
    [SSG_COMBINE_IN_DIRECT] = {.name = "direct", .types = SSG_T_COLOR,
     .doc = "direct light (diffuse + specular) of the visible surface, linear RGB"},
    [SSG_COMBINE_IN_ALBEDO] = {.name = "albedo", .types = SSG_T_COLOR,
     .doc = "diffuse reflectance, linear RGB"},
    [SSG_COMBINE_IN_AMBIENT_OCCLUSION] = {.name = "ambient_occlusion", .types = SSG_T_SCALAR,
     .optional = 1, .doc = "ambient occlusion, 1 = unoccluded; unconnected = 1 everywhere"},
    [SSG_COMBINE_IN_INDIRECT] = {.name = "indirect", .types = SSG_T_COLOR, .optional = 1,
     .doc = "indirect light (a bounce), linear RGB; unconnected = 0"},
    [SSG_COMBINE_IN_MODULATION] = {.name = "modulation", .types = SSG_T_SCALAR | SSG_T_COLOR,
     .optional = 1,
     .doc = "SSDO modulation factor (1 or 3 channels) darkening direct, environment, ambient "
            "and (darken_indirect) indirect light; unconnected = 1"},
    [SSG_COMBINE_IN_ENVIRONMENT] = {.name = "environment", .types = SSG_T_COLOR, .optional = 1,
     .doc = "unoccluded environment light (gbuffer.environment), darkened like the ambient "
            "term; unconnected = 0"},
    [SSG_COMBINE_IN_FAR_VISIBILITY] = {.name = "far_visibility", .types = SSG_T_SCALAR,
     .optional = 1,
     .doc = "visibility V already in environment (probe_light.visibility): the modulation "
            "then darkens it by min(1, M / V), not M, and far_bounce fills max(0, M - V); "
            "unconnected = no far field"},
};
_Static_assert(SSG_COUNT(inputs) == SSG_COMBINE_INPUTS, "one entry a port enumerator");

static const struct ssg_port_desc outputs[] = {
    [SSG_COMBINE_OUT_OUT] = {.name = "out", .types = SSG_T_COLOR, .same_as = "direct",
     .doc = "shaded frame, linear RGB (unbounded; write tone-maps its PNG)"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_COMBINE_OUTPUTS, "one entry a port enumerator");

static const struct ssg_param_desc param_table[] = {
    {.name = "ambient", SSG_FIELD_FLOAT(struct ssg_combine_params, ambient), .def = 0.3,
     .min = 0, .max = 10,
     .help = "strength of the uniform ambient light that AO darkens (linear, like direct)"},
    {.name = "ambient_color", SSG_FIELD_VEC3(struct ssg_combine_params, ambient_color),
     .min = 0, .max = 100, .def3 = {1, 1, 1},
     .unit = "linear RGB",
     .help = "tint of the ambient light"},
    {.name = "darken_indirect", SSG_FIELD_BOOL(struct ssg_combine_params, darken_indirect),
     .def = 1,
     .help = "the modulation factor darkens the indirect light too (the one-step SSDO rule "
             "against over-bright corners)"},
    {.name = "far_bounce", SSG_FIELD_BOOL(struct ssg_combine_params, far_bounce), .def = 1,
     .help = "with far_visibility: directions blocked beyond the modulation's reach bounce "
             "albedo x the pixel's own radiance"},
    {.name = "indirect_albedo", SSG_FIELD_BOOL(struct ssg_combine_params, indirect_albedo),
     .def = 0,
     .help = "indirect is multiplied by albedo first: a white receiver's bounce (rsm "
             "without albedo, upsampled) takes the full-resolution albedo"},
};

/* Flops per pixel (node.h): about 6 a colour channel (the light sum, the albedo product,
   modulation and ambient terms), whichever inputs are bound. */
static double combine_flops(const void *consts, const struct ssg_shape *in)
{
    (void)consts, (void)in;
    return 18.0;
}

const struct ssg_node_desc ssg_node_combine = {
    .name = "combine",
    .summary = "final shading: light darkened by AO or the SSDO modulation, plus indirect",
    .method = "out = M direct + M ao (environment + ambient ambient_color albedo) + "
              "(darken_indirect ? M : 1) indirect; AO darkens the ambient term only "
              "(Szentandrasi, Modern Methods of Realistic Lighting in Real Time, sec. 3.1; "
              "Belonogov, Global Illumination methods in simulated VR environments, sec. "
              "2.2.3 eq. 2.5 and sec. 3.2); the SSDO modulation factor M darkens light and "
              "bounce (Szentandrasi sec. 4.1); with far_visibility V (shadow-mapped "
              "environment) the environment is darkened by min(1, M / V) and far_bounce adds "
              "albedo max(0, M - V) own (one bounce from surroundings like the receiver, "
              "after Jimenez et al. 2016)",
    .doc = "Combines the G-buffer's direct light with the ambient light (a uniform ambient "
           "scaled by the albedo, and/or the scene's environment light) darkened by ambient "
           "occlusion, and indirect light. For one-step SSDO connect modulation (it darkens "
           "direct, environment and ambient light and, with darken_indirect, the bounce); "
           "for two-step SSDO connect SSDO's radiance as direct and the bounce as indirect. "
           "For near and far field together connect probe_light's out as environment and "
           "its visibility as far_visibility beside SSDO's modulation and bounce. "
           "Unconnected: ao and modulation 1, environment and indirect 0. Background pixels "
           "(albedo 0, light 0) stay black. Output is linear and may exceed 1; write's "
           "exposure and tonemap shape the PNG.",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(param_table, struct ssg_combine_params),
    .check = check,
    .flops_per_pixel = combine_flops,
    .run_cpu = ssg_combine_run_cpu,
    .run_gl = ssg_combine_run_gl,
};

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    for (int i = 0; i < SSG_COMBINE_INPUTS; i++) {
        if (in[i].channels != 0 && !ssg_shape_same_size(&in[i], &out[0])) {
            snprintf(why, why_len, "input '%s' is %dx%d, expected the frame's %dx%d",
                     inputs[i].name, in[i].width, in[i].height, out[0].width,
                     out[0].height);
            return SSG_E_SIZE;
        }
    }
    return SSG_OK;
}
