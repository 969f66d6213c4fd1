/* gl_scene.c - the scene on GL (gl_scene.h): its meshes, materials and textures laid out
 * and copied into storage buffers, once a run. The copy lives in the run's ssg_gl_shared
 * (graph/gl_backend.h): the first node that binds or draws the scene uploads it, every
 * later node and frame of the run (and of a live graph's later runs, the scene being
 * the graph's for its whole life) finds it there, and the run's owner clears it. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl/gl.h"
#include "gl/gl_fn.h"
#include "gl/gl_runtime.h"
#include "gl/gl_scene.h"
#include "graph/gl_backend.h"
#include "scene/coverage.h"
#include "scene/distance.h"
#include "scene/scene.h"

enum { VDATA, INDEX, TEXEL, MESHES, MATERIALS };

/* The fragment shader reports triangle numbers as floats: exact below 2^24. */
#define MAX_MESH_TRIANGLES (1 << 24)

struct ssg_gl_scene {
    GLuint buffer[SSG_GL_SCENE_BUFFERS]; /* the storage buffers of gl_scene.h, in order */
    GLuint vao;                 /* positions from vdata, indices from index[] */
    const struct ssg_scene *scene; /* what was uploaded: its meshes' triangle counts */
    struct ssg_gl_mesh *mesh;   /* the offsets, also needed for drawing */
    struct ssg_gl_material *material; /* the records as uploaded */
    int32_t *texel_at;          /* per scene texture: its float offset in texel[], -1 = unused */
    size_t bytes[SSG_GL_SCENE_BUFFERS]; /* each buffer's size */
    GLuint distance;            /* the distance field's voxels (scene/distance.h), 4 bytes
                                   of 0 without one */
    int borrowed;               /* a proxy view (scene/proxy.h): its textures, materials and
                                   distance field are the scene's buffers, not its own */
    struct ssg_scene view;      /* a view's copy: the node's view lives on its stack */
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
        const struct ssg_material *mt = &sc->materials[m->material];
        int uvs = m->uvs && (mt->texture >= 0 || mt->normal_texture >= 0 ||
                             mt->emission_texture >= 0); /* else unread */
        int tangents = uvs && m->tangents && mt->normal_texture >= 0;
        if (m->triangle_count >= MAX_MESH_TRIANGLES)
            return fail(ctx, SSG_E_VALUE, "a mesh has 2^24 triangles or more (the GL "
                        "visibility buffer numbers them in floats)");
        size_t at_tangents = floats + (uvs ? 8 : 6) * v;
        size_t at_colors = at_tangents + (tangents ? 4 : 0) * v;
        s->mesh[i] = (struct ssg_gl_mesh){(int32_t)floats, (int32_t)(floats + 3 * v),
                                          uvs ? (int32_t)(floats + 6 * v) : -1,
                                          (int32_t)indices, m->material,
                                          tangents ? (int32_t)at_tangents : -1,
                                          m->colors ? (int32_t)at_colors : -1};
        floats = at_colors + (m->colors ? 3 : 0) * v;
        indices += 3 * (size_t)m->triangle_count;
        if (floats > INT32_MAX || indices > INT32_MAX)
            return fail(ctx, SSG_E_NOMEM, "the scene's meshes are too large for GL");
    }
    s->bytes[VDATA] = floats * sizeof(float);
    s->bytes[INDEX] = indices * sizeof(uint32_t);
    s->bytes[MESHES] = (size_t)sc->mesh_count * sizeof(struct ssg_gl_mesh);
    return SSG_OK;
}

/* The float offset in texel[] of every texture a material uses (albedo or normal map),
   each once: its RGB, then its alpha plane when it has one. */
static enum ssg_err lay_out_textures(const struct ssg_node_ctx *ctx, struct ssg_gl_scene *s)
{
    const struct ssg_scene *sc = s->scene;
    size_t texels = 0;
    for (int i = 0; i < sc->texture_count; i++)
        s->texel_at[i] = -1;
    for (int i = 0; i < sc->material_count; i++) {
        const int used[3] = {sc->materials[i].texture, sc->materials[i].normal_texture,
                             sc->materials[i].emission_texture};
        for (int k = 0; k < 3; k++) {
            if (used[k] < 0 || s->texel_at[used[k]] >= 0)
                continue;
            const struct ssg_texture *t = &sc->textures[used[k]];
            s->texel_at[used[k]] = (int32_t)texels;
            texels += (t->alpha ? 4 : 3) * (size_t)t->width * (size_t)t->height;
            if (texels > INT32_MAX)
                return fail(ctx, SSG_E_NOMEM, "the scene's textures are too large for GL");
        }
    }
    s->bytes[TEXEL] = texels * sizeof(float);
    return SSG_OK;
}

