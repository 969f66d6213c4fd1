/* gl_runtime.c - the GL backend's state for the process: the lock, textures behind images
 * and the transfers between them (gl_backend.h), scratch images and timer queries. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "graph/exec.h"
#include "gl/gl.h"
#include "graph/gl_backend.h"
#include "gl/gl_fn.h"
#include "gl/gl_runtime.h"
#include "graph/image.h"
#include "lang/parse.h"

enum { SCRATCH_MAX = 32 };

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static struct {
    int created;           /* the context exists */
    int failed;            /* creation failed: why holds the cause */
    char why[300];
    char describe[200];
    GLuint zero_texture;   /* 1x1, 4 layers of 0: an unconnected optional input */
    GLuint timer[2];       /* timestamps before and after a node */
    struct ssg_image *scratch[SCRATCH_MAX]; /* released scratch images, for reuse */
    int scratch_count;
} gl;

static void shutdown_gl(void)
{
    pthread_mutex_lock(&lock);
    if (gl.created && ssg_gl_context_bind()) {
        for (int i = 0; i < gl.scratch_count; i++)
            ssg_image_destroy(&gl.scratch[i]);
        ssg_gl_programs_free();
        ssg_gl_buffers_free();
        glDeleteTextures(1, &gl.zero_texture);
        glDeleteQueries(2, gl.timer);
        ssg_gl_context_destroy();
    }
    gl.created = 0;
    pthread_mutex_unlock(&lock);
}

static GLuint new_texture(int width, int height, int layers)
{
    GLuint t = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &t);
    glTextureStorage3D(t, 1, GL_R32F, width, height, layers);
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

static int create(void)
{
    if (!ssg_gl_context_create(gl.why, sizeof gl.why))
        return 0;
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl.zero_texture = new_texture(1, 1, 4);
    const float zero[4] = {0, 0, 0, 0};
    glTextureSubImage3D(gl.zero_texture, 0, 0, 0, 0, 1, 1, 4, GL_RED, GL_FLOAT, zero);
    glCreateQueries(GL_TIMESTAMP, 2, gl.timer);
    snprintf(gl.describe, sizeof gl.describe, "%s: %s", ssg_gl_context_platform(),
             ssg_gl_context_renderer());
    if (glGetError() != GL_NO_ERROR) {
        snprintf(gl.why, sizeof gl.why, "%s failed while setting up", gl.describe);
        ssg_gl_context_destroy();
        return 0;
    }
    atexit(shutdown_gl);
    return 1;
}

enum ssg_err ssg_gl_open(struct ssg_diags *diags)
{
    pthread_mutex_lock(&lock);
    if (!gl.created && !gl.failed) {
        gl.created = create();
        gl.failed = !gl.created;
    }
    if (gl.created && !ssg_gl_context_bind()) {
        snprintf(gl.why, sizeof gl.why, "the GL context could not be made current");
        gl.created = 0;
        gl.failed = 1;
    }
    if (!gl.created) {
        ssg_diag_at(diags, SSG_E_BACKEND, (struct ssg_loc){0},
                    "GL backend unavailable: %s; run with --backend cpu (or backend cpu in "
                    "the graph) to use the CPU backend", gl.why);
        pthread_mutex_unlock(&lock);
        return SSG_E_BACKEND;
    }
    return SSG_OK;
}

void ssg_gl_close(void)
{
    glFinish();
    pthread_mutex_unlock(&lock);
}

int ssg_gl_alive(void)
{
    return gl.created;
}

const char *ssg_gl_describe(void)
{
    return gl.describe;
}

/* ---- images ---- */

/* The record of an image, with a texture of its shape; NULL when out of memory. */
static struct ssg_gl_image *record(const struct ssg_image *image)
{
    struct ssg_image *im = (struct ssg_image *)image; /* the record is a cache, not content */
    if (im->gpu)
        return im->gpu;
    im->gpu = calloc(1, sizeof *im->gpu);
    if (!im->gpu)
        return NULL;
    im->gpu->texture = new_texture(im->width, im->height, im->channels);
    im->gpu->cpu_valid = 1;
    return im->gpu;
}

static enum ssg_err gl_failure(struct ssg_diags *diags, const char *what)
{
    GLenum e = glGetError();
    if (e == GL_NO_ERROR)
        return SSG_OK;
    ssg_diag_at(diags, e == GL_OUT_OF_MEMORY ? SSG_E_NOMEM : SSG_E_BACKEND, (struct ssg_loc){0},
                "GL error 0x%04x while %s (%s)", (unsigned)e, what, gl.describe);
    return e == GL_OUT_OF_MEMORY ? SSG_E_NOMEM : SSG_E_BACKEND;
}

