// upsample.glsl - the `upsample` node on GL (method in README.md): one invocation per
// full-res pixel sums the size x size low-res taps around the one containing it in the
// CPU kernel's order (dy, then dx), relative to the centre tap's value, with the same
// log-weights (spatial from where each sample was taken, depth against the pixel's own
// plane there, p ln(n.N)) and one exp; when
// no tap has weight it takes the tap of closest depth (first in row-major order), the
// centre when all are background. exp and ln are bilateral_math.h's polynomials (common.glsl);
// `precise` keeps the compiler from fusing the multiply-adds the CPU rounds twice.
// in2 rides along with the same weights into dst_out2; unconnected, dst_out2 is written 0.
// Defines from upsample_gl.c: IN_CH (1 or 3), IN2_CH (0, 1 or 3), NORMALS (0 or 1).
uniform sampler2DArray src, in2;               // in (a GLSL keyword), in2 (low res)
uniform sampler2DArray depth, normal;          // full res
uniform sampler2DArray low_depth, low_normal;  // low res
layout(r32f) uniform writeonly image2DArray dst_out, dst_out2;
// prepare()'s factor, radius, spatial_k, depth_scale, max_slope and the normal term's
// normal_power, normal_min and squarings (upsample.h):
#pragma ssg_consts
#include "joint_weights.glsl" // joint_weight(): a tap's weight, as the CPU's add_tap

#if IN_CH == 3
#define VALUE vec3
#define LOAD ssg_load3
#define STORE SSG_STORE3
#else
#define VALUE float
#define LOAD ssg_load1
#define STORE SSG_STORE1
#endif

// upsample_cpu.c's plane_slope: the one-sided depth difference of smaller magnitude (ties:
// hi - d), 0 when neither neighbour (depth lo, hi; 0 = background or outside) is a surface
// or it is steeper than max_slope d (it crosses an edge).
float plane_slope(float d, float lo, float hi)
{
    float inf = uintBitsToFloat(0x7f800000u);
    precise float f = hi > 0.0 ? hi - d : inf;
    precise float b = lo > 0.0 ? d - lo : inf;
    float s = abs(f) <= abs(b) ? f : b;
    precise float limit = max_slope * d;
    return abs(s) <= limit ? s : 0.0;
}

// Full-res depth at p, 0 outside the image.
float depth_at(ivec2 p)
{
    ivec2 size = textureSize(depth, 0).xy;
    bool inside = all(greaterThanEqual(p, ivec2(0))) && all(lessThan(p, size));
    return inside ? ssg_load1(depth, p) : 0.0;
}

// upsample_cpu.c's sample_offset: where low-res pixel q (depth dq) was taken in its block,
// the first full-res pixel in row-major order of depth dq exactly, else the centre.
vec2 sample_offset(ivec2 q, float dq)
{
    ivec2 size = textureSize(depth, 0).xy, b0 = q * factor;
    ivec2 b1 = min(b0 + factor, size);
    if (dq > 0.0)
        for (int y = b0.y; y < b1.y; y++)
            for (int x = b0.x; x < b1.x; x++)
                if (ssg_load1(depth, ivec2(x, y)) == dq)
                    return vec2(ivec2(x, y) - b0);
    return vec2(0.5 * float(factor - 1));
}

// No tap had weight: the tap of closest depth (first in tap order on ties), or the centre.
ivec2 fallback(ivec2 l, float dp)
{
    ivec2 best = l, last = textureSize(low_depth, 0).xy - 1;
    float best_err = uintBitsToFloat(0x7f800000u); // +inf
    for (int qy = max(l.y - radius, 0); qy <= min(l.y + radius, last.y); qy++)
        for (int qx = max(l.x - radius, 0); qx <= min(l.x + radius, last.x); qx++) {
            float d = ssg_load1(low_depth, ivec2(qx, qy)), err = abs(d - dp);
            if (d > 0.0 && err < best_err) {
                best_err = err;
                best = ivec2(qx, qy);
            }
        }
    return best;
}

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    float dp = ssg_load1(depth, p);
    VALUE val = VALUE(0.0);
    VALUE2 val2 = VALUE2(0.0);
    if (dp > 0.0) { // background pixels stay 0
        ivec2 l = p / factor, last = textureSize(low_depth, 0).xy - 1;
        float kd = depth_scale / dp;
        vec3 nc = vec3(0.0);
#if NORMALS
        nc = ssg_unit_normal(normal, p);
#endif
        VALUE ref = LOAD(src, l);
        precise VALUE acc = VALUE(0.0);
#if IN2_CH
        VALUE2 ref2 = LOAD2(in2, l);
        precise VALUE2 acc2 = VALUE2(0.0);
#endif
        precise float wsum = 0.0;
        ivec2 ex = ivec2(1, 0), ey = ivec2(0, 1);
        vec2 slope = vec2(plane_slope(dp, depth_at(p - ex), depth_at(p + ex)),
                          plane_slope(dp, depth_at(p - ey), depth_at(p + ey)));
        for (int dy = -radius; dy <= radius; dy++) {
            int qy = l.y + dy;
            if (qy < 0 || qy > last.y)
                continue;
            for (int dx = -radius; dx <= radius; dx++) {
                ivec2 q = ivec2(l.x + dx, qy);
                if (q.x < 0 || q.x > last.x)
                    continue; // the CPU's padding: weight 0, adds nothing
                // the offset from the sample to the pixel, in full-res px (the CPU's rx, ry)
                vec2 at = sample_offset(q, ssg_load1(low_depth, q));
                precise vec2 r = vec2(p - q * factor) - at;
                precise float es = spatial_k * (r.x * r.x + r.y * r.y);
                precise float plane = dp - (slope.x * r.x + slope.y * r.y);
                float w = joint_weight(low_depth, low_normal, q, es, plane, kd, nc);
                wsum += w;
                acc += w * (LOAD(src, q) - ref);
#if IN2_CH
                acc2 += w * (LOAD2(in2, q) - ref2);
#endif
            }
        }
        ivec2 f = wsum > 0.0 ? l : fallback(l, dp);
        val = wsum > 0.0 ? ref + acc / wsum : LOAD(src, f);
#if IN2_CH
        val2 = wsum > 0.0 ? ref2 + acc2 / wsum : LOAD2(in2, f);
#endif
    }
    STORE(dst_out, p, val);
#if IN2_CH
    STORE2(dst_out2, p, val2);
#else
    STORE(dst_out2, p, VALUE(0.0)); // out2 is all 0, shaped like out
#endif
}
