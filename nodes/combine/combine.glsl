// combine.glsl - the `combine` node's GL side (method in README.md, C side combine_gl.c):
//   out = (darken_direct ? M : 1) direct + M ao (environment + k albedo) + (darken_indirect ? M : 1) indirect
//         + M ao albedo irradiance + emission
// (with far_visibility: the far-field form of README.md)
// per channel, with the CPU kernel's stand-ins for unconnected inputs (ao, M = 1;
// environment, indirect = 0) and its order of operations. `precise` keeps the compiler
// from fusing multiply-adds the CPU rounds separately, so a GPU with IEEE float maths gives
// the CPU's bits.
#pragma ssg_params
uniform sampler2DArray direct, albedo, ambient_occlusion, indirect, modulation, environment,
    far_visibility, irradiance, emission;
uniform bool ambient_occlusion_bound, indirect_bound, modulation_bound, environment_bound,
    far_visibility_bound, irradiance_bound, emission_bound;
layout(r32f) uniform writeonly image2DArray dst_out;
// prepare()'s modulation_last (its last layer: 0 or 2) and k (ambient * colour):
#pragma ssg_consts

float layer_or(sampler2DArray t, bool bound, ivec2 p, int layer, float unbound)
{
    return bound ? texelFetch(t, ivec3(p, layer), 0).r : unbound;
}

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    float occ = layer_or(ambient_occlusion, ambient_occlusion_bound, p, 0, 1.0);
    bool darken_direct = p_darken_direct != 0, darken_indirect = p_darken_indirect != 0;
    for (int c = 0; c < 3; c++) {
        float d = texelFetch(direct, ivec3(p, c), 0).r;
        float a = texelFetch(albedo, ivec3(p, c), 0).r;
        float m = layer_or(modulation, modulation_bound, p, min(c, modulation_last), 1.0);
        float env_albedo = p_environment_albedo != 0 ? a : 1.0; // E / pi of a white receiver
        precise float env = layer_or(environment, environment_bound, p, c, 0.0) * env_albedo;
        float bounce = layer_or(indirect, indirect_bound, p, c, 0.0);
        precise float far_light = layer_or(irradiance, irradiance_bound, p, c, 0.0) * a;
        precise float ambient = env + k[c] * a;
        precise float o;
        if (far_visibility_bound) { // combine_cpu.c combine_channel_far
            float v = texelFetch(far_visibility, ivec3(p, 0), 0).r;
            precise float q = v > 0.0 ? m / v : 1.0;
            q = q < 1.0 ? q : 1.0;
            precise float lit_env = q * occ * ambient;
            precise float own = (darken_direct ? m : 1.0) * d + lit_env;
            precise float gap = m - v;
            gap = gap > 0.0 ? gap : 0.0;
            precise float sent = irradiance_bound ? lit_env : own;
            o = own + (darken_indirect ? m : 1.0) * bounce + (p_far_bounce != 0 ? 1.0 : 0.0) * a * gap * sent
                + m * occ * far_light;
        } else {
            o = (darken_direct ? m : 1.0) * d + m * occ * ambient + (darken_indirect ? m : 1.0) * bounce
                + m * occ * far_light;
        }
        if (emission_bound) // added last, as it is (never darkened)
            o += texelFetch(emission, ivec3(p, c), 0).r;
        imageStore(dst_out, ivec3(p, c), vec4(o));
    }
}
