// copy_planes.glsl - ssg_gl_fill (core/gl/gl_pass.c): copies an image a node's prepare() made
// on the CPU (planar floats, as in ssgraph.h) from a storage buffer into `dst`. A float
// moved through a buffer and an R32F store keeps its bits, so tables made once (halton's
// kernel, lightprobe's lights) are bit-identical on both backends.
layout(std430, binding = 0) readonly buffer Planes { float planes[]; };

layout(r32f) uniform writeonly image2DArray dst;
uniform int channels;

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    int plane = ssg_grid.x * ssg_grid.y;
    for (int c = 0; c < channels; c++)
        imageStore(dst, ivec3(p, c), vec4(planes[c * plane + p.y * ssg_grid.x + p.x]));
}
