/* gl_pass.c - compute passes for the nodes' GL sides (gl.h): a program, its images and
 * uniforms, and dispatches. Errors are sticky per pass (see gl.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl/gl.h"
#include "gl/gl_fn.h"
#include "gl/gl_runtime.h"
#include "lang/parse.h"

enum { MAX_BUFFERS = 8 };
static GLuint buffers[MAX_BUFFERS]; /* one storage buffer per binding, reused */

static int usable(const struct ssg_gl_pass *p)
{
    return p->err == SSG_OK && p->program != 0;
}

/* The location of an optional uniform (`<input>_bound`, ssg_grid): -1 when the shader
   does not use it. */
static GLint where_optional(const struct ssg_gl_pass *p, const char *name)
{
    return usable(p) ? glGetUniformLocation(p->program, name) : -1;
}

/* The location of a uniform the node binds by name. A name the program lacks is an error
   of the pass, never a silent skip: a renamed or misspelled uniform would otherwise leave
   the shader reading zeros. GLSL compilers drop uniforms nothing reads, so a declared but
   unused one is refused the same way (bind only what the shader reads). */
static GLint where(struct ssg_gl_pass *p, const char *name)
{
    GLint loc = where_optional(p, name);
    if (loc < 0 && usable(p))
        p->err = ssg_node_fail(p->ctx, SSG_E_SHADER,
                               "shader %s has no active uniform '%s' (not declared, or "
                               "declared and unused: the compiler dropped it)",
                               p->shader, name);
    return loc;
}

/* 1 when the pass's program was compiled with `name` defined nonzero (a `#define NAME
   value` line of its defines, or one without a value), as GLSL's `#if NAME` reads it. */
static int define_on(const struct ssg_gl_pass *p, const char *name)
{
    size_t n = strlen(name);
    for (const char *d = p->defines; d && (d = strstr(d, "#define ")); d += 8) {
        const char *at = d + 8;
        if (strncmp(at, name, n) != 0 || (at[n] != ' ' && at[n] != '\n' && at[n] != 0))
            continue;
        char *end;
        long v = strtol(at + n, &end, 0);
        return end == at + n || v != 0;
    }
    return 0;
}

/* 1 when the pass's shader file is one of `files` (space-separated names). */
static int shader_in(const struct ssg_gl_pass *p, const char *files)
{
    size_t n = strlen(p->shader);
    for (const char *f = files; *f; f += strcspn(f, " "), f += strspn(f, " "))
        if (strncmp(f, p->shader, n) == 0 && (f[n] == ' ' || f[n] == 0))
            return 1;
    return 0;
}

/* 1 when the program must read a row or port marked gl_if (NULL: always) and gl_in (NULL:
   every shader of the node); one compiled without that define (a variant that does not
   need it), or another shader of the node, may leave it out. */
static int required(const struct ssg_gl_pass *p, const char *gl_if, const char *gl_in)
{
    return (!gl_if || define_on(p, gl_if)) && (!gl_in || shader_in(p, gl_in));
}

/* An INTS row: its SSG_INTS_MAX values into `int <name>[]`, and the count into
   `<name>_count` where the shader reads it. */
static void bind_ints(struct ssg_gl_pass *p, GLint loc, const char *name,
                      const struct ssg_ints *v)
{
    char count[104];
    snprintf(count, sizeof count, "%s_count", name);
    GLint count_loc = where_optional(p, count);
    glProgramUniform1iv(p->program, loc, SSG_INTS_MAX, v->v);
    if (count_loc >= 0)
        glProgramUniform1i(p->program, count_loc, v->count);
}

/* Sets every uniform a table declared in the program (gl_program.c) from the struct at
   `base`: the parameters (#pragma ssg_params, names p_<field>, from ctx->params) or the
   constants (#pragma ssg_consts, names <field>, from the consts' uniforms member). */
