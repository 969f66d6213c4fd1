/* @name@.h - the ports and parameters of the `@name@` node, one row each, shared by
 * @name@.c (the descriptor), @name@_cpu.c (the CPU kernel) and @name@_gl.c (the GL side).
 * The method: README.md in this folder. Nothing here changes after the graph is loaded;
 * the kernels only read it, from any thread. */
#ifndef SSG_@NAME@_H
#define SSG_@NAME@_H

#include "graph/node.h"

/* Ports, one row each (graph/node.h): enumerator, name, types, doc, further fields. The
   GL side binds input `src` as `uniform sampler2DArray src;` and output `out` as
   `dst_out` (ssg_gl_ports), so an input's name must not be a GLSL keyword ("in"). */
#define SSG_@NAME@_IN(X) X(SSG_@NAME@_IN_SRC, "src", SSG_T_IMAGE, "image to scale")
#define SSG_@NAME@_OUT(X) \
    X(SSG_@NAME@_OUT_OUT, "out", SSG_T_SCALAR, "gain x src, shaped and typed as src", \
      .same_as = "src")
SSG_PORT_ENUM(ssg_@name@_input, SSG_@NAME@_IN, SSG_@NAME@_INPUTS);
SSG_PORT_ENUM(ssg_@name@_output, SSG_@NAME@_OUT, SSG_@NAME@_OUTPUTS);

/* Parameters, one row each (lang/params.h): kind, field, doc, then default, range, unit.
   The struct below and the table in @name@.c are made from these rows; the shader reads
   every row not marked .host_only = 1 as p_<field> (#pragma ssg_params in @name@.glsl). */
#define SSG_@NAME@_PARAMS(P) \
    P(FLOAT, gain, "factor every channel of every pixel is multiplied by", .def = 1, \
      .min = -1e6, .max = 1e6, .soft_min = 0, .soft_max = 4)
SSG_PARAMS_STRUCT(ssg_@name@_params, SSG_@NAME@_PARAMS);

/* The descriptor (@name@.c); nodes/nodes.def lists it as X(@name@). */
extern const struct ssg_node_desc ssg_node_@name@;

/* The backends: `consts` is the parameters (struct ssg_@name@_params; a node with a
   prepare() gets the constants it made instead). */
enum ssg_err ssg_@name@_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io);
enum ssg_err ssg_@name@_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io);

#endif
