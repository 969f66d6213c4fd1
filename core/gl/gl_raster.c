/* gl_raster.c - the raster passes of gl_scene.h: the run's scene (gl_scene.c) drawn with
 * a depth test into an image's layers, through a camera's projection (the visibility
 * buffer) or a projection of the node's own per layer (shadow and light maps). */
#include <stdio.h>
#include <string.h>

#include "gl/gl.h"
#include "gl/gl_fn.h"
#include "gl/gl_runtime.h"
#include "gl/gl_scene.h"

enum { MAX_LAYERS = 8 };

/* World -> clip for node.h's projection, column-major: clip.x / clip.w is the pixel x
   mapped to [-1, 1], clip.y likewise for the pixel y (row 0 at y = -1, so the target's
   row 0 is the top), depth from near (-1) to far (+1). */
static void world_to_clip(const struct ssg_gl_camera *c, int w, int h, float m[16])
{
    const float *r = c->rot, *eye = c->eye;
    double n = c->near_z, f = c->far_z, view[3][4], proj[4][3];
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++)
            view[i][j] = r[3 * i + j];
        view[i][3] = -(r[3 * i] * (double)eye[0] + r[3 * i + 1] * (double)eye[1] +
                       r[3 * i + 2] * (double)eye[2]);
    }
    /* proj[row][view x, y, z]; the constant column is only in the depth row */
    const double px[3] = {2.0 * c->proj.f / w, 0, 1.0 - 2.0 * c->proj.cx / w};
    const double py[3] = {0, -2.0 * c->proj.f / h, 1.0 - 2.0 * c->proj.cy / h};
    const double pz[3] = {0, 0, -(f + n) / (f - n)}, pw[3] = {0, 0, -1};
    memcpy(proj[0], px, sizeof px), memcpy(proj[1], py, sizeof py);
    memcpy(proj[2], pz, sizeof pz), memcpy(proj[3], pw, sizeof pw);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double v = 0;
            for (int k = 0; k < 3; k++)
                v += proj[i][k] * view[k][j];
            if (i == 2 && j == 3)
                v += -2.0 * f * n / (f - n);
            m[4 * j + i] = (float)v;
        }
}

/* A framebuffer drawing into target's layers with a depth buffer of its size; 0 on
   failure. */
static GLuint make_target(struct ssg_image *target, GLuint *depth)
{
    GLuint fbo = 0, tex = ssg_gl_texture_of(target);
    GLenum draw[MAX_LAYERS];
    glCreateFramebuffers(1, &fbo);
    for (int i = 0; i < target->channels; i++) {
        glNamedFramebufferTextureLayer(fbo, GL_COLOR_ATTACHMENT0 + (GLenum)i, tex, 0, i);
        draw[i] = GL_COLOR_ATTACHMENT0 + (GLenum)i;
    }
    glNamedFramebufferDrawBuffers(fbo, target->channels, draw);
    glCreateRenderbuffers(1, depth);
    glNamedRenderbufferStorage(*depth, GL_DEPTH_COMPONENT32F, target->width, target->height);
    glNamedFramebufferRenderbuffer(fbo, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, *depth);
    if (glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        glDeleteFramebuffers(1, &fbo);
        glDeleteRenderbuffers(1, depth);
        return 0;
    }
    return fbo;
}

enum ssg_err ssg_gl_scene_draw_pass(struct ssg_gl_pass *pass,
                                    const struct ssg_gl_camera *camera,
                                    struct ssg_image *target)
{
    const struct ssg_node_ctx *ctx = pass->ctx;
    if (!pass->err && target->channels > MAX_LAYERS)
        pass->err = ssg_node_fail(ctx, SSG_E_VALUE, "a raster target has more than 8 layers");
    const struct ssg_gl_scene *s = ssg_gl_scene_of(pass);
    if (!s)
        return pass->err;
    GLuint prog = pass->program, depth = 0;
    GLuint fbo = make_target(target, &depth);
    if (!fbo)
        return pass->err = ssg_node_fail(ctx, SSG_E_BACKEND, "the GL framebuffer for the "
                                         "scene is incomplete");
    float m[16];
    const float zero[4] = {0, 0, 0, 0}, far = 1.0f;
    world_to_clip(camera, target->width, target->height, m);
    for (int i = 0; i < target->channels; i++)
        glClearNamedFramebufferfv(fbo, GL_COLOR, i, zero);
    glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &far);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, target->width, target->height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glUseProgram(prog);
    glProgramUniformMatrix4fv(prog, glGetUniformLocation(prog, "ssg_world_to_clip"), 1,
                              GL_FALSE, m);
    ssg_gl_scene_draw_meshes(s, prog);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(1, &depth);
    return pass->err = ssg_gl_node_status(ctx, "drawing the scene");
}

