// probe_light_frames.glsl - `probe_light` on GL, first pass (probe_light_gl.c): for every
// light of the list (one invocation each) the 16 floats of ssg_probe_light_frame
// (probe_light.h), computed in the C code's order (`precise`: no fused multiply-adds the
// CPU does not make), into layer k of the frames image.
uniform sampler2DArray lights;
layout(r32f) uniform writeonly image2DArray frames;
uniform float rot[9];  // view -> world: world = eye + rot^T view
uniform vec3 eye, centre;
uniform float radius;
uniform int frame_res;

vec3 rotate(vec3 w)
{
    precise vec3 r;
    for (int i = 0; i < 3; i++)
        r[i] = rot[3 * i] * w.x + rot[3 * i + 1] * w.y + rot[3 * i + 2] * w.z;
    return r;
}

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    vec3 l = vec3(texelFetch(lights, ivec3(p.x, 0, 0), 0).r,
                  texelFetch(lights, ivec3(p.x, 0, 1), 0).r,
                  texelFetch(lights, ivec3(p.x, 0, 2), 0).r);
    vec3 u, v;
    ssg_shadow_basis(l, u, v);
    precise vec3 origin = centre + radius * l;
    precise float s = 0.5 * float(frame_res) / radius;
    precise vec3 e = eye - origin;
    vec3 ru = rotate(u), rv = rotate(v), rl = rotate(l);
    precise float f[16];
    for (int k = 0; k < 3; k++) {
        f[k] = s * ru[k];
        f[4 + k] = s * rv[k];
        f[8 + k] = -rl[k];
        f[12 + k] = rl[k];
    }
    f[3] = s * (e.x * u.x + e.y * u.y + e.z * u.z) + 0.5 * float(frame_res);
    f[7] = s * (e.x * v.x + e.y * v.y + e.z * v.z) + 0.5 * float(frame_res);
    f[11] = -(e.x * l.x + e.y * l.y + e.z * l.z);
    f[15] = 0.0;
    for (int k = 0; k < 16; k++)
        imageStore(frames, ivec3(p.x, 0, k), vec4(f[k]));
}
