/* write.h - ports and parameters of the `write` sink node, shared by write.c (descriptor,
 * check), write_cpu.c (writing the files), write_meta.c and test_write.c. Method in
 * README.md; the files themselves are written by core/io/imageio.h. */
#ifndef SSG_WRITE_H
#define SSG_WRITE_H

#include <stddef.h>

#include "graph/node.h"

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields. */
#define SSG_WRITE_IN(X)                                                                    \
    X(SSG_WRITE_IN_IMAGE, "image", SSG_T_COLOR | SSG_T_SCALAR | SSG_T_VECTOR,              \
      "main image: EXR channels R,G,B (Y when scalar) and the PNG preview")
SSG_PORT_ENUM(ssg_write_input, SSG_WRITE_IN, SSG_WRITE_INPUTS);

/* The parameters, one row each (lang/params.h); the struct below and the table in write.c
   are made from these rows. tonemap is an enum ssg_tonemap, compression an enum
   ssg_exr_compression (io/imageio.h). */
#define SSG_WRITE_PARAMS(P)                                                                \
    P(STRING, name, "file stem: writes <out>/<name>.exr and <out>/<name>.png",             \
      .required = 1)                                                                       \
    P(FLOAT, exposure, "PNG only: values are scaled by 2^exposure before tone mapping",    \
      .def = 0, .min = -20, .max = 20, .soft_min = -8, .soft_max = 8, .unit = "stops")     \
    P(ENUM, tonemap,                                                                       \
      "PNG only: clamp = min(x,1), reinhard = x/(1+x), aces = Narkowicz 2015 fit",         \
      .def = SSG_TONEMAP_ACES, .choices = ssg_write_tonemap_choices)                       \
    P(BOOL, png, "write the 8-bit sRGB PNG preview", .def = 1)                             \
    P(BOOL, exr, "write the 32-bit float EXR with all layers", .def = 1)                   \
    P(ENUM, compression,                                                                   \
      "EXR compression, all lossless: zip (deflate level 1, chunks on every thread) is "   \
      "small; none ~1.7x faster to write and ~9x larger; rle and piz are slower",          \
      .def = SSG_EXR_ZIP, .choices = ssg_write_compression_choices)                      \
    P(BOOL, sequence,                                                                      \
      "write every frame of a run as <name>_0000.exr/.png, <name>_0001... (the frame "     \
      "index, 4 digits); false: the last frame only, as <name>.exr/.png", .def = 0)
SSG_PARAMS_STRUCT(ssg_write_params, SSG_WRITE_PARAMS);

/* 1 when `name` is a plain file stem: not empty, at most 200 bytes, no '/', '\', "..",
 * control characters or leading '.' (hidden names are reserved for temporary files).
 * Otherwise 0, with the reason in why. */
int ssg_write_name_ok(const char *name, char *why, size_t why_len);

/* The run's metadata for the EXR (write_meta.c): the frame and seed from ctx->frame, the
 * camera from ctx->scene (none without a scene), the graph and --set list from ctx. */
struct ssg_exr_meta;
void ssg_write_meta(const struct ssg_node_ctx *ctx, struct ssg_exr_meta *meta);

/* The file stem of frame `frame_index`: name, or name_0003 with sequence (at most
 * 200 + 12 bytes, len >= 220). */
void ssg_write_stem(const struct ssg_write_params *p, int frame_index, char *stem, size_t len);

/* The CPU backend (write_cpu.c); `consts` is a struct ssg_write_params. */
enum ssg_err ssg_write_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io);

#endif
