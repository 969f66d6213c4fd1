// gaussian.glsl - one axis of the separable Gaussian (method in README.md), per layer.
// Clamp-to-edge like the CPU kernel, taps summed in the same order (-radius..radius).
layout(std430, binding = 0) readonly buffer Weights { float weight[]; };

uniform sampler2DArray src;
layout(r32f) uniform writeonly image2DArray dst;
uniform ivec2 axis;   // (1, 0) horizontal, (0, 1) vertical
#pragma ssg_consts
uniform int layer;    // the channel being filtered

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    ivec2 last = textureSize(src, 0).xy - 1;
    float acc = 0.0;
    for (int t = -radius; t <= radius; t++) {
        ivec2 q = clamp(p + t * axis, ivec2(0), last);
        acc += weight[t + radius] * texelFetch(src, ivec3(q, layer), 0).r;
    }
    imageStore(dst, ivec3(p, layer), vec4(acc));
}