enum ssg_err ssg_gl_to_gpu(const struct ssg_image *image, double *ms, struct ssg_diags *diags)
{
    struct ssg_gl_image *r = record(image);
    if (!r) {
        ssg_diag_at(diags, SSG_E_NOMEM, (struct ssg_loc){0}, "out of memory for a texture");
        return SSG_E_NOMEM;
    }
    if (r->gl_valid)
        return SSG_OK;
    double t0 = ssg_now_ms();
    glTextureSubImage3D(r->texture, 0, 0, 0, 0, image->width, image->height, image->channels,
                        GL_RED, GL_FLOAT, image->data);
    r->gl_valid = 1;
    enum ssg_err e = gl_failure(diags, "uploading an image");
    *ms += ssg_now_ms() - t0;
    return e;
}

enum ssg_err ssg_gl_to_cpu(const struct ssg_image *image, double *ms, struct ssg_diags *diags)
{
    struct ssg_gl_image *r = image->gpu;
    if (!r || r->cpu_valid)
        return SSG_OK;
    double t0 = ssg_now_ms();
    size_t bytes = (size_t)image->width * (size_t)image->height * (size_t)image->channels *
                   sizeof(float);
    glGetTextureImage(r->texture, 0, GL_RED, GL_FLOAT, (GLsizei)bytes, image->data);
    r->cpu_valid = 1;
    enum ssg_err e = gl_failure(diags, "downloading an image");
    *ms += ssg_now_ms() - t0;
    return e;
}

void ssg_gl_mark_written(struct ssg_image *image, int on_gl)
{
    if (!image->gpu)
        return; /* a CPU node wrote a CPU-only image: nothing to track */
    image->gpu->cpu_valid = !on_gl;
    image->gpu->gl_valid = on_gl;
}

void ssg_gl_image_free(struct ssg_image *image)
{
    if (!image->gpu)
        return;
    if (gl.created)
        glDeleteTextures(1, &image->gpu->texture);
    free(image->gpu);
    image->gpu = NULL;
}

unsigned ssg_gl_texture_of(const struct ssg_image *image)
{
    struct ssg_gl_image *r = image ? record(image) : NULL;
    return r ? r->texture : gl.zero_texture;
}

unsigned ssg_gl_zero_texture(void)
{
    return gl.zero_texture;
}

/* ---- scratch images ---- */

struct ssg_image *ssg_gl_scratch(const struct ssg_node_ctx *ctx, int width, int height,
                                 int channels)
{
    for (int i = 0; i < gl.scratch_count; i++) {
        struct ssg_image *s = gl.scratch[i];
        if (s->width == width && s->height == height && s->channels == channels) {
            gl.scratch[i] = gl.scratch[--gl.scratch_count];
            return s;
        }
    }
    struct ssg_image *s = ssg_image_size_ok(width, height, channels) ? calloc(1, sizeof *s)
                                                                      : NULL;
    if (s) {
        s->width = width;
        s->height = height;
        s->channels = channels;
        if (!record(s))
            free(s), s = NULL;
    }
    if (!s || gl_failure(ctx->diags, "creating a scratch image")) {
        if (s)
            ssg_image_destroy(&s);
        ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for a scratch image");
        return NULL;
    }
    s->gpu->cpu_valid = 0;
    return s;
}

void ssg_gl_scratch_release(struct ssg_image **image)
{
    if (!image || !*image)
        return;
    if (gl.scratch_count < SCRATCH_MAX)
        gl.scratch[gl.scratch_count++] = *image;
    else
        ssg_image_destroy(image);
    *image = NULL;
}

/* ---- timers ---- */

/* Timestamps rather than GL_TIME_ELAPSED: llvmpipe answers elapsed-time queries around
 * compute dispatches with garbage, timestamps work on every driver. */
void ssg_gl_timer_begin(void)
{
    glQueryCounter(gl.timer[0], GL_TIMESTAMP);
}

double ssg_gl_timer_end(void)
{
    GLuint64 t0 = 0, t1 = 0;
    glQueryCounter(gl.timer[1], GL_TIMESTAMP);
    glGetQueryObjectui64v(gl.timer[0], GL_QUERY_RESULT, &t0);
    glGetQueryObjectui64v(gl.timer[1], GL_QUERY_RESULT, &t1);
    return t1 > t0 ? (double)(t1 - t0) * 1e-6 : 0.0;
}
