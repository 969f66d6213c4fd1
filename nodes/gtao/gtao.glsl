// gtao.glsl - the `gtao` node on GL (method and geometry in README.md): one invocation per
// pixel, its integrator on the march of nodes/common/horizon.glsl, gtao_cpu.c's
// operations in its order for one lane of its chunk (`precise`: no
// multiply-add fused where the CPU rounds twice): slices in order, per step the +D sample
// then the -D one, the same folded sample formulas and polynomial acos. Only sqrt,
// division and pow (power != 1) may round differently from the CPU's.
#define SSG_SAMPLING_NO_KERNEL 1 // gtao marches along slices, it has no kernel
#include "sampling.glsl" // position, depth, rotation and their helpers
uniform sampler2DArray back; // the depth of the next surface behind, when back_bound
uniform bool back_bound;
layout(r32f) uniform writeonly image2DArray dst_out;
layout(r32f) uniform writeonly image2DArray dst_bent_normal;

// The parameters (#pragma ssg_params: p_<field>) and what prepare() derived from them.
#pragma ssg_params
#pragma ssg_consts
uniform float slice_cos[32], slice_sin[32]; // this frame's (ssg_gtao_frame_of)
uniform float noise_shift; // this frame's jitter noise offset, pixels
#include "horizon.glsl" // the march: e1, invf, proj, the pixel, the slice, the steps

const float HALF_PI = SSG_HORIZON_HALF_PI;
const float OPEN_EPS = 1e-5; // gtao_cpu.c: a horizon this close to its lowest is none

// gtao_cpu.c load_chunk and ssg_horizon_setup: the tile's rotation, the step jitter
// 1 - interleaved gradient noise, and the march's step.
void setup_pixel(ivec2 p)
{
    precise float x = float(p.x) + noise_shift, y = float(p.y) + noise_shift;
    precise float u = 1.0 - ssg_ign(x, y);
    g_u = u;
    g_co = 1.0, g_si = 0.0;
    if (rotation_bound) {
        vec2 r = ssg_tile_rotation(p);
        g_co = r.x, g_si = r.y;
    }
    precise float rp = ssg_horizon_pixel(p, p_radius, p_max_screen_radius, false);
    precise float st = rp / float(p_steps);
    g_step = st;
}

// gtao_cpu.c weight: the linear fade, or the hard cutoff r <= R.
float weight(float q)
{
    if (!(p_falloff > 0.0))
        return q <= p_radius * p_radius ? 1.0 : 0.0;
    precise float w = sqrt(q) * fall_mul + fall_add;
    w = w < 0.0 ? 0.0 : w;
    return w < 1.0 ? w : 1.0;
}

// gtao_cpu.c horizon_one (general path): hc is the side's horizon cosine.
void horizon_one(float dq, float a, float r, float b, float e, float low, inout float hc)
{
    precise float hv = dq * r + g_ldp, pv = dq * a + g_ldp, pd = dq * b;
    precise float q = hv * hv + dq * dq * e;
    float w = weight(q);
    precise float shc = pv / sqrt(pv * pv + pd * pd);
    precise float sh = low + w * (shc - low);
    if (sh > hc)
        hc = sh;
    else if (w > 0.0 && p_thickness > 0.0) {
        precise float nh = hc + p_thickness * (sh - hc);
        hc = nh;
    }
}

// The back input at pixel p + o (inside: ssg_horizon_depth found the front there), as the CPU's
// padded back plane has it: +inf where not a plausible depth.
float back_at(ivec2 p, float ou, float ov)
{
    precise float qx = float(p.x) + ou, qy = float(p.y) + ov;
    float d = texelFetch(back, ivec3(int(qx), int(qy), 0), 0).r;
    return d > 0.0 && d <= 3.0e38 ? d : 1.0 / 0.0;
}

