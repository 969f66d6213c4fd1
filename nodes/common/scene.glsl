// scene.glsl - the scene's vertex, index and mesh buffers on GL (core/gl/gl_scene.h's
// bindings 0, 1 and 3), and a vertex's three floats from them, as gbuffer's ray casts and
// lightmaps read them (#include "scene.glsl" before surface.glsl, whose fetch2 reads vdata).
struct Mesh { int positions; int normals; int uvs; int indices; int material; int tangents; int colors; };
layout(std430, binding = 0) readonly buffer Vertices { float vdata[]; };
layout(std430, binding = 1) readonly buffer Indices { uint vindex[]; };
layout(std430, binding = 3) readonly buffer Meshes { Mesh scene_mesh[]; };

// Vertex `vertex`'s position or normal: the three floats at float offset base + 3 vertex.
vec3 fetch3(int base, uint vertex)
{
    int o = base + 3 * int(vertex);
    return vec3(vdata[o], vdata[o + 1], vdata[o + 2]);
}
