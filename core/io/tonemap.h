/* tonemap.h - the preview's tone curves and sRGB encoding, inline so that the PNG writer
 * (png_io.c) and the public functions (imageio_load.c: ssg_tonemap_apply,
 * ssg_tonemap_to_srgb8) compute the same bits from one definition. C and C++. */
#ifndef SSG_TONEMAP_H
#define SSG_TONEMAP_H

#include <math.h>

#include "io/imageio.h"

/* IEC 61966-2-1 encoding of a linear value in [0, 1]. */
static inline float ssg_srgb_encode(float v)
{
    return v <= 0.0031308f ? 12.92f * v : 1.055f * powf(v, 1.0f / 2.4f) - 0.055f;
}

/* Tone curve of an exposure-scaled value v. Inputs are capped at 1e4 so the rational
   curves never see inf/inf; every curve is already at 1 (to float precision) long before.
   The result is capped at 1 (a NaN would pass through, but none reaches it: v > 0). */
static inline float ssg_tonemap_scaled(enum ssg_tonemap tonemap, float v)
{
    if (!(v > 0.0f)) /* negative, zero, NaN */
        return 0.0f;
    v = 1e4f < v ? 1e4f : v;
    float d;
    switch (tonemap) {
    case SSG_TONEMAP_REINHARD:
        d = v / (1.0f + v);
        break;
    case SSG_TONEMAP_ACES: /* Narkowicz, "ACES Filmic Tone Mapping Curve", 2015 */
        d = (v * (2.51f * v + 0.03f)) / (v * (2.43f * v + 0.59f) + 0.14f);
        break;
    case SSG_TONEMAP_CLAMP:
    default:
        d = v;
        break;
    }
    return 1.0f < d ? 1.0f : d;
}

/* The 8-bit sRGB code of x times scale (2^exposure), rounded to nearest. */
static inline unsigned char ssg_srgb8_scaled(enum ssg_tonemap tonemap, float scale, float x)
{
    float s = ssg_srgb_encode(ssg_tonemap_scaled(tonemap, x * scale));
    int code = (int)(s * 255.0f + 0.5f);
    return (unsigned char)(code < 0 ? 0 : code > 255 ? 255 : code);
}

#endif
