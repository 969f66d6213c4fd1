/* gl_program.c - compiling the shader files into programs, once per (file, defines) for
 * the process, and reporting compiler messages against the file and line they are about.
 *
 * A program's text is: #version 450 core, the stage define (SSG_COMPUTE, SSG_VERTEX or
 * SSG_FRAGMENT), the node's defines, core/gl/common.glsl, then the node's file, with #line
 * directives so that the compiler counts lines in the files themselves. Drivers differ in
 * whether they report #line's source-string number (Mesa 22 prints 0), so the parts are
 * told apart by line number instead: the defines start at DEFINES_BASE + 1, common.glsl at
 * COMMON_BASE + 1 and the node's file at 1.
 *
 * A node's file may share code with others through `#include "file.glsl"` lines (for
 * example nodes/common/sampling.glsl, the screen-space sampling of ssao, hbao and ssdo):
 * each is replaced by that shader file's text, numbered from INCLUDE_BASE + 1 (the k-th
 * include from INCLUDE_BASE + k * INCLUDE_STRIDE + 1), and the node's own numbering
 * resumes after it. One level: an included file includes nothing.
 *
 * A node's own file may hold one line `#pragma ssg_params`: it is replaced (on that one
 * line, so line numbers stay the file's) by the declarations of the node's parameters from
 * its descriptor's table: `uniform float p_radius;` for each row not marked host_only
 * (float -> float, int/bool/enum -> int, vec3 -> vec3, mat3 -> float[9], an int list ->
 * int[SSG_INTS_MAX] with its count as `int p_<field>_count`), and for an enum
 * its choices as `const int MODE_HEMISPHERE = 0;` (parameter and choice in capitals). The
 * pass binds their values (gl_pass.c), so a parameter is written once, in C, and read in GLSL by
 * name. Likewise `#pragma ssg_consts` declares the node's constants' table (the
 * descriptor's `uniforms`, rows of what prepare() makes) under their own names, `uniform
 * float rf;`, bound from the consts: a constant is made once, in prepare(), and read by
 * name by both backends. Such a program is the node type's own: the cache keys it by the
 * descriptor too. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl/gl_fn.h"
#include "graph/node.h"
#include "lang/parse.h"
#include "gl/shaders.h"

enum {
    CACHE_MAX = 128,
    COMMON_BASE = 10000,
    DEFINES_BASE = 20000,
    INCLUDE_BASE = 30000,
    INCLUDE_STRIDE = 10000,
    INCLUDES_MAX = 4
};

/* A node's file with its #include lines resolved. */
struct source {
    const char *shader;               /* the node's file name */
    char *text;                       /* what is compiled after common.glsl (malloc'd) */
    char include[INCLUDES_MAX][64];   /* the included files, in order */
    int includes;
};

