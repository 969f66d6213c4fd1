// gtao.glsl - the `gtao` node on GL (method and geometry in gtao.c): one invocation per
// pixel, gtao_cpu.c's operations in its order (`precise`: no multiply-add fused where the
// CPU rounds twice): slices in order, per step the +D sample then the -D one. Only the
// transcendental functions (atan, acos, cos, sin) may round differently from the CPU's.
layout(std430, binding = 0) readonly buffer Columns {
    float e1[]; // per column x: e1x at x, e1z at width + x (prepare()'s, gtao.c)
};

#define SSG_SAMPLING_NO_KERNEL 1 // gtao marches along slices, it has no kernel
#include "sampling.glsl" // position, depth, rotation and their helpers
uniform sampler2DArray normal;
layout(r32f) uniform writeonly image2DArray dst;
layout(r32f) uniform writeonly image2DArray bent;

// The parameters (ssg_gl_params: p_<name>) and what prepare() derived from them.
uniform int p_slices;            // 1..32
uniform int p_steps;             // 1..64
uniform float p_radius;          // R
uniform float p_falloff;         // fraction of R faded (0 = hard cutoff)
uniform float p_thickness;
uniform float p_power;
uniform float p_max_screen_radius; // px (0 = no cap)
uniform float fall_mul, fall_add;
uniform float invf;        // 1 / f
uniform vec3 proj;         // (f, cx, cy) of this resolution
uniform float slice_cos[32], slice_sin[32];

const float SLICE_MIN = 0.01;
const float HALF_PI = 1.57079632679489661923;
const float OPEN_EPS = 1e-5; // gtao_cpu.c: a horizon this close to its lowest is none

// gtao_cpu.c struct pix.
float g_dp, g_au, g_av, g_e1x, g_e1z, g_vn, g_step, g_u, g_co, g_si;
vec3 g_v, g_n, g_e2;

// 1 - interleaved gradient noise (gtao_cpu.c step_jitter).
float step_jitter(ivec2 p)
{
    precise float a = 0.06711056 * float(p.x) + 0.00583715 * float(p.y);
    precise float b = 52.9829189 * (a - floor(a));
    precise float u = 1.0 - (b - floor(b));
    return u;
}

void setup_pixel(ivec2 p)
{
    precise float au = (float(p.x) + 0.5 - proj.y) * invf;
    precise float av = -(float(p.y) + 0.5 - proj.z) * invf;
    precise float il = 1.0 / sqrt(au * au + av * av + 1.0);
    precise vec3 v = vec3(-au * il, -av * il, il);
    g_au = au, g_av = av, g_v = v;
    g_e1x = e1[p.x];
    g_e1z = e1[ssg_grid.x + p.x];
    precise vec3 e2 = vec3(v.y * g_e1z, v.z * g_e1x - v.x * g_e1z, -v.y * g_e1x);
    g_e2 = e2;
    precise float vn = v.x * g_n.x + v.y * g_n.y + v.z * g_n.z;
    g_vn = vn > 1e-6 ? vn : 1e-6;
    precise float near = g_dp - p_radius, half_d = 0.5 * g_dp;
    precise float rp = proj.x * p_radius / (near > half_d ? near : half_d);
    rp = p_max_screen_radius > 0.0 && rp > p_max_screen_radius ? p_max_screen_radius : rp;
    precise float st = rp / float(p_steps);
    g_step = st;
    g_u = step_jitter(p);
    g_co = 1.0, g_si = 0.0;
    if (rotation_bound) {
        vec2 r = ssg_tile_rotation(p);
        g_co = r.x, g_si = r.y;
    }
}

// gtao_cpu.c sample: hc is the side's horizon cosine, low its lowest.
void sample_at(ivec2 p, vec3 d, vec3 m, float al, float be, float sg, float ou, float ov,
               float low, inout float hc)
{
    precise float qx = float(p.x) + sg * ou, qy = float(p.y) + sg * ov;
    if (!(qx >= 0.0 && qx < float(ssg_grid.x) && qy >= 0.0 && qy < float(ssg_grid.y)))
        return;
    float dq = ssg_occluder_depth(ivec2(int(qx), int(qy)));
    if (dq < 0.0)
        return;
    precise float aqu = (qx + 0.5 - proj.y) * invf, aqv = -(qy + 0.5 - proj.z) * invf;
    precise float hx = dq * aqu - g_dp * g_au, hy = dq * aqv - g_dp * g_av, hz = g_dp - dq;
    precise float hv = hx * g_v.x + hy * g_v.y + hz * g_v.z;
    precise float hd = hx * d.x + hy * d.y + hz * d.z;
    precise float hm = hx * m.x + hy * m.y + hz * m.z;
    precise float pv = hv + hm * al, pd = sg * (hd + hm * be);
    if (!(pd > abs(hm)))
        return;
    precise float r = sqrt(hx * hx + hy * hy + hz * hz);
    precise float w = p_falloff > 0.0 ? r * fall_mul + fall_add : (r <= p_radius ? 1.0 : 0.0);
    w = w < 0.0 ? 0.0 : w;
    w = w < 1.0 ? w : 1.0;
    precise float shc = pv / sqrt(pv * pv + pd * pd);
    precise float sh = low + w * (shc - low);
    if (sh > hc)
        hc = sh;
    else if (w > 0.0 && p_thickness > 0.0) {
        precise float nh = hc + p_thickness * (sh - hc);
        hc = nh;
    }
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
    precise float h = sg * acos(hc);
    h = sg > 0.0 ? (h < lim ? h : lim) : (h > lim ? h : lim);
    precise vec3 r = vec3(0.25 * (cn + 2.0 * h * sn - cos(2.0 * h - n)),
                          6.0 * sin(h - n) - sin(3.0 * h - n) - 3.0 * sin(h + n),
                          -cos(3.0 * h - n) - 3.0 * cos(h + n));
    return r;
}

