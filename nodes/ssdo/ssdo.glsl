// ssdo.glsl - the `ssdo` node on GL (method in README.md), and with SSDO_BOUNCE_NODE defined
// the `bounce` node (bounce.md): one invocation per pixel, the kernel samples in order.
// Both nodes share ssdo_sampling.h's maths on the CPU, so they share this file on GL.
// The maths is ssdo_cpu.c's and ssdo_sampling.h's lane by lane: the same tangent frame and
// projective coefficients, the same sums in the same order (`precise`, so that no
// multiply-add is fused where the CPU rounds twice). Where the CPU masks a lane (off
// screen, not behind the depth, past its count) this skips: adding 0 changes no bits.
#include "sampling.glsl" // position, depth, rotation, kernel and their helpers
uniform sampler2DArray normal;
uniform sampler2DArray albedo;
uniform sampler2DArray light;    // the senders' radiance (bounce)
layout(r32f) uniform writeonly image2DArray dst_out; // bounce: its only output

// The parameters (p_<field>, from the node's table: bounce's are ssdo's sampling rows) and
// what prepare() derived.
// cap, capped, proj: the node's constants (#pragma ssg_consts; bounce's are the first
// three of ssdo's, ssdo_sampling.h), and ssdo's out_channels, env, env_rgb, light_count.
#pragma ssg_params
#pragma ssg_consts

#ifdef SSDO_BOUNCE_NODE
#define DO_BOUNCE true      // gather the bounce: the node's purpose
#else
#define DO_BOUNCE (p_bounce != 0)
uniform sampler2DArray count;
uniform bool count_bound;
layout(r32f) uniform writeonly image2DArray dst_bounce;
// The environment as a view-space cube (core/scene/env.h), RGB per texel (env = ENV_CUBE).
layout(std430, binding = 1) readonly buffer EnvCube { float cube_rgb[]; };

const int MAX_LIGHTS = 8;   // SSG_SSDO_MAX_LIGHTS
const int ENV_CUBE = 1;     // enum ssg_ssdo_env
const int CUBE_SIZE = 16;   // SSG_ENV_CUBE_SIZE
// The lights, prepare()'s struct ssg_ssdo_light as it is (std430 lays it out as C does).
struct ssdo_light {
    int directional;  // 0 = point or spot light at v, 1 = directional light from unit v
    float v[3];       // point: view-space position; directional: unit direction to it
    float rgb[3];     // colour * intensity
    float axis[3];    // spot: the cone's view-space unit axis
    float cone_scale, cone_offset; // ssg_cone_falloff's (point: 0, 1)
};
layout(std430, binding = 2) readonly buffer Lights { ssdo_light lights[]; };
#endif

// Per-pixel constants (ssg_ssdo_setup).
struct pixel_frame {
    vec3 P, N, T, B; // P, unit N, T and B turned by the tile (unit, not scaled by r)
    vec2 shift;      // the tile's length shift (dl, k) at P (0: none)
    float r2;        // r^2 (range check)
    float ff;        // A_s / pi = strength r^2 / n
    float md2;       // min_distance^2
    vec4 cz, cu, cv; // Z - bias, u Z, v Z = dot(c, (1, s))
};

// Accumulated bounce of one pixel.
struct bounce_sum {
    float fsum; // sum F_i
    vec3 fl;    // sum F_i L_i
};

