// ssao.glsl - the `ssao` node on GL (method in README.md): one invocation per pixel, all three
// modes. The maths is ssao_cpu.c's, lane by lane: the same tangent frame folded into the
// same projective coefficients, the same sums in the same order (`precise`, so that no
// multiply-add is fused where the CPU rounds twice), samples in kernel order, sphere mode's
// reflected sample right after its sample, disc mode's opposite offset likewise. Where the
// CPU masks a lane (off screen, past its count), this skips: adding 0 changes no bits.
#include "sampling.glsl" // position, depth, rotation, kernel and their helpers
uniform sampler2DArray normal;   // read in mode hemisphere only
uniform sampler2DArray count;
uniform bool count_bound;
layout(r32f) uniform writeonly image2DArray dst_out;

#pragma ssg_params
#pragma ssg_consts
// proj (a constant): (f, cx, cy) of this resolution


// The weighted occlusion of one placed sample: scene depth d at its pixel occludes when
// 0 < d < zb (zb = -S.z - bias, or depth(P) - bias in disc mode), weighted by the range
// check on |depth(P) - d| against r (ssao_cpu.c lookup_chunk).
float occlusion(ivec2 q, float zb, float dp, float r)
{
    float d = ssg_scene_depth(q);
    if (!(d > 0.0 && d < zb))
        return 0.0;
    precise float gap = abs(dp - d);
    if (p_range_check == RANGE_CHECK_NONE || gap <= r)
        return 1.0;
    if (p_range_check == RANGE_CHECK_HARD)
        return 0.0;
    precise float t = r / gap; // smooth: smoothstep(0, 1, r / |dp - d|), gap > r
    precise float w = t * t * (3.0 - 2.0 * t);
    return w;
}


// Projective coefficients of the sample frame (ssao_cpu.c setup_chunk): for a kernel
// sample s, Z - bias = dot(cz, (1, s)), u Z = dot(cu, (1, s)), v Z = dot(cv, (1, s)).
struct frame_coeffs {
    vec4 cz, cu, cv;
};

// Duff et al.'s branch-free basis about N (-0 counts as negative, as copysignf does),
// turned by the tile's (co, si), scaled by r and folded with the projection.
frame_coeffs setup_frame(vec3 P, vec3 N, vec2 rot, float r)
{
    float f = proj.x, cx = proj.y, cy = proj.z;
    vec3 t, b;
    ssg_tangent_basis(N, t, b);
    float t0 = t.x, t1 = t.y, t2 = t.z, b0 = b.x, b1 = b.y, b2 = b.z;
    precise float co = r * rot.x, si = r * rot.y;
    precise float tx = co * t0 + si * b0, ty = co * t1 + si * b1, tz = co * t2 + si * b2;
    precise float bx = co * b0 - si * t0, by = co * b1 - si * t1, bz = co * b2 - si * t2;
    precise float nxr = r * N.x, nyr = r * N.y, nzr = r * N.z;
    precise float qz = -P.z;
    frame_coeffs k;
    k.cz = vec4(qz - p_bias, -tz, -bz, -nzr);
    precise float cu0 = f * P.x + cx * qz, cu1 = f * tx - cx * tz;
    precise float cu2 = f * bx - cx * bz, cu3 = f * nxr - cx * nzr;
    precise float cv0 = cy * qz - f * P.y, cv1 = -cy * tz - f * ty;
    precise float cv2 = -cy * bz - f * by, cv3 = -cy * nzr - f * nyr;
    k.cu = vec4(cu0, cu1, cu2, cu3);
    k.cv = vec4(cv0, cv1, cv2, cv3);
    return k;
}

// One sample S = P + r R s of the hemisphere or sphere modes (ssao_cpu.c place_chunk):
// projected, then tested; behind the camera or off screen it is unoccluded.
float sample_point(frame_coeffs k, vec3 s, float dp, float r)
{
    ivec2 q;
    float zb;
    if (!ssg_project_sample(k.cz, k.cu, k.cv, s, p_bias, q, zb))
        return 0.0;
    return occlusion(q, zb, dp, r);
}

// Disc mode (ssao_cpu.c place_disc): the depth sample at offset sign * rp R (s.x, s.y)
// px, rounded to whole pixels (ties to even), +y up the screen.
float sample_disc(ivec2 p, vec2 rot, vec3 s, float sgn, float rp, float dp, float r)
{
    precise float ou = roundEven(rp * (rot.x * s.x - rot.y * s.y));
    precise float ov = roundEven(rp * (rot.y * s.x + rot.x * s.y));
    precise float u = float(p.x) + sgn * ou, v = float(p.y) - sgn * ov;
    vec2 size = vec2(ssg_grid);
    if (!(u >= 0.0 && u < size.x && v >= 0.0 && v < size.y))
        return 0.0;
    precise float zb = dp - p_bias;
    return occlusion(ivec2(int(u), int(v)), zb, dp, r);
}

// Weighted occluded samples of a surface pixel over its first n kernel samples.
float occluded_sum(ivec2 p, vec3 N, float dp, int n)
{
    vec2 rot = ssg_tile_rotation(p);
    vec2 shift = ssg_tile_shift(p); // the sample lengths' shift at p (0: none)
    precise float rcap = cap * dp;
    float r = capped != 0 && rcap < p_radius ? rcap : p_radius;
    precise float occ = 0.0;
    if (p_mode == MODE_DISC) {
        precise float rp = proj.x * r / dp;
        for (int s = 0; s < n; s++) {
            vec3 ks = ssg_shifted_sample(s, ssg_kernel_sample(s), shift);
            occ += sample_disc(p, rot, ks, 1.0, rp, dp, r);
            occ += sample_disc(p, rot, ks, -1.0, rp, dp, r);
        }
        return occ;
    }
    frame_coeffs k = setup_frame(ssg_load3(position, p), N, rot, r);
    for (int s = 0; s < n; s++) {
        vec3 ks = ssg_shifted_sample(s, ssg_kernel_sample(s), shift);
        occ += sample_point(k, ks, dp, r);
        if (p_mode == MODE_SPHERE)
            occ += sample_point(k, -ks, dp, r);
    }
    return occ;
}

// (1 - occluded / n)^power, or clamp(2 - occluded / n, 0, 1)^power normal-free.
float visibility(float occ, int n, int samples)
{
    precise float icnt = n == samples ? inv_samples : 1.0 / float(n);
    precise float v = (p_mode == MODE_HEMISPHERE ? 1.0 : 2.0) - occ * icnt;
    v = v > 0.0 ? v : 0.0;
    v = v < 1.0 || p_mode == MODE_HEMISPHERE ? v : 1.0;
    if (p_power != 1.0)
        v = p_power == 0.0 ? 1.0 : pow(v, p_power); // powf(x, 0) = 1, even at 0
    return v;
}

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    float dp = ssg_scene_depth(p);
    vec3 N = p_mode == MODE_HEMISPHERE ? ssg_load3(normal, p) : vec3(0.0, 0.0, 1.0);
    if (!ssg_surface_normal(dp, N)) { // background or garbage: 1
        SSG_STORE1(dst_out, p, 1.0);
        return;
    }
    int samples = textureSize(kernel, 0).x;
    int n = ssg_pixel_count(count, count_bound, p, samples);
    SSG_STORE1(dst_out, p, visibility(occluded_sum(p, N, dp, n), n, samples));
}
