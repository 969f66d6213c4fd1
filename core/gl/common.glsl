// common.glsl - what every ssgraph shader gets before its own file (core/gl/gl.h).
// Images are sampler2DArray / image2DArray of R32F with one layer per channel (the CPU's
// planar layout); texel (x, y) is pixel (x, y), row 0 the top. Compute shaders run 8 x 8
// invocations per work group over a grid of ssg_grid pixels.
#ifdef SSG_COMPUTE
layout(local_size_x = 8, local_size_y = 8) in;
#endif

uniform ivec2 ssg_grid; // the dispatch's width and height (set by ssg_gl_dispatch)

const float SSG_PI = 3.14159265358979323846;

// ssg_cone_falloff (core/scene/scene.h): a spot light's share along a direction whose
// cosine to its axis is c; scale 0 and offset 1 (a point light) give 1.
float ssg_cone_falloff(float c, float scale, float offset)
{
    float t = clamp(c * scale + offset, 0.0, 1.0);
    return t * t;
}

#ifdef SSG_COMPUTE
ivec2 ssg_pixel() { return ivec2(gl_GlobalInvocationID.xy); }
#endif
bool ssg_outside(ivec2 p) { return p.x >= ssg_grid.x || p.y >= ssg_grid.y; }

float ssg_load1(sampler2DArray t, ivec2 p) { return texelFetch(t, ivec3(p, 0), 0).r; }
vec2 ssg_load2(sampler2DArray t, ivec2 p)
{
    return vec2(texelFetch(t, ivec3(p, 0), 0).r, texelFetch(t, ivec3(p, 1), 0).r);
}
vec3 ssg_load3(sampler2DArray t, ivec2 p)
{
    return vec3(texelFetch(t, ivec3(p, 0), 0).r, texelFetch(t, ivec3(p, 1), 0).r,
                texelFetch(t, ivec3(p, 2), 0).r);
}
// The same with p clamped into the image (clamp-to-edge reads).
ivec2 ssg_clamp_pixel(sampler2DArray t, ivec2 p)
{
    return clamp(p, ivec2(0), textureSize(t, 0).xy - 1);
}

// Stores; img is an image2DArray declared layout(r32f).
#define SSG_STORE1(img, p, v) imageStore(img, ivec3(p, 0), vec4(v))
#define SSG_STORE2(img, p, v)                                                          \
    do {                                                                               \
        vec2 ssg_v_ = (v);                                                             \
        imageStore(img, ivec3(p, 0), vec4(ssg_v_.x));                                  \
        imageStore(img, ivec3(p, 1), vec4(ssg_v_.y));                                  \
    } while (false)
#define SSG_STORE3(img, p, v)                                                          \
    do {                                                                               \
        vec3 ssg_v_ = (v);                                                             \
        imageStore(img, ivec3(p, 0), vec4(ssg_v_.x));                                  \
        imageStore(img, ivec3(p, 1), vec4(ssg_v_.y));                                  \
        imageStore(img, ivec3(p, 2), vec4(ssg_v_.z));                                  \
    } while (false)

// node.h's projection: proj = (f, cx, cy); a view-space point to pixel coordinates.
vec2 ssg_project(vec3 proj, vec3 v)
{
    float inv = 1.0 / -v.z;
    return vec2(proj.y + proj.x * v.x * inv, proj.z - proj.x * v.y * inv);
}

// bilateral_math.h's exp_neg: e^x for x <= 0, clamped at -80, Taylor series to g^6, so the
// filters' weights are the CPU's to the last bit or two. `precise` keeps the compiler from
// fusing the multiply-adds the CPU rounds twice.
float ssg_exp_neg(float x)
{
    x = x < -80.0 ? -80.0 : x;
    precise float t = x * 1.44269504088896341;
    float k = floor(t + 0.5);
    precise float g = (t - k) * 0.693147180559945309;
    precise float p = 1.0 + g * (1.0 + g * (0.5 + g * (1.0 / 6.0 + g * (1.0 / 24.0 +
                      g * (1.0 / 120.0 + g * (1.0 / 720.0))))));
    precise float r = p * intBitsToFloat((int(k) + 127) << 23);
    return r;
}

// bilateral_math.h's log_pos: ln(c) of a positive normal float, atanh series to s^9.
float ssg_log_pos(float c)
{
    int bits = floatBitsToInt(c);
    int e = (bits >> 23) - 127;
    float m = intBitsToFloat((bits & 0x007FFFFF) | 0x3F800000);
    bool big = m > 1.41421356;
    m = big ? 0.5 * m : m;
    e = big ? e + 1 : e;
    precise float s = (m - 1.0) / (m + 1.0), s2 = s * s;
    precise float lm = 2.0 * s * (1.0 + s2 * (1.0 / 3.0 + s2 * (1.0 / 5.0 + s2 * (1.0 / 7.0 +
                       s2 * (1.0 / 9.0)))));
    precise float r = float(e) * 0.693147180559945309 + lm;
    return r;
}

// bilateral_math.h's ssg_normal_factor: the joint filters' normal term of a tap with
// clamped cosine c, the factor c^p by `squarings` squarings (p = 2^squarings), or, for
// other powers (squarings < 0), 1 with p ln(c) added to the log-weight e.
float ssg_normal_factor(float c, float p, int squarings, inout float e)
{
    precise float wn = 1.0;
    if (squarings < 0) {
        precise float sum = e + p * ssg_log_pos(c);
        e = sum;
    } else {
        wn = c;
        for (int s = 0; s < squarings; s++)
            wn *= wn;
    }
    return wn;
}

// The unit normal of normal image t at p, 0 where it is 0 (the CPU filters' setup).
vec3 ssg_unit_normal(sampler2DArray t, ivec2 p)
{
    precise vec3 n = ssg_load3(t, p);
    precise float nn = n.x * n.x + n.y * n.y + n.z * n.z;
    precise float inv = nn > 0.0 ? 1.0 / sqrt(nn) : 0.0;
    precise vec3 u = n * inv;
    return u;
}

// A per-pixel sample count from a `count` input (ao_common.c): round(count) half up,
// clamped to [1, k]; k when the input is unbound or the value is NaN.
int ssg_pixel_count(sampler2DArray count, bool bound, ivec2 p, int k)
{
    if (!bound)
        return k;
    float v = ssg_load1(count, p);
    if (isnan(v))
        return k;
    v = v < 1.0 ? 1.0 : v;
    v = v <= float(k) ? v : float(k);
    return min(int(v + 0.5), k);
}

// nodes/common/shadowmap.c's ssg_shadow_frame_make basis (Duff et al. 2017): u, v from the unit
// light direction l alone; the sign test reads the bit, as copysignf does for -0.
void ssg_shadow_basis(vec3 l, out vec3 u, out vec3 v)
{
    float s = floatBitsToInt(l.z) < 0 ? -1.0 : 1.0;
    float a = -1.0 / (s + l.z);
    float b = l.x * l.y * a;
    u = vec3(1.0 + s * l.x * l.x * a, s * b, -s * l.x);
    v = vec3(b, s + l.y * l.y * a, -l.y);
}

// The second image a filter carries along with the same weights (bilateral's and
// upsample's in2): its value type, load and store, from the node's IN2_CH define (1 or 3;
// 0 = none, the macros then unused).
#if defined(IN2_CH)
#if IN2_CH == 3
#define VALUE2 vec3
#define LOAD2 ssg_load3
#define STORE2 SSG_STORE3
#else
#define VALUE2 float
#define LOAD2 ssg_load1
#define STORE2 SSG_STORE1
#endif
#endif
