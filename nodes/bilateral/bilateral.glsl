// bilateral.glsl - the `bilateral` node on GL (method in README.md): one invocation per
// pixel sums the window's taps in the CPU kernel's order (dy, then dx, taps outside the
// image skipped) with the same weights: spatial log-weight from prepare(), relative depth
// term, normal term by squarings (power 2^m) or p ln(c), one exp. exp and ln are
// bilateral_math.h's polynomials (ssg_exp_neg, ssg_log_pos in common.glsl), so weights are
// the CPU's to the last bit or two;
// `precise` keeps the compiler from fusing the multiply-adds the CPU rounds twice.
// separable=true dispatches this twice (reach (r, 0) into a scratch image, then (0, r));
// the `atrous` node once a pass, its 5 x 5 taps `step` px apart.
// CHANNELS (1 or 3), IN2_CH (0, 1 or 3) and NORMALS (0 or 1) are defines from bilateral_gl.c.
// in2 rides along with the same weights into dst2; unconnected, dst2 is written 0.
layout(std430, binding = 0) readonly buffer Spatial { float spatial[]; };

uniform sampler2DArray src;   // the image to smooth (or the row pass's result)
uniform sampler2DArray src2;  // in2 (or its row pass's result)
uniform sampler2DArray depth; // linear depth; 0 = background
uniform sampler2DArray normal;
layout(r32f) uniform writeonly image2DArray dst, dst2;
uniform ivec2 reach;          // half-widths walked: (r, r), (r, 0) or (0, r)
uniform int step;             // px between taps: 1, or an a-trous pass's dilation
// prepare()'s radius and size (of the spatial table: row (dy + radius) * size + dx +
// radius), depth_scale (1 / sigma_depth), and with NORMALS squarings (normal weight
// c^(2^squarings); -1: p ln(c) in the exponent), normal_power and normal_min:
#pragma ssg_consts
#include "joint_weights.glsl" // joint_weight(): a tap's weight, as the CPU's add_tap

#if CHANNELS == 3
#define VALUE vec3
#define LOAD ssg_load3
#define STORE SSG_STORE3
#else
#define VALUE float
#define LOAD ssg_load1
#define STORE SSG_STORE1
#endif

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    float dc = ssg_load1(depth, p);
    float kd = dc > 0.0 ? depth_scale / dc : 0.0;
    vec3 nc = vec3(0.0);
#if NORMALS
    nc = ssg_unit_normal(normal, p);
#endif
    precise VALUE acc = VALUE(0.0);
    precise VALUE2 acc2 = VALUE2(0.0);
    precise float wsum = 0.0;
    ivec2 last = ssg_grid - 1;
    for (int dy = -reach.y; dy <= reach.y; dy++) {
        if (p.y + dy * step < 0 || p.y + dy * step > last.y)
            continue;
        for (int dx = -reach.x; dx <= reach.x; dx++) {
            ivec2 q = p + ivec2(dx, dy) * step;
            if (q.x < 0 || q.x > last.x)
                continue;
            float w = joint_weight(depth, normal, q,
                                   spatial[(dy + radius) * size + dx + radius], dc, kd, nc);
            wsum += w;
            acc += w * LOAD(src, q);
#if IN2_CH
            acc2 += w * LOAD2(src2, q);
#endif
        }
    }
    // Background, or nothing with weight (zero normal): pass through.
    bool keep = !(dc > 0.0) || !(wsum > 0.0);
    STORE(dst, p, keep ? LOAD(src, p) : acc / wsum);
#if IN2_CH
    STORE2(dst2, p, keep ? LOAD2(src2, p) : acc2 / wsum);
#else
    STORE(dst2, p, VALUE(0.0)); // out2 is all 0, shaped like out
#endif
}
