// ssilvb.glsl - the `ssilvb` node on GL (method in README.md): one invocation per pixel,
// ssilvb_cpu.c's operations in its order for one lane of its chunk (`precise`: no
// multiply-add fused where the CPU rounds twice): slices in order, per step the +D sample
// then the -D one. Only sqrt and division may round differently from the CPU's, which can
// move a sector boundary (a bit) now and then.
layout(std430, binding = 0) readonly buffer Columns {
    float e1[]; // per column x: e1x at x, e1z at width + x (prepare()'s)
};

#define SSG_SAMPLING_NO_KERNEL 1 // ssilvb marches along slices, it has no kernel
#include "sampling.glsl" // position, depth and their helpers
uniform sampler2DArray normal;
uniform sampler2DArray light;
uniform sampler2DArray albedo;
uniform sampler2DArray back;
uniform bool back_bound;
layout(r32f) uniform writeonly image2DArray dst_ao;
layout(r32f) uniform writeonly image2DArray dst_bounce;

// The parameters (p_<field>, from the descriptor's table) and what prepare() derived.
#pragma ssg_params
uniform float invf;     // 1 / f
uniform vec3 proj;      // (f, cx, cy) of this resolution
uniform vec4 noise_off; // the seed's offsets of the two noise patterns
uniform float slice_cos[32], slice_sin[32];
uniform float turn_cos[64], turn_sin[64];

const float SLICE_MIN = 0.01;
const float HALF_PI = 1.57079632679489661923;
const float BACK_MAX = 1.0e6;
const int TURNS = 64;

// ssilvb_cpu.c struct chunk, one lane.
float g_dp, g_au, g_av, g_e1x, g_e1z, g_vn, g_step, g_u, g_co, g_si, g_l, g_ldp, g_vxf, g_vyf;
float g_e1n, g_e2n;
vec3 g_n, g_e2, g_b;
float g_vis, g_wsum;
// per slice
float s_du, s_dv, s_dxf, s_dyf, s_mxf, s_myf, s_ax, s_ay, s_bx, s_by, s_cn, s_sn, s_g1, s_ia;
float s_w, s_w32;
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

// ssilvb_cpu.c setup_chunk.
void setup_pixel(ivec2 p)
{
    precise float xf = float(p.x), yf = float(p.y);
    precise float au = (xf + 0.5 - proj.y) * invf;
    precise float av = -(yf + 0.5 - proj.z) * invf;
    precise float l = sqrt(au * au + av * av + 1.0), il = 1.0 / l;
    precise vec3 v = vec3(-au * il, -av * il, il);
    g_au = au, g_av = av, g_l = l;
    precise float ldp = l * g_dp, vxf = v.x * invf, vyf = -v.y * invf;
    g_ldp = ldp, g_vxf = vxf, g_vyf = vyf;
    g_e1x = e1[p.x];
    g_e1z = e1[ssg_grid.x + p.x];
    precise vec3 e2 = vec3(v.y * g_e1z, v.z * g_e1x - v.x * g_e1z, -v.y * g_e1x);
    g_e2 = e2;
    precise float e1n = g_e1x * g_n.x + g_e1z * g_n.z;
    precise float e2n = e2.x * g_n.x + e2.y * g_n.y + e2.z * g_n.z;
    g_e1n = e1n, g_e2n = e2n;
    precise float vn = v.x * g_n.x + v.y * g_n.y + v.z * g_n.z;
    g_vn = vn > 1e-6 ? vn : 1e-6;
    precise float near = g_dp - p_radius, half_d = 0.5 * g_dp;
    precise float rp = proj.x * p_radius / (near > half_d ? near : half_d);
    rp = p_max_screen_radius > 0.0 && rp > p_max_screen_radius ? p_max_screen_radius : rp;
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
    float dc = slice_cos[k], ds = slice_sin[k];
    precise float cs = dc * g_co - ds * g_si, s = ds * g_co + dc * g_si;
    precise vec3 d = vec3(cs * g_e1x + s * g_e2.x, s * g_e2.y, cs * g_e1z + s * g_e2.z);
    precise float mx = cs * g_e2.x - s * g_e1x, my = cs * g_e2.y;
    precise float dn = cs * g_e1n + s * g_e2n, mn = cs * g_e2n - s * g_e1n;
    precise float sl = g_vn * g_vn + dn * dn;
    precise float pl = sqrt(sl), cn = g_vn / pl, sn = dn / pl;
    precise float isl = mn / sl, al = isl * g_vn, be = isl * dn;
    precise float du = (d.x + g_au * d.z) * g_step, dv = -(d.y + g_av * d.z) * g_step;
    s_du = du, s_dv = dv;
    precise float dxf = d.x * invf, dyf = -d.y * invf, mxf = mx * invf, myf = -my * invf;
    s_dxf = dxf, s_dyf = dyf, s_mxf = mxf, s_myf = myf;
    precise float ax = g_vxf + mxf * al, ay = g_vyf + myf * al;
    precise float bx = dxf + mxf * be, by = dyf + myf * be;
    s_ax = ax, s_ay = ay, s_bx = bx, s_by = by;
    precise float n = HALF_PI - ssg_acos(sn);
    precise float area = cn + n * sn;
    s_cn = cn, s_sn = sn;
    precise float l0 = HALF_PI + n, l1 = HALF_PI - n;
    s_lim[0] = l0, s_lim[1] = l1;
    precise float g1 = 0.5 * (cn + (n - HALF_PI) * sn), ia = 1.0 / area;
    s_g1 = g1, s_ia = ia;
    precise float w = sl >= SLICE_MIN ? pl * area : 0.0;
    precise float w32 = w * (1.0 / 32.0);
    s_w = w, s_w32 = w32;
    s_mask = 0u;
}

