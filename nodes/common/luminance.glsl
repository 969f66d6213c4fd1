// luminance.glsl - the luminance (Rec. 709 / sRGB weights) of an RGB value, the twin of
// nodes/common/luminance.h's ssg_luminance (`precise`: the CPU's two roundings, no fused
// multiply-add): direct_light.glsl and probe_light.glsl include it.
float luminance(vec3 e)
{
    precise float l = 0.2126 * e.r + 0.7152 * e.g + 0.0722 * e.b;
    return l;
}