enum ssg_err ssg_gl_scene_draw(const struct ssg_node_ctx *ctx, const char *shader,
                               const struct ssg_gl_camera *camera, struct ssg_image *target)
{
    struct ssg_gl_pass pass;
    ssg_gl_raster_begin(&pass, ctx, shader);
    return ssg_gl_scene_draw_pass(&pass, camera, target);
}

enum ssg_err ssg_gl_raster_begin(struct ssg_gl_pass *pass, const struct ssg_node_ctx *ctx,
                                 const char *shader)
{
    return ssg_gl_pass_open(pass, ctx, shader, NULL, SSG_GL_RASTER);
}

/* A framebuffer with a depth buffer of w x h and no colour attachment yet; 0 on failure. */
static GLuint make_layer_target(int w, int h, GLuint *depth)
{
    GLuint fbo = 0;
    glCreateFramebuffers(1, &fbo);
    glCreateRenderbuffers(1, depth);
    glNamedRenderbufferStorage(*depth, GL_DEPTH_COMPONENT32F, w, h);
    glNamedFramebufferRenderbuffer(fbo, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, *depth);
    glNamedFramebufferDrawBuffer(fbo, GL_COLOR_ATTACHMENT0);
    return fbo;
}

enum ssg_err ssg_gl_scene_draw_layers(struct ssg_gl_pass *pass, struct ssg_image *target,
                                      float clear)
{
    /* One stack of one layer a draw: layer i is draw i. */
    const struct ssg_gl_stack stack = {target, 1, clear};
    return ssg_gl_scene_draw_stacks(pass, &stack, 1, target->channels);
}

/* Attaches draw i's layers of every stack; the number of outputs. */
static int attach_stacks(GLuint fbo, const struct ssg_gl_stack *stacks, int count, int i)
{
    GLenum draw[MAX_LAYERS];
    int n = 0;
    for (int k = 0; k < count; k++)
        for (int l = 0; l < stacks[k].layers && n < MAX_LAYERS; l++, n++) {
            /* an unread on_demand output (NULL): its fragment outputs go nowhere */
            draw[n] = stacks[k].image ? GL_COLOR_ATTACHMENT0 + (GLenum)n : GL_NONE;
            if (stacks[k].image)
                glNamedFramebufferTextureLayer(fbo, GL_COLOR_ATTACHMENT0 + (GLenum)n,
                                               ssg_gl_texture_of(stacks[k].image), 0,
                                               i * stacks[k].layers + l);
        }
    glNamedFramebufferDrawBuffers(fbo, n, draw);
    return n;
}

enum ssg_err ssg_gl_scene_draw_stacks(struct ssg_gl_pass *pass,
                                      const struct ssg_gl_stack *stacks, int count, int draws)
{
    int outputs = 0;
    for (int k = 0; k < count; k++)
        outputs += stacks[k].layers;
    if (!pass->err && outputs > MAX_LAYERS)
        pass->err = ssg_node_fail(pass->ctx, SSG_E_VALUE, "a stacked draw has more than 8 "
                                  "outputs");
    const struct ssg_gl_scene *s = ssg_gl_scene_of(pass);
    if (!s)
        return pass->err;
    GLuint depth = 0, prog = pass->program;
    GLuint fbo = make_layer_target(stacks[0].image->width, stacks[0].image->height, &depth);
    GLint layer_at = glGetUniformLocation(prog, "ssg_layer");
    const float far = 1.0f;
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, stacks[0].image->width, stacks[0].image->height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glUseProgram(prog);
    for (int i = 0; i < draws && !pass->err; i++) {
        attach_stacks(fbo, stacks, count, i);
        if (i == 0 && glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) !=
                          GL_FRAMEBUFFER_COMPLETE)
            pass->err = ssg_node_fail(pass->ctx, SSG_E_BACKEND, "the GL framebuffer of a "
                                      "stacked draw is incomplete");
        for (int k = 0, o = 0; k < count; k++)
            for (int l = 0; l < stacks[k].layers; l++, o++)
                if (stacks[k].image)
                    glClearNamedFramebufferfv(fbo, GL_COLOR, o, &stacks[k].clear);
        glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &far);
        if (layer_at >= 0)
            glProgramUniform1i(prog, layer_at, i);
        ssg_gl_scene_draw_meshes(s, prog);
    }
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(1, &depth);
    enum ssg_err e = ssg_gl_node_status(pass->ctx, "drawing the scene's stacked layers");
    return pass->err ? pass->err : (pass->err = e);
}

