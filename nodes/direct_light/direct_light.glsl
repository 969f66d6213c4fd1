// direct_light.glsl - `direct_light` on GL (direct_light_gl.c): per pixel, the scene's
// lights in order, each as direct_light_cpu.c's add_light: the G-buffer's irradiance
// (nodes/common/direct.h), the normal offset, the receiver plane, the PCF disc of bilinear
// taps turned by interleaved gradient noise, the PCSS blocker search; the faces, lights
// and taps are the CPU's bytes (storage buffers).
uniform sampler2DArray position, normal, albedo, maps;
layout(r32f) uniform writeonly image2DArray dst_out, dst_visibility;
struct Face { int light; int ortho; float origin[3]; float u[3]; float v[3]; float axis[3];
              float half_side; };
struct Light { float pos[3]; float dir[3]; float color[3]; float intensity; int point;
               int face; float texel; float spread; int cube; int tiles;
               float cone_scale; float cone_offset; };
layout(std430, binding = 0) readonly buffer Faces { Face face[]; };
layout(std430, binding = 1) readonly buffer Lights { Light light[]; };
layout(std430, binding = 2) readonly buffer Taps { float taps[]; };
#pragma ssg_params
#pragma ssg_consts
const float MAX_RADIUS = 24.0, MAX_SLOPE = 10.0, EMPTY = 1.0e30, TINY = 1e-30;
const int EARLY = 4; // direct_light_cpu.c's
const int CONTACT_STEPS = 8; // SSG_DIRECT_LIGHT_CONTACT_STEPS
const float CONTACT_GRAZING = 0.2; // SSG_DIRECT_LIGHT_CONTACT_GRAZING

vec3 fu(int f) { return vec3(face[f].u[0], face[f].u[1], face[f].u[2]); }
vec3 fv(int f) { return vec3(face[f].v[0], face[f].v[1], face[f].v[2]); }
vec3 fa(int f) { return vec3(face[f].axis[0], face[f].axis[1], face[f].axis[2]); }
vec3 fo(int f) { return vec3(face[f].origin[0], face[f].origin[1], face[f].origin[2]); }

int cube_face(vec3 d) // ssg_lightmap_cube_face
{
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z)
        return d.x >= 0.0 ? 0 : 1;
    if (a.y >= a.z)
        return d.y >= 0.0 ? 2 : 3;
    return d.z >= 0.0 ? 4 : 5;
}

float cube_depth(int first, int f, int x, int y) // direct_light_cpu.c
{
    if (x >= 0 && y >= 0 && x < res && y < res)
        return texelFetch(maps, ivec3(x, y, first + f), 0).r;
    float a = 2.0 * (float(x) + 0.5) / float(res) - 1.0;
    float b = 2.0 * (float(y) + 0.5) / float(res) - 1.0;
    vec3 d = fa(first + f) + a * fu(first + f) + b * fv(first + f);
    int g = first + cube_face(d);
    float z = dot(d, fa(g));
    int gx = clamp(int(floor((dot(d, fu(g)) / z + 1.0) * 0.5 * float(res))), 0, res - 1);
    int gy = clamp(int(floor((dot(d, fv(g)) / z + 1.0) * 0.5 * float(res))), 0, res - 1);
    return texelFetch(maps, ivec3(gx, gy, g), 0).r / z;
}

struct Lookup { int l; int f; float x, y, r, z, texel, bias, gx, gy, nq; vec3 n; };

float occluder(Lookup k, int x, int y)
{
    if (light[k.l].cube != 0)
        return cube_depth(light[k.l].face, k.f, x, y);
    int tiles = light[k.l].tiles, side = res * tiles;
    if (x < 0 || y < 0 || x >= side || y >= side) // off the map; a spot: outside its cone
        return EMPTY;
    ivec2 tile = ivec2(x, y) / res; // ssg_lightmap_tile_texel
    return texelFetch(maps, ivec3(x - tile.x * res, y - tile.y * res,
                                  light[k.l].face + tile.y * tiles + tile.x), 0).r;
}

