// downsample.glsl - the `downsample` node on GL (method in README.md): one invocation
// per output pixel picks its block's representative (the pixel whose depth is closest to
// the median of the block's surface depths, ties to the first in row-major order, the
// first pixel when all is background) exactly as downsample_cpu.c does, then copies every
// port from it; an unconnected port's output is 0.
// Inputs by their port names, outputs as dst_<port> (ssg_gl_ports); p_factor, the block
// side (2 or 4), from the parameter table.
uniform sampler2DArray depth;
uniform sampler2DArray position, normal, albedo, direct, environment, motion;
uniform bool position_bound, normal_bound, albedo_bound, direct_bound, environment_bound,
    motion_bound;
layout(r32f) uniform writeonly image2DArray dst_depth;
layout(r32f) uniform writeonly image2DArray dst_position, dst_normal, dst_albedo, dst_direct,
    dst_environment, dst_motion;
#pragma ssg_params

const int MAX_BLOCK = 16;

// The median of v[0 .. n - 1], n > 0: the CPU's body (downsample_cpu.c), one text.
float median(inout float v[MAX_BLOCK], int n)
{
#include "median.glsl"
}

ivec2 representative(ivec2 b)
{
    ivec2 p0 = b * p_factor, p1 = min(p0 + p_factor, textureSize(depth, 0).xy);
    float v[MAX_BLOCK];
    int n = 0;
    for (int y = p0.y; y < p1.y; y++)
        for (int x = p0.x; x < p1.x; x++) {
            float d = ssg_load1(depth, ivec2(x, y));
            if (d > 0.0)
                v[n++] = d;
        }
    ivec2 best = p0;
    if (n == 0)
        return best; // all background: its first pixel
    float m = median(v, n), best_err = uintBitsToFloat(0x7f800000u); // +inf
    for (int y = p0.y; y < p1.y; y++)
        for (int x = p0.x; x < p1.x; x++) {
            float d = ssg_load1(depth, ivec2(x, y)), err = abs(d - m);
            if (d > 0.0 && err < best_err) { // strict: ties keep the first
                best_err = err;
                best = ivec2(x, y);
            }
        }
    return best;
}

#define COPY3(port, q, p) \
    SSG_STORE3(dst_##port, p, port##_bound ? ssg_load3(port, q) : vec3(0.0))

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    ivec2 q = representative(p);
    SSG_STORE1(dst_depth, p, ssg_load1(depth, q));
    COPY3(position, q, p);
    COPY3(normal, q, p);
    COPY3(albedo, q, p);
    COPY3(direct, q, p);
    COPY3(environment, q, p);
    // motion in output pixels from p's centre, as downsample_cpu.c's rescale_motion (1 / f
    // is exact for f = 2 or 4, so the products are too)
    vec3 m = motion_bound ? ssg_load3(motion, q) : vec3(0.0);
    float inv_f = 1.0 / float(p_factor);
    if (motion_bound)
        m.xy = m.xy * inv_f + ((vec2(q) + 0.5) * inv_f - (vec2(p) + 0.5));
    SSG_STORE3(dst_motion, p, m);
}
