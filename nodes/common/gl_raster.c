/* gl_raster.c - a scene's meshes, materials and textures in GL storage buffers, and the
 * rasterisation of its triangles into an image's layers (see gl_raster.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl/gl.h"
#include "gl/gl_fn.h"
#include "common/gl_raster.h"
#include "gl/gl_runtime.h"
#include "scene/scene.h"

enum { VDATA, INDEX, TEXEL, MESHES, MATERIALS };

/* The fragment shader reports triangle numbers as floats: exact below 2^24. */
#define MAX_MESH_TRIANGLES (1 << 24)
enum { MAX_LAYERS = 8 };

struct ssg_gl_scene {
    GLuint buffer[SSG_GL_SCENE_BUFFERS];
    GLuint vao;                 /* positions from vdata, indices from index[] */
    const struct ssg_scene *scene;
    struct ssg_gl_mesh *mesh;   /* the offsets, also needed for drawing */
    struct ssg_gl_material *material;
    size_t bytes[SSG_GL_SCENE_BUFFERS];
};

static enum ssg_err fail(const struct ssg_node_ctx *ctx, enum ssg_err code, const char *what)
{
    return ssg_node_fail(ctx, code, "%s", what);
}

/* Float offsets of every mesh's arrays in vdata and of its indices; sizes into s->bytes. */
static enum ssg_err lay_out_meshes(const struct ssg_node_ctx *ctx, struct ssg_gl_scene *s)
{
    const struct ssg_scene *sc = s->scene;
    size_t floats = 0, indices = 0;
    for (int i = 0; i < sc->mesh_count; i++) {
        const struct ssg_mesh *m = &sc->meshes[i];
        size_t v = (size_t)m->vertex_count;
        int uvs = m->uvs && sc->materials[m->material].texture >= 0; /* else unread */
        if (m->triangle_count >= MAX_MESH_TRIANGLES)
            return fail(ctx, SSG_E_VALUE, "a mesh has 2^24 triangles or more (the GL "
                        "visibility buffer numbers them in floats)");
        s->mesh[i] = (struct ssg_gl_mesh){(int32_t)floats, (int32_t)(floats + 3 * v),
                                          uvs ? (int32_t)(floats + 6 * v) : -1,
                                          (int32_t)indices, m->material};
        floats += (uvs ? 8 : 6) * v;
        indices += 3 * (size_t)m->triangle_count;
        if (floats > INT32_MAX || indices > INT32_MAX)
            return fail(ctx, SSG_E_NOMEM, "the scene's meshes are too large for GL");
    }
    s->bytes[VDATA] = floats * sizeof(float);
    s->bytes[INDEX] = indices * sizeof(uint32_t);
    s->bytes[MESHES] = (size_t)sc->mesh_count * sizeof(struct ssg_gl_mesh);
    return SSG_OK;
}

/* The material records, with the float offset of each used texture in texel[]. */
static enum ssg_err lay_out_materials(const struct ssg_node_ctx *ctx, struct ssg_gl_scene *s)
{
    const struct ssg_scene *sc = s->scene;
    size_t texels = 0;
    for (int i = 0; i < sc->material_count; i++) {
        const struct ssg_material *mt = &sc->materials[i];
        const struct ssg_texture *t = mt->texture >= 0 ? &sc->textures[mt->texture] : NULL;
        struct ssg_gl_material *g = &s->material[i];
        memcpy(g->albedo, mt->albedo, sizeof g->albedo);
        memcpy(g->specular, mt->specular, sizeof g->specular);
        g->shininess = mt->shininess;
        g->texels = -1;
        for (int j = 0; t && j < i && g->texels < 0; j++) /* a texture shared: upload once */
            if (sc->materials[j].texture == mt->texture)
                g->texels = s->material[j].texels;
        if (t && g->texels < 0) {
            g->texels = (int32_t)texels;
            texels += 3 * (size_t)t->width * (size_t)t->height;
        }
        g->width = t ? t->width : 0, g->height = t ? t->height : 0;
        if (texels > INT32_MAX)
            return fail(ctx, SSG_E_NOMEM, "the scene's textures are too large for GL");
    }
    s->bytes[TEXEL] = texels * sizeof(float);
    s->bytes[MATERIALS] = (size_t)sc->material_count * sizeof(struct ssg_gl_material);
    return SSG_OK;
}

static enum ssg_err check_limits(const struct ssg_node_ctx *ctx, const struct ssg_gl_scene *s)
{
    GLint most = 0;
    glGetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &most);
    static const char *const what[] = {"vertices", "indices", "textures", "meshes",
                                       "materials"};
    for (int b = 0; b < SSG_GL_SCENE_BUFFERS; b++)
        if (s->bytes[b] > (size_t)most) {
            char msg[200];
            snprintf(msg, sizeof msg, "the scene's %s take %zu bytes, more than this GL's "
                     "storage buffer limit of %d bytes", what[b], s->bytes[b], (int)most);
            return fail(ctx, SSG_E_NOMEM, msg);
        }
    return SSG_OK;
}

