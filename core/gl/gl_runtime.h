/* gl_runtime.h - what gl_pass.c (and nodes/common/gl_raster.c) need from the runtime besides the
 * executor's view (gl_backend.h). Internal to libssgraph. */
#ifndef SSG_GL_RUNTIME_H
#define SSG_GL_RUNTIME_H

#include "ssgraph.h"

/* The texture of an image, created on first use (NULL: the 1x1 zero texture). Does not
 * transfer: the executor already did (gl_backend.h). */
unsigned ssg_gl_texture_of(const struct ssg_image *image);
unsigned ssg_gl_zero_texture(void);
/* Starts a pass with the program of `shader` (SSG_GL_COMPUTE or SSG_GL_RASTER, gl_fn.h),
   binding the node's parameters when the file declares them (#pragma ssg_params); does
   not make it current. ssg_gl_pass_begin and ssg_gl_raster_begin are made of it. */
struct ssg_gl_pass;
struct ssg_node_ctx;
enum ssg_err ssg_gl_pass_open(struct ssg_gl_pass *pass, const struct ssg_node_ctx *ctx,
                              const char *shader, const char *defines, int stages);
/* Deletes gl_pass.c's storage buffers (at shutdown). */
void ssg_gl_buffers_free(void);

#endif