// gtao_cpu.c horizon_back: the sample occludes between its front and back points (the
// back clipped to the sphere of radius R, down to the previous sample's front when the
// surface runs on from it); raises the top hc, lowers the bottom bot.
void horizon_back(float dq, float db, float a, float r, float b, float e, float low,
                  inout float hc, inout float bot, inout float pdep, inout float pcos)
{
    precise float hv = dq * r + g_ldp, pv = dq * a + g_ldp, pd = dq * b;
    precise float q = hv * hv + dq * dq * e;
    float w = weight(q);
    precise float qa = r * r + e, qb = r * g_ldp, qc = g_ldp * g_ldp - p_radius * p_radius;
    precise float disc = qb * qb - qa * qc;
    precise float ex = (sqrt(disc > 0.0 ? disc : 0.0) - qb) / qa;
    precise float d = db < ex ? db : ex;
    d = d > dq ? d : dq;
    precise float bv = d * a + g_ldp, bd = d * b;
    precise float top = pv / sqrt(pv * pv + pd * pd), under = bv / sqrt(bv * bv + bd * bd);
    precise float ft = low + w * (top - low), fu = low + w * (under - low);
    fu = db < 1.0 / 0.0 ? fu : low; // none behind: solid
    fu = pdep <= db + link && pcos < fu ? pcos : fu;
    pdep = dq, pcos = ft;
    if (!(w > 0.0 && ft > low + OPEN_EPS))
        return;
    if (fu < bot)
        bot = fu;
    if (ft > hc)
        hc = ft;
}

// gtao_cpu.c horizon_fast: (hv, hq) = H'.V and |H'|^2 of the highest sample within R.
void horizon_fast(float dq, float a, float r, float b, float e, inout float hv, inout float hq)
{
    precise float rv = dq * r + g_ldp, pv = dq * a + g_ldp, pd = dq * b;
    precise float d2 = rv * rv + dq * dq * e;
    precise float q = pv * pv + pd * pd;
    precise float lhs = pv * abs(pv) * hq, rhs = hv * abs(hv) * q;
    if (d2 <= p_radius * p_radius && lhs > rhs)
        hv = pv, hq = q;
}

// gtao_cpu.c side_arc: half the inner integral and the side's bent-normal terms.
vec3 side_arc(float hc, float low, float sg, float n, float cn, float sn)
{
    precise float lim = n + sg * HALF_PI;
    if (!(hc > low + OPEN_EPS)) {
        precise float c2 = cn * cn - sn * sn, s2 = 2.0 * sn * cn;
        precise vec3 r = vec3(0.25 * (cn + 2.0 * lim * sn + cn), sg * (6.0 - 2.0 * c2),
                              2.0 * sg * s2);
        return r;
    }
    precise float h = sg * ssg_acos(hc);
    bool clamp_h = sg > 0.0 ? !(h < lim) : !(h > lim);
    precise float ch = hc, sh = sg * sqrt((1.0 - hc) * (1.0 + hc));
    if (clamp_h) {
        h = lim;
        ch = -sg * sn;
        sh = sg * cn;
    }
    precise float c2h = ch * ch - sh * sh, s2h = 2.0 * sh * ch;
    precise float c3h = ch * c2h - sh * s2h, s3h = sh * c2h + ch * s2h;
    precise float sin_hmn = sh * cn - ch * sn, sin_hpn = sh * cn + ch * sn;
    precise float sin_3hmn = s3h * cn - c3h * sn, cos_3hmn = c3h * cn + s3h * sn;
    precise float cos_hpn = ch * cn - sh * sn, cos_2hmn = c2h * cn + s2h * sn;
    precise vec3 r = vec3(0.25 * (cn + 2.0 * h * sn - cos_2hmn),
                          6.0 * sin_hmn - sin_3hmn - 3.0 * sin_hpn, -cos_3hmn - 3.0 * cos_hpn);
    return r;
}

// gtao_cpu.c side_arc_back: visible = side up to the top + the arc from the bottom down.
vec3 side_arc_back(float hc, float bot, float low, float sg, float n, float cn, float sn)
{
    vec3 t = side_arc(hc, low, sg, n, cn, sn);
    vec3 u = side_arc(bot > 1.5 ? low : bot, low, sg, n, cn, sn);
    vec3 o = side_arc(low, low, sg, n, cn, sn);
    precise vec3 r = vec3(t.x + (o.x - u.x), t.y + (o.y - u.y), t.z + (o.z - u.z));
    return r;
}