static void bind_table(struct ssg_gl_pass *p, struct ssg_param_table table, const void *base,
                       const char *prefix, const char *pragma)
{
    if (!base) {
        p->err = ssg_node_fail(p->ctx, SSG_E_BACKEND, "shader %s has #pragma %s but the "
                               "pass has no values for it (run the node through the "
                               "executor, which sets ctx->params and ctx->consts)",
                               p->shader, pragma);
        return;
    }
    char name[96];
    for (int i = 0; i < table.count && usable(p); i++) {
        const struct ssg_param_desc *d = &table.params[i];
        const void *at = (const char *)base + d->offset;
        int is_int = d->type == SSG_P_INT || d->type == SSG_P_BOOL || d->type == SSG_P_ENUM;
        if (d->host_only || (!is_int && d->type != SSG_P_FLOAT && d->type != SSG_P_VEC3 &&
                             d->type != SSG_P_MAT3 && d->type != SSG_P_INTS))
            continue;
        snprintf(name, sizeof name, "%s%s", prefix, d->name);
        GLint loc = where_optional(p, name);
        if (loc < 0 && !required(p, d->gl_if, d->gl_in))
            continue;
        if (loc < 0) {
            p->err = ssg_node_fail(p->ctx, SSG_E_SHADER, "shader %s declares %s '%s' "
                                   "(#pragma %s) but does not read it: read it as %s, or "
                                   "mark its row host_only when only prepare() or the "
                                   "CPU kernel needs it", p->shader,
                                   *prefix ? "parameter" : "constant", d->name, pragma,
                                   name);
        } else if (is_int) {
            glProgramUniform1i(p->program, loc, *(const int *)at);
        } else if (d->type == SSG_P_FLOAT) {
            glProgramUniform1f(p->program, loc, *(const float *)at);
        } else if (d->type == SSG_P_MAT3) {
            glProgramUniform1fv(p->program, loc, 9, at);
        } else if (d->type == SSG_P_INTS) {
            bind_ints(p, loc, name, at);
        } else {
            const float *v = at;
            glProgramUniform3f(p->program, loc, v[0], v[1], v[2]);
        }
    }
}

enum ssg_err ssg_gl_pass_open(struct ssg_gl_pass *pass, const struct ssg_node_ctx *ctx,
                              const char *shader, const char *defines, int stages)
{
    memset(pass, 0, sizeof *pass);
    pass->ctx = ctx;
    pass->shader = shader;
    pass->defines = defines;
    int binds = 0;
    pass->program = ssg_gl_program_get(ctx, shader, defines, stages, &binds);
    if (!pass->program) {
        pass->err = SSG_E_SHADER;
        return pass->err;
    }
    if (binds & SSG_GL_BINDS_PARAMS)
        bind_table(pass, ctx->desc->params, ctx->params, "p_", "ssg_params");
    const char *consts = ctx->consts;
    if (binds & SSG_GL_BINDS_CONSTS)
        bind_table(pass, ctx->desc->uniforms, consts ? consts + ctx->desc->uniforms_offset : NULL,
                   "", "ssg_consts");
    return pass->err;
}

enum ssg_err ssg_gl_pass_begin(struct ssg_gl_pass *pass, const struct ssg_node_ctx *ctx,
                               const char *shader, const char *defines)
{
    if (ssg_gl_pass_open(pass, ctx, shader, defines, SSG_GL_COMPUTE) == SSG_OK)
        glUseProgram(pass->program);
    return pass->err;
}

void ssg_gl_input(struct ssg_gl_pass *pass, const char *name, const struct ssg_image *image)
{
    GLint loc = where(pass, name);
    char bound[96];
    snprintf(bound, sizeof bound, "%s_bound", name);
    GLint bound_loc = where_optional(pass, bound);
    if (bound_loc >= 0)
        glProgramUniform1i(pass->program, bound_loc, image != NULL);
    if (loc < 0)
        return;
    int unit = pass->next_unit++;
    glBindTextureUnit((GLuint)unit, image ? ssg_gl_texture_of(image) : ssg_gl_zero_texture());
    glProgramUniform1i(pass->program, loc, unit);
}

