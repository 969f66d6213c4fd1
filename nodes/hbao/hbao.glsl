// hbao.glsl - the `hbao` node on GL (method and geometry in README.md): one invocation per
// pixel, its integrator on the march of nodes/common/horizon.glsl. The maths is
// hbao_cpu.c's lane by lane: the same per-pixel basis and march length, per-direction
// coefficients (setup_direction), rounded steps, slice projection and horizon tests
// (place_step, horizon_one), the same sums in the same
// order (`precise`: no multiply-add fused where the CPU rounds twice): directions in pairs
// D, -D when their number is even, per step D's sample then -D's. Where the CPU lets a
// sample fail through +inf or NaN (off screen, background, rejected by place_step) or
// masks a direction past the pixel's count, this skips it: the CPU adds exactly 0 there.
#define SSG_SAMPLING_NO_KERNEL 1 // hbao marches along directions, it has no kernel
#include "sampling.glsl" // position, depth, rotation and their helpers
uniform sampler2DArray count;
uniform bool count_bound;
layout(r32f) uniform writeonly image2DArray dst_out;

#pragma ssg_params
#pragma ssg_consts
uniform float dir_cos[64], dir_sin[64];
uniform int dir_rank[64]; // place of each direction in the count input's order
#include "horizon.glsl" // the march: e1, invf, proj, the pixel, the slice, the steps

// The tile's rotation at p and the step jitter u in (0, 1] from the cell half a tile away
// (hbao_pattern.c; the angle in float here, in double there).
void load_pattern(ivec2 p)
{
    g_co = 1.0, g_si = 0.0, g_u = 1.0;
    if (!rotation_bound)
        return;
    int n = textureSize(rotation, 0).x;
    vec2 r = ssg_load2(rotation, p % n), h = ssg_load2(rotation, (p + n / 2) % n);
    g_co = r.x, g_si = r.y;
    float a = atan(h.y, h.x) / (2.0 * SSG_PI);
    float u = 1.0 - (a - floor(a));
    g_u = u > 0.0 ? u : 1.0;
}

// Direction k (hbao_cpu.c setup_direction): sin(t + bias) of D and -D, and which member
// adds nothing (past the zenith, or a slice too thin).
vec2 s_stb;
bvec2 s_off;

void setup_direction(int k)
{
    ssg_horizon_slice(dir_cos[k], dir_sin[k]);
    precise float ir = 1.0 / sqrt(s_sl);
    precise float isl = s_mn * ir * ir;
    ssg_horizon_fold(isl);
    precise float st = -s_dn * ir, ct = g_vn * ir;
    precise float stb = st * cos_bias + ct * sin_bias, ctb = ct * cos_bias - st * sin_bias;
    precise float stb2 = ct * sin_bias - st * cos_bias, ctb2 = ct * cos_bias + st * sin_bias;
    s_stb = vec2(stb, stb2);
    bool thin = s_sl < SSG_HORIZON_SLICE_MIN;
    s_off = bvec2(ctb < 0.0 || thin, ctb2 < 0.0 || thin);
}

// The sample at pixel p + o with H'.V = dq a + L dp, H'.D = dq b raises the horizon
// (bv, bq) when within R and higher (hbao_cpu.c horizon_one); linear adds its term.
void horizon(ivec2 p, vec2 o, float a, float b, inout float bv, inout float bq,
             inout float occ)
{
    float dq = ssg_horizon_depth(p, o.x, o.y);
    if (!(dq < 1.0 / 0.0))
        return;
    precise float hv = dq * a + g_ldp;
    precise float hd = dq * b;
    precise float q = hv * hv + hd * hd;
    if (!(q > 0.0 && q <= r2))
        return; // P's own pixel (q = 0) is never higher
    if (p_falloff == FALLOFF_LINEAR) {
        precise float r = sqrt(q);
        precise float sh = hv / r;
        if (sh > bv) {
            precise float gain = (sh - bv) * (1.0 - r * inv_radius);
            occ += gain;
            bv = sh;
        }
    } else {
        precise float lhs = hv * abs(hv) * bq, rhs = bv * abs(bv) * q;
        if (lhs > rhs) {
            bv = hv;
            bq = q;
        }
    }
}

// Direction k, and its opposite when `pair`; `act` says which members the pixel uses.
void march(ivec2 p, int k, bool pair, bvec2 act, inout float occ)
{
    setup_direction(k);
    bool on0 = act.x && !s_off.x, on1 = pair && act.y && !s_off.y;
    if (!on0 && !on1)
        return;
    float bv0 = s_stb.x, bv1 = s_stb.y, bq0 = 1.0, bq1 = 1.0;
    for (int j = 0; j < p_steps; j++) {
        ssg_horizon_place(j);
        if (!t_ok)
            continue; // more off the slice than along it (place_step)
        if (on0)
            horizon(p, vec2(t_ou, t_ov), t_a.x, t_b, bv0, bq0, occ);
        if (on1)
            horizon(p, -vec2(t_ou, t_ov), t_a.y, t_b, bv1, bq1, occ);
    }
    if (p_falloff == FALLOFF_LINEAR)
        return;
    // Falloff none: sin h - sin(t + bias) of the final horizon (finish_direction).
    precise float g0 = bv0 / sqrt(bq0) - s_stb.x, g1 = bv1 / sqrt(bq1) - s_stb.y;
    if (on0 && g0 > 0.0)
        occ += g0;
    if (on1 && g1 > 0.0)
        occ += g1;
}

// The sum of the horizon terms over the pixel's first n directions (in the count
// order), marched in the CPU's order: pairs k, k + directions / 2, or one by one.
float occlusion(ivec2 p, int n)
{
    precise float occ = 0.0;
    int half_n = p_directions / 2;
    if (p_directions % 2 == 0) {
        for (int k = 0; k < half_n; k++) {
            bvec2 act = bvec2(dir_rank[k] < n, dir_rank[k + half_n] < n);
            if (any(act))
                march(p, k, true, act, occ);
        }
    } else {
        for (int k = 0; k < p_directions; k++)
            if (dir_rank[k] < n)
                march(p, k, false, bvec2(true, false), occ);
    }
    return occ;
}

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    if (!ssg_horizon_surface(p)) { // background or garbage: 1
        SSG_STORE1(dst_out, p, 1.0);
        return;
    }
    load_pattern(p);
    precise float st = ssg_horizon_pixel(p, p_radius, p_max_screen_radius, true) * inv_steps;
    g_step = st;
    int n = ssg_pixel_count(count, count_bound, p, p_directions);
    float occ = occlusion(p, n);
    precise float sc = n == p_directions ? scale : p_strength / float(n);
    precise float v = 1.0 - occ * sc;
    v = v > 0.0 ? v : 0.0;
    SSG_STORE1(dst_out, p, v < 1.0 ? v : 1.0);
}
