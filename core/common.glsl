// common.glsl - what every ssgraph shader gets before its own file (core/gl.h).
// Images are sampler2DArray / image2DArray of R32F with one layer per channel (the CPU's
// planar layout); texel (x, y) is pixel (x, y), row 0 the top. Compute shaders run 8 x 8
// invocations per work group over a grid of ssg_grid pixels.
#ifdef SSG_COMPUTE
layout(local_size_x = 8, local_size_y = 8) in;
#endif

uniform ivec2 ssg_grid; // the dispatch's width and height (set by ssg_gl_dispatch)

const float SSG_PI = 3.14159265358979323846;

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
