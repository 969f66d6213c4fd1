/* ssilvb.h - parameters and prepared constants of the `ssilvb` node, shared by ssilvb.c
 * (descriptor, check, prepare), ssilvb_cpu.c (the CPU kernel) and ssilvb_gl.c (the GL
 * side). Method and conventions: README.md in this folder. Read-only after prepare(); the
 * kernel is thread-safe. */
#ifndef SSG_SSILVB_H
#define SSG_SSILVB_H

#include "common/horizon.h"
#include "graph/node.h"

#define SSG_SSILVB_MAX_SLICES 32
#define SSG_SSILVB_MAX_STEPS 64
/* Sectors of a slice's bitmask: one 32-bit word (paper sec. 3.2). */
#define SSG_SSILVB_SECTORS 32
/* Levels of the per-pixel slice rotation: the noise picks one of these turns. */
#define SSG_SSILVB_TURNS 64

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields. */
#define SSG_SSILVB_IN(X)                                                                   \
    X(SSG_SSILVB_IN_POSITION, "position", SSG_T_VECTOR,                                    \
      "view-space position (its -z is the depth unless depth is given)")                   \
    X(SSG_SSILVB_IN_NORMAL, "normal", SSG_T_VECTOR, "unit view-space normal")              \
    X(SSG_SSILVB_IN_DEPTH, "depth", SSG_T_SCALAR,                                          \
      "linear depth the points are reconstructed from; none = -position.z", .optional = 1) \
    X(SSG_SSILVB_IN_LIGHT, "light", SSG_T_COLOR,                                           \
      "outgoing radiance of each pixel, the bounce's senders (as ssdo's light)")           \
    X(SSG_SSILVB_IN_ALBEDO, "albedo", SSG_T_COLOR, "diffuse albedo of the receiver")       \
    X(SSG_SSILVB_IN_BACK, "back", SSG_T_SCALAR,                                            \
      "linear depth of the second surface behind the first along the pixel's ray; none "   \
      "(or not behind) = depth + thickness",                                               \
      .optional = 1)
#define SSG_SSILVB_OUT(X)                                                                  \
    X(SSG_SSILVB_OUT_AO, "ao", SSG_T_SCALAR,                                               \
      "cosine-weighted visibility within radius from the sector bitmasks, 1 = unoccluded") \
    X(SSG_SSILVB_OUT_BOUNCE, "bounce", SSG_T_COLOR,                                        \
      "one indirect bounce from the on-screen senders, albedo / pi x received irradiance " \
      "(as ssdo's bounce)")
SSG_PORT_ENUM(ssg_ssilvb_input, SSG_SSILVB_IN, SSG_SSILVB_INPUTS);
SSG_PORT_ENUM(ssg_ssilvb_output, SSG_SSILVB_OUT, SSG_SSILVB_OUTPUTS);

/* The parameters, one row each (lang/params.h): kind, field, doc, then default, range and
   unit. The struct below and the table in ssilvb.c are made from these rows; the shader
   reads every one as p_<field> (#pragma ssg_params). */
#define SSG_SSILVB_PARAMS(P)                                                               \
    P(INT, slices,                                                                         \
      "slice directions per pixel over the half circle about the view vector, each "       \
      "marched both ways (turned per pixel by the noise)",                                 \
      .def = 4, .min = 1, .max = SSG_SSILVB_MAX_SLICES, .soft_min = 1,                     \
      .soft_max = SSG_SSILVB_MAX_SLICES)                                                   \
    P(INT, steps, "depth samples on each side of a slice", .def = 12, .min = 1,            \
      .max = SSG_SSILVB_MAX_STEPS, .soft_min = 1, .soft_max = 32)                          \
    P(FLOAT, radius,                                                                       \
      "R: samples farther than this from the pixel neither occlude nor send light",        \
      .def = 2, .min = 1e-6, .max = 1e6, .soft_min = 0.1, .soft_max = 10,                  \
      .unit = "scene units")                                                               \
    P(FLOAT, thickness,                                                                    \
      "depth of every occluder behind its front surface, where `back` is unconnected or "  \
      "not behind it",                                                                     \
      .def = 0.5, .min = 0, .max = 1e6, .soft_min = 0, .soft_max = 2,                      \
      .unit = "scene units")                                                               \
    P(FLOAT, power,                                                                        \
      "ao = visibility^power (screen space misses what lies beyond the radius or off "     \
      "screen; 2.5 measured against reference_gi)",                                        \
      .def = 2.5, .min = 0.1, .max = 8, .soft_min = 0.1, .soft_max = 8)                    \
    P(FLOAT, strength,                                                                     \
      "scale of the bounce (1.2 measured against reference_gi: senders off screen or "     \
      "beyond the radius are missing)",                                                    \
      .def = 1.2, .min = 0, .max = 16, .soft_min = 0, .soft_max = 4)                       \
    P(FLOAT, max_screen_radius,                                                            \
      "caps the projected radius f R / (depth - R) of the march; 0 = no cap", .def = 0,    \
      .min = 0, .max = 16384, .soft_min = 0, .soft_max = 512, .unit = "px")
SSG_PARAMS_STRUCT(ssg_ssilvb_params, SSG_SSILVB_PARAMS);

struct ssg_ssilvb_consts {
    struct ssg_ssilvb_params p;   /* the parameters as given */
    struct ssg_projection proj;   /* the frame's camera at the G-buffer's resolution */
    float invf;                   /* 1 / proj.f */
    float noise_off[4];           /* seed-derived pixel offsets of the two noise patterns
                                     (rotation x, y; jitter x, y), whole numbers */
    float turn_cos[SSG_SSILVB_TURNS];       /* cos(pi (j + 0.5) / (TURNS slices)) */
    float turn_sin[SSG_SSILVB_TURNS];       /* sin of the same */
    /* Per column x of the G-buffer (width w): e1 = (1, 0, a_u) / sqrt(1 + a_u^2), e1x at
       [x] and e1z at [w + x] (ssg_horizon_frame); read by both backends; sized by
       consts_size_of. */
    float e1[];
};

/* What changes from one frame of a sequence to the next (README.md, "Frames"), made by
   ssg_ssilvb_frame_of for both backends: the slice table turned by a golden-ratio
   fraction of one slice, and the noise offsets moved by the temporal noise shift. */
struct ssg_ssilvb_frame {
    float slice_cos[SSG_SSILVB_MAX_SLICES]; /* cos(pi (k + ssg_sampling_frame_turn) / slices) */
    float slice_sin[SSG_SSILVB_MAX_SLICES]; /* sin of the same */
    float noise_off[4]; /* the consts' offsets + ssg_sampling_frame_shift; theirs in frame 0 */
};
void ssg_ssilvb_frame_of(const struct ssg_ssilvb_consts *c, int frame,
                         struct ssg_ssilvb_frame *f);

/* The descriptor (ssilvb.c). */
extern const struct ssg_node_desc ssg_node_ssilvb;

enum ssg_err ssg_ssilvb_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io);
/* The GL side (ssilvb_gl.c, shader ssilvb.glsl). */
enum ssg_err ssg_ssilvb_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io);

#endif