/* Creates the buffers and copies the scene's arrays straight into them. */
static void copy_data(struct ssg_gl_scene *s)
{
    const struct ssg_scene *sc = s->scene;
    glCreateBuffers(SSG_GL_SCENE_BUFFERS, s->buffer);
    for (int b = 0; b < SSG_GL_SCENE_BUFFERS; b++) /* 4 bytes at least: never size 0 */
        glNamedBufferData(s->buffer[b], (GLsizeiptr)(s->bytes[b] ? s->bytes[b] : 4), NULL,
                          GL_STATIC_DRAW);
    for (int i = 0; i < sc->mesh_count; i++) {
        const struct ssg_mesh *m = &sc->meshes[i];
        const struct ssg_gl_mesh *g = &s->mesh[i];
        GLsizeiptr v3 = (GLsizeiptr)(3 * sizeof(float) * (size_t)m->vertex_count);
        glNamedBufferSubData(s->buffer[VDATA], 4 * (GLintptr)g->positions, v3, m->positions);
        glNamedBufferSubData(s->buffer[VDATA], 4 * (GLintptr)g->normals, v3, m->normals);
        if (g->uvs >= 0)
            glNamedBufferSubData(s->buffer[VDATA], 4 * (GLintptr)g->uvs, v3 / 3 * 2, m->uvs);
        glNamedBufferSubData(s->buffer[INDEX], 4 * (GLintptr)g->indices,
                             (GLsizeiptr)(12 * (size_t)m->triangle_count), m->indices);
    }
    for (int i = 0; i < sc->material_count; i++) {
        const struct ssg_gl_material *g = &s->material[i];
        int first = g->texels >= 0; /* only the first material of a shared texture copies */
        for (int j = 0; first && j < i; j++)
            first = s->material[j].texels != g->texels;
        if (first)
            glNamedBufferSubData(s->buffer[TEXEL], 4 * (GLintptr)g->texels,
                                 (GLsizeiptr)(12 * (size_t)g->width * (size_t)g->height),
                                 sc->textures[sc->materials[i].texture].rgb);
    }
    if (s->bytes[MESHES])
        glNamedBufferSubData(s->buffer[MESHES], 0, (GLsizeiptr)s->bytes[MESHES], s->mesh);
    if (s->bytes[MATERIALS])
        glNamedBufferSubData(s->buffer[MATERIALS], 0, (GLsizeiptr)s->bytes[MATERIALS],
                             s->material);
}

static void make_vao(struct ssg_gl_scene *s)
{
    glCreateVertexArrays(1, &s->vao);
    glVertexArrayAttribFormat(s->vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(s->vao, 0, 0);
    glEnableVertexArrayAttrib(s->vao, 0);
    glVertexArrayElementBuffer(s->vao, s->buffer[INDEX]);
}

static enum ssg_err gl_status(const struct ssg_node_ctx *ctx, const char *doing)
{
    GLenum e = glGetError();
    if (e == GL_NO_ERROR)
        return SSG_OK;
    char msg[160];
    snprintf(msg, sizeof msg, "GL error 0x%04x while %s", (unsigned)e, doing);
    return fail(ctx, e == GL_OUT_OF_MEMORY ? SSG_E_NOMEM : SSG_E_BACKEND, msg);
}

enum ssg_err ssg_gl_scene_upload(const struct ssg_node_ctx *ctx, const struct ssg_scene *scene,
                                 struct ssg_gl_scene **out)
{
    *out = NULL;
    struct ssg_gl_scene *s = calloc(1, sizeof *s);
    if (s) {
        s->scene = scene;
        s->mesh = calloc((size_t)scene->mesh_count + 1, sizeof *s->mesh);
        s->material = calloc((size_t)scene->material_count + 1, sizeof *s->material);
    }
    if (!s || !s->mesh || !s->material) {
        ssg_gl_scene_free(&s);
        return fail(ctx, SSG_E_NOMEM, "out of memory for the scene's GL tables");
    }
    enum ssg_err e = lay_out_meshes(ctx, s);
    if (!e)
        e = lay_out_materials(ctx, s);
    if (!e)
        e = check_limits(ctx, s);
    if (!e) {
        copy_data(s);
        make_vao(s);
        e = gl_status(ctx, "uploading the scene");
    }
    if (e)
        ssg_gl_scene_free(&s);
    *out = s;
    return e;
}

void ssg_gl_scene_bind(const struct ssg_gl_scene *s)
{
    for (int b = 0; b < SSG_GL_SCENE_BUFFERS; b++)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, (GLuint)(SSG_GL_SCENE_BINDING + b),
                         s->buffer[b]);
}

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