void ssg_gl_output(struct ssg_gl_pass *pass, const char *name, struct ssg_image *image)
{
    GLint loc = where(pass, name);
    if (loc < 0 || !image)
        return;
    int unit = pass->next_image++;
    glBindImageTexture((GLuint)unit, ssg_gl_texture_of(image), 0, GL_TRUE, 0, GL_READ_WRITE,
                       GL_R32F);
    glProgramUniform1i(pass->program, loc, unit);
}

/* Binds one port as ssg_gl_input or ssg_gl_output would; a port marked gl_if or gl_in
   that this program variant or shader does not read is left out. */
static void bind_port(struct ssg_gl_pass *pass, const struct ssg_port_desc *port,
                      const char *name, const struct ssg_image *in, struct ssg_image *out)
{
    if (!required(pass, port->gl_if, port->gl_in) && where_optional(pass, name) < 0)
        return;
    if (out)
        ssg_gl_output(pass, name, out);
    else
        ssg_gl_input(pass, name, in);
}

/* An on_demand output nobody reads (node.h: no image) whose store the shader still makes:
   a scratch image of the port's shape takes the stores, which an unbound image uniform
   would send to unit 0, another output's image. One the shader leaves out (gl_if) needs
   none. Freed by ssg_gl_pass_end. */
static void bind_unread(struct ssg_gl_pass *pass, int k, const char *name)
{
    const struct ssg_shape *s = &pass->ctx->out_shape[k];
    if (where_optional(pass, name) < 0 || pass->err)
        return;
    struct ssg_image *im = NULL;
    if (pass->unread_count < SSG_COUNT(pass->unread))
        im = ssg_gl_scratch(pass->ctx, s->width, s->height, s->channels);
    if (!im) {
        pass->err = ssg_node_fail(pass->ctx, SSG_E_NOMEM, "out of memory for output %s",
                                  name);
        return;
    }
    pass->unread[pass->unread_count++] = im;
    ssg_gl_output(pass, name, im);
}

void ssg_gl_ports(struct ssg_gl_pass *pass, const struct ssg_io *io)
{
    const struct ssg_node_desc *d = pass->ctx->desc;
    char name[96];
    for (int i = 0; i < d->input_count; i++) {
        const struct ssg_port_desc *in = &d->inputs[i];
        bind_port(pass, in, in->gl_name ? in->gl_name : in->name, io->in[i], NULL);
    }
    for (int i = 0; i < d->output_count; i++) {
        snprintf(name, sizeof name, "dst_%s", d->outputs[i].name);
        if (io->out[i])
            bind_port(pass, &d->outputs[i], name, NULL, io->out[i]);
        else
            bind_unread(pass, i, name);
    }
}

void ssg_gl_int(struct ssg_gl_pass *pass, const char *name, int value)
{
    GLint loc = where(pass, name);
    if (loc >= 0)
        glProgramUniform1i(pass->program, loc, value);
}

void ssg_gl_ivec2(struct ssg_gl_pass *pass, const char *name, int x, int y)
{
    GLint loc = where(pass, name);
    if (loc >= 0)
        glProgramUniform2i(pass->program, loc, x, y);
}

void ssg_gl_float(struct ssg_gl_pass *pass, const char *name, float value)
{
    GLint loc = where(pass, name);
    if (loc >= 0)
        glProgramUniform1f(pass->program, loc, value);
}

void ssg_gl_vec2(struct ssg_gl_pass *pass, const char *name, float x, float y)
{
    GLint loc = where(pass, name);
    if (loc >= 0)
        glProgramUniform2f(pass->program, loc, x, y);
}

void ssg_gl_vec3(struct ssg_gl_pass *pass, const char *name, const float v[3])
{
    GLint loc = where(pass, name);
    if (loc >= 0)
        glProgramUniform3f(pass->program, loc, v[0], v[1], v[2]);
}