// ssilvb_cpu.c side_index and side_bits, and step_both's bounce sum for this side.
void sample_side(ivec2 p, float ou, float ov, float sg, bool ok, float bb, float e)
{
    precise float su = sg * ou, sv = sg * ov;
    precise float pr = su * g_vxf + sv * g_vyf, pa = su * s_ax + sv * s_ay;
    precise float a = pa - g_l, r = pr - g_l;
    precise float qx = float(p.x) + su, qy = float(p.y) + sv;
    float dq = 1.0 / 0.0;
    if (qx >= 0.0 && qx < float(ssg_grid.x) && qy >= 0.0 && qy < float(ssg_grid.y)) {
        float d = ssg_occluder_depth(ivec2(int(qx), int(qy)));
        dq = d < 0.0 ? 1.0 / 0.0 : d;
    }
    qx = qx > 0.0 ? qx : 0.0;
    qx = qx < float(ssg_grid.x) - 1.0 ? qx : float(ssg_grid.x) - 1.0;
    qy = qy > 0.0 ? qy : 0.0;
    qy = qy < float(ssg_grid.y) - 1.0 ? qy : float(ssg_grid.y) - 1.0;
    ivec2 q = ivec2(int(qx), int(qy));
    precise float hv = dq * r + g_ldp;
    precise float d2 = hv * hv + dq * dq * e;
    bool valid = ok && dq < 1.0 / 0.0 && d2 <= p_radius * p_radius;
    if (!valid)
        return; // no bits, no light (the CPU's selects give the same)
    float bk = back_bound ? ssg_load1(back, q) : 0.0;
    precise float dt = dq + p_thickness;
    float db = bk > dq ? bk : dt;
    db = db < BACK_MAX ? db : BACK_MAX;
    int m = sg > 0.0 ? 0 : 1;
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
    g_dp = ssg_scene_depth(p);
    vec3 N = ssg_load3(normal, p);
    if (!ssg_surface_normal(g_dp, N)) { // background or garbage: 1, no bounce
        SSG_STORE1(dst_ao, p, 1.0);
        SSG_STORE3(dst_bounce, p, vec3(0.0));
        return;
    }
    g_n = N;
    setup_pixel(p);
    g_vis = 0.0, g_wsum = 0.0, g_b = vec3(0.0);
    for (int k = 0; k < p_slices; k++) {
        setup_slice(k);
        for (int st = 0; st < p_steps; st++) {
            precise float t = float(st) + g_u;
            precise float ou = roundEven(s_du * t), ov = roundEven(s_dv * t);
            precise float c = ou * s_mxf + ov * s_myf;
            precise float bd = ou * s_dxf + ov * s_dyf;
            precise float bb = ou * s_bx + ov * s_by;
            precise float e = bd * bd + c * c;
            bool ok = bb > abs(c);
            sample_side(p, ou, ov, 1.0, ok, bb, e);
            sample_side(p, ou, ov, -1.0, ok, bb, e);
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
