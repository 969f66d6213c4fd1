// probe_light.glsl - `probe_light` on GL, second pass (probe_light_gl.c): per pixel, the
// lights in list order, each as probe_light_cpu.c's add_light: N.l from the frame, then
// the soft lookup (soft_visible) or the jittered texel and depth and one comparison
// against the light's map layer (visible), sums in the same order (`precise` keeps the
// CPU's roundings).
uniform sampler2DArray position, normal, albedo, lights, shadowmaps, frames;
uniform bool albedo_bound; // unconnected: a white receiver's E / pi
uniform bool shadowmaps_bound;
layout(std430, binding = 0) readonly buffer Rotations { float cos_sin[]; };
layout(std430, binding = 1) readonly buffer Noise { float noise[]; };
layout(std430, binding = 2) readonly buffer Taps { float tap[]; };
layout(r32f) uniform writeonly image2DArray dst_out, dst_visibility;
#pragma ssg_params
#pragma ssg_consts
const float MAX_SLOPE = 10.0; // SSG_PROBE_LIGHT_MAX_SLOPE

float frame(int light, int k)
{
    return texelFetch(frames, ivec3(light, 0, k), 0).r;
}

#include "luminance.glsl"

// Point P0 (view space, normal N, sin(N, l_i) = sine) moved along the normal by
// normal_world x sine (the normal offset, README.md), on light i's map: texel x, y, depth
// (probe_light_cpu.c's lift).
vec3 lifted(int i, vec3 P0, vec3 N, float sine)
{
    precise float up = normal_world * sine;
    precise vec3 P = vec3(P0.x + up * N.x, P0.y + up * N.y, P0.z + up * N.z);
    precise vec3 m;
    m.x = P.x * frame(i, 0) + P.y * frame(i, 1) + P.z * frame(i, 2) + frame(i, 3);
    m.y = P.x * frame(i, 4) + P.y * frame(i, 5) + P.z * frame(i, 6) + frame(i, 7);
    m.z = P.x * frame(i, 8) + P.y * frame(i, 9) + P.z * frame(i, 10) + frame(i, 11);
    return m;
}

// V_i of point P (view space, normal N) with jitter j (texels) for light i, N.l_i = cosine.
float visible(int i, vec3 P0, vec3 N, vec2 j, float cosine)
{
    precise float sine = sqrt(max(0.0, 1.0 - cosine * cosine));
    vec3 m = lifted(i, P0, N, sine);
    precise float x = m.x, y = m.y, d = m.z;
    float cr = cos_sin[2 * i], sr = cos_sin[2 * i + 1];
    precise float jx = cr * j.x - sr * j.y, jy = sr * j.x + cr * j.y;
    x += jx;
    y += jy;
    if (!(x >= 0.0 && y >= 0.0 && x < float(res) && y < float(res)))
        return 1.0;
    precise float tangent = cosine > 0.0 ? sine / cosine : 0.0;
    tangent = tangent < MAX_SLOPE ? tangent : MAX_SLOPE;
    precise float limit = texelFetch(shadowmaps, ivec3(int(x), int(y), i), 0).r +
                          (offset_world + slope_world * tangent);
    return d <= limit ? 1.0 : 0.0;
}

// One tap at (ox, oy) texels from the lifted point (x, y), depth d, receiver slope g:
// the map's depth there minus the receiver plane's (probe_light_cpu.c's soft_tap); a
// tap outside the map reads as lit (-inf, as the CPU's).
float tap_height(int i, float x, float y, float d, vec2 g, float ox, float oy)
{
    precise float tx = x + ox, ty = y + oy;
    if (!(tx >= 0.0 && ty >= 0.0 && tx < float(res) && ty < float(res)))
        return -uintBitsToFloat(0x7F800000u); // -inf
    precise float ref = d + (g.x * ox + g.y * oy);
    precise float h = ref - texelFetch(shadowmaps, ivec3(int(tx), int(ty), i), 0).r;
    return h;
}

