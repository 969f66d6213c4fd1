/* direct_light_cpu.h - what the CPU kernel's files share (direct_light_cpu.c runs the
 * rows, direct_light_lookup.c reads the maps one pixel at a time, direct_light_lanes.c
 * runs the PCF taps and direct_light_contact.c the contact march over a chunk's lit
 * pixels at once). Private to the kernel; read-only data, so any thread may call it.
 *
 * Why lanes: the per-pixel code branches on every tap (the receiver plane, the cube's
 * faces, the test itself) and spends its time waiting on chains of divisions and square
 * roots. Run as straight loops over a chunk's pixels (one lane a pixel, every array here
 * SoA), the same IEEE operations vectorise; what a loop cannot do in lanes (a texel past a
 * cube face's edge, a step that reaches a plane) it leaves to the per-pixel code of
 * direct_light_lookup.c and direct_light_contact.c, which makes the same operations, so
 * the result is the same bits either way. */
#ifndef SSG_DIRECT_LIGHT_CPU_H
#define SSG_DIRECT_LIGHT_CPU_H

#include <math.h>
#include <stddef.h>

#include "direct_light.h"

enum { DL_CHUNK = 64 }; /* pixels of a row taken at once */

struct dl_job {
    const struct ssg_direct_light_consts *c;
    const struct ssg_io *io;
    const float *maps; /* the depth planes, face f at f R^2 */
    int w, h;
    int map_index; /* 1: every map element has an int index (the lanes' gathers) */
};

/* Where the receiver is on a light's maps: its face, texel coordinates and distance, and
   its plane, so that each tap compares against the receiver's own distance along the
   tap's ray ("receiver plane depth bias", Isidoro, GDC 2006): a flat receiver never
   shadows itself, whatever the disc's radius. */
struct dl_lookup {
    const struct ssg_direct_light_light *l;
    int f;        /* face of the light (0 for a directional one) */
    float x, y;   /* texel coordinates on it */
    float r;      /* distance: along the ray (point) or depth (directional) */
    float z;      /* depth along the face's axis (the maps' measure) */
    float texel;  /* a texel at the receiver, scene units */
    float bias;   /* the constant offset, scene units */
    float gx, gy; /* directional: the receiver plane's depth change a texel along x, y */
    float n[3];   /* point: the receiver's normal and n . (q - light) */
    float nq;
};

/* A chunk's pixels: their G-buffer and, for the light at hand, what it gives them. */
struct dl_pixels {
    int len;                                 /* pixels in use */
    float p[3][DL_CHUNK], n[3][DL_CHUNK];    /* world point and normal (0: background) */
    float e[DL_CHUNK], l[3][DL_CHUNK];       /* the light's irradiance, unit direction */
    float texel[DL_CHUNK];                   /* its maps' texel at the receiver (e > 0) */
    float v[DL_CHUNK];                       /* its visibility */
};

/* One light's lookups over a chunk's lit pixels (e > 0), lane a the a-th of them. */
struct dl_lanes {
    int count;                           /* lanes in use */
    int pixel[DL_CHUNK];                 /* the chunk's pixel of each lane */
    int f[DL_CHUNK];                     /* dl_lookup's, per lane */
    float x[DL_CHUNK], y[DL_CHUNK], r[DL_CHUNK], z[DL_CHUNK], texel[DL_CHUNK];
    float bias[DL_CHUNK], gx[DL_CHUNK], gy[DL_CHUNK], n[3][DL_CHUNK], nq[DL_CHUNK];
    int base[DL_CHUNK];                  /* the first map element of the lane's face */
    float axis[3][DL_CHUNK], u[3][DL_CHUNK], v[3][DL_CHUNK]; /* point: the lane's face */
    float half[DL_CHUNK];
    float cs[DL_CHUNK], sn[DL_CHUNK];    /* the turn of its tap disc */
    float radius[DL_CHUNK];              /* its PCF radius, texels (< 0: fully lit) */
    float sum[DL_CHUNK];                 /* the taps' sum so far */
};

/* The PCF radius in texels for a disc turned by (cs, sn); < 0: no blocker, fully lit. */
float dl_filter_radius(const struct dl_job *j, const struct dl_lookup *k, float cs, float sn);
/* The bilinear blend of the four tests around texel coordinates (x, y). */
float dl_bilinear_test(const struct dl_job *j, const struct dl_lookup *k, float x, float y);

