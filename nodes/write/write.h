/* write.h - the parameters of the `write` sink node, shared by write.c (descriptor,
 * check), write_cpu.c (writing the files) and tests/test_write.c.
 * The files themselves are written by core/io/imageio.h. */
#ifndef SSG_WRITE_H
#define SSG_WRITE_H

#include <stddef.h>

#include "graph/node.h"

/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_write_input {
    SSG_WRITE_IN_IMAGE,
    SSG_WRITE_INPUTS
};

/* Parameters as the graph file sets them (see the table in write.c). */
struct ssg_write_params {
    char name[SSG_STR_MAX]; /* file stem: writes <out_dir>/<name>.exr and .png; required */
    float exposure;         /* PNG exposure in stops (x 2^exposure), -20..20; default 0 */
    int tonemap;            /* PNG tone curve, enum ssg_tonemap (imageio.h); default aces */
    int png;                /* 1 = write the 8-bit PNG preview; default 1 */
    int exr;                /* 1 = write the float EXR with every layer; default 1 */
    int compression;        /* EXR compression, enum ssg_exr_compression; default zip */
};

/* 1 when `name` is a plain file stem: not empty, at most 200 bytes, no '/', '\', "..",
 * control characters or leading '.' (hidden names are reserved for temporary files).
 * Otherwise 0, with the reason in why. */
int ssg_write_name_ok(const char *name, char *why, size_t why_len);

/* The run's metadata for the EXR (write_meta.c): the frame and seed from ctx->frame, the
 * camera from ctx->scene (none without a scene), the graph and --set list from ctx. */
struct ssg_exr_meta;
void ssg_write_meta(const struct ssg_node_ctx *ctx, struct ssg_exr_meta *meta);

/* The CPU backend (write_cpu.c); `consts` is a struct ssg_write_params. */
enum ssg_err ssg_write_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io);

#endif