void ssg_gl_vec4(struct ssg_gl_pass *pass, const char *name, const float v[4])
{
    GLint loc = where(pass, name);
    if (loc >= 0)
        glProgramUniform4f(pass->program, loc, v[0], v[1], v[2], v[3]);
}

void ssg_gl_floats(struct ssg_gl_pass *pass, const char *name, int count, const float *v)
{
    GLint loc = where(pass, name);
    if (loc >= 0 && count > 0)
        glProgramUniform1fv(pass->program, loc, count, v);
}

void ssg_gl_ints(struct ssg_gl_pass *pass, const char *name, int count, const int *v)
{
    GLint loc = where(pass, name);
    if (loc >= 0 && count > 0)
        glProgramUniform1iv(pass->program, loc, count, v);
}

void ssg_gl_projection(struct ssg_gl_pass *pass, const char *name,
                       const struct ssg_projection *p)
{
    const float v[3] = {p->f, p->cx, p->cy};
    ssg_gl_vec3(pass, name, v);
}

void ssg_gl_buffer(struct ssg_gl_pass *pass, int binding, const void *data, size_t bytes)
{
    if (!usable(pass))
        return;
    if (binding < 0 || binding >= MAX_BUFFERS) {
        pass->err = ssg_node_fail(pass->ctx, SSG_E_BACKEND, "storage buffer binding "
                                  "out of range (0 to 7)");
        return;
    }
    if (!buffers[binding])
        glCreateBuffers(1, &buffers[binding]);
    glNamedBufferData(buffers[binding], (GLsizeiptr)(bytes ? bytes : 4), data, GL_STREAM_DRAW);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, (GLuint)binding, buffers[binding]);
}

void ssg_gl_dispatch(struct ssg_gl_pass *pass, int width, int height)
{
    GLint loc = where_optional(pass, "ssg_grid");
    if (!usable(pass) || width < 1 || height < 1)
        return;
    if (loc >= 0)
        glProgramUniform2i(pass->program, loc, width, height);
    glDispatchCompute((GLuint)((width + SSG_GL_GROUP - 1) / SSG_GL_GROUP),
                      (GLuint)((height + SSG_GL_GROUP - 1) / SSG_GL_GROUP), 1);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

enum ssg_err ssg_gl_fill(const struct ssg_node_ctx *ctx, const float *const *planes,
                         struct ssg_image *const *dst, int count)
{
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "copy_planes.glsl", NULL);
    for (int i = 0; i < count; i++) {
        size_t texels = (size_t)dst[i]->width * (size_t)dst[i]->height *
                        (size_t)dst[i]->channels;
        ssg_gl_buffer(&p, 0, planes[i], texels * sizeof(float));
        ssg_gl_output(&p, "dst", dst[i]);
        ssg_gl_int(&p, "channels", dst[i]->channels);
        ssg_gl_dispatch(&p, dst[i]->width, dst[i]->height);
    }
    return ssg_gl_pass_end(&p);
}

enum ssg_err ssg_gl_pass_end(struct ssg_gl_pass *pass)
{
    for (int k = 0; k < pass->unread_count; k++)
        ssg_gl_scratch_release(&pass->unread[k]);
    pass->unread_count = 0;
    GLenum e = glGetError();
    if (e != GL_NO_ERROR && pass->err == SSG_OK) {
        pass->err = ssg_node_fail(pass->ctx, e == GL_OUT_OF_MEMORY ? SSG_E_NOMEM : SSG_E_BACKEND,
                                  "GL error 0x%04x in a pass of %s", (unsigned)e,
                                  pass->shader ? pass->shader : "?");
    }
    return pass->err;
}

void ssg_gl_buffers_free(void)
{
    glDeleteBuffers(MAX_BUFFERS, buffers);
    memset(buffers, 0, sizeof buffers);
}
