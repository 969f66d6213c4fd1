// combine.glsl - the `combine` node's GL side (equation in combine.c, C side combine_gl.c):
//   out = M direct + M ao (environment + k albedo) + (darken_indirect ? M : 1) indirect
// (with far_visibility: the far-field form of combine.c)
// per channel, with the CPU kernel's stand-ins for unconnected inputs (ao, M = 1;
// environment, indirect = 0) and its order of operations. `precise` keeps the compiler
// from fusing multiply-adds the CPU rounds separately, so a GPU with IEEE float maths gives
// the CPU's bits.
uniform sampler2DArray direct, albedo, ao, indirect, modulation, environment, far_visibility;
uniform bool ao_bound, indirect_bound, modulation_bound, environment_bound, far_visibility_bound;
uniform bool far_bounce;
layout(r32f) uniform writeonly image2DArray dst;
uniform int modulation_last; // last layer of the modulation: 0 (one factor) or 2 (RGB)
uniform bool darken_indirect, indirect_albedo;
uniform vec3 k;              // ambient * ambient_color, made on the CPU

float layer_or(sampler2DArray t, bool bound, ivec2 p, int layer, float unbound)
{
    return bound ? texelFetch(t, ivec3(p, layer), 0).r : unbound;
}

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    float occ = layer_or(ao, ao_bound, p, 0, 1.0);
    for (int c = 0; c < 3; c++) {
        float d = texelFetch(direct, ivec3(p, c), 0).r;
        float a = texelFetch(albedo, ivec3(p, c), 0).r;
        float m = layer_or(modulation, modulation_bound, p, min(c, modulation_last), 1.0);
        float env = layer_or(environment, environment_bound, p, c, 0.0);
        precise float bounce = layer_or(indirect, indirect_bound, p, c, 0.0);
        bounce = indirect_albedo ? bounce * a : bounce;
        precise float ambient = env + k[c] * a;
        precise float o;
        if (far_visibility_bound) { // combine_cpu.c combine_channel_far
            float v = texelFetch(far_visibility, ivec3(p, 0), 0).r;
            precise float q = v > 0.0 ? m / v : 1.0;
            q = q < 1.0 ? q : 1.0;
            precise float own = m * d + q * occ * ambient;
            precise float gap = m - v;
            gap = gap > 0.0 ? gap : 0.0;
            o = own + (darken_indirect ? m : 1.0) * bounce + (far_bounce ? 1.0 : 0.0) * a * gap * own;
        } else {
            o = m * d + m * occ * ambient + (darken_indirect ? m : 1.0) * bounce;
        }
        imageStore(dst, ivec3(p, c), vec4(o));
    }
}
