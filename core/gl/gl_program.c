/* gl_program.c - compiling the shader files into programs, once per (file, defines) for
 * the process, and reporting compiler messages against the file and line they are about.
 *
 * A program's text is: #version 450 core, the stage define (SSG_COMPUTE, SSG_VERTEX or
 * SSG_FRAGMENT), the node's defines, core/gl/common.glsl, then the node's file, with #line
 * directives so that the compiler counts lines in the files themselves. Drivers differ in
 * whether they report #line's source-string number (Mesa 22 prints 0), so the parts are
 * told apart by line number instead: the defines start at DEFINES_BASE + 1, common.glsl at
 * COMMON_BASE + 1 and the node's file at 1. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl/gl_fn.h"
#include "graph/node.h"
#include "lang/parse.h"
#include "gl/shaders.h"

enum { CACHE_MAX = 128, COMMON_BASE = 10000, DEFINES_BASE = 20000 };

struct cached {
    char shader[64];
    char *defines;
    int stages;
    GLuint program;
};
static struct cached cache[CACHE_MAX];
static int cache_count;

/* "2:14(3): error: x" (Mesa) or "2(14) : error C1008: x" (NVIDIA): string, line, rest. */
static int parse_log_line(const char *line, int *string, int *lineno, const char **rest)
{
    char *end;
    long s = strtol(line, &end, 10);
    if (end == line || (*end != ':' && *end != '('))
        return 0;
    const char *p = end + 1;
    long l = strtol(p, &end, 10);
    if (end == p)
        return 0;
    while (*end && *end != ':')
        end++;
    *string = (int)s;
    *lineno = (int)l;
    *rest = *end ? end + 1 : end;
    while (**rest == ' ')
        (*rest)++;
    return 1;
}

static void report_log(const struct ssg_node_ctx *ctx, const char *shader, const char *what,
                       const char *log)
{
    char line[600];
    int reported = 0;
    for (const char *p = log; *p && reported < 8;) {
        size_t n = strcspn(p, "\n");
        snprintf(line, sizeof line, "%.*s", (int)(n < sizeof line - 1 ? n : sizeof line - 1), p);
        p += n + (p[n] == '\n');
        int string, lineno;
        const char *rest;
        if (!line[0])
            continue;
        if (parse_log_line(line, &string, &lineno, &rest)) {
            const char *file = lineno > DEFINES_BASE  ? "defines"
                               : lineno > COMMON_BASE ? "common.glsl"
                                                      : shader;
            lineno -= lineno > DEFINES_BASE ? DEFINES_BASE : lineno > COMMON_BASE ? COMMON_BASE : 0;
            ssg_diag_at(ctx->diags, SSG_E_SHADER, (struct ssg_loc){0},
                        "node '%s': %s %s:%d: %s", ctx->instance, what, file, lineno, rest);
        } else {
            ssg_diag_at(ctx->diags, SSG_E_SHADER, (struct ssg_loc){0}, "node '%s': %s %s: %s",
                        ctx->instance, what, shader, line);
        }
        reported++;
    }
    if (!reported)
        ssg_diag_at(ctx->diags, SSG_E_SHADER, (struct ssg_loc){0},
                    "node '%s': %s %s failed without a message", ctx->instance, what, shader);
}

static GLuint compile_stage(const struct ssg_node_ctx *ctx, GLenum stage, const char *stage_define,
                            const char *shader, const char *source, const char *defines)
{
    char head[160];
    snprintf(head, sizeof head, "#version 450 core\n#define %s 1\n#line %d\n", stage_define,
             DEFINES_BASE + 1);
    char common_line[32];
    snprintf(common_line, sizeof common_line, "\n#line %d\n", COMMON_BASE + 1);
    const char *parts[] = {head, defines ? defines : "", common_line,
                           ssg_shader_source("common.glsl"), "\n#line 1\n", source};
    GLuint sh = glCreateShader(stage);
    glShaderSource(sh, 6, parts, NULL);
    glCompileShader(sh);
    GLint ok = 0, len = 0;
    glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        glGetShaderiv(sh, GL_INFO_LOG_LENGTH, &len);
        char *log = calloc(1, (size_t)len + 1);
        if (log)
            glGetShaderInfoLog(sh, len, NULL, log);
        report_log(ctx, shader, "shader", log ? log : "");
        free(log);
        glDeleteShader(sh);
        return 0;
    }
    return sh;
}

static GLuint link_program(const struct ssg_node_ctx *ctx, const char *shader, GLuint a,
                           GLuint b)
{
    GLuint prog = glCreateProgram();
    glAttachShader(prog, a);
    if (b)
        glAttachShader(prog, b);
    glLinkProgram(prog);
    GLint ok = 0, len = 0;
    glGetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (!ok) {
        glGetProgramiv(prog, GL_INFO_LOG_LENGTH, &len);
        char *log = calloc(1, (size_t)len + 1);
        if (log)
            glGetProgramInfoLog(prog, len, NULL, log);
        report_log(ctx, shader, "linking", log ? log : "");
        free(log);
        glDeleteProgram(prog);
        prog = 0;
    }
    return prog;
}

static GLuint build(const struct ssg_node_ctx *ctx, const char *shader, const char *defines,
                    int stages)
{
    const char *source = ssg_shader_source(shader);
    if (!source) {
        ssg_diag_at(ctx->diags, SSG_E_SHADER, (struct ssg_loc){0},
                    "node '%s': no shader file '%s' is compiled into ssgraph", ctx->instance,
                    shader);
        return 0;
    }
    GLuint a, b = 0, prog = 0;
    if (stages == SSG_GL_COMPUTE) {
        a = compile_stage(ctx, GL_COMPUTE_SHADER, "SSG_COMPUTE", shader, source, defines);
    } else {
        a = compile_stage(ctx, GL_VERTEX_SHADER, "SSG_VERTEX", shader, source, defines);
        b = a ? compile_stage(ctx, GL_FRAGMENT_SHADER, "SSG_FRAGMENT", shader, source, defines)
              : 0;
        if (!b && a) {
            glDeleteShader(a);
            a = 0;
        }
    }
    if (a)
        prog = link_program(ctx, shader, a, b);
    if (a)
        glDeleteShader(a);
    if (b)
        glDeleteShader(b);
    return prog;
}

GLuint ssg_gl_program_get(const struct ssg_node_ctx *ctx, const char *shader,
                          const char *defines, int stages)
{
    const char *d = defines ? defines : "";
    for (int i = 0; i < cache_count; i++)
        if (cache[i].stages == stages && !strcmp(cache[i].shader, shader) &&
            !strcmp(cache[i].defines, d))
            return cache[i].program;
    GLuint prog = build(ctx, shader, defines, stages);
    if (!prog || cache_count == CACHE_MAX || strlen(shader) >= sizeof cache[0].shader)
        return prog; /* uncached (a rare overflow costs a recompile, never a wrong program) */
    struct cached *c = &cache[cache_count];
    c->defines = strdup(d);
    if (!c->defines)
        return prog;
    snprintf(c->shader, sizeof c->shader, "%s", shader);
    c->stages = stages;
    c->program = prog;
    cache_count++;
    return prog;
}

void ssg_gl_programs_free(void)
{
    for (int i = 0; i < cache_count; i++) {
        glDeleteProgram(cache[i].program);
        free(cache[i].defines);
    }
    cache_count = 0;
}
