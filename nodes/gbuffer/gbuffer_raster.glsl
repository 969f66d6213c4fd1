// gbuffer_raster.glsl - the G-buffer's visibility pass on GL (core/gl/gl_scene.h): each
// pixel centre gets the mesh (+1, 0 = background) and the triangle of the nearest surface
// there; gbuffer.glsl does the rest from the scene's own data.
#ifdef SSG_VERTEX
layout(location = 0) in vec3 ssg_position;
uniform mat4 ssg_world_to_clip;

void main()
{
    gl_Position = ssg_world_to_clip * vec4(ssg_position, 1.0);
}
#endif

#ifdef SSG_FRAGMENT
uniform int ssg_mesh;
layout(location = 0) out float mesh_id;  // layer 0
layout(location = 1) out float triangle; // layer 1

void main()
{
    mesh_id = float(ssg_mesh + 1);
    triangle = float(gl_PrimitiveID); // exact: gl_scene.c keeps meshes below 2^24 triangles
}
#endif
