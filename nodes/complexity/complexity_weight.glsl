// complexity_weight.glsl - second pass of the `complexity` node's GL side (mapping in
// README.md, C side complexity_gl.c): one invocation per cell, its weight t from the
// normal and relative depth gradients over its non-empty 4-neighbours, in the CPU's order
// (left, right, up, down) and with its float expressions (complexity_cpu.c, cell_weight);
// `precise` keeps multiply-adds unfused as on the CPU. 0 for an empty cell.
uniform sampler2DArray nd; // mean normal x, y, z and mean depth (0 = empty cell)
uniform sampler2DArray pt; // mean view-space point
layout(r32f) uniform writeonly image2DArray weight;
// p_normal_threshold, p_normal_gain, p_depth_threshold, p_depth_gain from the table:
#pragma ssg_params

vec4 load4(sampler2DArray t, ivec2 p)
{
    return vec4(ssg_load3(t, p), texelFetch(t, ivec3(p, 3), 0).r);
}

// The CPU's clamp01 (a NaN gives 0, where GLSL's clamp is undefined).
float clamp01(float v)
{
    return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;
}

float cell_weight(ivec2 g, vec4 c)
{
    const ivec2 towards[4] = ivec2[](ivec2(-1, 0), ivec2(1, 0), ivec2(0, -1), ivec2(0, 1));
    ivec2 cells = textureSize(nd, 0).xy;
    vec3 n = c.xyz, pc = ssg_load3(pt, g);
    precise float len = sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    precise float inv = len > 1e-6 ? 1.0 / len : 0.0;
    precise float gn = 0.0, gd = 0.0;
    for (int k = 0; k < 4; k++) {
        ivec2 b = g + towards[k];
        if (any(lessThan(b, ivec2(0))) || any(greaterThanEqual(b, cells)))
            continue;
        vec4 nb = load4(nd, b);
        if (!(nb.w > 0.0))
            continue;
        vec3 e = n - nb.xyz, pb = ssg_load3(pt, b);
        gn += sqrt(e.x * e.x + e.y * e.y + e.z * e.z);
        float off = n.x * (pb.x - pc.x) + n.y * (pb.y - pc.y) + n.z * (pb.z - pc.z);
        gd += abs(off) * inv;
    }
    gd /= c.w;
    precise float tn = clamp01((gn - p_normal_threshold) * p_normal_gain);
    precise float td = clamp01((gd - p_depth_threshold) * p_depth_gain);
    return tn > td ? tn : td;
}

void main()
{
    ivec2 g = ssg_pixel();
    if (ssg_outside(g))
        return;
    vec4 c = load4(nd, g);
    SSG_STORE1(weight, g, c.w > 0.0 ? cell_weight(g, c) : 0.0);
}
