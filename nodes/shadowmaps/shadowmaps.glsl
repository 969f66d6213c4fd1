// shadowmaps.glsl - the `shadowmaps` node on GL (shadowmaps_gl.c): the scene drawn once
// per light into layer ssg_layer with nodes/common/shadowmap.h's orthographic frame, built here
// from the light's direction as ssg_shadow_frame_make builds it; each texel keeps the
// nearest surface's distance from the map's plane along -l (linear in an orthographic
// view, so the interpolated value is the surface's own). A masked mesh's holes are
// discarded (surface.glsl's mesh_covers): they cast no shadow.
#include "scene.glsl"   // Mesh, vdata, scene_mesh
#include "surface.glsl" // Material, mesh_covers
uniform int ssg_mesh;
#ifdef SSG_VERTEX
layout(location = 0) in vec3 ssg_position;
layout(location = 1) in vec2 ssg_uv;
out vec2 surface_uv;
uniform sampler2DArray lights; // the light list: row 0 the directions towards the lights
uniform int ssg_layer;         // the light, and the layer drawn
uniform vec3 centre;           // the scene's bounding sphere
uniform float radius;
out float depth;

void main()
{
    vec3 l = vec3(texelFetch(lights, ivec3(ssg_layer, 0, 0), 0).r,
                  texelFetch(lights, ivec3(ssg_layer, 0, 1), 0).r,
                  texelFetch(lights, ivec3(ssg_layer, 0, 2), 0).r);
    vec3 u, v;
    ssg_shadow_basis(l, u, v);
    vec3 d = ssg_position - (centre + radius * l);
    depth = -dot(d, l);
    surface_uv = ssg_uv;
    // x, y: texel x = (dot(d, u) / radius + 1) R / 2, so NDC is dot(d, u) / radius; depth
    // in [0, 2 radius] inside the sphere maps to [-1, 1].
    gl_Position = vec4(dot(d, u) / radius, dot(d, v) / radius, depth / radius - 1.0, 1.0);
    // A light that carries nothing casts no shadow worth drawing: every vertex outside the
    // clip volume leaves its layer empty, as the CPU leaves its map (README.md).
    vec3 e = vec3(texelFetch(lights, ivec3(ssg_layer, 1, 0), 0).r,
                  texelFetch(lights, ivec3(ssg_layer, 1, 1), 0).r,
                  texelFetch(lights, ivec3(ssg_layer, 1, 2), 0).r);
    if (e == vec3(0.0))
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
}
#endif

#ifdef SSG_FRAGMENT
in float depth;
in vec2 surface_uv;
layout(location = 0) out float map_depth;

void main()
{
    if (!mesh_covers(ssg_mesh, surface_uv))
        discard;
    map_depth = depth;
}
#endif
