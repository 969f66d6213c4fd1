// hbao.glsl - the `hbao` node on GL (method and geometry in README.md): one invocation per
// pixel. The maths is hbao_cpu.c's lane by lane: the same per-pixel basis and march
// length (setup_chunk), per-direction coefficients (setup_direction), rounded steps,
// slice projection and horizon tests (place_step, horizon_one), the same sums in the same
// order (`precise`: no multiply-add fused where the CPU rounds twice): directions in pairs
// D, -D when their number is even, per step D's sample then -D's. Where the CPU lets a
// sample fail through +inf or NaN (off screen, background, rejected by place_step) or
// masks a direction past the pixel's count, this skips it: the CPU adds exactly 0 there.
layout(std430, binding = 0) readonly buffer Columns {
    float e1[]; // per column x: e1x at x, e1z at width + x (prepare()'s, hbao.c)
};

#define SSG_SAMPLING_NO_KERNEL 1 // hbao marches along directions, it has no kernel
#include "sampling.glsl" // position, depth, rotation and their helpers
uniform sampler2DArray normal;
uniform sampler2DArray count;
uniform bool count_bound;
layout(r32f) uniform writeonly image2DArray dst_out;

#pragma ssg_params
#pragma ssg_consts
uniform float invf;       // 1 / f
uniform vec3 proj;        // (f, cx, cy) of this resolution
uniform float dir_cos[64], dir_sin[64];
uniform int dir_rank[64]; // place of each direction in the count input's order

const float SLICE_MIN = 0.01; // hbao_cpu.c: slices this close to the tangent plane add 0

// What depends on the pixel only (hbao_cpu.c setup_chunk, struct chunk).
float g_dp, g_au, g_av, g_lp, g_ldp, g_vxf, g_vyf, g_e1x, g_e1z, g_e1n, g_e2n, g_vn;
float g_step, g_u, g_co, g_si;
vec3 g_e2;

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

// V, the basis e1, e2 = V x e1, V.N, e1.N, e2.N and the step length (hbao_cpu.c
// setup_chunk).
void setup_pixel(ivec2 p, vec3 N)
{
    precise float av = -(float(p.y) + 0.5 - proj.z) * invf;
    precise float au = (float(p.x) + 0.5 - proj.y) * invf;
    precise float l = sqrt(au * au + av * av + 1.0);
    precise float near = g_dp - p_radius, half_d = 0.5 * g_dp;
    float den = near > half_d ? near : half_d;
    precise float inv = 1.0 / (l * den);
    precise float il = den * inv;
    precise float vx = -au * il, vy = -av * il, vz = il;
    g_e1x = e1[p.x];
    g_e1z = e1[ssg_grid.x + p.x];
    precise vec3 e2 = vec3(vy * g_e1z, vz * g_e1x - vx * g_e1z, -vy * g_e1x);
    g_e2 = e2;
    g_au = au, g_av = av, g_lp = l;
    precise float ldp = l * g_dp, vxf = vx * invf, vyf = -vy * invf;
    g_ldp = ldp, g_vxf = vxf, g_vyf = vyf;
    precise float vn = vx * N.x + vy * N.y + vz * N.z;
    g_vn = vn > 1e-6 ? vn : 1e-6;
    precise float e1n = g_e1x * N.x + g_e1z * N.z;
    precise float e2n = e2.x * N.x + e2.y * N.y + e2.z * N.z;
    g_e1n = e1n, g_e2n = e2n;
    precise float rp = rf * l * inv;
    float cap = p_max_screen_radius; // px, 0 = no cap
    rp = cap > 0.0 && rp > cap ? cap : rp;
    precise float st = rp * inv_steps;
    g_step = st;
}

// One direction's screen step and slice coefficients (hbao_cpu.c setup_direction).
struct slice {
    float du, dv;     // screen step, px
    float mxf, myf;   // H.M = dq (ou mxf + ov myf)
    float ax, ay;     // H'.V = dq (ou ax + ov ay - L) + L dp
    float bx, by;     // H'.D = dq (ou bx + ov by)
    vec2 stb;         // sin(t + bias) of D and -D
    bvec2 off;        // member adds nothing: past the zenith, or a slice too thin
};