// Soft V_i (README.md, soft lookups; probe_light_cpu.c's soft_visibility, the same
// floats): a blocker search over search_radius texels, then a filter over the penumbra
// their mean height over the receiver makes (PCSS).
float soft_visible(int i, vec3 P0, vec3 N, float cosine)
{
    precise float sine = sqrt(max(0.0, 1.0 - cosine * cosine));
    vec3 m = lifted(i, P0, N, sine);
    precise float x = m.x, y = m.y, d = m.z;
    precise float nu = N.x * frame(i, 0) + N.y * frame(i, 1) + N.z * frame(i, 2);
    precise float nv = N.x * frame(i, 4) + N.y * frame(i, 5) + N.z * frame(i, 6);
    precise float tt = texel * texel, gmax = MAX_SLOPE * texel;
    precise float gx = nu * tt / cosine, gy = nv * tt / cosine;
    vec2 g = vec2(clamp(gx, -gmax, gmax), clamp(gy, -gmax, gmax));
    precise float tangent = min(sine / cosine, MAX_SLOPE);
    precise float add = offset_world + slope_world * tangent;
    float cr = cos_sin[2 * i], sr = cos_sin[2 * i + 1];
    precise float hsum = 0.0, hcnt = 0.0, lit = 0.0;
    int s0 = 2 * p_taps; // the search's pattern follows the filter's
    for (int t = 0; t < p_search_taps; t++) {
        precise float ox = cr * tap[s0 + t] - sr * tap[s0 + p_search_taps + t];
        precise float oy = sr * tap[s0 + t] + cr * tap[s0 + p_search_taps + t];
        precise float sx = p_search_radius * ox, sy = p_search_radius * oy;
        float h = tap_height(i, x, y, d, g, sx, sy);
        if (h > add) {
            hsum += h;
            hcnt += 1.0;
        } else if (t == 0) {
            lit = 1.0; // the centre: the filter's first tap too
        }
    }
    if (!(hcnt > 0.0))
        return 1.0;
    if (!(hcnt < float(p_search_taps)))
        return 0.0; // the umbra, as the CPU's
    precise float r = hsum / hcnt * cone_tan;
    r = r > 1.0 ? (r < p_search_radius ? r : p_search_radius) : 1.0;
    for (int t = 1; t < p_taps; t++) {
        precise float ox = cr * tap[t] - sr * tap[p_taps + t];
        precise float oy = sr * tap[t] + cr * tap[p_taps + t];
        precise float sx = r * ox, sy = r * oy;
        if (!(tap_height(i, x, y, d, g, sx, sy) > add))
            lit += 1.0;
    }
    precise float share = 1.0 / float(p_taps);
    return lit * share;
}

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    vec3 P = ssg_load3(position, p), N = ssg_load3(normal, p);
    int tile = p_noise_tile, cell = (p.y % tile) * tile + p.x % tile;
    precise vec2 j = p_noise_radius * vec2(noise[cell], noise[tile * tile + cell]);
    precise vec3 sum = vec3(0.0);
    precise float lum_lit = 0.0, lum_all = 0.0;
    // the lights of the pixel's interleave cell, each standing for n^2 (probe_light_cpu.c)
    int n = p_interleave;
    for (int i = (p.y % n) * n + p.x % n; i < count; i += n * n) {
        precise float cosine = N.x * frame(i, 12) + N.y * frame(i, 13) + N.z * frame(i, 14);
        if (!(cosine > 0.0))
            continue; // adds exact zeros (as the CPU's skipped lights)
        vec3 e = vec3(texelFetch(lights, ivec3(i, 1, 0), 0).r,
                      texelFetch(lights, ivec3(i, 1, 1), 0).r,
                      texelFetch(lights, ivec3(i, 1, 2), 0).r);
        if (e == vec3(0.0))
            continue; // a light that carries nothing (lightprobe missing=dark), as the CPU
        float w = cosine;
        float v = !shadowmaps_bound ? 1.0
                  : cone_tan > 0.0 ? soft_visible(i, P, N, cosine)
                                   : visible(i, P, N, j, cosine);
        precise float lit = v * w;
        sum += lit * e;
        lum_lit += lit * luminance(e);
        lum_all += w * luminance(e);
    }
    bool bg = N.x == 0.0 && N.y == 0.0 && N.z == 0.0;
    vec3 a = albedo_bound ? ssg_load3(albedo, p) : vec3(1.0); // none: a white receiver
    precise float weight = float(n * n);
    precise vec3 out_rgb = a * 0.318309886183790671 * (sum * weight);
    SSG_STORE3(dst_out, p, bg ? vec3(0.0) : out_rgb);
    SSG_STORE1(dst_visibility, p, bg || !(lum_all > 0.0) ? 1.0 : lum_lit / lum_all);
}