float tap_limit(Lookup k, float x, float y)
{
    float dx = x - k.x, dy = y - k.y;
    float m = k.texel * MAX_SLOPE * (abs(dx) + abs(dy) + 1.0), t;
    if (light[k.l].point == 0) {
        t = k.r + k.gx * dx + k.gy * dy;
    } else {
        int f = light[k.l].face + k.f;
        float a = 2.0 * x / float(res) - 1.0, b = 2.0 * y / float(res) - 1.0;
        vec3 d = fa(f) + (face[f].half_side * a) * fu(f) + (face[f].half_side * b) * fv(f);
        float len = length(d), nd = dot(k.n, d) / len;
        t = nd < 0.0 ? k.nq / nd : k.r + m;
        t = clamp(t, k.r - m, k.r + m);
        return (t - (k.bias + k.texel * p_tap_slope * sqrt(dx * dx + dy * dy))) / len;
    }
    t = clamp(t, k.r - m, k.r + m);
    return t - k.bias - k.texel * p_tap_slope * sqrt(dx * dx + dy * dy);
}

float bilinear_test(Lookup k, float x, float y)
{
    float fx = x - 0.5, fy = y - 0.5, x0 = floor(fx), y0 = floor(fy);
    float wx = fx - x0, wy = fy - y0, limit = tap_limit(k, x, y);
    int ix = int(x0), iy = int(y0);
    float t00 = limit <= occluder(k, ix, iy) ? 1.0 : 0.0;
    float t10 = limit <= occluder(k, ix + 1, iy) ? 1.0 : 0.0;
    float t01 = limit <= occluder(k, ix, iy + 1) ? 1.0 : 0.0;
    float t11 = limit <= occluder(k, ix + 1, iy + 1) ? 1.0 : 0.0;
    return (1.0 - wy) * ((1.0 - wx) * t00 + wx * t10) + wy * ((1.0 - wx) * t01 + wx * t11);
}

vec2 tap(int s, float cs, float sn)
{
    return vec2(cs * taps[2 * s] - sn * taps[2 * s + 1], sn * taps[2 * s] + cs * taps[2 * s + 1]);
}

float pcf_radius(Lookup k, float cs, float sn)
{
    float spread = light[k.l].spread;
    if (!(spread > 0.0))
        return p_filter;
    bool point = light[k.l].point != 0;
    float search = point ? spread / k.texel : k.r * spread / k.texel;
    search = min(max(search, p_filter), MAX_RADIUS);
    float sum = 0.0;
    int n = 0;
    for (int s = 0; s < p_samples; s++) {
        vec2 o = tap(s, cs, sn);
        float x = k.x + search * o.x, y = k.y + search * o.y;
        float d = occluder(k, int(floor(x)), int(floor(y)));
        if (d < tap_limit(k, x, y)) {
            sum += d;
            n++;
        }
    }
    if (n == 0)
        return -1.0;
    float blocker = sum / float(n);
    float penumbra = point ? spread * (k.z - blocker) / blocker : spread * (k.z - blocker);
    return min(p_filter + 0.5 * penumbra / k.texel, MAX_RADIUS);
}

// direct_light_cpu.c's receiver_texel: a texel of light li's maps at the receiver p.
float receiver_texel(int li, vec3 p)
{
    if (light[li].point == 0)
        return light[li].texel;
    vec3 lp = vec3(light[li].pos[0], light[li].pos[1], light[li].pos[2]);
    return light[li].texel * length(p - lp);
}

Lookup locate(int li, vec3 p, vec3 n, vec3 l)
{
    Lookup k;
    k.l = li;
    float cosine = dot(n, l), sine = sqrt(max(1.0 - cosine * cosine, 0.0));
    vec3 lp = vec3(light[li].pos[0], light[li].pos[1], light[li].pos[2]);
    bool point = light[li].point != 0;
    k.texel = receiver_texel(li, p);
    vec3 q = p + p_normal_offset * k.texel * sine * n;
    k.f = light[li].cube != 0 ? cube_face(q - lp) : 0;
    k.r = length(q - lp);
    int f = light[li].face + k.f;
    vec3 d = q - fo(f);
    float z = dot(d, fa(f));
    float scale = face[f].ortho != 0 ? 1.0 / face[f].half_side : 1.0 / (z * face[f].half_side);
    k.x = (dot(d, fu(f)) * scale + 1.0) * 0.5 * float(res);
    k.y = (dot(d, fv(f)) * scale + 1.0) * 0.5 * float(res);
    if (!point)
        k.r = z;
    k.z = z;
    k.bias = p_offset * k.texel;
    k.gx = k.texel * dot(n, fu(f)) / cosine;
    k.gy = k.texel * dot(n, fv(f)) / cosine;
    k.n = n;
    k.nq = dot(n, q - lp);
    return k;
}

