/* params.h - parameter tables: declared once per node (or scene entity) in C, with offsetof
 * into the owner's params struct. The same table parses the graph and scene files, checks
 * ranges, fills defaults, prints `ssgraph describe`, writes the Markdown docs and gives the
 * viewer's sliders their span.
 *
 * Storage of each type inside the params struct:
 *   SSG_P_FLOAT  float          SSG_P_INT   int        SSG_P_BOOL  int (0/1)
 *   SSG_P_ENUM   int (index into .choices)             SSG_P_STRING char[SSG_STR_MAX]
 *   SSG_P_VEC3   float[3]       SSG_P_INTS  struct ssg_ints
 *   SSG_P_NAME   char[SSG_NAME_MAX] (an identifier naming another entity, e.g. a material)
 *   SSG_P_MAT3   float[9], a 3 x 3 matrix row by row: rows of constants only (below),
 *                never parsed from a file
 * Tables are read-only and thread-safe. */
#ifndef SSG_PARAMS_H
#define SSG_PARAMS_H

#include <stddef.h>
#include <stdio.h>

#include "lang/parse.h"
#include "ssgraph.h"

#define SSG_STR_MAX 256
#define SSG_NAME_MAX 64
#define SSG_INTS_MAX 8

/* The magnitude limit of a number parameter declared without a range (min = max = 0):
 * scene coordinates and the like; past it a value is refused as out of range. */
#define SSG_PARAM_ABS_MAX 1e9

enum ssg_param_type {
    SSG_P_FLOAT,
    SSG_P_INT,
    SSG_P_BOOL,
    SSG_P_ENUM,
    SSG_P_STRING,
    SSG_P_VEC3,
    SSG_P_INTS,
    SSG_P_NAME,
    SSG_P_MAT3,
};

struct ssg_ints {
    int count;              /* values used */
    int v[SSG_INTS_MAX];    /* the values */
};

struct ssg_param_desc {
    const char *name;           /* as written in files, e.g. "radius" */
    enum ssg_param_type type;
    size_t offset;              /* offsetof(params struct, field) */
    double def;                 /* default for FLOAT/INT/BOOL/ENUM (ENUM: choice index) */
    double min, max;            /* inclusive range for FLOAT/INT/VEC3 components/INTS values;
                                   min == max == 0 means unbounded */
    double soft_min, soft_max;  /* FLOAT/INT: the useful range (Blender's soft limits): what
                                   a slider spans and a user normally wants, inside min..max
                                   and around the default; a typed value may lie anywhere in
                                   min..max. Every node's number row sets one
                                   (test_param_soft); 0, 0 = none (scene entities) */
    const char *unit;           /* "px", "scene units", "degrees", ... or NULL */
    const char *help;           /* one line */
    const char *const *choices; /* ENUM: NULL-terminated names */
    float def3[3];              /* VEC3 default */
    const char *def_str;        /* STRING/NAME default, NULL = "" */
    int def_ints[SSG_INTS_MAX]; /* INTS default values ... */
    int def_ints_count;         /* ... and how many */
    int min_count, max_count;   /* INTS: allowed number of values (max <= SSG_INTS_MAX) */
    int required;               /* 1 = must be given (no default) */
    int host_only;              /* 1 = read by the node's prepare() or CPU code only: no
                                   GLSL uniform is declared or bound for it (gl.h) */
    const char *gl_if;          /* NULL, or a define of the node's shader (NORMALS): the
                                   shader reads the uniform only in programs compiled with
                                   it nonzero, and the pass requires it there (gl.h) */
    const char *gl_in;          /* NULL, or the node's shader files that read it, space-
                                   separated ("rsm_cells.glsl rsm.glsl"), for a node of
                                   several shaders: the pass requires it only in those, the
                                   others may leave it out (gl.h) */
};

/* The storage of a parameter: its type and its offset in the owner's params struct, e.g.
 *   {.name = "radius", SSG_FIELD_FLOAT(struct ssg_ssao_params, radius), .def = 0.5, ...}
 * Each macro compiles only when the field has the C type its parameter type stores
 * (table above): a table entry that names a field of the wrong type is a compile error
 * ("parameter field has the wrong C type"), never a write of the wrong size at run time.
 * The check is _Generic on a pointer to the field inside a static assertion (the idea of
 * libplacebo's option tables); it costs nothing at run time. */
#define SSG_FIELD_OFFSET(owner, field, field_ptr_type)                                     \
    (offsetof(owner, field) +                                                            \
     0 * sizeof(struct {                                                                 \
         _Static_assert(_Generic(&((owner *)0)->field, field_ptr_type: 1, default: 0),   \
                        "parameter field has the wrong C type");                         \
         int checked;                                                                    \
     }))
