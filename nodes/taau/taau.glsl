// taau.glsl - the `taau` node on GL (method in README.md): taau_cpu.c's maths, one
// invocation per output pixel, each channel a layer, the same operations in the same
// order; `precise` keeps the compiler from fusing the multiply-adds the CPU rounds twice.
// CHANNELS (in's: 1 or 3) is a define from taau_gl.c.
uniform sampler2DArray src;        // input port `in` (a GLSL keyword, hence the name)
uniform sampler2DArray motion;     // x, y: previous pixel minus this one (in's pixels)
uniform sampler2DArray history, weight_in;
layout(r32f) uniform writeonly image2DArray dst_out, dst_weight;
uniform int reset;                 // ctx->history_reset: no history

#pragma ssg_params
#pragma ssg_consts

// One axis (make_axis on the CPU): the nearest sample's index, clamped into in, and the
// Gaussian factor and inside flag of the samples at index - 1, index, index + 1.
int axis(int x, int size, float jit, out vec3 wt, out vec3 inside)
{
    precise float centre = (float(x) + 0.5) * inv_factor;
    precise float c0 = centre - jit;
    int i0 = int(floor(c0));
    i0 = i0 < 0 ? 0 : (i0 > size - 1 ? size - 1 : i0);
    for (int d = 0; d < 3; d++) {
        int i = i0 + d - 1;
        precise float dist = (float(i) + 0.5 + jit - centre) * fac;
        bool in_ = i >= 0 && i < size;
        precise float e = neg_inv_2s2 * (dist * dist);
        wt[d] = in_ ? exp(e) : 0.0;
        inside[d] = in_ ? 1.0 : 0.0;
    }
    return i0;
}

vec4 catmull_rom(float f)
{
    precise vec4 w;
    w.x = f * (-0.5 + f * (1.0 - 0.5 * f));
    w.y = 1.0 + f * f * (-2.5 + 1.5 * f);
    w.z = f * (0.5 + f * (2.0 - 1.5 * f));
    w.w = f * f * (-0.5 + 0.5 * f);
    return w;
}

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    ivec2 in_size = textureSize(src, 0).xy;
    vec3 wx, wy, inx, iny;
    int i0 = axis(p.x, in_size.x, jitter_x, wx, inx);
    int j0 = axis(p.y, in_size.y, jitter_y, wy, iny);
    // the three columns' sums over the three rows (row_sums on the CPU), then the row's
    precise float wsum = ((wx[0] + wx[1]) + wx[2]) * ((wy[0] + wy[1]) + wy[2]);
    precise float count = ((inx[0] + inx[1]) + inx[2]) * ((iny[0] + iny[1]) + iny[2]);
    int ys[3], xs[3];
    for (int d = 0; d < 3; d++) {
        int y = j0 + d - 1, x = i0 + d - 1;
        ys[d] = y < 0 ? 0 : (y > in_size.y - 1 ? in_size.y - 1 : y);
        xs[d] = x < 0 ? 0 : (x > in_size.x - 1 ? in_size.x - 1 : x);
    }
    precise float sum[CHANNELS], m1[CHANNELS], m2[CHANNELS];
    for (int c = 0; c < CHANNELS; c++) {
        precise float cv[3], c1[3], c2[3];
        for (int d = 0; d < 3; d++) {
            float a = texelFetch(src, ivec3(xs[d], ys[0], c), 0).r;
            float b = texelFetch(src, ivec3(xs[d], ys[1], c), 0).r;
            float e = texelFetch(src, ivec3(xs[d], ys[2], c), 0).r;
            cv[d] = wy[0] * a + wy[1] * b + wy[2] * e;
            c1[d] = iny[0] * a + iny[1] * b + iny[2] * e;
            c2[d] = iny[0] * (a * a) + iny[1] * (b * b) + iny[2] * (e * e);
        }
        sum[c] = wx[0] * cv[0] + wx[1] * cv[1] + wx[2] * cv[2];
        m1[c] = inx[0] * c1[0] + inx[1] * c1[1] + inx[2] * c1[2];
        m2[c] = inx[0] * c2[0] + inx[1] * c2[1] + inx[2] * c2[2];
    }
    ivec2 big = ssg_grid;
    vec3 m = ssg_load3(motion, ivec2(i0, j0));
    precise float px = (float(p.x) + 0.5) + m.x * fac;
    precise float py = (float(p.y) + 0.5) + m.y * fac;
    bool valid = reset == 0 && px >= 0.0 && px < float(big.x) && py >= 0.0 &&
                 py < float(big.y);
    float hw = 0.0;
    float h[CHANNELS];
    for (int c = 0; c < CHANNELS; c++)
        h[c] = 0.0;
    if (valid) {
        hw = ssg_load1(weight_in, ivec2(int(px), int(py)));
        hw = hw < p_max_weight ? hw : p_max_weight;
        precise float sx = px - 0.5, sy = py - 0.5;
        float fx0 = floor(sx), fy0 = floor(sy);
        vec4 cx = catmull_rom(sx - fx0), cy = catmull_rom(sy - fy0);
        ivec4 tx, ty;
        for (int k = 0; k < 4; k++) {
            int x = int(fx0) - 1 + k, y = int(fy0) - 1 + k;
            tx[k] = x < 0 ? 0 : (x > big.x - 1 ? big.x - 1 : x);
            ty[k] = y < 0 ? 0 : (y > big.y - 1 ? big.y - 1 : y);
        }
        // per column the four rows, then the columns (history() on the CPU)
        for (int c = 0; c < CHANNELS; c++) {
            precise float col[4];
            for (int a = 0; a < 4; a++) {
                col[a] = cy[0] * texelFetch(history, ivec3(tx[a], ty[0], c), 0).r +
                         cy[1] * texelFetch(history, ivec3(tx[a], ty[1], c), 0).r;
                col[a] = col[a] + cy[2] * texelFetch(history, ivec3(tx[a], ty[2], c), 0).r;
                col[a] = col[a] + cy[3] * texelFetch(history, ivec3(tx[a], ty[3], c), 0).r;
            }
            precise float s = cx[0] * col[0] + cx[1] * col[1];
            s = s + cx[2] * col[2];
            h[c] = s + cx[3] * col[3];
        }
    }
    precise float total = hw + wsum;
    precise float inv_wsum = 1.0 / wsum, inv_total = 1.0 / total;
    for (int c = 0; c < CHANNELS; c++) {
        precise float mean = m1[c] / count;
        precise float var = m2[c] / count - mean * mean;
        // a subnormal weight counts as none (1 / W would be infinite), as on the CPU
        precise float cur = wsum >= 1.17549435e-38 ? sum[c] * inv_wsum : mean;
        precise float sd = p_gamma * sqrt(var > 0.0 ? var : 0.0);
        precise float lo = mean - sd, hi = mean + sd;
        // a history that is not finite is this frame's estimate (it washes out)
        float hf = isnan(h[c]) || isinf(h[c]) ? cur : h[c];
        float hc = hf < lo ? lo : hf;
        hc = hc > hi ? hi : hc;
        float hv = p_gamma > 0.0 ? hc : hf;
        precise float blended = (hw * hv + wsum * cur) * inv_total;
        imageStore(dst_out, ivec3(p, c), vec4(total >= 1.17549435e-38 ? blended : cur));
    }
    SSG_STORE1(dst_weight, p, total < p_max_weight ? total : p_max_weight);
}