slice setup_direction(int k)
{
    float dc = dir_cos[k], ds = dir_sin[k];
    precise float c = dc * g_co - ds * g_si, s = ds * g_co + dc * g_si;
    precise float dx = c * g_e1x + s * g_e2.x, dy = s * g_e2.y, dz = c * g_e1z + s * g_e2.z;
    slice sl;
    precise float du = (dx + g_au * dz) * g_step, dv = -(dy + g_av * dz) * g_step;
    precise float mx = c * g_e2.x - s * g_e1x, my = c * g_e2.y;
    precise float dn = c * g_e1n + s * g_e2n, mn = c * g_e2n - s * g_e1n;
    precise float sq = g_vn * g_vn + dn * dn;
    precise float ir = 1.0 / sqrt(sq);
    precise float isl = mn * ir * ir;
    precise float mxf = mx * invf, myf = -my * invf, al = isl * g_vn, be = isl * dn;
    precise float ax = g_vxf + mxf * al, ay = g_vyf + myf * al;
    precise float bx = dx * invf + mxf * be, by = -dy * invf + myf * be;
    precise float st = -dn * ir, ct = g_vn * ir;
    precise float stb = st * cos_bias + ct * sin_bias, ctb = ct * cos_bias - st * sin_bias;
    precise float stb2 = ct * sin_bias - st * cos_bias, ctb2 = ct * cos_bias + st * sin_bias;
    sl.du = du, sl.dv = dv, sl.mxf = mxf, sl.myf = myf;
    sl.ax = ax, sl.ay = ay, sl.bx = bx, sl.by = by;
    sl.stb = vec2(stb, stb2);
    sl.off = bvec2(ctb < 0.0 || sq < SLICE_MIN, ctb2 < 0.0 || sq < SLICE_MIN);
    return sl;
}

// The sample at pixel p + o with H'.V = dq a + L dp, H'.D = dq b raises the horizon
// (bv, bq) when within R and higher (hbao_cpu.c horizon_one); linear adds its term.
void horizon(ivec2 p, vec2 o, float a, float b, inout float bv, inout float bq,
             inout float occ)
{
    precise vec2 s = vec2(p) + o;
    if (!(s.x >= 0.0 && s.x < float(ssg_grid.x) && s.y >= 0.0 && s.y < float(ssg_grid.y)))
        return;
    float dq = ssg_occluder_depth(ivec2(s));
    if (dq < 0.0)
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
    slice sl = setup_direction(k);
    bool on0 = act.x && !sl.off.x, on1 = pair && act.y && !sl.off.y;
    if (!on0 && !on1)
        return;
    float bv0 = sl.stb.x, bv1 = sl.stb.y, bq0 = 1.0, bq1 = 1.0;
    for (int j = 0; j < p_steps; j++) {
        precise float t = float(j) + g_u;
        precise float ou = roundEven(sl.du * t), ov = roundEven(sl.dv * t);
        precise float pa = ou * sl.ax + ov * sl.ay;
        precise float b = ou * sl.bx + ov * sl.by;
        precise float c = ou * sl.mxf + ov * sl.myf;
        if (!(b > abs(c)))
            continue; // more off the slice than along it (place_step)
        precise float a0 = pa - g_lp, a1 = -(pa + g_lp);
        if (on0)
            horizon(p, vec2(ou, ov), a0, b, bv0, bq0, occ);
        if (on1)
            horizon(p, -vec2(ou, ov), a1, b, bv1, bq1, occ);
    }
    if (p_falloff == FALLOFF_LINEAR)
        return;
    // Falloff none: sin h - sin(t + bias) of the final horizon (finish_direction).
    precise float g0 = bv0 / sqrt(bq0) - sl.stb.x, g1 = bv1 / sqrt(bq1) - sl.stb.y;
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
    g_dp = ssg_scene_depth(p);
    vec3 N = ssg_load3(normal, p);
    if (!ssg_surface_normal(g_dp, N)) { // background or garbage: 1
        SSG_STORE1(dst_out, p, 1.0);
        return;
    }
    load_pattern(p);
    setup_pixel(p, N);
    int n = ssg_pixel_count(count, count_bound, p, p_directions);
    float occ = occlusion(p, n);
    precise float sc = n == p_directions ? scale : p_strength / float(n);
    precise float v = 1.0 - occ * sc;
    v = v > 0.0 ? v : 0.0;
    SSG_STORE1(dst_out, p, v < 1.0 ? v : 1.0);
}
