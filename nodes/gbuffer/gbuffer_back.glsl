// gbuffer_back.glsl - the second layer's depth on GL (README.md, `back`): the pixel's ray
// (gbuffer_cpu.c's make_rays) cast at the triangle gbuffer_peel.glsl found behind the
// first surface, with gbuffer.glsl's intersection; +inf where the peel found none, 0 on
// background, as the CPU's second Embree ray gives.
#include "scene.glsl"       // Mesh, vdata, vindex, scene_mesh, fetch3
#pragma ssg_consts
// proj (f, cx, cy), inv_f (1 / f rounded on the CPU), rot (world -> view, row-major), eye
#include "gbuffer_ray.glsl" // intersect

uniform sampler2DArray ids;   // the peel's layer 0: mesh + 1 (0 = none), layer 1: triangle
uniform sampler2DArray first; // the first layer's depth (0 = background)
layout(r32f) uniform writeonly image2DArray dst_back;

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    int id = int(texelFetch(ids, ivec3(p, 0), 0).r) - 1;
    if (!(texelFetch(first, ivec3(p, 0), 0).r > 0.0)) { // background
        SSG_STORE1(dst_back, p, 0.0);
        return;
    }
    if (id < 0) { // nothing behind the first surface up to far
        SSG_STORE1(dst_back, p, 1.0 / 0.0);
        return;
    }
    vec2 ray;
    vec3 w = pixel_ray(p, ray);
    Mesh me = scene_mesh[id];
    uvec3 v = triangle_vertices(me, int(texelFetch(ids, ivec3(p, 1), 0).r));
    vec3 p0 = fetch3(me.positions, v.x), p1 = fetch3(me.positions, v.y);
    vec3 p2 = fetch3(me.positions, v.z);
    SSG_STORE1(dst_back, p, intersect(w, p0, p1, p2).x);
}