// Duff et al.'s branch-free basis about N (-0 counts as negative, as copysignf does),
// turned by the tile's (co, si); the radius (capped) and the projective coefficients.
pixel_frame setup_frame(vec3 P, vec3 N, vec2 rot, float dp, int n)
{
    float f = proj.x, cx = proj.y, cy = proj.z;
    vec3 t, b;
    ssg_tangent_basis(N, t, b);
    float t0 = t.x, t1 = t.y, t2 = t.z, b0 = b.x, b1 = b.y, b2 = b.z;
    float co = rot.x, si = rot.y;
    precise vec3 T = vec3(co * t0 + si * b0, co * t1 + si * b1, co * t2 + si * b2);
    precise vec3 B = vec3(co * b0 - si * t0, co * b1 - si * t1, co * b2 - si * t2);
    precise float rcap = cap * dp;
    float r = capped != 0 && rcap < p_radius ? rcap : p_radius;
    precise float qz = -P.z;
    precise float rtz = r * T.z, rbz = r * B.z, rnz = r * N.z;
    pixel_frame k;
    k.P = P, k.N = N, k.T = T, k.B = B;
    k.shift = vec2(0.0); // main() sets the tile's
    k.cz = vec4(qz - p_bias, -rtz, -rbz, -rnz);
    precise float cu0 = f * P.x + cx * qz, cu1 = f * (r * T.x) - cx * rtz;
    precise float cu2 = f * (r * B.x) - cx * rbz, cu3 = f * (r * N.x) - cx * rnz;
    precise float cv0 = cy * qz - f * P.y, cv1 = -cy * rtz - f * (r * T.y);
    precise float cv2 = -cy * rbz - f * (r * B.y), cv3 = -cy * rnz - f * (r * N.y);
    k.cu = vec4(cu0, cu1, cu2, cu3);
    k.cv = vec4(cv0, cv1, cv2, cv3);
    precise float per_n = p_strength / float(n);
    precise float r2 = r * r;
    precise float ff = per_n * r2;
    k.r2 = r2;
    k.ff = ff;
    k.md2 = p_min_distance > 0.0 ? p_min_distance * p_min_distance : ff;
    return k;
}

// The form factor of an occluded sample's sender patch at pixel q (ssg_ssdo_range_bounce),
// v = P_i - P and dd = |v|^2 already computed; adds F_i and F_i L_i.
void add_bounce(inout bounce_sum acc, pixel_frame k, ivec2 q, vec3 v, float dd)
{
    vec3 M = ssg_load3(normal, q);
    precise float inv = 1.0 / sqrt(dd > 1e-30 ? dd : 1e-30);
    precise vec3 w = vec3(v.x * inv, v.y * inv, v.z * inv);
    precise float cr = k.N.x * w.x + k.N.y * w.y + k.N.z * w.z;
    precise float cs = -(M.x * w.x + M.y * w.y + M.z * w.z);
    cr = cr > 0.0 ? cr : 0.0;
    cs = cs > 0.0 ? cs : 0.0;
    float d2 = dd > k.md2 ? dd : k.md2;
    precise float fi = k.ff * cr * cs / d2;
    vec3 L = ssg_load3(light, q);
    acc.fsum += fi;
    precise vec3 fl = vec3(fi * L.x, fi * L.y, fi * L.z);
    acc.fl += fl;
}

// Kernel sample number i's (s) visibility V (1 or 0) around the pixel (ssg_ssdo_place,
// ssg_ssdo_depth_test, ssg_ssdo_range_bounce), gathering its bounce when occluded; its
// length shifted by the tile's (its direction, which the weights see, kept).
float sample_visibility(pixel_frame k, int i, vec3 s, inout bounce_sum acc)
{
    ivec2 q;
    float zb;
    vec3 placed = ssg_shifted_sample(i, s, k.shift);
    if (!ssg_project_sample(k.cz, k.cu, k.cv, placed, p_bias, q, zb))
        return 1.0;
    float d = ssg_scene_depth(q);
    if (!(d > 0.0 && d < zb))
        return 1.0;
    precise vec3 dv = ssg_load3(position, q) - k.P;
    precise float dd = dv.x * dv.x + dv.y * dv.y + dv.z * dv.z;
    if (!(dd <= k.r2))
        return 1.0;
    if (DO_BOUNCE)
        add_bounce(acc, k, q, dv, dd);
    return 0.0;
}

// albedo sum F_i L_i, the F_i scaled by 1 / sum when the sum exceeds 1
// (ssg_ssdo_finish_bounce).
vec3 finish_bounce(ivec2 p, bounce_sum acc)
{
    float s = acc.fsum > 1.0 ? 1.0 / acc.fsum : 1.0;
    vec3 a = ssg_load3(albedo, p);
    precise vec3 fl = vec3(acc.fl.x * s, acc.fl.y * s, acc.fl.z * s);
    precise vec3 x = vec3(a.x * fl.x, a.y * fl.y, a.z * fl.z);
    return x;
}