/* The material records, with their textures' offsets in texel[]. */
static void lay_out_materials(struct ssg_gl_scene *s)
{
    const struct ssg_scene *sc = s->scene;
    for (int i = 0; i < sc->material_count; i++) {
        const struct ssg_material *mt = &sc->materials[i];
        const struct ssg_texture *t = mt->texture >= 0 ? &sc->textures[mt->texture] : NULL;
        const struct ssg_texture *nt =
            mt->normal_texture >= 0 ? &sc->textures[mt->normal_texture] : NULL;
        struct ssg_gl_material *g = &s->material[i];
        memcpy(g->albedo, mt->albedo, sizeof g->albedo);
        memcpy(g->specular, mt->specular, sizeof g->specular);
        g->shininess = mt->shininess;
        g->texels = t ? s->texel_at[mt->texture] : -1;
        g->width = t ? t->width : 0, g->height = t ? t->height : 0;
        g->opacity = mt->opacity;
        g->alpha_cutoff = mt->alpha_cutoff;
        g->masked = ssg_material_masked(mt);
        g->alpha_texels = t && t->alpha ? g->texels + 3 * t->width * t->height : -1;
        g->normal_texels = nt ? s->texel_at[mt->normal_texture] : -1;
        g->normal_width = nt ? nt->width : 0, g->normal_height = nt ? nt->height : 0;
        g->normal_scale = mt->normal_scale;
        const struct ssg_texture *et =
            mt->emission_texture >= 0 ? &sc->textures[mt->emission_texture] : NULL;
        memcpy(g->emission, mt->emission, sizeof g->emission);
        g->emission_texels = et ? s->texel_at[mt->emission_texture] : -1;
        g->emission_width = et ? et->width : 0, g->emission_height = et ? et->height : 0;
    }
    s->bytes[MATERIALS] = (size_t)sc->material_count * sizeof(struct ssg_gl_material);
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
    for (int b = 0; b < SSG_GL_SCENE_BUFFERS; b++) { /* 4 bytes at least: never size 0 */
        if (s->borrowed && (b == TEXEL || b == MATERIALS))
            continue;
        glCreateBuffers(1, &s->buffer[b]);
        glNamedBufferData(s->buffer[b], (GLsizeiptr)(s->bytes[b] ? s->bytes[b] : 4), NULL,
                          GL_STATIC_DRAW);
    }
    for (int i = 0; i < sc->mesh_count; i++) {
        const struct ssg_mesh *m = &sc->meshes[i];
        const struct ssg_gl_mesh *g = &s->mesh[i];
        GLsizeiptr v3 = (GLsizeiptr)(3 * sizeof(float) * (size_t)m->vertex_count);
        glNamedBufferSubData(s->buffer[VDATA], 4 * (GLintptr)g->positions, v3, m->positions);
        glNamedBufferSubData(s->buffer[VDATA], 4 * (GLintptr)g->normals, v3, m->normals);
        if (g->uvs >= 0)
            glNamedBufferSubData(s->buffer[VDATA], 4 * (GLintptr)g->uvs, v3 / 3 * 2, m->uvs);
        if (g->tangents >= 0)
            glNamedBufferSubData(s->buffer[VDATA], 4 * (GLintptr)g->tangents, v3 / 3 * 4,
                                 m->tangents);
        if (g->colors >= 0)
            glNamedBufferSubData(s->buffer[VDATA], 4 * (GLintptr)g->colors, v3, m->colors);
        glNamedBufferSubData(s->buffer[INDEX], 4 * (GLintptr)g->indices,
                             (GLsizeiptr)(12 * (size_t)m->triangle_count), m->indices);
    }
    for (int i = 0; i < sc->texture_count && !s->borrowed; i++) {
        const struct ssg_texture *t = &sc->textures[i];
        GLsizeiptr plane = (GLsizeiptr)(4 * (size_t)t->width * (size_t)t->height);
        if (s->texel_at[i] < 0)
            continue;
        glNamedBufferSubData(s->buffer[TEXEL], 4 * (GLintptr)s->texel_at[i], 3 * plane, t->rgb);
        if (t->alpha)
            glNamedBufferSubData(s->buffer[TEXEL], 4 * (GLintptr)s->texel_at[i] + 3 * plane,
                                 plane, t->alpha);
    }
    if (s->bytes[MESHES])
        glNamedBufferSubData(s->buffer[MESHES], 0, (GLsizeiptr)s->bytes[MESHES], s->mesh);
    if (s->bytes[MATERIALS] && !s->borrowed)
        glNamedBufferSubData(s->buffer[MATERIALS], 0, (GLsizeiptr)s->bytes[MATERIALS],
                             s->material);
}

