/* horizon_gl.h - the GL side the horizon nodes (hbao, gtao, ssilvb) share: one pass whose
 * shader includes horizon.glsl, which reads the column basis e1 from buffer 0
 * (layout(std430, binding = 0) readonly buffer Columns { float e1[]; }), 1 / f as `uniform
 * float invf` and the projection as `uniform vec3 proj`, all made by prepare()
 * (ssg_horizon_frame, horizon.h). */
#ifndef SSG_HORIZON_GL_H
#define SSG_HORIZON_GL_H

#include "gl/gl.h"

/* Begins the pass of `shader` (no defines), binds io's ports (ssg_gl_ports) and the above,
 * e1 for io's input 0 (the G-buffer's position, whose width is the columns'). The node
 * binds the rest and dispatches; errors are the pass's (sticky, gl.h). */
void ssg_horizon_gl_begin(struct ssg_gl_pass *p, const struct ssg_node_ctx *ctx,
                          const char *shader, const struct ssg_io *io, const float *e1,
                          const struct ssg_projection *proj, float invf);

#endif
