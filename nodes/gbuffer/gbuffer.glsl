// gbuffer.glsl - the G-buffer's shading pass on GL (method in README.md). Per pixel, the
// ray through the pixel centre is intersected with the triangle gbuffer_raster.glsl found
// there (a visibility buffer, core/gl/gl_scene.h), so depth and barycentrics come from the
// ray as on the CPU; normal, albedo, direct and environment light then follow
// gbuffer_cpu.c operation by operation, reading the scene's buffers (core/gl/gl_scene.h).
#include "scene.glsl"       // Mesh, vdata, vindex, scene_mesh, fetch3
#include "surface.glsl"     // Material, texel, scene_material, fetch2, wrap, sample_texture
#pragma ssg_params
// proj, inv_f (1 / f rounded on the CPU, as gbuffer_cpu.c has it), rot (world -> view,
// row-major), eye, light_count, env_mode (0 black, 1 constant, 2 the irradiance table),
// env_constant (mode 1: pi * the constant radiance), env_north, env_south (mode 2: the
// table's values at the poles): gbuffer.h's rows
#pragma ssg_consts
#include "gbuffer_ray.glsl" // intersect
// Per light (gbuffer_gl.c), 16 floats: position xyz, direction xyz, colour rgb, intensity,
// kind (0 point or spot, 1 directional), the cone's scale and offset (ssg_cone_falloff),
// unused.
layout(std430, binding = 5) readonly buffer Lights { float light[]; };
// env.h's irradiance table, 32 rows x 64 columns x rgb (environment mode 2).
layout(std430, binding = 6) readonly buffer Irradiance { float irradiance[]; };

uniform sampler2DArray ids; // layer 0: mesh + 1 (0 = background), layer 1: triangle
layout(r32f) uniform writeonly image2DArray dst_position;
layout(r32f) uniform writeonly image2DArray dst_normal;
layout(r32f) uniform writeonly image2DArray dst_depth;
layout(r32f) uniform writeonly image2DArray dst_albedo;
layout(r32f) uniform writeonly image2DArray dst_direct;
layout(r32f) uniform writeonly image2DArray dst_environment;

const float TINY = 1e-30;                      // gbuffer_cpu.c's
const float INV_PI = 0.318309886183790671538;  // (float)(1.0 / M_PI)
const float PI_F = 3.14159265358979323846;
const float TWO_PI_F = 6.28318530717958647692;
const int ENV_W = 64, ENV_H = 32;              // SSG_ENV_COARSE_W, _H

vec3 env_row(int y, int x0, int x1, float ax)
{
    if (y < 0)
        return env_north;
    if (y > ENV_H - 1)
        return env_south;
    int a = 3 * (y * ENV_W + x0), b = 3 * (y * ENV_W + x1);
    vec3 ta = vec3(irradiance[a], irradiance[a + 1], irradiance[a + 2]);
    vec3 tb = vec3(irradiance[b], irradiance[b + 1], irradiance[b + 2]);
    return (1.0 - ax) * ta + ax * tb;
}

// core/scene/env.c's table_bilinear on the irradiance table, for unit world normal n.
vec3 env_irradiance(vec3 n)
{
    float u = 0.5 + atan(n.x, -n.z) / TWO_PI_F, v = acos(clamp(n.y, -1.0, 1.0)) / PI_F;
    float fx = u * float(ENV_W) - 0.5, fy = v * float(ENV_H) - 0.5;
    float x0f = floor(fx), ax = fx - x0f, ay = fy - floor(fy);
    int x0 = wrap(int(x0f), ENV_W), x1 = (x0 + 1) % ENV_W, y = int(floor(fy));
    vec3 r0 = env_row(y, x0, x1, ax), r1 = env_row(y + 1, x0, x1, ax);
    // the poles sit half a texel beyond the outer row centres
    float w = y < 0 ? 2.0 * ay - 1.0 : y >= ENV_H - 1 ? 2.0 * ay : ay;
    w = clamp(w, 0.0, 1.0);
    return (1.0 - w) * r0 + w * r1;
}

// (N.H)^shininess where the light reaches, as powf has it (0^0 = 1).
float blinn_phong(vec3 n, vec3 l, vec3 to_eye, float e, float shininess)
{
    vec3 h = l + to_eye;
    float hinv = 1.0 / sqrt(dot(h, h) + TINY);
    float ndh = max(dot(n, h) * hinv, 0.0);
    if (!(e > 0.0))
        return 0.0;
    return shininess == 0.0 ? 1.0 : ndh > 0.0 ? pow(ndh, shininess) : 0.0;
}

