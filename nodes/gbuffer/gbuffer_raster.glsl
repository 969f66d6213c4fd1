// gbuffer_raster.glsl - the G-buffer's visibility pass on GL (core/gl/gl_scene.h): each
// pixel centre gets the mesh (+1, 0 = background) and the triangle of the nearest surface
// there; gbuffer.glsl does the rest from the scene's own data. An alpha-masked mesh's
// fragments where it has no surface are discarded (surface.glsl's mesh_covers), so the
// surface behind shows.
#include "scene.glsl"   // Mesh, vdata, scene_mesh
#include "surface.glsl" // Material, mesh_covers
#ifdef SSG_VERTEX
layout(location = 0) in vec3 ssg_position;
layout(location = 1) in vec2 ssg_uv;
uniform mat4 ssg_world_to_clip;
out vec2 surface_uv;

void main()
{
    gl_Position = ssg_world_to_clip * vec4(ssg_position, 1.0);
    surface_uv = ssg_uv;
}
#endif

#ifdef SSG_FRAGMENT
uniform int ssg_mesh;
layout(location = 0) out float mesh_id;  // layer 0
layout(location = 1) out float triangle; // layer 1
in vec2 surface_uv;

void main()
{
    if (!mesh_covers(ssg_mesh, surface_uv))
        discard;
    mesh_id = float(ssg_mesh + 1);
    triangle = float(gl_PrimitiveID); // exact: gl_scene.c keeps meshes below 2^24 triangles
}
#endif
