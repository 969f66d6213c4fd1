// ssilvb.glsl - the `ssilvb` node on GL (method in README.md): one invocation per pixel,
// its integrator on the march of nodes/common/horizon.glsl, ssilvb_cpu.c's operations in
// its order for one lane of its chunk (`precise`: no
// multiply-add fused where the CPU rounds twice): slices in order, per step the +D sample
// then the -D one. Only sqrt and division may round differently from the CPU's, which can
// move a sector boundary (a bit) now and then.
#define SSG_SAMPLING_NO_KERNEL 1 // ssilvb marches along slices, it has no kernel
#include "sampling.glsl" // position, depth and their helpers
uniform sampler2DArray light;
uniform sampler2DArray albedo;
uniform sampler2DArray back;
uniform bool back_bound;
layout(r32f) uniform writeonly image2DArray dst_ao;
layout(r32f) uniform writeonly image2DArray dst_bounce;

// The parameters (p_<field>, from the descriptor's table) and what prepare() derived.
#pragma ssg_params
uniform vec4 noise_off; // the seed's offsets of the two noise patterns
uniform float slice_cos[32], slice_sin[32];
uniform float turn_cos[64], turn_sin[64];
#include "horizon.glsl" // the march: e1, invf, proj, the pixel, the slice, the steps

const float HALF_PI = SSG_HORIZON_HALF_PI;
const float BACK_MAX = 1.0e6;
const int TURNS = 64;

vec3 g_b;
float g_vis, g_wsum;
// per slice (ssilvb_cpu.c struct chunk, one lane)
float s_g1, s_ia, s_w, s_w32;
float s_lim[2];
uint s_mask;

uint sector_bits(float u0, float u1)
{
    float lo = u0 < u1 ? u0 : u1, hi = u0 < u1 ? u1 : u0;
    precise float lf = lo * 32.0 + 0.5, hf = hi * 32.0 + 0.5;
    int l = int(lf), h = int(hf);
    uint ml = l >= 32 ? 0xFFFFFFFFu : (1u << uint(l & 31)) - 1u;
    uint mh = h >= 32 ? 0xFFFFFFFFu : (1u << uint(h & 31)) - 1u;
    return mh & ~ml;
}

// ssilvb_cpu.c sector_u.
float sector_u(float hv, float hd, float sg, float lim)
{
    precise float c = hv / sqrt(hv * hv + hd * hd);
    c = c < 1.0 ? c : 1.0;
    c = c > -1.0 ? c : -1.0;
    precise float s2 = (1.0 - c) * (1.0 + c), s = sqrt(s2);
    precise float a = ssg_acos(c);
    precise float cm = 0.5 * (sg * s_cn * s2 + s_sn * (a - s * c));
    precise float u = (cm + s_g1) * s_ia;
    u = u > 0.0 ? u : 0.0;
    u = u < 1.0 ? u : 1.0;
    float edge = sg > 0.0 ? 1.0 : 0.0;
    return a > lim ? edge : u;
}

// ssilvb_cpu.c load_chunk and ssg_horizon_setup: the turn picked by noise, the step
// jitter and the march's step.
void setup_pixel(ivec2 p)
{
    precise float xf = float(p.x), yf = float(p.y);
    precise float rp = ssg_horizon_pixel(p, p_radius, p_max_screen_radius, false);
    precise float st = rp / float(p_steps);
    g_step = st;
    precise float rx = xf + noise_off.x, ry = yf + noise_off.y;
    precise float turn = ssg_ign(rx, ry) * float(TURNS);
    int t = int(turn);
    t = t < TURNS - 1 ? t : TURNS - 1;
    g_co = turn_cos[t], g_si = turn_sin[t];
    precise float jx = yf + noise_off.z, jy = xf + noise_off.w;
    precise float u = 1.0 - ssg_ign(jx, jy);
    g_u = u;
}

// ssilvb_cpu.c setup_slice.
void setup_slice(int k)
{
    ssg_horizon_slice_arc(slice_cos[k], slice_sin[k]);
    float pl = s_pl, cn = s_cn, sn = s_sn;
    precise float n = HALF_PI - ssg_acos(sn);
    precise float area = cn + n * sn;
    precise float l0 = HALF_PI + n, l1 = HALF_PI - n;
    s_lim[0] = l0, s_lim[1] = l1;
    precise float g1 = 0.5 * (cn + (n - HALF_PI) * sn), ia = 1.0 / area;
    s_g1 = g1, s_ia = ia;
    precise float w = s_sl >= SSG_HORIZON_SLICE_MIN ? pl * area : 0.0;
    precise float w32 = w * (1.0 / 32.0);
    s_w = w, s_w32 = w32;
    s_mask = 0u;
}