/* The distance field goes up with the triangles it was made of: 3.4 MB at 96 voxels a side,
   once a run, where rsm's visibility would otherwise copy it every frame. */
static void copy_distance(struct ssg_gl_scene *s)
{
    const struct ssg_distance *f = s->scene->distance;
    static const float none = 0.0f;
    size_t bytes = f ? sizeof(float) * (size_t)f->n[0] * f->n[1] * f->n[2] : sizeof none;
    glCreateBuffers(1, &s->distance);
    glNamedBufferData(s->distance, (GLsizeiptr)bytes, f ? (const void *)f->d : &none,
                      GL_STATIC_DRAW);
}

static void make_vao(struct ssg_gl_scene *s)
{
    glCreateVertexArrays(1, &s->vao);
    glVertexArrayAttribFormat(s->vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(s->vao, 0, 0);
    glEnableVertexArrayAttrib(s->vao, 0);
    glVertexArrayAttribFormat(s->vao, 1, 2, GL_FLOAT, GL_FALSE, 0); /* uv, where a mesh has */
    glVertexArrayAttribBinding(s->vao, 1, 1);
    glVertexArrayElementBuffer(s->vao, s->buffer[INDEX]);
}

enum ssg_err ssg_gl_node_status(const struct ssg_node_ctx *ctx, const char *doing)
{
    GLenum e = glGetError();
    if (e == GL_NO_ERROR)
        return SSG_OK;
    char msg[160];
    snprintf(msg, sizeof msg, "GL error 0x%04x while %s", (unsigned)e, doing);
    return fail(ctx, e == GL_OUT_OF_MEMORY ? SSG_E_NOMEM : SSG_E_BACKEND, msg);
}

static void scene_free(struct ssg_gl_scene **scene)
{
    struct ssg_gl_scene *s = *scene;
    if (!s)
        return;
    for (int b = 0; b < SSG_GL_SCENE_BUFFERS && ssg_gl_alive(); b++)
        if (s->buffer[b] && !(s->borrowed && (b == TEXEL || b == MATERIALS)))
            glDeleteBuffers(1, &s->buffer[b]); /* GL defers it until queued passes end */
    if (s->vao && ssg_gl_alive())
        glDeleteVertexArrays(1, &s->vao);
    if (s->distance && !s->borrowed && ssg_gl_alive())
        glDeleteBuffers(1, &s->distance);
    free(s->mesh);
    free(s->material);
    free(s->texel_at);
    free(s);
    *scene = NULL;
}

/* Uploads scene, or with `base` the proxy view scene of base's scene: then only its
   meshes, the rest borrowed from base. */
static enum ssg_err upload(const struct ssg_node_ctx *ctx, const struct ssg_scene *scene,
                           const struct ssg_gl_scene *base, struct ssg_gl_scene **out)
{
    *out = NULL;
    struct ssg_gl_scene *s = calloc(1, sizeof *s);
    if (s) {
        s->scene = scene;
        if (base) {
            s->view = *scene, s->scene = &s->view, s->borrowed = 1;
            s->buffer[TEXEL] = base->buffer[TEXEL];
            s->buffer[MATERIALS] = base->buffer[MATERIALS];
            s->distance = base->distance;
        }
        s->mesh = calloc((size_t)scene->mesh_count + 1, sizeof *s->mesh);
        s->material = calloc((size_t)scene->material_count + 1, sizeof *s->material);
        s->texel_at = calloc((size_t)scene->texture_count + 1, sizeof *s->texel_at);
    }
    if (!s || !s->mesh || !s->material || !s->texel_at) {
        scene_free(&s);
        return fail(ctx, SSG_E_NOMEM, "out of memory for the scene's GL tables");
    }
    enum ssg_err e = lay_out_meshes(ctx, s);
    if (!e && !base)
        e = lay_out_textures(ctx, s);
    if (!e && !base)
        lay_out_materials(s);
    if (!e)
        e = check_limits(ctx, s);
    if (!e) {
        copy_data(s);
        if (!base)
            copy_distance(s);
        make_vao(s);
        e = ssg_gl_node_status(ctx, "uploading the scene");
    }
    if (e)
        scene_free(&s);
    *out = s;
    return e;
}

void ssg_gl_shared_clear(struct ssg_gl_shared *shared)
{
    for (int i = 0; i < SSG_GL_VIEWS; i++) /* before the scene whose buffers they borrow */
        scene_free(&shared->view[i]);
    scene_free(&shared->scene);
    shared->scene_of = NULL;
}

/* The proxy view's upload (scene/proxy.h), found by its meshes (a level's array is the
   scene's for its life) or made; the oldest of SSG_GL_VIEWS makes room. */
static enum ssg_err view_of(const struct ssg_node_ctx *ctx, struct ssg_gl_shared *sh,
                            const struct ssg_gl_scene **out)
{
    for (int i = 0; i < SSG_GL_VIEWS; i++)
        if (sh->view[i] && sh->view[i]->view.meshes == ctx->scene->meshes) {
            *out = sh->view[i];
            return SSG_OK;
        }
    scene_free(&sh->view[SSG_GL_VIEWS - 1]);
    memmove(&sh->view[1], &sh->view[0], (SSG_GL_VIEWS - 1) * sizeof sh->view[0]);
    sh->view[0] = NULL;
    enum ssg_err e = upload(ctx, ctx->scene, sh->scene, &sh->view[0]);
    *out = sh->view[0];
    return e;
}

/* The executor gives every node a holder (exec.c lends one to a node run alone), so a
   NULL one is a caller bypassing it: an error, not a crash. */
static enum ssg_err scene_of(const struct ssg_node_ctx *ctx, const struct ssg_gl_scene **out)
{
    struct ssg_gl_shared *sh = ctx->gl_shared;
    *out = NULL;
    if (!sh)
        return fail(ctx, SSG_E_BACKEND, "no run holds the GL scene (run the node through "
                    "the executor)");
    if (!ctx->scene)
        return fail(ctx, SSG_E_SCENE, "the GL raster needs a scene");
    const struct ssg_scene *scene = ctx->scene->proxy_of ? ctx->scene->proxy_of : ctx->scene;
    if (sh->scene && sh->scene_of != scene)
        ssg_gl_shared_clear(sh);
    enum ssg_err e = SSG_OK;
    if (!sh->scene) {
        e = upload(ctx, scene, NULL, &sh->scene);
        sh->scene_of = sh->scene ? scene : NULL;
        sh->uploads += sh->scene != NULL;
    }
    *out = sh->scene;
    if (!e && ctx->scene->proxy_of)
        e = view_of(ctx, sh, out);
    return e;
}

const struct ssg_gl_scene *ssg_gl_scene_of(struct ssg_gl_pass *pass)
{
    const struct ssg_gl_scene *s = NULL;
    if (!pass->err)
        pass->err = scene_of(pass->ctx, &s);
    return s;
}

void ssg_gl_scene_bind(struct ssg_gl_pass *pass)
{
    const struct ssg_gl_scene *s = ssg_gl_scene_of(pass);
    for (int b = 0; s && b < SSG_GL_SCENE_BUFFERS; b++)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, (GLuint)(SSG_GL_SCENE_BINDING + b),
                         s->buffer[b]);
}