// Loads P, N and depth; false for the background (depth 0, no normal) or garbage. A
// normal that is not unit is normalised (the CPU does so for its whole chunk).
bool load_pixel(ivec2 p, out vec3 P, out vec3 N, out float dp)
{
    dp = ssg_scene_depth(p);
    N = ssg_load3(normal, p);
    P = ssg_load3(position, p);
    return ssg_surface_normal(dp, N);
}

// Each node's part of main() (at the end): what a background pixel gets, the samples a
// pixel takes and its gather over them.
#ifdef SSDO_BOUNCE_NODE

void store_background(ivec2 p)
{
    SSG_STORE3(dst_out, p, vec3(0.0));
}

int pixel_samples(ivec2 p)
{
    return textureSize(kernel, 0).x;
}

void gather(ivec2 p, pixel_frame k, int n)
{
    bounce_sum acc = bounce_sum(0.0, vec3(0.0));
    for (int s = 0; s < n; s++)
        sample_visibility(k, s, ssg_kernel_sample(s), acc);
    SSG_STORE3(dst_out, p, finish_bounce(p, acc));
}

#else

// What one pixel's lights and environment gather over its samples.
struct light_sums {
    float ws[MAX_LIGHTS]; // sum of lobe weights w_il
    float wv[MAX_LIGHTS]; // sum of w_il V_i
    float litw, fullw;    // constant environment: sum of nw V, sum of nw
    float cosw;           // sum of nw over the pixel's samples, in order: dw = pi / cosw
    vec3 lit, full;       // cube: sum of L_env nw V, sum of L_env nw
};

// Per light, L in the turned tangent frame (T.L, B.L, N.L) and the unshadowed
// irradiance factor max(0, N.L) (/ d^2 for a point light) (ssdo_cpu.c setup_lights).
void setup_lights(pixel_frame k, out vec3 lt[MAX_LIGHTS], out float e[MAX_LIGHTS])
{
    for (int l = 0; l < MAX_LIGHTS; l++) {
        lt[l] = vec3(0.0);
        e[l] = 0.0;
        if (l >= light_count)
            continue;
        float point = lights[l].directional != 0 ? 0.0 : 1.0;
        precise float lx = lights[l].v[0] - point * k.P.x;
        precise float ly = lights[l].v[1] - point * k.P.y;
        precise float lz = lights[l].v[2] - point * k.P.z;
        precise float d2 = lx * lx + ly * ly + lz * lz;
        precise float inv = 1.0 / sqrt(d2 > 1e-30 ? d2 : 1e-30);
        precise vec3 L = vec3(lx * inv, ly * inv, lz * inv);
        precise float ndl = k.N.x * L.x + k.N.y * L.y + k.N.z * L.z;
        precise float fall = lights[l].directional != 0 ? 1.0 : inv * inv;
        vec3 axis = vec3(lights[l].axis[0], lights[l].axis[1], lights[l].axis[2]);
        float cone = ssg_cone_falloff(-dot(axis, L), lights[l].cone_scale,
                                      lights[l].cone_offset);
        precise float el = (ndl > 0.0 ? ndl : 0.0) * fall * cone;
        e[l] = el;
        precise float tl = k.T.x * L.x + k.T.y * L.y + k.T.z * L.z;
        precise float bl = k.B.x * L.x + k.B.y * L.y + k.B.z * L.z;
        lt[l] = vec3(tl, bl, ndl);
    }
}

// max(0, cl)^lobe nw by squaring, bits of lobe from the lowest (ssdo_cpu.c lobe_pow).
float lobe_pow(float cl, float nw)
{
    precise float c = cl > 0.0 ? cl : 0.0, p = nw;
    for (int e = p_lobe; e != 0; e >>= 1) {
        if ((e & 1) != 0)
            p *= c;
        if (e > 1)
            c *= c;
    }
    return p;
}

