/* gl_runtime.h - what core/gl's files need from each other besides the executor's view
 * (graph/gl_backend.h): textures behind images, opening passes, the run's scene
 * (gl_scene.c) for the raster passes (gl_raster.c). Internal to core/gl. */
#ifndef SSG_GL_RUNTIME_H
#define SSG_GL_RUNTIME_H

#include "ssgraph.h"

/* The texture of an image, created on first use (NULL: the 1x1 zero texture). Does not
 * transfer: the executor already did (gl_backend.h). */
unsigned ssg_gl_texture_of(const struct ssg_image *image);
unsigned ssg_gl_zero_texture(void);
/* 1 while the context exists and was last made current without failing: GL objects may be
   deleted. */
int ssg_gl_alive(void);
/* Starts a pass with the program of `shader` (SSG_GL_COMPUTE or SSG_GL_RASTER, gl_fn.h),
   binding the node's parameters when the file declares them (#pragma ssg_params); does
   not make it current. ssg_gl_pass_begin and ssg_gl_raster_begin are made of it. */
struct ssg_gl_pass;
struct ssg_node_ctx;
enum ssg_err ssg_gl_pass_open(struct ssg_gl_pass *pass, const struct ssg_node_ctx *ctx,
                              const char *shader, const char *defines, int stages);
/* Deletes gl_pass.c's storage buffers (at shutdown). */
void ssg_gl_buffers_free(void);

/* The run's scene on GL (gl_scene.h) for a draw or bind of the pass, uploaded into
   pass->ctx->gl_shared when no node of the run has yet; NULL when the pass already failed
   or the upload does (its error, reported as the node's, then sticky in the pass). */
struct ssg_gl_scene;
const struct ssg_gl_scene *ssg_gl_scene_of(struct ssg_gl_pass *pass);
/* Draws every mesh of the scene with the current program and framebuffer, setting
   `uniform int ssg_mesh` (when the program reads it) to the mesh's index. */
void ssg_gl_scene_draw_meshes(const struct ssg_gl_scene *scene, unsigned program);
/* SSG_OK, or the pending GL error reported as the node's ("GL error 0x0505 while
   <doing>"): SSG_E_NOMEM for GL_OUT_OF_MEMORY, else SSG_E_BACKEND. */
enum ssg_err ssg_gl_node_status(const struct ssg_node_ctx *ctx, const char *doing);

#endif
