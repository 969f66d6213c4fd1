// gbuffer_emission.glsl - the G-buffer's emission on GL (gbuffer.h, `emission`, on demand):
// the pixel's ray (gbuffer_cpu.c's make_rays) cast at the triangle the visibility pass
// found, with gbuffer.glsl's intersection, and the material's emission x emission texture
// at its uv, as surface.c's ssg_hit_emission; 0 on background.
#include "scene.glsl"       // Mesh, vdata, vindex, scene_mesh, fetch3
#include "surface.glsl"     // Material, scene_material, fetch2, sample_rgb
#pragma ssg_consts
// proj (f, cx, cy), inv_f (1 / f rounded on the CPU), rot (world -> view, row-major), eye
#include "gbuffer_ray.glsl" // intersect

uniform sampler2DArray ids; // the visibility pass: layer 0 mesh + 1 (0 = none), 1 triangle
layout(r32f) uniform writeonly image2DArray dst_emission;

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    int id = int(texelFetch(ids, ivec3(p, 0), 0).r) - 1;
    if (id < 0) {
        SSG_STORE3(dst_emission, p, vec3(0.0));
        return;
    }
    Mesh me = scene_mesh[id];
    Material m = scene_material[me.material];
    vec3 e = vec3(m.emission[0], m.emission[1], m.emission[2]);
    if (m.emission_texels >= 0 && me.uvs >= 0 && any(greaterThan(e, vec3(0.0)))) {
        vec2 ray;
        vec3 w = pixel_ray(p, ray);
        uvec3 v = triangle_vertices(me, int(texelFetch(ids, ivec3(p, 1), 0).r));
        vec3 tuv = intersect(w, fetch3(me.positions, v.x), fetch3(me.positions, v.y),
                             fetch3(me.positions, v.z));
        float w0 = 1.0 - tuv.y - tuv.z;
        vec2 uv = w0 * fetch2(me.uvs, v.x) + tuv.y * fetch2(me.uvs, v.y) +
                  tuv.z * fetch2(me.uvs, v.z);
        e *= sample_rgb(m.emission_texels, m.emission_width, m.emission_height, uv);
    }
    SSG_STORE3(dst_emission, p, e);
}