float visibility(int li, ivec2 pix, vec3 p, vec3 n, vec3 l)
{
    Lookup k = locate(li, p, n, l);
    float f = 0.06711056 * float(pix.x) + 0.00583715 * float(pix.y);
    f = 52.9829189 * (f - floor(f));
    float turn = (f - floor(f)) + 0.618034 * float(li);
    float angle = 2.0 * SSG_PI * (turn - floor(turn)), cs = cos(angle), sn = sin(angle);
    float radius = pcf_radius(k, cs, sn);
    if (radius < 0.0)
        return 1.0;
    // the outermost EARLY taps first; all agreeing: wholly lit or shadowed (the CPU's)
    int early = p_samples >= 2 * EARLY ? EARLY : 0;
    float sum = 0.0;
    for (int i = 0; i < p_samples; i++) {
        vec2 o = tap(p_samples - 1 - i, cs, sn);
        sum += bilinear_test(k, k.x + radius * o.x, k.y + radius * o.y);
        if (i + 1 == early && (sum == 0.0 || sum == float(early)))
            return sum / float(early);
    }
    return sum / float(p_samples);
}

// direct_light_cpu.c's pixel_plane: pixel (u, w) as a plane, its geometric normal from
// its neighbours' points; false off the image, on the background, edge-on or alone.
bool is_surface(ivec2 b)
{
    vec3 m = ssg_load3(normal, b);
    return m.x != 0.0 || m.y != 0.0 || m.z != 0.0;
}

bool pixel_plane(float u, float w, out vec3 pt, out vec3 n)
{
    pt = vec3(0.0), n = vec3(0.0);
    if (!(u >= 0.0 && w >= 0.0 && u < float(ssg_grid.x) && w < float(ssg_grid.y)))
        return false;
    ivec2 b = ivec2(int(u), int(w));
    pt = ssg_load3(position, b);
    if (!is_surface(b))
        return false;
    vec3 e[2];
    for (int axis = 0; axis < 2; axis++) {
        int best = 0;
        float best_dz = 3.0e38;
        for (int side = -1; side <= 1; side += 2) {
            ivec2 o = axis != 0 ? ivec2(b.x, b.y + side) : ivec2(b.x + side, b.y);
            if (o.x < 0 || o.y < 0 || o.x >= ssg_grid.x || o.y >= ssg_grid.y || !is_surface(o))
                continue;
            vec3 q = ssg_load3(position, o);
            float dz = abs(q.z - pt.z);
            if (dz < best_dz) {
                best_dz = dz, best = side;
                e[axis] = (q - pt) * float(side);
            }
        }
        if (best == 0)
            return false;
    }
    precise vec3 c = vec3(e[0].y * e[1].z - e[0].z * e[1].y, e[0].z * e[1].x - e[0].x * e[1].z,
                          e[0].x * e[1].y - e[0].y * e[1].x);
    precise float len2 = c.x * c.x + c.y * c.y + c.z * c.z;
    precise float facing = -(c.x * pt.x + c.y * pt.y + c.z * pt.z);
    precise float dist2 = pt.x * pt.x + pt.y * pt.y + pt.z * pt.z;
    precise float g2 = CONTACT_GRAZING * CONTACT_GRAZING;
    if (!(facing * facing > g2 * len2 * dist2))
        return false; // seen edge-on (a silhouette): a pixel there is no plane
    float s = (facing < 0.0 ? -1.0 : 1.0) / sqrt(len2);
    n = c * s;
    return true;
}

float behind(vec3 q, vec3 pt, vec3 n)
{
    precise float d = n.x * (q.x - pt.x) + n.y * (q.y - pt.y) + n.z * (q.z - pt.z);
    return -d;
}

// direct_light_cpu.c's behind_shading: q behind the plane of pixel (u, w)'s point and its
// shading normal (the cheap half of the test).
bool behind_shading(float u, float w, vec3 q)
{
    if (!(u >= 0.0 && w >= 0.0 && u < float(ssg_grid.x) && w < float(ssg_grid.y)))
        return false;
    ivec2 b = ivec2(int(u), int(w));
    return behind(q, ssg_load3(position, b), ssg_load3(normal, b)) > 0.0;
}