// Sum over the lights of (albedo / pi + specular * (N.H)^s) * colour * E (README.md).
vec3 direct_light(vec3 n, vec3 pw, vec3 w, vec3 alb, Material m)
{
    vec3 spec = vec3(m.specular[0], m.specular[1], m.specular[2]);
    bool shiny = any(greaterThan(spec, vec3(0.0))); // else the term is 0 (the CPU skips it)
    vec3 to_eye = -w * (1.0 / sqrt(dot(w, w)));
    vec3 sum = vec3(0.0);
    for (int i = 0; i < light_count; i++) {
        int o = 16 * i;
        vec3 axis = vec3(light[o + 3], light[o + 4], light[o + 5]);
        vec3 l = -axis;
        float inv = 1.0, cone = 1.0;
        if (light[o + 10] == 0.0) { // point or spot light: 1 / d^2 and the cone
            l = vec3(light[o], light[o + 1], light[o + 2]) - pw;
            inv = 1.0 / sqrt(dot(l, l) + TINY);
            l *= inv;
            cone = ssg_cone_falloff(-dot(axis, l), light[o + 11], light[o + 12]);
        }
        float e = light[o + 9] * cone * max(dot(n, l), 0.0) * inv * inv;
        float s = shiny ? blinn_phong(n, l, to_eye, e, m.shininess) : 0.0;
        vec3 color = vec3(light[o + 6], light[o + 7], light[o + 8]);
        sum += (alb * INV_PI + spec * s) * color * e;
    }
    return sum;
}

vec3 surface_albedo(Mesh me, Material m, uvec3 tri, float u, float v)
{
    vec3 a = vec3(m.albedo[0], m.albedo[1], m.albedo[2]);
    float w0 = 1.0 - u - v;
    if (m.texels >= 0 && me.uvs >= 0) {
        vec2 uv = w0 * fetch2(me.uvs, tri.x) + u * fetch2(me.uvs, tri.y) +
                  v * fetch2(me.uvs, tri.z);
        a = sample_texture(m, uv) * a;
    }
    return vertex_colour(me, tri, u, v, a);
}

void store_background(ivec2 p)
{
    SSG_STORE3(dst_position, p, vec3(0.0));
    SSG_STORE3(dst_normal, p, vec3(0.0));
    SSG_STORE1(dst_depth, p, 0.0);
    SSG_STORE3(dst_albedo, p, vec3(0.0));
    SSG_STORE3(dst_direct, p, vec3(0.0));
    SSG_STORE3(dst_environment, p, vec3(0.0));
}

// The surface hit by the pixel's ray w (view direction ray, z = -1) on triangle `tri` of
// mesh `id`: depth t, unit world and view normals turned to the camera, albedo.
struct Surface { float t; vec3 n; vec3 nv; vec3 alb; };
Surface surface_at(int id, int tri, vec2 ray, vec3 w)
{
    Mesh me = scene_mesh[id];
    uvec3 v = triangle_vertices(me, tri);
    vec3 p0 = fetch3(me.positions, v.x), p1 = fetch3(me.positions, v.y);
    vec3 p2 = fetch3(me.positions, v.z);
    vec3 tuv = intersect(w, p0, p1, p2);
    float w0 = 1.0 - tuv.y - tuv.z;
    Material m = scene_material[me.material];
    vec3 n = p_normals == NORMALS_FACE ? cross(p1 - p0, p2 - p0)
                       : shading_normal(me, m, v, tuv.y, tuv.z,
                                        w0 * fetch3(me.normals, v.x) +
                                            tuv.y * fetch3(me.normals, v.y) +
                                            tuv.z * fetch3(me.normals, v.z));
    n *= 1.0 / sqrt(dot(n, n) + TINY);
    vec3 nv = vec3(rot[0] * n.x + rot[1] * n.y + rot[2] * n.z,
                   rot[3] * n.x + rot[4] * n.y + rot[5] * n.z,
                   rot[6] * n.x + rot[7] * n.y + rot[8] * n.z);
    // seen from behind (n . view direction > 0): shade the side facing the camera
    float flip = nv.x * ray.x + nv.y * ray.y - nv.z > 0.0 ? -1.0 : 1.0;
    return Surface(tuv.x, flip * n, flip * nv, surface_albedo(me, m, v, tuv.y, tuv.z));
}

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    int id = int(texelFetch(ids, ivec3(p, 0), 0).r) - 1;
    if (id < 0) {
        store_background(p);
        return;
    }
    // the ray with view z = -1 (gbuffer_cpu.c's make_rays): its parameter is the depth
    vec2 ray;
    vec3 w = pixel_ray(p, ray);
    Surface s = surface_at(id, int(texelFetch(ids, ivec3(p, 1), 0).r), ray, w);
    Material m = scene_material[scene_mesh[id].material];
    vec3 e_env = env_mode == 2 ? env_irradiance(s.n) : env_mode == 1 ? env_constant : vec3(0.0);
    SSG_STORE3(dst_position, p, vec3(s.t * ray.x, s.t * ray.y, 0.0 - s.t));
    SSG_STORE3(dst_normal, p, s.nv);
    SSG_STORE1(dst_depth, p, s.t);
    SSG_STORE3(dst_albedo, p, s.alb);
    SSG_STORE3(dst_direct, p, direct_light(s.n, eye + s.t * w, w, s.alb, m));
    SSG_STORE3(dst_environment, p, s.alb * INV_PI * e_env);
}
