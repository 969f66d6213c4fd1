/* direct_light.h - the `direct_light` node (direct_light.c): a G-buffer lit by the scene's
 * own point and directional lights through their maps (lightmaps), with filtered shadows.
 * Shared by both backends: the constants prepare() makes. */
#ifndef SSG_DIRECT_LIGHT_H
#define SSG_DIRECT_LIGHT_H

#include "graph/node.h"
#include "common/lightmap.h"

enum { SSG_DIRECT_LIGHT_MAX_SAMPLES = 64, SSG_DIRECT_LIGHT_MAX_LIGHTS = SSG_LIGHTMAP_FACES_MAX };
/* The widest PCF disc a pixel may get (soft shadows), texels. */
#define SSG_DIRECT_LIGHT_MAX_RADIUS 24.0f

/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_direct_light_input {
    SSG_DIRECT_LIGHT_IN_POSITION,
    SSG_DIRECT_LIGHT_IN_NORMAL,
    SSG_DIRECT_LIGHT_IN_ALBEDO,
    SSG_DIRECT_LIGHT_IN_MAPS,
    SSG_DIRECT_LIGHT_INPUTS
};
enum ssg_direct_light_output {
    SSG_DIRECT_LIGHT_OUT_OUT,
    SSG_DIRECT_LIGHT_OUT_VISIBILITY,
    SSG_DIRECT_LIGHT_OUTPUTS
};

struct ssg_direct_light_params {
    int samples;         /* PCF taps (Vogel disc); default 12 */
    float filter;        /* PCF disc radius, texels; default 1.5 */
    float offset;        /* constant depth offset, texels; default 0.5 */
    float normal_offset; /* lookup moved along N by normal_offset x sin(N, l) texels; 2 */
    float light_size;    /* point lights' diameter, scene units; 0 = hard (PCF only) */
    float sun_angle;     /* directional lights' angular diameter, degrees; 0 = hard */
};

/* One light as both backends read it. */
struct ssg_direct_light_light {
    float pos[3];   /* point: position; directional: unused */
    float dir[3];   /* directional: direction the light travels; point: unused */
    float color[3]; /* linear RGB */
    float intensity; /* point: radiant intensity; directional: irradiance */
    int point;      /* 1 = point light (a cube of six faces), 0 = directional (one) */
    int face;       /* its first face in the maps */
    float texel;    /* directional: the map's texel, scene units; point: 2 / R (a texel
                       at distance d is d x this) */
    float spread;   /* soft shadows: point light_size; directional tan(sun_angle) */
};

struct ssg_direct_light_consts {
    struct ssg_direct_light_params p;
    float rot[9], eye[3];  /* view -> world: world = eye + rot^T view */
    int res;               /* the maps' side R */
    int lights;            /* point and directional lights of the scene */
    float taps[2 * SSG_DIRECT_LIGHT_MAX_SAMPLES]; /* Vogel disc in the unit disc, x y x y */
    struct ssg_direct_light_light light[SSG_DIRECT_LIGHT_MAX_LIGHTS];
    struct ssg_lightmap_face faces[SSG_LIGHTMAP_FACES_MAX];
};

/* The per-pixel rotation of the tap disc, in turns [0, 1): interleaved gradient noise
   (Jimenez, "Next Generation Post Processing in Call of Duty: Advanced Warfare", SIGGRAPH
   2014 course), which has no structure a filter or the eye picks up at any scale. */
static inline float ssg_direct_light_turn(int x, int y)
{
    float f = 0.06711056f * (float)x + 0.00583715f * (float)y;
    f = 52.9829189f * (f - floorf(f));
    return f - floorf(f);
}

enum ssg_err ssg_direct_light_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                      const struct ssg_io *io);
enum ssg_err ssg_direct_light_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                     const struct ssg_io *io);

extern const struct ssg_node_desc ssg_node_direct_light;

#endif