// direct_light_cpu.c's contact_visibility: the march towards world direction l.
float contact_visibility(ivec2 pix, vec3 l, float reach)
{
    vec3 p = ssg_load3(position, pix);
    precise vec3 v = vec3(rot[0] * l.x + rot[1] * l.y + rot[2] * l.z,
                          rot[3] * l.x + rot[4] * l.y + rot[5] * l.z,
                          rot[6] * l.x + rot[7] * l.y + rot[8] * l.z);
    float f = proj.x, cx = proj.y, cy = proj.z;
    float step = reach / float(CONTACT_STEPS), soft = 0.125 * reach, shadow = 0.0;
    for (int s = 1; s <= CONTACT_STEPS; s++) {
        precise float t = step * float(s);
        precise vec3 q = p + t * v;
        if (!(q.z < 0.0))
            break;
        vec3 pt, n, pt2, n2;
        float u = cx + f * q.x / -q.z, w = cy - f * q.y / -q.z;
        if (!behind_shading(u, w, q) || !pixel_plane(u, w, pt, n))
            continue;
        float d = behind(q, pt, n);
        if (!(d > 0.0 && d < reach))
            continue;
        precise vec3 q0 = q - step * v;
        float before = behind(q0, pt, n);
        float a = before < 0.0 ? before / (before - d) : 0.0;
        precise vec3 xp = q0 + a * step * v;
        if (!(xp.z < 0.0) || !pixel_plane(cx + f * xp.x / -xp.z, cy - f * xp.y / -xp.z, pt2, n2))
            continue;
        if (!(abs(behind(xp, pt2, n2)) < step))
            continue; // the crossing is not on a surface the camera sees
        shadow = max(shadow, min(d / soft, 1.0));
        if (shadow == 1.0)
            break; // no later step can shadow more
    }
    return 1.0 - shadow;
}

// nodes/common/direct.h: the G-buffer's irradiance, E without the colour, and L.
float irradiance(int li, vec3 p, vec3 n, out vec3 l)
{
    if (light[li].point == 0) {
        l = -vec3(light[li].dir[0], light[li].dir[1], light[li].dir[2]);
        precise float ndl = dot(n, l);
        return light[li].intensity * max(ndl, 0.0);
    }
    precise vec3 d = vec3(light[li].pos[0], light[li].pos[1], light[li].pos[2]) - p;
    precise float inv = 1.0 / sqrt(d.x * d.x + d.y * d.y + d.z * d.z + TINY);
    l = d * inv;
    precise float ndl = n.x * l.x + n.y * l.y + n.z * l.z;
    vec3 axis = vec3(light[li].dir[0], light[li].dir[1], light[li].dir[2]);
    float cone = ssg_cone_falloff(-dot(axis, l), light[li].cone_scale, light[li].cone_offset);
    return light[li].intensity * cone * max(ndl, 0.0) * inv * inv;
}

#include "luminance.glsl"

void main()
{
    ivec2 pix = ssg_pixel();
    if (ssg_outside(pix))
        return;
    vec3 v = ssg_load3(position, pix), m = ssg_load3(normal, pix);
    precise vec3 p = eye + vec3(rot[0] * v.x + rot[3] * v.y + rot[6] * v.z,
                                rot[1] * v.x + rot[4] * v.y + rot[7] * v.z,
                                rot[2] * v.x + rot[5] * v.y + rot[8] * v.z);
    precise vec3 n = vec3(rot[0] * m.x + rot[3] * m.y + rot[6] * m.z,
                          rot[1] * m.x + rot[4] * m.y + rot[7] * m.z,
                          rot[2] * m.x + rot[5] * m.y + rot[8] * m.z);
    vec3 sum = vec3(0.0);
    float lum_lit = 0.0, lum_all = 0.0;
    for (int li = 0; li < lights; li++) {
        vec3 l;
        float e = irradiance(li, p, n, l);
        if (!(e > 0.0))
            continue;
        float vis = visibility(li, pix, p, n, l);
        if (p_contact > 0.0 && vis > 0.0)
            vis *= contact_visibility(pix, l, p_contact * receiver_texel(li, p));
        float lit = vis * e;
        vec3 c = vec3(light[li].color[0], light[li].color[1], light[li].color[2]);
        sum += lit * c;
        lum_lit += lit * luminance(c);
        lum_all += e * luminance(c);
    }
    bool bg = m.x == 0.0 && m.y == 0.0 && m.z == 0.0;
    SSG_STORE3(dst_out, pix, bg ? vec3(0.0) : ssg_load3(albedo, pix) * 0.318309886183790671 * sum);
    SSG_STORE1(dst_visibility, pix, bg || !(lum_all > 0.0) ? 1.0 : lum_lit / lum_all);
}