void ssg_gl_scene_bind_distance(struct ssg_gl_pass *pass, int binding)
{
    const struct ssg_gl_scene *s = ssg_gl_scene_of(pass);
    if (s)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, (GLuint)binding, s->distance);
}

void ssg_gl_scene_draw_meshes(const struct ssg_gl_scene *s, unsigned prog)
{
    GLint mesh_at = glGetUniformLocation(prog, "ssg_mesh");
    glBindVertexArray(s->vao);
    for (int b = 0; b < SSG_GL_SCENE_BUFFERS; b++) /* a mask reads the mesh's material */
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, (GLuint)(SSG_GL_SCENE_BINDING + b),
                         s->buffer[b]);
    for (int i = 0; i < s->scene->mesh_count; i++) {
        const struct ssg_gl_mesh *g = &s->mesh[i];
        int triangles = s->scene->meshes[i].triangle_count;
        if (triangles < 1)
            continue;
        glVertexArrayVertexBuffer(s->vao, 0, s->buffer[VDATA], 4 * (GLintptr)g->positions,
                                  3 * sizeof(float));
        if (g->uvs >= 0) {
            glVertexArrayVertexBuffer(s->vao, 1, s->buffer[VDATA], 4 * (GLintptr)g->uvs,
                                      2 * sizeof(float));
            glEnableVertexArrayAttrib(s->vao, 1);
        } else {
            glDisableVertexArrayAttrib(s->vao, 1); /* reads (0, 0): a mesh without a texture
                                                      has no alpha plane to look up */
        }
        if (mesh_at >= 0)
            glProgramUniform1i(prog, mesh_at, i);
        glDrawElements(GL_TRIANGLES, 3 * triangles, GL_UNSIGNED_INT,
                       (const void *)(4 * (uintptr_t)g->indices));
    }
    glBindVertexArray(0);
}