#define SSG_FIELD_FLOAT(owner, field) \
    .type = SSG_P_FLOAT, .offset = SSG_FIELD_OFFSET(owner, field, float *)
#define SSG_FIELD_INT(owner, field) \
    .type = SSG_P_INT, .offset = SSG_FIELD_OFFSET(owner, field, int *)
#define SSG_FIELD_BOOL(owner, field) \
    .type = SSG_P_BOOL, .offset = SSG_FIELD_OFFSET(owner, field, int *)
#define SSG_FIELD_ENUM(owner, field) \
    .type = SSG_P_ENUM, .offset = SSG_FIELD_OFFSET(owner, field, int *)
#define SSG_FIELD_STRING(owner, field) \
    .type = SSG_P_STRING, .offset = SSG_FIELD_OFFSET(owner, field, char(*)[SSG_STR_MAX])
#define SSG_FIELD_NAME(owner, field) \
    .type = SSG_P_NAME, .offset = SSG_FIELD_OFFSET(owner, field, char(*)[SSG_NAME_MAX])
#define SSG_FIELD_VEC3(owner, field) \
    .type = SSG_P_VEC3, .offset = SSG_FIELD_OFFSET(owner, field, float(*)[3])
#define SSG_FIELD_INTS(owner, field) \
    .type = SSG_P_INTS, .offset = SSG_FIELD_OFFSET(owner, field, struct ssg_ints *)
#define SSG_FIELD_MAT3(owner, field) \
    .type = SSG_P_MAT3, .offset = SSG_FIELD_OFFSET(owner, field, float(*)[9])

/* One-line parameter rows (the idea of libplacebo's OPT_* rows). A node writes each
 * parameter once, as one row of a list macro: its kind (the SSG_P_* suffix), its field,
 * its one-line doc, then the rest of its entry as designated initialisers (default, range,
 * useful range, unit, choices, host_only):
 *   #define SSG_SSAO_PARAMS(P)                                                        \
 *       P(FLOAT, radius, "hemisphere radius around the pixel", .def = 0.5,            \
 *         .min = 1e-6, .max = 1e6, .soft_min = 0.05, .soft_max = 5,                   \
 *         .unit = "scene units")                                                      \
 *       P(ENUM, mode, "sampling region", .def = 0, .choices = ssg_ssao_mode_choices)
 *   SSG_PARAMS_STRUCT(ssg_ssao_params, SSG_SSAO_PARAMS);          (in the node's header)
 *   SSG_PARAMS_TABLE(params, ssg_ssao_params, SSG_SSAO_PARAMS);   (in its descriptor file)
 * The struct gets one field a row, of the C type its kind stores (table above), and the
 * table one entry a row, type-checked as SSG_FIELD_* checks it. A number row (FLOAT, INT)
 * gives both ranges: min..max is what is valid (parsing refuses the rest), soft_min..soft_max
 * what is useful, for the viewer's slider and the docs (where min..max is itself useful,
 * such as 0..1, the soft range repeats it). A row needs at least one
 * initialiser after the doc (ISO C wants an argument for `...`). One generated table a
 * translation unit (the table names its struct through one file-scope typedef). A GL
 * shader reads every row not marked host_only as `p_<field>` (gl.h, #pragma ssg_params). */