// The nearest cube texel's float offset for direction d (core/scene/env.h ssg_env_cube_index).
int cube_offset(vec3 d)
{
    const int n = CUBE_SIZE;
    float ax = d.x < 0.0 ? -d.x : d.x, ay = d.y < 0.0 ? -d.y : d.y;
    float az = d.z < 0.0 ? -d.z : d.z;
    bool xm = ax >= ay && ax >= az, ym = !xm && ay >= az;
    float ma = xm ? ax : ym ? ay : az;
    int face = xm ? (d.x >= 0.0 ? 0 : 1) : ym ? (d.y >= 0.0 ? 2 : 3) : (d.z >= 0.0 ? 4 : 5);
    float sc = xm ? (d.x >= 0.0 ? -d.z : d.z) : ym ? d.x : (d.z >= 0.0 ? d.x : -d.x);
    float tc = xm ? -d.y : ym ? (d.y >= 0.0 ? d.z : -d.z) : -d.y;
    precise float inv = 0.5 * float(n) / ma;
    precise float fi = sc * inv + 0.5 * float(n), fj = tc * inv + 0.5 * float(n);
    int i = clamp(int(fi), 0, n - 1), j = clamp(int(fj), 0, n - 1);
    return 3 * ((face * n + j) * n + i);
}

// The environment's share of sample s: direction w in view space, weight nw = N.w.
void add_environment(inout light_sums acc, pixel_frame k, vec3 s, float nw, float vis)
{
    if (env != ENV_CUBE) {
        precise float lw = nw * vis;
        acc.litw += lw;
        acc.fullw += nw;
        return;
    }
    precise vec3 d = vec3(k.T.x * s.x + k.B.x * s.y + k.N.x * s.z,
                          k.T.y * s.x + k.B.y * s.y + k.N.y * s.z,
                          k.T.z * s.x + k.B.z * s.y + k.N.z * s.z);
    int o = cube_offset(d);
    precise vec3 v = vec3(cube_rgb[o] * nw, cube_rgb[o + 1] * nw, cube_rgb[o + 2] * nw);
    acc.full += v;
    precise vec3 lv = vec3(v.x * vis, v.y * vis, v.z * vis);
    acc.lit += lv;
}

// Every light's lobe weight for sample s (ssdo_cpu.c add_lights).
void add_lights(inout light_sums acc, vec3 lt[MAX_LIGHTS], vec3 s, float il, float nw,
                float vis)
{
    for (int l = 0; l < MAX_LIGHTS; l++) {
        if (l >= light_count)
            break;
        precise float cl = (s.x * lt[l].x + s.y * lt[l].y + s.z * lt[l].z) * il;
        precise float p = lobe_pow(cl, nw);
        acc.ws[l] += p;
        precise float pv = p * vis;
        acc.wv[l] += pv;
    }
}

// Numerator and denominator per channel: the environment term, then each light's
// E vis and E in light order (ssdo_cpu.c light_sums); dw = pi / sum of N.w.
void light_totals(light_sums acc, float e[MAX_LIGHTS], float dw, out vec3 num, out vec3 den)
{
    if (env != ENV_CUBE) {
        precise vec3 scale = vec3(env_rgb.x * dw, env_rgb.y * dw, env_rgb.z * dw);
        num = vec3(scale.x * acc.litw, scale.y * acc.litw, scale.z * acc.litw);
        den = vec3(scale.x * acc.fullw, scale.y * acc.fullw, scale.z * acc.fullw);
    } else {
        num = vec3(acc.lit.x * dw, acc.lit.y * dw, acc.lit.z * dw);
        den = vec3(acc.full.x * dw, acc.full.y * dw, acc.full.z * dw);
    }
    for (int l = 0; l < MAX_LIGHTS; l++) {
        if (l >= light_count)
            break;
        precise float q = acc.wv[l] / acc.ws[l];
        float vis = acc.ws[l] > 0.0 ? q : 1.0;
        precise vec3 el = vec3(lights[l].rgb[0] * e[l], lights[l].rgb[1] * e[l],
                               lights[l].rgb[2] * e[l]);
        precise vec3 ev = vec3(el.x * vis, el.y * vis, el.z * vis);
        num += ev;
        den += el;
    }
}


