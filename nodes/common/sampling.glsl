// sampling.glsl - the screen-space sampling the `ssao`, `hbao`, `ssdo` and `bounce` shaders
// share (#include "sampling.glsl" after their uniforms; core/gl/gl_program.c resolves it),
// the GL twin of nodes/common/sampling.h and of the loops of ssao_cpu.c and
// ssdo_sampling.h: the same operations in the same order (`precise`), so that both backends
// start from the same bits. It declares the inputs every sampling node has (bound by
// name by the C side); a node without a kernel defines SSG_SAMPLING_NO_KERNEL first.

uniform sampler2DArray position; // view-space position (z alone where depth is unbound)
uniform sampler2DArray depth;    // linear depth, when depth_bound
uniform sampler2DArray rotation; // n x n, 2 layers (cos, sin) or 4 (and the length shift)
uniform bool depth_bound;
uniform bool rotation_bound;
#ifndef SSG_SAMPLING_NO_KERNEL
uniform sampler2DArray kernel;   // K x 1, 3 layers: the samples
#endif

// The scene depth at pixel q: the depth input, or -position.z.
float ssg_scene_depth(ivec2 q)
{
    return depth_bound ? ssg_load1(depth, q) : -texelFetch(position, ivec3(q, 2), 0).r;
}

// The depth of an occluder at pixel q (inside the image), or -1 where the CPU kernels of
// the horizon nodes (horizon.h's padded plane) find none: background, negative, NaN or
// infinite depth.
float ssg_occluder_depth(ivec2 q)
{
    float d = ssg_scene_depth(q);
    return d > 0.0 && d <= 3.0e38 ? d : -1.0;
}

// The rotation (cos, sin) of the tile at pixel p; none bound: no rotation.
vec2 ssg_tile_rotation(ivec2 p)
{
    if (!rotation_bound)
        return vec2(1.0, 0.0);
    int tile = textureSize(rotation, 0).x;
    return ssg_load2(rotation, p % tile);
}

// The length shift (dl, k) of pixel p: the tile's layers 3 and 4 (halton
// lengths=shifted; sampling.h ssg_sampling_offsets); (0, 0) without them: no change.
vec2 ssg_tile_shift(ivec2 p)
{
    if (!rotation_bound || textureSize(rotation, 0).z < 4)
        return vec2(0.0);
    ivec2 q = p % textureSize(rotation, 0).x;
    return vec2(texelFetch(rotation, ivec3(q, 2), 0).r, texelFetch(rotation, ivec3(q, 3), 0).r);
}

// A pixel of depth dp and normal N is a surface when dp is a plausible depth and N is not
// zero: false for the background (depth 0, no normal) or garbage. A surface's normal that
// is not unit is normalised (the CPU does so for its whole chunk).
bool ssg_surface_normal(float dp, inout vec3 N)
{
    precise float nn = N.x * N.x + N.y * N.y + N.z * N.z;
    if (!(dp > 0.0 && dp <= 3.0e38 && nn > 1e-12))
        return false;
    precise float ninv = 1.0 / sqrt(nn);
    if (abs(nn - 1.0) > 1e-5)
        N = vec3(N.x * ninv, N.y * ninv, N.z * ninv);
    return true;
}

#ifndef SSG_SAMPLING_NO_KERNEL
// Kernel sample s (tangent space, the hemisphere about +z).
vec3 ssg_kernel_sample(int s)
{
    return vec3(texelFetch(kernel, ivec3(s, 0, 0), 0).r,
                texelFetch(kernel, ivec3(s, 0, 1), 0).r,
                texelFetch(kernel, ivec3(s, 0, 2), 0).r);
}

// |s| (sampling.h ssg_sampling_len: the same operations).
float ssg_sample_len(vec3 s)
{
    precise float l = sqrt(s.x * s.x + s.y * s.y + s.z * s.z);
    return l;
}

// Kernel sample number i, s, of a pixel with length shift (dl, k) = shift: s g, its
// direction with the length of sample (i + k) mod K plus dl (sampling.h
// ssg_sampling_shift_factor, the same operations); no shift returns s's bits.
vec3 ssg_shifted_sample(int i, vec3 s, vec2 shift)
{
    if (shift.x == 0.0 && shift.y == 0.0)
        return s;
    int count = textureSize(kernel, 0).x;
    int j = i + int(shift.y);
    j = j >= count ? j - count : j;
    precise float ls = ssg_sample_len(s);
    precise float il = ls > 0.0 ? 1.0 / ls : 0.0;
    precise float g = 1.0 + (ssg_sample_len(ssg_kernel_sample(j)) - ls + shift.x) * il;
    precise vec3 r = vec3(s.x * g, s.y * g, s.z * g);
    return r;
}
#endif

// Duff et al.'s branch-free orthonormal basis about unit N ("Building an Orthonormal
// Basis, Revisited", JCGT 2017; -0 counts as negative, as copysignf does): T = t, B = b,
// T x B = N, before the tile's turn.
void ssg_tangent_basis(vec3 N, out vec3 t, out vec3 b)
{
    float sgn = (floatBitsToUint(N.z) >> 31) != 0u ? -1.0 : 1.0;
    precise float a = -1.0 / (sgn + N.z);
    precise float c = N.x * N.y * a;
    precise float t0 = 1.0 + sgn * N.x * N.x * a, t1 = sgn * c, t2 = -sgn * N.x;
    precise float b1 = sgn + N.y * N.y * a;
    t = vec3(t0, t1, t2);
    b = vec3(c, b1, -N.y);
}

// Projects kernel sample s through a pixel's projective coefficients (Z - bias = dot(cz,
// (1, s)), u Z = dot(cu, (1, s)), v Z = dot(cv, (1, s))): false behind the camera or off
// screen; else the pixel q it lands on and zb = Z - bias, the depth an occluder must be
// nearer than.
bool ssg_project_sample(vec4 cz, vec4 cu, vec4 cv, vec3 s, float bias, out ivec2 q,
                        out float zb)
{
    precise float zs = cz.x + cz.y * s.x + cz.z * s.y + cz.w * s.z;
    precise float z = zs + bias;
    precise float nu = cu.x + cu.y * s.x + cu.z * s.y + cu.w * s.z;
    precise float nv = cv.x + cv.y * s.x + cv.z * s.y + cv.w * s.z;
    precise float inv = 1.0 / z;
    precise float u = nu * inv, v = nv * inv;
    zb = zs;
    q = ivec2(0);
    vec2 size = vec2(ssg_grid);
    if (!(z > 0.0 && u >= 0.0 && u < size.x && v >= 0.0 && v < size.y))
        return false;
    q = ivec2(int(u), int(v));
    return true;
}

// sampling.h's ssg_acos: Abramowitz and Stegun 4.4.46, the same operations (gtao, ssilvb).
float ssg_acos(float x)
{
    precise float ax = abs(x);
    precise float p = -0.0012624911;
    p = p * ax + 0.0066700901;
    p = p * ax - 0.0170881256;
    p = p * ax + 0.0308918810;
    p = p * ax - 0.0501743046;
    p = p * ax + 0.0889789874;
    p = p * ax - 0.2145988016;
    p = p * ax + 1.5707963050;
    precise float r = sqrt(1.0 - ax) * p;
    precise float m = 3.14159265358979323846 - r;
    return x < 0.0 ? m : r;
}