struct cached {
    char shader[64];
    char *defines;
    int stages;
    int binds;                         /* SSG_GL_BINDS_*: the pragmas of its file */
    const struct ssg_node_desc *owner; /* the node whose tables they declared, else NULL */
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

/* The file and line a compiler's line number is about. */
static const char *line_file(const struct source *src, int *lineno)
{
    if (*lineno > INCLUDE_BASE) {
        int k = (*lineno - INCLUDE_BASE - 1) / INCLUDE_STRIDE;
        *lineno -= INCLUDE_BASE + k * INCLUDE_STRIDE;
        return k < src->includes ? src->include[k] : "include";
    }
    if (*lineno > DEFINES_BASE) {
        *lineno -= DEFINES_BASE;
        return "defines";
    }
    if (*lineno > COMMON_BASE) {
        *lineno -= COMMON_BASE;
        return "common.glsl";
    }
    return src->shader;
}

static void report_log(const struct ssg_node_ctx *ctx, const struct source *src,
                       const char *what, const char *log)
{
    const char *shader = src->shader;
    char line[600];
    int reported = 0;
    for (const char *p = log; *p && reported < 8;) {
        size_t n = strcspn(p, "\n");
        snprintf(line, sizeof line, "%.*s", (int)(n < sizeof line - 1 ? n : sizeof line - 1),
                 p);
        p += n + (p[n] == '\n');
        int string, lineno;
        const char *rest;
        if (!line[0])
            continue;
        if (parse_log_line(line, &string, &lineno, &rest)) {
            const char *file = line_file(src, &lineno);
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

/* 1 when a shader did not compile (is_program 0) or a program did not link (1); its info
   log is then reported against the files and lines of src. */
static int build_failed(const struct ssg_node_ctx *ctx, const struct source *src,
                        GLuint object, int is_program)
{
    GLint ok = 0, len = 0;
    if (is_program)
        glGetProgramiv(object, GL_LINK_STATUS, &ok);
    else
        glGetShaderiv(object, GL_COMPILE_STATUS, &ok);
    if (ok)
        return 0;
    if (is_program)
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &len);
    else
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &len);
    char *log = calloc(1, (size_t)len + 1);
    if (log && is_program)
        glGetProgramInfoLog(object, len, NULL, log);
    else if (log)
        glGetShaderInfoLog(object, len, NULL, log);
    report_log(ctx, src, is_program ? "linking" : "shader", log ? log : "");
    free(log);
    return 1;
}

static GLuint compile_stage(const struct ssg_node_ctx *ctx, GLenum stage,
                            const char *stage_define, const struct source *src,
                            const char *defines)
{
    char head[160];
    snprintf(head, sizeof head, "#version 450 core\n#define %s 1\n#line %d\n", stage_define,
             DEFINES_BASE + 1);
    char common_line[32];
    snprintf(common_line, sizeof common_line, "\n#line %d\n", COMMON_BASE + 1);
    const char *parts[] = {head, defines ? defines : "", common_line,
                           ssg_shader_source("common.glsl"), "\n#line 1\n", src->text};
    GLuint sh = glCreateShader(stage);
    glShaderSource(sh, 6, parts, NULL);
    glCompileShader(sh);
    if (build_failed(ctx, src, sh, 0)) {
        glDeleteShader(sh);
        return 0;
    }
    return sh;
}

static GLuint link_program(const struct ssg_node_ctx *ctx, const struct source *src,
                           GLuint a, GLuint b)
{
    GLuint prog = glCreateProgram();
    glAttachShader(prog, a);
    if (b)
        glAttachShader(prog, b);
    glLinkProgram(prog);
    if (build_failed(ctx, src, prog, 1)) {
        glDeleteProgram(prog);
        prog = 0;
    }
    return prog;
}

/* Appends n bytes of text to *buf (grown by doubling); 0 when out of memory. */
static int append(char **buf, size_t *len, size_t *cap, const char *text, size_t n)
{
    if (*len + n + 1 > *cap) {
        size_t want = (*len + n + 1) * 2;
        char *grown = realloc(*buf, want);
        if (!grown)
            return 0;
        *buf = grown;
        *cap = want;
    }
    memcpy(*buf + *len, text, n);
    *len += n;
    (*buf)[*len] = 0;
    return 1;
}

/* The name in a line `#include "name"` (leading blanks allowed), or 0. */
static int include_name(const char *line, size_t n, char *name, size_t name_len)
{
    size_t i = 0;
    while (i < n && (line[i] == ' ' || line[i] == '\t'))
        i++;
    if (n - i < 10 || strncmp(line + i, "#include", 8) != 0)
        return 0;
    const char *open = memchr(line + i + 8, '"', n - i - 8);
    const char *close = open ? memchr(open + 1, '"', (size_t)(line + n - open - 1)) : NULL;
    if (!close || (size_t)(close - open - 1) >= name_len)
        return 0;
    snprintf(name, name_len, "%.*s", (int)(close - open - 1), open + 1);
    return 1;
}

/* 1 when a line of text is an #include line (comments that mention one are not). */
static int has_include(const char *text)
{
    char name[64];
    for (const char *p = text; *p;) {
        size_t n = strcspn(p, "\n");
        if (include_name(p, n, name, sizeof name))
            return 1;
        p += n + (p[n] == '\n');
    }
    return 0;
}

/* 1 when a line (n bytes, leading blanks allowed) is exactly `pragma`. */
static int is_pragma(const char *line, size_t n, const char *pragma)
{
    while (n && (*line == ' ' || *line == '\t'))
        line++, n--;
    while (n && (line[n - 1] == ' ' || line[n - 1] == '\t' || line[n - 1] == '\r'))
        n--;
    return n == strlen(pragma) && !memcmp(line, pragma, n);
}

/* SSG_GL_BINDS_PARAMS | SSG_GL_BINDS_CONSTS: the tables the shader file declares through
   the pragmas. */
static int declared_tables(const char *text)
{
    int binds = 0;
    for (const char *p = text; *p;) {
        size_t n = strcspn(p, "\n");
        binds |= is_pragma(p, n, "#pragma ssg_params") ? SSG_GL_BINDS_PARAMS : 0;
        binds |= is_pragma(p, n, "#pragma ssg_consts") ? SSG_GL_BINDS_CONSTS : 0;
        p += n + (p[n] == '\n');
    }
    return binds;
}

/* Appends `text` upper-cased, with every character not allowed in a GLSL name as '_'. */
static int append_upper(char **buf, size_t *len, size_t *cap, const char *text)
{
    int ok = 1;
    for (const char *c = text; ok && *c; c++) {
        char u = *c >= 'a' && *c <= 'z' ? (char)(*c - 'a' + 'A') : *c;
        if (!((u >= 'A' && u <= 'Z') || (u >= '0' && u <= '9')))
            u = '_';
        ok = append(buf, len, cap, &u, 1);
    }
    return ok;
}

/* The one line that replaces `#pragma ssg_params` (prefix "p_": the uniforms and enum
   constants of the node's parameter table) or `#pragma ssg_consts` (prefix "": the
   uniforms of its constants' table); see the top of this file. */
static int append_table_block(char **buf, size_t *len, size_t *cap,
                              struct ssg_param_table table, const char *prefix)
{
    char decl[160];
    int ok = 1;
    for (int i = 0; ok && i < table.count; i++) {
        const struct ssg_param_desc *d = &table.params[i];
        const char *type = d->type == SSG_P_FLOAT || d->type == SSG_P_MAT3 ? "float"
                           : d->type == SSG_P_VEC3 ? "vec3"
                           : d->type == SSG_P_INT || d->type == SSG_P_BOOL ||
                                   d->type == SSG_P_ENUM || d->type == SSG_P_INTS ? "int"
                                                                                 : NULL;
        if (!type || d->host_only)
            continue;
        char size[16] = "";
        if (d->type == SSG_P_MAT3 || d->type == SSG_P_INTS)
            snprintf(size, sizeof size, "[%d]", d->type == SSG_P_MAT3 ? 9 : SSG_INTS_MAX);
        snprintf(decl, sizeof decl, "uniform %s %s%s%s; ", type, prefix, d->name, size);
        ok = append(buf, len, cap, decl, strlen(decl));
        if (ok && d->type == SSG_P_INTS) { /* its count, read where the shader needs it */
            snprintf(decl, sizeof decl, "uniform int %s%s_count; ", prefix, d->name);
            ok = append(buf, len, cap, decl, strlen(decl));
        }
        for (int k = 0; ok && d->type == SSG_P_ENUM && d->choices && d->choices[k]; k++) {
            ok = append(buf, len, cap, "const int ", 10) && append_upper(buf, len, cap, d->name) &&
                 append(buf, len, cap, "_", 1) && append_upper(buf, len, cap, d->choices[k]);
            snprintf(decl, sizeof decl, " = %d; ", k);
            ok = ok && append(buf, len, cap, decl, strlen(decl));
        }
    }
    return ok && append(buf, len, cap, "\n", 1);
}

/* src->text: the node's file with each #include line replaced by the file it names, and
   its `#pragma ssg_params` line by the node's parameter declarations. */
static enum ssg_err resolve_includes(const struct ssg_node_ctx *ctx, const char *text,
                                     struct source *src)
{
    char *buf = NULL, name[64], mark[48];
    size_t len = 0, cap = 0;
    int lineno = 1, ok = append(&buf, &len, &cap, "", 0);
    for (const char *p = text; ok && *p; lineno++) {
        size_t n = strcspn(p, "\n");
        const int is_include = include_name(p, n, name, sizeof name);
        const char *body = is_include ? ssg_shader_source(name) : NULL;
        if (is_include &&
            (!body || src->includes == INCLUDES_MAX || has_include(body))) {
            ssg_diag_at(ctx->diags, SSG_E_SHADER, (struct ssg_loc){0},
                        "node '%s': shader %s:%d: cannot include '%s' (%s)", ctx->instance,
                        src->shader, lineno, name,
                        !body ? "no such shader file is compiled into ssgraph"
                        : src->includes == INCLUDES_MAX ? "too many includes"
                                                        : "it includes another file");
            free(buf);
            return SSG_E_SHADER;
        }
        if (is_pragma(p, n, "#pragma ssg_params")) {
            ok = append_table_block(&buf, &len, &cap, ctx->desc->params, "p_");
        } else if (is_pragma(p, n, "#pragma ssg_consts")) {
            ok = append_table_block(&buf, &len, &cap, ctx->desc->uniforms, "");
        } else if (body) {
            snprintf(mark, sizeof mark, "#line %d\n",
                     INCLUDE_BASE + src->includes * INCLUDE_STRIDE + 1);
            snprintf(src->include[src->includes++], sizeof src->include[0], "%s", name);
            ok = append(&buf, &len, &cap, mark, strlen(mark)) &&
                 append(&buf, &len, &cap, body, strlen(body));
            snprintf(mark, sizeof mark, "\n#line %d\n", lineno + 1);
            ok = ok && append(&buf, &len, &cap, mark, strlen(mark));
        } else {
            ok = append(&buf, &len, &cap, p, n + (p[n] == '\n'));
        }
        p += n + (p[n] == '\n');
    }
    if (!ok) {
        free(buf);
        ssg_diag_at(ctx->diags, SSG_E_NOMEM, (struct ssg_loc){0},
                    "node '%s': out of memory for shader %s", ctx->instance, src->shader);
        return SSG_E_NOMEM;
    }
    src->text = buf;
    return SSG_OK;
}

static GLuint build(const struct ssg_node_ctx *ctx, const char *shader, const char *defines,
                    int stages)
{
    const char *text = ssg_shader_source(shader);
    if (!text) {
        ssg_diag_at(ctx->diags, SSG_E_SHADER, (struct ssg_loc){0},
                    "node '%s': no shader file '%s' is compiled into ssgraph", ctx->instance,
                    shader);
        return 0;
    }
    struct source src = {.shader = shader};
    if (resolve_includes(ctx, text, &src))
        return 0;
    GLuint a, b = 0, prog = 0;
    if (stages == SSG_GL_COMPUTE) {
        a = compile_stage(ctx, GL_COMPUTE_SHADER, "SSG_COMPUTE", &src, defines);
    } else {
        a = compile_stage(ctx, GL_VERTEX_SHADER, "SSG_VERTEX", &src, defines);
        b = a ? compile_stage(ctx, GL_FRAGMENT_SHADER, "SSG_FRAGMENT", &src, defines) : 0;
        if (!b && a) {
            glDeleteShader(a);
            a = 0;
        }
    }
    if (a)
        prog = link_program(ctx, &src, a, b);
    if (a)
        glDeleteShader(a);
    if (b)
        glDeleteShader(b);
    free(src.text);
    return prog;
}

GLuint ssg_gl_program_get(const struct ssg_node_ctx *ctx, const char *shader,
                          const char *defines, int stages, int *binds)
{
    const char *d = defines ? defines : "";
    /* A program without pragmas serves every node; one with them only its own. The file
       is read for its pragmas only when it is compiled, never on a hit. */
    for (int i = 0; i < cache_count; i++)
        if (cache[i].stages == stages && !strcmp(cache[i].shader, shader) &&
            !strcmp(cache[i].defines, d) && (!cache[i].binds || cache[i].owner == ctx->desc)) {
            *binds = cache[i].binds;
            return cache[i].program;
        }
    const char *text = ssg_shader_source(shader);
    *binds = text && ctx->desc ? declared_tables(text) : 0;
    GLuint prog = build(ctx, shader, defines, stages);
    if (!prog || cache_count == CACHE_MAX || strlen(shader) >= sizeof cache[0].shader)
        return prog; /* uncached (a rare overflow costs a recompile, never a wrong program) */
    struct cached *c = &cache[cache_count];
    c->defines = strdup(d);
    if (!c->defines)
        return prog;
    snprintf(c->shader, sizeof c->shader, "%s", shader);
    c->stages = stages;
    c->binds = *binds;
    c->owner = *binds ? ctx->desc : NULL;
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
