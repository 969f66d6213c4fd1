// gbuffer_peel.glsl - the second layer's visibility pass on GL, a depth peel (Everitt,
// "Interactive Order-Independent Transparency", NVIDIA 2001): the scene drawn again with
// the depth test, every fragment at or before the first layer's depth d + d * gap
// (gbuffer.h's SSG_GBUFFER_BACK_GAP) discarded, so the nearest surface left is the next
// one along the pixel's ray. Writes mesh + 1 (0 = none) and triangle, as
// gbuffer_raster.glsl does; gbuffer_back.glsl casts the ray at that triangle. A masked
// mesh's holes are discarded, as there.
#include "scene.glsl"   // Mesh, vdata, scene_mesh
#include "surface.glsl" // Material, mesh_covers
#ifdef SSG_VERTEX
layout(location = 0) in vec3 ssg_position;
layout(location = 1) in vec2 ssg_uv;
uniform mat4 ssg_world_to_clip;
out float view_depth; // clip w = -z_view = the depth, interpolated perspective-correctly
out vec2 surface_uv;

void main()
{
    gl_Position = ssg_world_to_clip * vec4(ssg_position, 1.0);
    view_depth = gl_Position.w;
    surface_uv = ssg_uv;
}
#endif

#ifdef SSG_FRAGMENT
uniform int ssg_mesh;
uniform sampler2DArray first; // the first layer's depth (0 = background)
#pragma ssg_consts
// gap: gbuffer.h's SSG_GBUFFER_BACK_GAP
in float view_depth;
in vec2 surface_uv;
layout(location = 0) out float mesh_id;  // layer 0
layout(location = 1) out float triangle; // layer 1

void main()
{
    float d = texelFetch(first, ivec3(ivec2(gl_FragCoord.xy), 0), 0).r;
    precise float limit = d + d * gap;
    if (!(d > 0.0) || !(view_depth > limit) || !mesh_covers(ssg_mesh, surface_uv))
        discard;
    mesh_id = float(ssg_mesh + 1);
    triangle = float(gl_PrimitiveID); // exact: gl_scene.c keeps meshes below 2^24 triangles
}
#endif
