// temporal.glsl - the `temporal` node on GL (method in README.md): temporal_cpu.c's
// maths, one invocation per pixel, each channel a layer, the same operations in the same
// order; `precise` keeps the compiler from fusing the multiply-adds the CPU rounds twice.
// CHANNELS (in's: 1 or 3), IN2_CH (0 or 3) and NORMALS (0 or 1) are defines from
// temporal_gl.c.
uniform sampler2DArray src;         // input port `in` (a GLSL keyword, hence the name)
uniform sampler2DArray in2;         // read only with IN2_CH > 0
uniform sampler2DArray history, history2, length_in;
uniform sampler2DArray motion;      // x, y: previous pixel minus this one (px); z: depth there
uniform sampler2DArray depth, prev_depth;
uniform sampler2DArray normal, prev_normal; // read only with NORMALS
layout(r32f) uniform writeonly image2DArray dst_out, dst_out2, dst_length;
uniform int reset;                  // ctx->history_reset: out = in, length 1

#pragma ssg_params
#pragma ssg_consts

// The four bilinear taps of the previous frame (reproject() in temporal_cpu.c): pixels and
// weights, 0 for a rejected tap.
ivec2 tap_q[4];
float tap_w[4];

float tap_sum(ivec2 p, vec3 m)
{
    ivec2 size = ssg_grid;
    float px = float(p.x) + m.x, py = float(p.y) + m.y;
    px = px > -2.0 ? px : -2.0;
    px = px < float(size.x) + 1.0 ? px : float(size.x) + 1.0;
    py = py > -2.0 ? py : -2.0;
    py = py < float(size.y) + 1.0 ? py : float(size.y) + 1.0;
    float fx0 = floor(px), fy0 = floor(py);
    precise float fx = px - fx0, fy = py - fy0;
    ivec2 i0 = ivec2(int(fx0), int(fy0));
    bool here = ssg_load1(depth, p) > 0.0 && m.z > 0.0;
#if NORMALS
    vec3 n = ssg_load3(normal, p);
#endif
    precise float wsum = 0.0;
    for (int t = 0; t < 4; t++) {
        ivec2 q = i0 + ivec2(t & 1, t >> 1);
        bool inside = q.x >= 0 && q.x < size.x && q.y >= 0 && q.y < size.y;
        q = inside ? q : p;
        precise float wx = (t & 1) != 0 ? fx : 1.0 - fx;
        precise float wy = (t >> 1) != 0 ? fy : 1.0 - fy;
        float pd = ssg_load1(prev_depth, q);
        precise float dz = abs(m.z - pd), lim = p_depth_tolerance * m.z;
        bool ok = here && inside && pd > 0.0 && dz <= lim;
#if NORMALS
        vec3 pn = ssg_load3(prev_normal, q);
        precise float c = n.x * pn.x + n.y * pn.y + n.z * pn.z;
        ok = ok && c >= p_normal_tolerance;
#endif
        precise float w = ok ? wx * wy : 0.0;
        tap_q[t] = q;
        tap_w[t] = w;
        wsum += w;
    }
    return wsum;
}

// The tap-weighted mean of layer c of a previous-frame image (fetch() on the CPU).
float fetch(sampler2DArray t, int c, float wsum)
{
    precise float s = tap_w[0] * texelFetch(t, ivec3(tap_q[0], c), 0).r +
                      tap_w[1] * texelFetch(t, ivec3(tap_q[1], c), 0).r;
    s = s + tap_w[2] * texelFetch(t, ivec3(tap_q[2], c), 0).r;
    s = s + tap_w[3] * texelFetch(t, ivec3(tap_q[3], c), 0).r;
    return s / wsum;
}

// One channel: the 3 x 3 moments of the current value (dy, then dx, taps outside the
// image left out), the history clamped to mean +/- gamma sigma, the blend.
float channel(sampler2DArray cur, sampler2DArray hist, int c, ivec2 p, bool valid,
              float alpha, float wsum)
{
    precise float m1 = 0.0, m2 = 0.0, count = 0.0;
    for (int dy = -1; dy <= 1; dy++) {
        if (p.y + dy < 0 || p.y + dy >= ssg_grid.y)
            continue;
        for (int dx = -1; dx <= 1; dx++) {
            if (p.x + dx < 0 || p.x + dx >= ssg_grid.x)
                continue;
            float a = texelFetch(cur, ivec3(p + ivec2(dx, dy), c), 0).r;
            count += 1.0;
            m1 += a;
            m2 += a * a;
        }
    }
    precise float hv = valid ? fetch(hist, c, wsum) : 0.0;
    precise float mean = m1 / count;
    precise float var = m2 / count - mean * mean;
    float sd = sqrt(var > 0.0 ? var : 0.0);
    precise float lo = mean - p_gamma * sd, hi = mean + p_gamma * sd;
    float hc = hv < lo ? lo : hv;
    hc = hc > hi ? hi : hc;
    hv = p_gamma > 0.0 ? hc : hv;
    float v = texelFetch(cur, ivec3(p, c), 0).r;
    precise float blended = hv + alpha * (v - hv);
    return valid ? blended : v;
}

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    if (reset != 0) { // no earlier frame may be reused
        for (int c = 0; c < CHANNELS; c++)
            imageStore(dst_out, ivec3(p, c), vec4(texelFetch(src, ivec3(p, c), 0).r));
#if IN2_CH
        for (int c = 0; c < IN2_CH; c++)
            imageStore(dst_out2, ivec3(p, c), vec4(texelFetch(in2, ivec3(p, c), 0).r));
#endif
        SSG_STORE1(dst_length, p, 1.0);
    } else {
        float wsum = tap_sum(p, ssg_load3(motion, p));
        bool valid = wsum >= SSG_TEMPORAL_MIN_WEIGHT;
        float n = valid ? fetch(length_in, 0, wsum) : 0.0;
        precise float l = n + 1.0;
        float a = 1.0 / l;
        float alpha = a > inv_max_length ? a : inv_max_length;
        SSG_STORE1(dst_length, p, valid ? (l < length_cap ? l : length_cap) : 1.0);
        for (int c = 0; c < CHANNELS; c++)
            imageStore(dst_out, ivec3(p, c), vec4(channel(src, history, c, p, valid, alpha,
                                                          wsum)));
#if IN2_CH
        for (int c = 0; c < IN2_CH; c++)
            imageStore(dst_out2, ivec3(p, c), vec4(channel(in2, history2, c, p, valid,
                                                           alpha, wsum)));
#endif
    }
#if IN2_CH == 0
    for (int c = 0; c < CHANNELS; c++) // out2 is all 0, shaped like out
        imageStore(dst_out2, ivec3(p, c), vec4(0.0));
#endif
}
