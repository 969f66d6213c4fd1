/* luminance.h - the luminance (Rec. 709 / sRGB weights) by which the direct-light nodes
 * weigh each light's visibility into their `visibility` output (direct_light, probe_light).
 * Its GL twin is luminance.glsl, the same products and sums in the same order. Pure. */
#ifndef SSG_LUMINANCE_H
#define SSG_LUMINANCE_H

static inline float ssg_luminance(float r, float g, float b)
{
    return 0.2126f * r + 0.7152f * g + 0.0722f * b;
}

#endif