static void draw_meshes(const struct ssg_gl_scene *s, GLuint prog)
{
    GLint mesh_at = glGetUniformLocation(prog, "ssg_mesh");
    glBindVertexArray(s->vao);
    for (int i = 0; i < s->scene->mesh_count; i++) {
        const struct ssg_gl_mesh *g = &s->mesh[i];
        int triangles = s->scene->meshes[i].triangle_count;
        if (triangles < 1)
            continue;
        glVertexArrayVertexBuffer(s->vao, 0, s->buffer[VDATA], 4 * (GLintptr)g->positions,
                                  3 * sizeof(float));
        if (mesh_at >= 0)
            glProgramUniform1i(prog, mesh_at, i);
        glDrawElements(GL_TRIANGLES, 3 * triangles, GL_UNSIGNED_INT,
                       (const void *)(4 * (uintptr_t)g->indices));
    }
    glBindVertexArray(0);
}

enum ssg_err ssg_gl_scene_draw_pass(struct ssg_gl_pass *pass, const struct ssg_gl_scene *s,
                                    const struct ssg_gl_camera *camera,
                                    struct ssg_image *target)
{
    if (pass->err)
        return pass->err;
    const struct ssg_node_ctx *ctx = pass->ctx;
    GLuint prog = pass->program, depth = 0;
    if (target->channels > MAX_LAYERS)
        return pass->err = fail(ctx, SSG_E_VALUE, "a raster target has more than 8 layers");
    GLuint fbo = make_target(target, &depth);
    if (!fbo)
        return pass->err = fail(ctx, SSG_E_BACKEND, "the GL framebuffer for the scene is "
                                                    "incomplete");
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
    draw_meshes(s, prog);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(1, &depth);
    return pass->err = gl_status(ctx, "drawing the scene");
}

enum ssg_err ssg_gl_scene_draw(const struct ssg_node_ctx *ctx, const struct ssg_gl_scene *s,
                               const char *shader, const struct ssg_gl_camera *camera,
                               struct ssg_image *target)
{
    struct ssg_gl_pass pass;
    ssg_gl_raster_begin(&pass, ctx, shader);
    return ssg_gl_scene_draw_pass(&pass, s, camera, target);
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

enum ssg_err ssg_gl_scene_draw_layers(struct ssg_gl_pass *pass, const struct ssg_gl_scene *s,
                                      struct ssg_image *target, float clear)
{
    /* One stack of one layer a draw: layer i is draw i. */
    const struct ssg_gl_stack stack = {target, 1, clear};
    return ssg_gl_scene_draw_stacks(pass, s, &stack, 1, target->channels);
}

/* Attaches draw i's layers of every stack; the number of outputs. */
static int attach_stacks(GLuint fbo, const struct ssg_gl_stack *stacks, int count, int i)
{
    GLenum draw[MAX_LAYERS];
    int n = 0;
    for (int k = 0; k < count; k++)
        for (int l = 0; l < stacks[k].layers && n < MAX_LAYERS; l++, n++) {
            glNamedFramebufferTextureLayer(fbo, GL_COLOR_ATTACHMENT0 + (GLenum)n,
                                           ssg_gl_texture_of(stacks[k].image), 0,
                                           i * stacks[k].layers + l);
            draw[n] = GL_COLOR_ATTACHMENT0 + (GLenum)n;
        }
    glNamedFramebufferDrawBuffers(fbo, n, draw);
    return n;
}

enum ssg_err ssg_gl_scene_draw_stacks(struct ssg_gl_pass *pass, const struct ssg_gl_scene *s,
                                      const struct ssg_gl_stack *stacks, int count, int draws)
{
    int outputs = 0;
    for (int k = 0; k < count; k++)
        outputs += stacks[k].layers;
    if (!pass->err && outputs > MAX_LAYERS)
        pass->err = fail(pass->ctx, SSG_E_VALUE, "a stacked draw has more than 8 outputs");
    if (pass->err)
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
            pass->err = fail(pass->ctx, SSG_E_BACKEND, "the GL framebuffer of a stacked "
                                                       "draw is incomplete");
        for (int k = 0, o = 0; k < count; k++)
            for (int l = 0; l < stacks[k].layers; l++, o++)
                glClearNamedFramebufferfv(fbo, GL_COLOR, o, &stacks[k].clear);
        glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &far);
        if (layer_at >= 0)
            glProgramUniform1i(prog, layer_at, i);
        draw_meshes(s, prog);
    }
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(1, &depth);
    enum ssg_err e = gl_status(pass->ctx, "drawing the scene's stacked layers");
    return pass->err ? pass->err : (pass->err = e);
}

void ssg_gl_scene_free(struct ssg_gl_scene **scene)
{
    struct ssg_gl_scene *s = scene ? *scene : NULL;
    if (!s)
        return;
    if (s->buffer[0]) /* GL defers the deletion until passes already queued are done */
        glDeleteBuffers(SSG_GL_SCENE_BUFFERS, s->buffer);
    if (s->vao)
        glDeleteVertexArrays(1, &s->vao);
    free(s->mesh);
    free(s->material);
    free(s);
    *scene = NULL;
}