// gtao_cpu.c setup_slice, the steps (place_step, horizon_step) and finish_slice.
void slice(ivec2 p, int k, inout float vis, inout float open, inout vec3 b)
{
    ssg_horizon_slice_arc(slice_cos[k], slice_sin[k]);
    if (!(s_sl >= SSG_HORIZON_SLICE_MIN))
        return;
    float pl = s_pl, cn = s_cn, snn = s_sn;
    bool fast = p_falloff <= 0.0 && p_thickness <= 0.0 && !back_bound;
    float low2 = -snn, low1 = snn, hc2 = low2, hc1 = low1, hq2 = 1.0, hq1 = 1.0;
    float bot2 = 2.0, bot1 = 2.0; // with back: the sides' lowest bottoms (2 = none)
    float pdep2 = g_dp, pdep1 = g_dp, pcos2 = low2, pcos1 = low1; // the last valid samples
    for (int st = 0; st < p_steps; st++) {
        ssg_horizon_place(st);
        if (!t_ok)
            continue; // more off the slice than along it, or P's own pixel
        float ou = t_ou, ov = t_ov, bb = t_b, e = t_e;
        float a2 = t_a.x, a1 = t_a.y, r2 = t_r.x, r1 = t_r.y;
        float d2 = ssg_horizon_depth(p, ou, ov), d1 = ssg_horizon_depth(p, -ou, -ov);
        if (back_bound) {
            if (d2 < 1.0 / 0.0)
                horizon_back(d2, back_at(p, ou, ov), a2, r2, bb, e, low2, hc2, bot2, pdep2,
                             pcos2);
            if (d1 < 1.0 / 0.0)
                horizon_back(d1, back_at(p, -ou, -ov), a1, r1, bb, e, low1, hc1, bot1, pdep1,
                             pcos1);
        } else if (fast) {
            if (d2 < 1.0 / 0.0)
                horizon_fast(d2, a2, r2, bb, e, hc2, hq2);
            if (d1 < 1.0 / 0.0)
                horizon_fast(d1, a1, r1, bb, e, hc1, hq1);
        } else {
            if (d2 < 1.0 / 0.0)
                horizon_one(d2, a2, r2, bb, e, low2, hc2);
            if (d1 < 1.0 / 0.0)
                horizon_one(d1, a1, r1, bb, e, low1, hc1);
        }
    }
    if (fast) {
        precise float f2 = hc2 / sqrt(hq2), f1 = hc1 / sqrt(hq1);
        hc2 = f2, hc1 = f1;
    }
    precise float n = HALF_PI - ssg_acos(snn);
    vec3 a1 = back_bound ? side_arc_back(hc1, bot1, low1, -1.0, n, cn, snn)
                         : side_arc(hc1, low1, -1.0, n, cn, snn);
    vec3 a2 = back_bound ? side_arc_back(hc2, bot2, low2, 1.0, n, cn, snn)
                         : side_arc(hc2, low2, 1.0, n, cn, snn);
    precise float lim1 = n - HALF_PI, lim2 = n + HALF_PI;
    precise float nv = vis + pl * (a1.x + a2.x);
    precise float no = open + pl * (0.25 * (cn + 2.0 * lim1 * snn + cn) +
                                    0.25 * (cn + 2.0 * lim2 * snn + cn));
    vis = nv, open = no;
    precise float t0 = (a1.y + a2.y + 16.0 * snn) / 12.0;
    precise float t1 = (a1.z + a2.z + 8.0 * cn) / 12.0;
    precise vec3 nb = vec3(b.x + pl * (t0 * s_d.x + t1 * g_v.x),
                           b.y + pl * (t0 * s_d.y + t1 * g_v.y),
                           b.z + pl * (t0 * s_d.z + t1 * g_v.z));
    b = nb;
}

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    if (!ssg_horizon_surface(p)) { // background or garbage: 1, no bent normal
        SSG_STORE1(dst_out, p, 1.0);
        SSG_STORE3(dst_bent_normal, p, vec3(0.0));
        return;
    }
    setup_pixel(p);
    float vis = 0.0, open = 0.0;
    vec3 b = vec3(0.0);
    for (int k = 0; k < p_slices; k++)
        slice(p, k, vis, open, b);
    precise float v = open > 0.0 ? vis / open : 1.0;
    v = v > 0.0 ? v : 0.0;
    v = v < 1.0 ? v : 1.0;
    SSG_STORE1(dst_out, p, p_power == 1.0 ? v : pow(v, p_power));
    precise float bl = sqrt(b.x * b.x + b.y * b.y + b.z * b.z);
    precise float ib = bl > 0.0 ? 1.0 / bl : 0.0;
    SSG_STORE3(dst_bent_normal, p, bl > 0.0 ? vec3(b.x * ib, b.y * ib, b.z * ib) : g_n);
}
