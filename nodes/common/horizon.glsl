// horizon.glsl - the horizon march the `hbao`, `gtao` and `ssilvb` shaders share, the GL
// twin of nodes/common/horizon.h for one lane: the column basis and the camera prepare()
// made, the per-pixel setup (ssg_horizon_pixel), the per-slice setup (ssg_horizon_slice,
// ssg_horizon_fold), where a step's samples land with their folded coefficients
// (ssg_horizon_place) and the depth read there (ssg_horizon_depth). The same operations in
// the same order as the C (`precise`), so both backends start from the same bits. A node
// #includes it after sampling.glsl and its #pragma lines, and writes its integrator: what a
// sample does to its per-slice state and how a slice ends. Bound by the C side
// (horizon_gl.h): the buffer Columns, invf and proj.
layout(std430, binding = 0) readonly buffer Columns {
    float e1[]; // per column x: e1x at x, e1z at width + x (prepare()'s ssg_horizon_frame)
};
uniform float invf; // 1 / f
uniform vec3 proj;  // (f, cx, cy) of this resolution
uniform sampler2DArray normal; // the input every horizon node has (bound by ssg_gl_ports)

const float SSG_HORIZON_SLICE_MIN = 0.01; // horizon.h: a slice this close to the tangent
                                          // plane adds nothing
const float SSG_HORIZON_HALF_PI = 1.57079632679489661923;

// The pixel (horizon.h struct ssg_horizon_lanes, one lane): g_dp and g_n the node's before
// ssg_horizon_pixel, g_u, g_co and g_si (the step jitter and the slices' turn) the node's
// before the first slice.
float g_dp, g_au, g_av, g_l, g_ldp, g_vxf, g_vyf, g_e1x, g_e1z, g_e1n, g_e2n, g_vn, g_step;
float g_u, g_co, g_si;
vec3 g_n, g_v, g_e2;

// The slice (ssg_horizon_slice, ssg_horizon_fold).
vec3 s_d;                                       // D
float s_dn, s_mn, s_sl;                         // D.N, M.N, |proj N|^2
float s_du, s_dv, s_dxf, s_dyf, s_mxf, s_myf;   // screen step, D / f, M / f
float s_ax, s_ay, s_bx, s_by;                   // the folded coefficients
float s_pl, s_cn, s_sn;                         // |proj N|, cos n, sin n (slice_arc)

// The step (ssg_horizon_place): +D's offset; per side (x: +D, y: -D) H'.V = d a + L dp,
// sg H'.D = d b, H.V = d r + L dp, |H|^2 = (H.V)^2 + d^2 e; ok: along the slice.
float t_ou, t_ov, t_b, t_c, t_e;
vec2 t_a, t_r;
bool t_ok;

// Pixel p's depth g_dp and unit normal g_n; false on background or garbage, where the node
// writes its background values.
bool ssg_horizon_surface(ivec2 p)
{
    g_dp = ssg_scene_depth(p);
    vec3 N = ssg_load3(normal, p);
    if (!ssg_surface_normal(g_dp, N))
        return false;
    g_n = N;
    return true;
}

// horizon.h's ssg_horizon_setup for pixel p: V, e2 = V x e1, V.N, e1.N, e2.N from g_dp,
// g_n; returns the march's projected radius f R / den, capped (the node divides it into
// steps). one_division: 1 / L and 1 / den from one division (hbao's rounding).
float ssg_horizon_pixel(ivec2 p, float radius, float cap, bool one_division)
{
    precise float au = (float(p.x) + 0.5 - proj.y) * invf;
    precise float av = -(float(p.y) + 0.5 - proj.z) * invf;
    precise float l = sqrt(au * au + av * av + 1.0);
    precise float near = g_dp - radius, half_d = 0.5 * g_dp;
    float den = near > half_d ? near : half_d;
    precise float rf = proj.x * radius;
    precise float inv = 1.0 / (l * den), il1 = den * inv, rp1 = rf * l * inv;
    precise float il2 = 1.0 / l, rp2 = rf / den;
    float il = one_division ? il1 : il2;
    float rp = one_division ? rp1 : rp2;
    precise vec3 v = vec3(-au * il, -av * il, il);
    g_au = au, g_av = av, g_l = l, g_v = v;
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
    return cap > 0.0 && rp > cap ? cap : rp;
}