// ssilvb_cpu.c image_index and side_bits, and step_both's bounce sum for this side (m 0:
// +D, 1: -D).
void sample_side(ivec2 p, int m)
{
    float sg = m == 0 ? 1.0 : -1.0, a = m == 0 ? t_a.x : t_a.y, r = m == 0 ? t_r.x : t_r.y;
    precise float su = sg * t_ou, sv = sg * t_ov;
    precise float qx = float(p.x) + su, qy = float(p.y) + sv;
    float dq = ssg_horizon_depth(p, su, sv), bb = t_b, e = t_e;
    qx = qx > 0.0 ? qx : 0.0;
    qx = qx < float(ssg_grid.x) - 1.0 ? qx : float(ssg_grid.x) - 1.0;
    qy = qy > 0.0 ? qy : 0.0;
    qy = qy < float(ssg_grid.y) - 1.0 ? qy : float(ssg_grid.y) - 1.0;
    ivec2 q = ivec2(int(qx), int(qy));
    precise float hv = dq * r + g_ldp;
    precise float d2 = hv * hv + dq * dq * e;
    bool valid = t_ok && dq < 1.0 / 0.0 && d2 <= p_radius * p_radius;
    if (!valid)
        return; // no bits, no light (the CPU's selects give the same)
    float bk = back_bound ? ssg_load1(back, q) : 0.0;
    precise float dt = dq + p_thickness;
    float db = bk > dq ? bk : dt;
    db = db < BACK_MAX ? db : BACK_MAX;
    float lim = s_lim[m];
    precise float fv = dq * a + g_ldp, fd = dq * bb, bv = db * a + g_ldp, bd = db * bb;
    float uf = sector_u(fv, fd, sg, lim), ub = sector_u(bv, bd, sg, lim);
    uint bits = sector_bits(uf, ub);
    uint fresh = bits & ~s_mask;
    s_mask |= bits;
    precise float aq = g_au + su * invf, vq = g_av - sv * invf;
    vec3 nq = ssg_load3(normal, q);
    precise float facing = dq * (nq.x * aq + nq.y * vq - nq.z) -
                           g_dp * (nq.x * g_au + nq.y * g_av - nq.z);
    precise float t = facing < 0.0 ? float(bitCount(fresh)) * s_w32 : 0.0;
    if (t > 0.0) {
        vec3 lq = ssg_load3(light, q);
        precise vec3 nb = vec3(g_b.x + t * lq.x, g_b.y + t * lq.y, g_b.z + t * lq.z);
        g_b = nb;
    }
}

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    if (!ssg_horizon_surface(p)) { // background or garbage: 1, no bounce
        SSG_STORE1(dst_ao, p, 1.0);
        SSG_STORE3(dst_bounce, p, vec3(0.0));
        return;
    }
    setup_pixel(p);
    g_vis = 0.0, g_wsum = 0.0, g_b = vec3(0.0);
    for (int k = 0; k < p_slices; k++) {
        setup_slice(k);
        for (int st = 0; st < p_steps; st++) {
            ssg_horizon_place(st);
            sample_side(p, 0);
            sample_side(p, 1);
        }
        precise float open = float(32u - uint(bitCount(s_mask)));
        precise float nv = g_vis + s_w32 * open, nw = g_wsum + s_w;
        g_vis = nv, g_wsum = nw;
    }
    precise float v = g_wsum > 0.0 ? g_vis / g_wsum : 1.0;
    v = v > 0.0 ? v : 0.0;
    v = v < 1.0 ? v : 1.0;
    SSG_STORE1(dst_ao, p, p_power == 1.0 ? v : pow(v, p_power));
    vec3 alb = ssg_load3(albedo, p);
    precise vec3 s = g_wsum > 0.0 ? vec3(p_strength * g_b.x / g_wsum,
                                         p_strength * g_b.y / g_wsum,
                                         p_strength * g_b.z / g_wsum) : vec3(0.0);
    precise vec3 o = vec3(alb.x * s.x, alb.y * s.y, alb.z * s.z);
    SSG_STORE3(dst_bounce, p, o);
}