#define SSG_PARAM_DECL_FLOAT(f) float f
#define SSG_PARAM_DECL_INT(f) int f
#define SSG_PARAM_DECL_BOOL(f) int f
#define SSG_PARAM_DECL_ENUM(f) int f
#define SSG_PARAM_DECL_STRING(f) char f[SSG_STR_MAX]
#define SSG_PARAM_DECL_NAME(f) char f[SSG_NAME_MAX]
#define SSG_PARAM_DECL_VEC3(f) float f[3]
#define SSG_PARAM_DECL_INTS(f) struct ssg_ints f
#define SSG_PARAM_DECL_MAT3(f) float f[9]
#define SSG_PARAM_AS_FIELD(kind, field, doc, ...) SSG_PARAM_DECL_##kind(field);
#define SSG_PARAM_AS_ROW(kind, field, doc, ...) \
    {.name = #field, SSG_FIELD_##kind(ssg_params_owner, field), .help = doc, __VA_ARGS__},
#define SSG_PARAMS_STRUCT(tag, LIST) struct tag { LIST(SSG_PARAM_AS_FIELD) }
#define SSG_PARAMS_TABLE(var, tag, LIST)  \
    typedef struct tag ssg_params_owner; \
    static const struct ssg_param_desc var[] = {LIST(SSG_PARAM_AS_ROW)}

/* Rows of constants, the same way: what a node's prepare() makes from its parameters and
 * shapes for both backends (1 / f, R^2, a cap), one row each: kind FLOAT, INT, BOOL, VEC3,
 * MAT3 (float[9], read as `float name[9]`) or PROJECTION (struct ssg_projection, read as
 * `vec3 name` = (f, cx, cy); graph/node.h), field, doc, then any further initialisers
 * (.gl_if):
 *   #define SSG_HBAO_UNIFORMS(U) U(FLOAT, rf, "f R") U(FLOAT, r2, "R^2")
 *   SSG_UNIFORMS_STRUCT(ssg_hbao_uniforms, SSG_HBAO_UNIFORMS);        (the struct)
 *   SSG_UNIFORMS_TABLE(uniforms, ssg_hbao_uniforms, SSG_HBAO_UNIFORMS); (the table)
 * The struct is a member of the node's consts (SSG_NODE_UNIFORMS in graph/node.h), and a
 * shader with `#pragma ssg_consts` reads each row as a uniform of its own name. (The doc
 * opens the variadic part, so a row of three arguments is ISO C.) */
#define SSG_UNIFORM_AS_FIELD(kind, field, ...) SSG_PARAM_DECL_##kind(field);
#define SSG_UNIFORM_AS_ROW(kind, field, ...) \
    {.name = #field, SSG_FIELD_##kind(ssg_uniforms_owner, field), .help = __VA_ARGS__},
#define SSG_UNIFORMS_STRUCT(tag, LIST) struct tag { LIST(SSG_UNIFORM_AS_FIELD) }
#define SSG_UNIFORMS_TABLE(var, tag, LIST) \
    typedef struct tag ssg_uniforms_owner; \
    static const struct ssg_param_desc var[] = {LIST(SSG_UNIFORM_AS_ROW)}

/* Rows of constants that the consts already keep, at a path inside them (a nested member,
 * a field the CPU reads under another name): kind, the GLSL name, the path, doc, then any
 * further initialisers:
 *   #define SSG_RSM_UNIFORMS(U) U(INT, ncells, cells, "cells per face side")
 *   SSG_UNIFORMS_AT_TABLE(uniforms, ssg_rsm_consts, SSG_RSM_UNIFORMS);
 * with the descriptor's `.uniforms = SSG_TABLE(uniforms)` and uniforms_offset 0 (the
 * paths are the consts' own). Type-checked as SSG_FIELD_* checks a row. */
#define SSG_UNIFORM_AT_ROW(kind, glsl_name, path, ...) \
    {.name = #glsl_name, SSG_FIELD_##kind(ssg_uniforms_owner, path), .help = __VA_ARGS__},
#define SSG_UNIFORMS_AT_TABLE(var, tag, LIST) \
    typedef struct tag ssg_uniforms_owner; \
    static const struct ssg_param_desc var[] = {LIST(SSG_UNIFORM_AT_ROW)}

/* A table and its length, so callers pass one thing. */
struct ssg_param_table {
    const struct ssg_param_desc *params;
    int count;
};
#define SSG_TABLE(arr) {(arr), (int)(sizeof(arr) / sizeof((arr)[0]))}

/* Index of the named parameter, or -1. */
int ssg_param_find(struct ssg_param_table table, const char *name, size_t name_len);

/* Writes every default into the params struct (zeroes it first). */
void ssg_params_defaults(struct ssg_param_table table, void *params);

/* Parses `value` into parameter `index` of params, checking type and range. On failure
 * reports (code SSG_E_TYPE, SSG_E_RANGE or SSG_E_VALUE) at the value's location with what
 * was expected, and returns that code. `owner` names the node or entity in messages. */
enum ssg_err ssg_param_set(struct ssg_param_table table, int index, void *params,
                           const struct ssg_value *value, const char *owner,
                           struct ssg_diags *diags);

/* Parses a "param=value" string (command line) with the same lexer and rules; locations
 * in messages are columns in `text`, file `origin`. */
enum ssg_err ssg_param_set_text(struct ssg_param_table table, void *params, const char *text,
                                const char *origin, const char *owner, struct ssg_diags *diags);

/* Comma-separated list of parameter names ("radius, bias, samples") for messages. */
void ssg_param_names(struct ssg_param_table table, char *buf, size_t len);

/* 1 when p is a number with a useful range (soft_min < soft_max), else 0. */
int ssg_param_has_soft(const struct ssg_param_desc *p);

/* Prints one parameter line for `describe`: name, type, default, range, unit, useful range
 * (the slider's), help. */
void ssg_param_describe(const struct ssg_param_desc *p, FILE *stream);
/* Same as a Markdown table row. */
void ssg_param_markdown(const struct ssg_param_desc *p, FILE *stream);
/* The type as `describe` names it: "float", "int", "bool", "enum", "string", ... */
const char *ssg_param_type_name(const struct ssg_param_desc *p);
/* Formats the current value of parameter p in params as it would be written in a file. */
void ssg_param_format(const struct ssg_param_desc *p, const void *params, char *buf,
                      size_t len);

#endif
