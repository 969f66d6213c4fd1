// @name@.glsl - the `@name@` node on GL (method in README.md): @name@_cpu.c's maths, one
// invocation per pixel, each channel a layer. `precise` keeps the compiler from fusing a
// multiply and an add that the CPU rounds one after the other, so both give the same bits.
uniform sampler2DArray src;                          // input port `src`
layout(r32f) uniform writeonly image2DArray dst_out; // output port `out`

#pragma ssg_params

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    int channels = textureSize(src, 0).z;
    for (int c = 0; c < channels; c++) {
        precise float v = p_gain * texelFetch(src, ivec3(p, c), 0).r;
        imageStore(dst_out, ivec3(p, c), vec4(v));
    }
}
