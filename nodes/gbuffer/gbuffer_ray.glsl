// gbuffer_ray.glsl - what the G-buffer's compute passes on GL share (#include'd by
// gbuffer.glsl and gbuffer_back.glsl): the scene's vertex, index and mesh buffers
// (core/gl/gl_scene.h), the camera's position and the intersection of a pixel's ray
// with the triangle the rasteriser found there, so that both layers' depths come from the
// same float operations.
struct Mesh { int positions; int normals; int uvs; int indices; int material; };
layout(std430, binding = 0) readonly buffer Vertices { float vdata[]; };
layout(std430, binding = 1) readonly buffer Indices { uint vindex[]; };
layout(std430, binding = 3) readonly buffer Meshes { Mesh scene_mesh[]; };
uniform vec3 eye;           // world

vec3 fetch3(int base, uint vertex)
{
    int o = base + 3 * int(vertex);
    return vec3(vdata[o], vdata[o + 1], vdata[o + 2]);
}

// (t, u, v) of the ray eye + t w in the plane of the triangle (Moller and Trumbore 1997).
// No inside test: the rasteriser put the pixel centre on this triangle, and where it
// misses by a rounding error the plane and the barycentrics extend continuously.
vec3 intersect(vec3 w, vec3 p0, vec3 p1, vec3 p2)
{
    vec3 e1 = p1 - p0, e2 = p2 - p0, s = eye - p0;
    vec3 pv = cross(w, e2), qv = cross(s, e1);
    float inv_det = 1.0 / dot(e1, pv);
    return vec3(dot(e2, qv), dot(s, pv), dot(w, qv)) * inv_det;
}