// gtao_cpu.c slice.
void slice(ivec2 p, int k, inout float vis, inout float open, inout vec3 b)
{
    float dc = slice_cos[k], ds = slice_sin[k];
    precise float cs = dc * g_co - ds * g_si, sn = ds * g_co + dc * g_si;
    precise vec3 d = vec3(cs * g_e1x + sn * g_e2.x, sn * g_e2.y, cs * g_e1z + sn * g_e2.z);
    precise vec3 m = vec3(cs * g_e2.x - sn * g_e1x, cs * g_e2.y, cs * g_e2.z - sn * g_e1z);
    precise float dn = d.x * g_n.x + d.y * g_n.y + d.z * g_n.z;
    precise float mn = m.x * g_n.x + m.y * g_n.y + m.z * g_n.z;
    precise float sl = g_vn * g_vn + dn * dn;
    if (!(sl >= SLICE_MIN))
        return;
    precise float pl = sqrt(sl), n = atan(dn, g_vn), cn = g_vn / pl, snn = dn / pl;
    precise float isl = mn / sl, al = isl * g_vn, be = isl * dn;
    float low2 = -snn, low1 = snn, hc2 = low2, hc1 = low1;
    precise float su = (d.x + g_au * d.z) * g_step, sv = -(d.y + g_av * d.z) * g_step;
    for (int s = 0; s < p_steps; s++) {
        precise float t = float(s) + g_u;
        precise float ou = roundEven(su * t), ov = roundEven(sv * t);
        sample_at(p, d, m, al, be, 1.0, ou, ov, low2, hc2);
        sample_at(p, d, m, al, be, -1.0, ou, ov, low1, hc1);
    }
    vec3 a1 = side_arc(hc1, low1, -1.0, n, cn, snn), a2 = side_arc(hc2, low2, 1.0, n, cn, snn);
    precise float lim1 = n - HALF_PI, lim2 = n + HALF_PI;
    precise float nv = vis + pl * (a1.x + a2.x);
    precise float no = open + pl * (0.25 * (cn + 2.0 * lim1 * snn + cn) +
                                    0.25 * (cn + 2.0 * lim2 * snn + cn));
    vis = nv, open = no;
    precise float t0 = (a1.y + a2.y + 16.0 * snn) / 12.0;
    precise float t1 = (a1.z + a2.z + 8.0 * cn) / 12.0;
    precise vec3 nb = vec3(b.x + pl * (t0 * d.x + t1 * g_v.x), b.y + pl * (t0 * d.y + t1 * g_v.y),
                           b.z + pl * (t0 * d.z + t1 * g_v.z));
    b = nb;
}

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    g_dp = ssg_scene_depth(p);
    vec3 N = ssg_load3(normal, p);
    if (!ssg_surface_normal(g_dp, N)) { // background or garbage: 1, no bent normal
        SSG_STORE1(dst, p, 1.0);
        SSG_STORE3(bent, p, vec3(0.0));
        return;
    }
    g_n = N;
    setup_pixel(p);
    float vis = 0.0, open = 0.0;
    vec3 b = vec3(0.0);
    for (int k = 0; k < p_slices; k++)
        slice(p, k, vis, open, b);
    precise float v = open > 0.0 ? vis / open : 1.0;
    v = v > 0.0 ? v : 0.0;
    v = v < 1.0 ? v : 1.0;
    SSG_STORE1(dst, p, p_power == 1.0 ? v : pow(v, p_power));
    precise float bl = sqrt(b.x * b.x + b.y * b.y + b.z * b.z);
    precise float ib = bl > 0.0 ? 1.0 / bl : 0.0;
    SSG_STORE3(bent, p, bl > 0.0 ? vec3(b.x * ib, b.y * ib, b.z * ib) : N);
}