// horizon.h's ssg_horizon_slice: the slice angle (dc, ds) turned by the pixel's.
void ssg_horizon_slice(float dc, float ds)
{
    precise float c = dc * g_co - ds * g_si, s = ds * g_co + dc * g_si;
    precise vec3 d = vec3(c * g_e1x + s * g_e2.x, s * g_e2.y, c * g_e1z + s * g_e2.z);
    precise float mx = c * g_e2.x - s * g_e1x, my = c * g_e2.y;
    precise float dn = c * g_e1n + s * g_e2n, mn = c * g_e2n - s * g_e1n;
    precise float sl = g_vn * g_vn + dn * dn;
    precise float du = (d.x + g_au * d.z) * g_step, dv = -(d.y + g_av * d.z) * g_step;
    precise float dxf = d.x * invf, dyf = -d.y * invf, mxf = mx * invf, myf = -my * invf;
    s_d = d, s_dn = dn, s_mn = mn, s_sl = sl, s_du = du, s_dv = dv;
    s_dxf = dxf, s_dyf = dyf, s_mxf = mxf, s_myf = myf;
}

// horizon.h's ssg_horizon_fold: the tangent-plane correction, isl = mn / sl (the node's).
void ssg_horizon_fold(float isl)
{
    precise float al = isl * g_vn, be = isl * s_dn;
    precise float ax = g_vxf + s_mxf * al, ay = g_vyf + s_myf * al;
    precise float bx = s_dxf + s_mxf * be, by = s_dyf + s_myf * be;
    s_ax = ax, s_ay = ay, s_bx = bx, s_by = by;
}

// horizon.h's ssg_horizon_slice_arc: the slice with isl = mn / sl, and the normal projected
// on it (s_pl, s_cn, s_sn).
void ssg_horizon_slice_arc(float dc, float ds)
{
    ssg_horizon_slice(dc, ds);
    precise float pl = sqrt(s_sl), cn = g_vn / pl, sn = s_dn / pl;
    precise float isl = s_mn / s_sl;
    ssg_horizon_fold(isl);
    s_pl = pl, s_cn = cn, s_sn = sn;
}

// horizon.h's ssg_horizon_place: step st at (st + u) step, rounded (ties to even).
void ssg_horizon_place(int st)
{
    precise float t = float(st) + g_u;
    precise float ou = roundEven(s_du * t), ov = roundEven(s_dv * t);
    precise float pa = ou * s_ax + ov * s_ay, pr = ou * g_vxf + ov * g_vyf;
    precise float b = ou * s_bx + ov * s_by, c = ou * s_mxf + ov * s_myf;
    precise float bd = ou * s_dxf + ov * s_dyf;
    precise float e = bd * bd + c * c;
    precise vec2 a = vec2(pa - g_l, -(pa + g_l)), r = vec2(pr - g_l, -(pr + g_l));
    t_ou = ou, t_ov = ov, t_b = b, t_c = c, t_e = e, t_a = a, t_r = r;
    t_ok = b > abs(c);
}

// The depth at pixel p + (ou, ov), or +inf off screen or on background (the CPU's padded
// plane).
float ssg_horizon_depth(ivec2 p, float ou, float ov)
{
    precise float qx = float(p.x) + ou, qy = float(p.y) + ov;
    if (!(qx >= 0.0 && qx < float(ssg_grid.x) && qy >= 0.0 && qy < float(ssg_grid.y)))
        return 1.0 / 0.0;
    float d = ssg_occluder_depth(ivec2(int(qx), int(qy)));
    return d < 0.0 ? 1.0 / 0.0 : d;
}

// horizon.h's ssg_ign: interleaved gradient noise (Jimenez 2014) in [0, 1).
float ssg_ign(float x, float y)
{
    precise float a = 0.06711056 * x + 0.00583715 * y;
    precise float b = 52.9829189 * (a - floor(a));
    precise float r = b - floor(b);
    return r;
}