// M^power (ssdo_cpu.c raise_to_power; powf(x, 0) = 1, even at 0).
vec3 raised(vec3 m)
{
    if (p_power == 1.0)
        return m;
    return p_power == 0.0 ? vec3(1.0) : pow(m, vec3(p_power));
}

// Modulation (per channel or of luminances) or radiance (ssdo_cpu.c finish_chunk).
void store_out(ivec2 p, vec3 num, vec3 den)
{
    if (p_mode == MODE_RADIANCE) {
        const float inv_pi = 0.31830988618379067154; // (float)(1.0 / M_PI)
        vec3 a = ssg_load3(albedo, p);
        precise vec3 v = vec3(a.x * inv_pi * num.x, a.y * inv_pi * num.y, a.z * inv_pi * num.z);
        SSG_STORE3(dst_out, p, v);
    } else if (out_channels == 3) {
        precise vec3 q = vec3(num.x / den.x, num.y / den.y, num.z / den.z);
        SSG_STORE3(dst_out, p, raised(vec3(den.x > 1e-30 ? q.x : 1.0,
                                           den.y > 1e-30 ? q.y : 1.0,
                                           den.z > 1e-30 ? q.z : 1.0)));
    } else {
        precise float yn = 0.2126 * num.x + 0.7152 * num.y + 0.0722 * num.z;
        precise float yd = 0.2126 * den.x + 0.7152 * den.y + 0.0722 * den.z;
        precise float q = yn / yd;
        SSG_STORE1(dst_out, p, raised(vec3(yd > 1e-30 ? q : 1.0)).x);
    }
}

void store_background(ivec2 p)
{
    if (p_mode == MODE_RADIANCE || out_channels == 3)
        SSG_STORE3(dst_out, p, vec3(p_mode == MODE_RADIANCE ? 0.0 : 1.0));
    else
        SSG_STORE1(dst_out, p, 1.0);
    SSG_STORE3(dst_bounce, p, vec3(0.0));
}

int pixel_samples(ivec2 p)
{
    return ssg_pixel_count(count, count_bound, p, textureSize(kernel, 0).x);
}

void gather(ivec2 p, pixel_frame k, int n)
{
    vec3 lt[MAX_LIGHTS];
    float e[MAX_LIGHTS];
    setup_lights(k, lt, e);
    light_sums acc;
    for (int l = 0; l < MAX_LIGHTS; l++)
        acc.ws[l] = acc.wv[l] = 0.0;
    acc.litw = acc.fullw = acc.cosw = 0.0;
    acc.lit = acc.full = vec3(0.0);
    bounce_sum b = bounce_sum(0.0, vec3(0.0));
    for (int s = 0; s < n; s++) {
        vec3 ks = ssg_kernel_sample(s);
        // 1 / |s| and N.w = s.z / |s| (ssdo_cpu.c kernel_constants)
        precise float len = sqrt(ks.x * ks.x + ks.y * ks.y + ks.z * ks.z);
        precise float il = len > 0.0 ? 1.0 / len : 0.0;
        precise float nw = ks.z * il;
        nw = nw > 0.0 ? nw : 0.0;
        acc.cosw += nw;
        float vis = sample_visibility(k, s, ks, b);
        add_environment(acc, k, ks, nw, vis);
        add_lights(acc, lt, ks, il, nw, vis);
    }
    vec3 num, den;
    // ssdo_cpu.c kernel_constants: pi over the samples' own cosine sum
    precise float dw = acc.cosw > 0.0 ? 3.14159265358979 / acc.cosw : 0.0;
    light_totals(acc, e, dw, num, den);
    store_out(p, num, den);
    SSG_STORE3(dst_bounce, p, DO_BOUNCE ? finish_bounce(p, b) : vec3(0.0));
}

#endif

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    vec3 P, N;
    float dp;
    if (!load_pixel(p, P, N, dp)) {
        store_background(p);
        return;
    }
    int n = pixel_samples(p);
    pixel_frame k = setup_frame(P, N, ssg_tile_rotation(p), dp, n);
    k.shift = ssg_tile_shift(p);
    gather(p, k, n);
}
