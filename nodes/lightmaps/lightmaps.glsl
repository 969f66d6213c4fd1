// lightmaps.glsl - `lightmaps` on GL (lightmaps_gl.c): the scene drawn once per face with
// that face's projection (orthographic, or a 90 degree perspective along the cube axis,
// GL clipping at the CPU's near plane); the nearest fragment of each texel intersects the
// texel centre's ray with its own triangle (read from the scene's buffers, core/gl/gl_scene.h)
// and writes lightmaps_cpu.c's depth, normal (turned to the light) and flux.
#include "scene.glsl"   // Mesh, vdata, vindex, scene_mesh, fetch3
#include "surface.glsl" // Material, texel, scene_material, fetch2, wrap, sample_texture
// Per face (prepare()'s face_floats): origin, u, v, axis, half, ortho, flux rgb, has a light,
// the depth range's half (orthographic: the scene's radius, whatever the map's side), the
// light's cone scale and offset (ssg_cone_falloff) and its axis.
layout(std430, binding = 5) readonly buffer Faces { float face[]; };
const int FACE = 24;
#pragma ssg_params
uniform int ssg_layer, ssg_mesh;
#pragma ssg_consts

vec3 face3(int k) { int o = FACE * ssg_layer + k; return vec3(face[o], face[o + 1], face[o + 2]); }

#ifdef SSG_VERTEX
layout(location = 0) in vec3 ssg_position;
layout(location = 1) in vec2 ssg_uv;
out vec2 surface_uv;

void main()
{
    surface_uv = ssg_uv;
    vec3 d = ssg_position - face3(0);
    float du = dot(d, face3(3)), dv = dot(d, face3(6)), z = dot(d, face3(9));
    float half_side = face[FACE * ssg_layer + 12];
    if (face[FACE * ssg_layer + 17] == 0.0)
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // the empty face of a scene without lights
    else if (face[FACE * ssg_layer + 13] != 0.0) // depth 0 .. 2 radius: the whole scene
        gl_Position = vec4(du / half_side, dv / half_side, z / face[FACE * ssg_layer + 18] - 1.0,
                           1.0);
    else // a perspective face half_side wide (a cube face: 1)
        gl_Position = vec4(du / half_side, dv / half_side,
                           (z * (far_z + near_z) - 2.0 * far_z * near_z) / (far_z - near_z), z);
}
#endif

#ifdef SSG_FRAGMENT
layout(location = 0) out float out_depth;
layout(location = 1) out float out_nx;
layout(location = 2) out float out_ny;
layout(location = 3) out float out_nz;
layout(location = 4) out float out_r;
layout(location = 5) out float out_g;
layout(location = 6) out float out_b;
in vec2 surface_uv;

void main()
{
    if (!mesh_covers(ssg_mesh, surface_uv)) // a masked mesh's hole: no sender, no shadow
        discard;
    int x = int(gl_FragCoord.x), y = int(gl_FragCoord.y), f = FACE * ssg_layer;
    float a = 2.0 * (float(x) + 0.5) / float(p_resolution) - 1.0;
    float b = 2.0 * (float(y) + 0.5) / float(p_resolution) - 1.0;
    bool ortho = face[f + 13] != 0.0;
    vec3 u = face3(3), v = face3(6), axis = face3(9), o = face3(0), d = axis;
    if (ortho)
        o += face[f + 12] * (a * u + b * v);
    else
        d += (face[f + 12] * a) * u + (face[f + 12] * b) * v;
    Mesh m = scene_mesh[ssg_mesh];
    uint i0 = vindex[m.indices + 3 * gl_PrimitiveID], i1 = vindex[m.indices + 3 * gl_PrimitiveID + 1];
    uint i2 = vindex[m.indices + 3 * gl_PrimitiveID + 2];
    vec3 p0 = fetch3(m.positions, i0), e1 = fetch3(m.positions, i1) - p0;
    vec3 e2 = fetch3(m.positions, i2) - p0, s = o - p0;
    vec3 pv = cross(d, e2), qv = cross(s, e1);
    float det = dot(e1, pv), inv = det != 0.0 ? 1.0 / det : 0.0;
    float t = dot(e2, qv) * inv;
    float bu = clamp(dot(s, pv) * inv, 0.0, 1.0);
    float bv = clamp(dot(d, qv) * inv, 0.0, 1.0 - bu);
    float w0 = 1.0 - bu - bv;
    Material mat = scene_material[m.material];
    vec3 n = shading_normal(m, mat, uvec3(i0, i1, i2), bu, bv,
                            w0 * fetch3(m.normals, i0) + bu * fetch3(m.normals, i1) +
                                bv * fetch3(m.normals, i2));
    if (!(length(n) > 0.0))
        n = cross(e1, e2);
    n = normalize(n) * (dot(n, d) > 0.0 ? -1.0 : 1.0);
    vec3 albedo = vec3(mat.albedo[0], mat.albedo[1], mat.albedo[2]);
    if (m.uvs >= 0 && mat.texels >= 0) {
        vec2 uv = w0 * fetch2(m.uvs, i0) + bu * fetch2(m.uvs, i1) + bv * fetch2(m.uvs, i2);
        albedo *= sample_texture(mat, uv);
    }
    albedo = vertex_colour(m, uvec3(i0, i1, i2), bu, bv, albedo);
    // ssg_lightmap_texel_solid_angle x the spot's falloff (lightmaps_cpu.c's texel_weight)
    float h = face[f + 12], q = 1.0 + h * h * (a * a + b * b), side = 2.0 * h / float(p_resolution);
    float cone = ssg_cone_falloff(dot(face3(21), normalize(d)), face[f + 19], face[f + 20]);
    float omega = ortho ? 1.0 : side * side / (q * sqrt(q)) * cone;
    vec3 flux = albedo * face3(14) * omega;
    out_depth = t;
    out_nx = n.x, out_ny = n.y, out_nz = n.z;
    out_r = flux.r, out_g = flux.g, out_b = flux.b;
}
#endif
