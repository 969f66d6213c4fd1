/* gl_runtime.h - what gl_pass.c (and nodes/common/gl_raster.c) need from the runtime besides the
 * executor's view (gl_backend.h). Internal to libssgraph. */
#ifndef SSG_GL_RUNTIME_H
#define SSG_GL_RUNTIME_H

#include "ssgraph.h"

/* The texture of an image, created on first use (NULL: the 1x1 zero texture). Does not
 * transfer: the executor already did (gl_backend.h). */
unsigned ssg_gl_texture_of(const struct ssg_image *image);
unsigned ssg_gl_zero_texture(void);
/* Deletes gl_pass.c's storage buffers (at shutdown). */
void ssg_gl_buffers_free(void);

#endif