/* Light li's lanes over chunk px of row y from column x0 (direct_light_locate.c): the
   pixels it reaches, located on its maps (px->texel too), discs turned, radii found. */
void dl_lanes_fill(const struct dl_job *j, int li, int y, int x0, struct dl_pixels *px,
                   struct dl_lanes *L);
/* Lane a's lookup, as the per-pixel code takes it (direct_light_lanes.c). */
void dl_lane_lookup(const struct dl_lanes *L, const struct ssg_direct_light_light *l, int a,
                    struct dl_lookup *k);
/* Their PCF visibilities into px->v (the lanes' pixels only). Reorders the lanes. */
void dl_lanes_visibility(const struct dl_job *j, int li, struct dl_lanes *L,
                         struct dl_pixels *px);

/* px->v of the pixels lit so far (v > 0) times the light their contact marches let
   through towards the light (direct_light_contact.c); row y from column x0. */
void dl_contact(const struct dl_job *j, int y, int x0, struct dl_pixels *px);

/* Tap limit of a point light's face (axis, u, v, half; res texels a side) at texel
   coordinates (x, y), for a receiver at (kx, ky), distance r, a texel `texel`, offset
   `bias`, plane normal n with n . (q - light) = nq: the distance along the face's axis
   that the occluder must reach for the tap to be lit. Kept within
   SSG_DIRECT_LIGHT_MAX_SLOPE texels a texel of the centre's (a grazing plane), and
   tap_slope texels more a texel of the tap's distance from the centre: where the surface
   bends towards the light within the disc (a concave corner: a step's tread meeting the
   next riser) the plane alone would shadow the corner over the disc's radius. One code for
   the per-pixel test and the lanes: the same operations in the same order. */
static inline float dl_point_limit(float x, float y, float kx, float ky, float r,
                                   float texel, float bias, float tap_slope, const float n[3],
                                   float nq, const float axis[3], const float u[3],
                                   const float v[3], float half, int res, int pow2)
{
    float dx = x - kx, dy = y - ky, m = texel * SSG_DIRECT_LIGHT_MAX_SLOPE *
                                         (fabsf(dx) + fabsf(dy) + 1.0f);
    /* pow2 (res a power of two): the division as the product by 1 / res, the same bits
       (both scale by a power of two exactly) */
    float a = (pow2 ? 2.0f * x * (1.0f / (float)res) : 2.0f * x / (float)res) - 1.0f;
    float b = (pow2 ? 2.0f * y * (1.0f / (float)res) : 2.0f * y / (float)res) - 1.0f;
    float d[3], len2 = 0.0f, nd = 0.0f, ha = half * a, hb = half * b;
    for (int i = 0; i < 3; i++) {
        d[i] = axis[i] + ha * u[i] + hb * v[i];
        len2 += d[i] * d[i], nd += n[i] * d[i];
    }
    float len = sqrtf(len2);
    nd /= len;
    float t = nd < 0.0f ? nq / nd : r + m; /* the tap's ray meets the plane at t */
    t = t < r + m ? (t > r - m ? t : r - m) : r + m;
    t -= bias + texel * tap_slope * sqrtf(dx * dx + dy * dy);
    return t / len; /* along the ray -> along the face's axis, as the map */
}

/* The same for a directional light: the receiver plane changes depth by gx, gy a texel. */
static inline float dl_directional_limit(float x, float y, float kx, float ky, float r,
                                         float texel, float bias, float tap_slope, float gx,
                                         float gy)
{
    float dx = x - kx, dy = y - ky, m = texel * SSG_DIRECT_LIGHT_MAX_SLOPE *
                                         (fabsf(dx) + fabsf(dy) + 1.0f);
    float t = r + gx * dx + gy * dy;
    t = t < r + m ? (t > r - m ? t : r - m) : r + m;
    return t - bias - texel * tap_slope * sqrtf(dx * dx + dy * dy);
}

/* Whether pixel b of normal planes nrm (plane floats apart) is a surface (normal not 0). */
static inline int dl_is_surface(const float *nrm, size_t plane, size_t b)
{
    return nrm[b] != 0.0f || nrm[plane + b] != 0.0f || nrm[2 * plane + b] != 0.0f;
}

/* The bilinear blend of four 0/1 tests at fractions wx, wy. */
static inline float dl_blend(float wx, float wy, float t00, float t10, float t01, float t11)
{
    return (1.0f - wy) * ((1.0f - wx) * t00 + wx * t10) + wy * ((1.0f - wx) * t01 + wx * t11);
}

#endif
