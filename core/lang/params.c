/* params.c - parsing, checking, defaults and documentation of parameter tables (params.h).
 * One table per node or scene entity drives all of these, so a parameter is declared once. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "lang/params.h"

#define FIELD(params, p, type) ((type *)((char *)(params) + (p)->offset))
#define CFIELD(params, p, type) ((const type *)((const char *)(params) + (p)->offset))

int ssg_param_find(struct ssg_param_table table, const char *name, size_t name_len)
{
    for (int i = 0; i < table.count; i++)
        if (ssg_tok_eq(name, name_len, table.params[i].name))
            return i;
    return -1;
}

static int bounded(const struct ssg_param_desc *p)
{
    return !(p->min == 0 && p->max == 0);
}

/* The range a number must lie in: its own, or for a parameter declared without one
   (coordinates, offsets) +-SSG_PARAM_ABS_MAX: a float must hold it, and so must its
   square, or ray tracing and projection overflow (a camera at 3e38 crashed Embree). */
static double lowest(const struct ssg_param_desc *p)
{
    return bounded(p) ? p->min : -SSG_PARAM_ABS_MAX;
}

static double highest(const struct ssg_param_desc *p)
{
    return bounded(p) ? p->max : SSG_PARAM_ABS_MAX;
}

void ssg_params_defaults(struct ssg_param_table table, void *params)
{
    for (int i = 0; i < table.count; i++) {
        const struct ssg_param_desc *p = &table.params[i];
        switch (p->type) {
        case SSG_P_FLOAT: *FIELD(params, p, float) = (float)p->def; break;
        case SSG_P_INT:
        case SSG_P_BOOL:
        case SSG_P_ENUM: *FIELD(params, p, int) = (int)p->def; break;
        case SSG_P_STRING:
            snprintf(FIELD(params, p, char), SSG_STR_MAX, "%s", p->def_str ? p->def_str : "");
            break;
        case SSG_P_NAME:
            snprintf(FIELD(params, p, char), SSG_NAME_MAX, "%s", p->def_str ? p->def_str : "");
            break;
        case SSG_P_VEC3: memcpy(FIELD(params, p, float), p->def3, 3 * sizeof(float)); break;
        case SSG_P_MAT3: memset(FIELD(params, p, float), 0, 9 * sizeof(float)); break;
        case SSG_P_INTS: {
            struct ssg_ints *v = FIELD(params, p, struct ssg_ints);
            v->count = p->def_ints_count;
            memcpy(v->v, p->def_ints, sizeof v->v);
            break;
        }
        }
    }
}

/* "a number in [0, 10] px" and the like: what the parameter expects, for messages. */
static void expected_text(const struct ssg_param_desc *p, char *buf, size_t len)
{
    char range[96];
    snprintf(range, sizeof range, " in [%g, %g]", lowest(p), highest(p));
    const char *unit = p->unit ? p->unit : "";
    const char *sp = p->unit ? " " : "";
    switch (p->type) {
    case SSG_P_FLOAT: snprintf(buf, len, "a number%s%s%s", range, sp, unit); break;
    case SSG_P_INT: snprintf(buf, len, "an integer%s%s%s", range, sp, unit); break;
    case SSG_P_BOOL: snprintf(buf, len, "true or false"); break;
    case SSG_P_ENUM: {
        size_t n = (size_t)snprintf(buf, len, "one of: ");
        for (int i = 0; p->choices[i] && n < len; i++)
            n += (size_t)snprintf(buf + n, len - n, "%s%s", i ? ", " : "", p->choices[i]);
        break;
    }
    case SSG_P_STRING: snprintf(buf, len, "a string"); break;
    case SSG_P_NAME: snprintf(buf, len, "a name"); break;
    case SSG_P_VEC3: snprintf(buf, len, "a list of 3 numbers%s%s%s", range, sp, unit); break;
    case SSG_P_MAT3: snprintf(buf, len, "a 3 x 3 matrix (made by prepare())"); break;
    case SSG_P_INTS:
        snprintf(buf, len, "a list of %d to %d integers%s", p->min_count, p->max_count, range);
        break;
    }
}

static enum ssg_err bad_value(const struct ssg_param_desc *p, const struct ssg_value *v,
                              enum ssg_err code, const char *owner, const char *got,
                              struct ssg_diags *diags)
{
    char expected[256];
    expected_text(p, expected, sizeof expected);
    ssg_diag_at(diags, code, v->loc, "parameter '%s' of '%s' expects %s, got %s", p->name,
                owner, expected, got);
    return code;
}

static enum ssg_err wrong_kind(const struct ssg_param_desc *p, const struct ssg_value *v,
                               const char *owner, struct ssg_diags *diags)
{
    return bad_value(p, v, SSG_E_TYPE, owner, ssg_value_kind_text(v->kind), diags);
}

static enum ssg_err check_number(const struct ssg_param_desc *p, const struct ssg_value *v,
                                 int want_integer, const char *owner, struct ssg_diags *diags)
{
    char got[64];
    if (v->kind != SSG_V_NUMBER)
        return wrong_kind(p, v, owner, diags);
    if (want_integer && !v->is_integer) {
        snprintf(got, sizeof got, "%g", v->number);
        return bad_value(p, v, SSG_E_TYPE, owner, got, diags);
    }
    if (!isfinite(v->number) || v->number < lowest(p) || v->number > highest(p) ||
        (want_integer && fabs(v->number) > 2e9)) {
        snprintf(got, sizeof got, "%g", v->number);
        return bad_value(p, v, SSG_E_RANGE, owner, got, diags);
    }
    return SSG_OK;
}

static enum ssg_err set_bool(const struct ssg_param_desc *p, int *out,
                             const struct ssg_value *v, const char *owner,
                             struct ssg_diags *diags)
{
    if (v->kind == SSG_V_IDENT && (ssg_tok_eq(v->text, v->len, "true") ||
                                   ssg_tok_eq(v->text, v->len, "on"))) {
        *out = 1;
    } else if (v->kind == SSG_V_IDENT && (ssg_tok_eq(v->text, v->len, "false") ||
                                          ssg_tok_eq(v->text, v->len, "off"))) {
        *out = 0;
    } else if (v->kind == SSG_V_NUMBER && (v->number == 0 || v->number == 1)) {
        *out = (int)v->number;
    } else {
        return wrong_kind(p, v, owner, diags);
    }
    return SSG_OK;
}

static enum ssg_err set_enum(const struct ssg_param_desc *p, int *out,
                             const struct ssg_value *v, const char *owner,
                             struct ssg_diags *diags)
{
    if (v->kind != SSG_V_IDENT && v->kind != SSG_V_STRING)
        return wrong_kind(p, v, owner, diags);
    for (int i = 0; p->choices[i]; i++) {
        if (ssg_tok_eq(v->text, v->len, p->choices[i])) {
            *out = i;
            return SSG_OK;
        }
    }
    char got[96];
    snprintf(got, sizeof got, "'%.*s'", (int)(v->len < 64 ? v->len : 64), v->text);
    return bad_value(p, v, SSG_E_VALUE, owner, got, diags);
}

static enum ssg_err set_text(const struct ssg_param_desc *p, char *out, size_t cap,
                             const struct ssg_value *v, enum ssg_value_kind want,
                             const char *owner, struct ssg_diags *diags)
{
    if (v->kind != want)
        return wrong_kind(p, v, owner, diags);
    if (v->len >= cap) {
        ssg_diag_at(diags, SSG_E_RANGE, v->loc, "parameter '%s' of '%s' is too long "
                    "(%zu bytes; at most %zu)", p->name, owner, v->len, cap - 1);
        return SSG_E_RANGE;
    }
    memcpy(out, v->text, v->len);
    out[v->len] = 0;
    return SSG_OK;
}

/* A single number is accepted for a vector and used for all three components. */
static enum ssg_err set_vec3(const struct ssg_param_desc *p, float *out,
                             const struct ssg_value *v, const char *owner,
                             struct ssg_diags *diags)
{
    if (v->kind == SSG_V_NUMBER) {
        enum ssg_err e = check_number(p, v, 0, owner, diags);
        for (int i = 0; i < 3 && !e; i++)
            out[i] = (float)v->number;
        return e;
    }
    if (v->kind != SSG_V_LIST)
        return wrong_kind(p, v, owner, diags);
    if (v->count != 3) {
        char got[64];
        snprintf(got, sizeof got, "a list of %d values", v->count);
        return bad_value(p, v, SSG_E_TYPE, owner, got, diags);
    }
    for (int i = 0; i < 3; i++) {
        enum ssg_err e = check_number(p, &v->items[i], 0, owner, diags);
        if (e)
            return e;
        out[i] = (float)v->items[i].number;
    }
    return SSG_OK;
}

static enum ssg_err set_ints(const struct ssg_param_desc *p, struct ssg_ints *out,
                             const struct ssg_value *v, const char *owner,
                             struct ssg_diags *diags)
{
    const struct ssg_value *items = v;
    int count = 1;
    if (v->kind == SSG_V_LIST) {
        items = v->items;
        count = v->count;
    } else if (v->kind != SSG_V_NUMBER) {
        return wrong_kind(p, v, owner, diags);
    }
    if (count < p->min_count || count > p->max_count || count > SSG_INTS_MAX) {
        char got[64];
        snprintf(got, sizeof got, "%d value%s", count, count == 1 ? "" : "s");
        return bad_value(p, v, SSG_E_RANGE, owner, got, diags);
    }
    for (int i = 0; i < count; i++) {
        enum ssg_err e = check_number(p, &items[i], 1, owner, diags);
        if (e)
            return e;
        out->v[i] = (int)items[i].number;
    }
    out->count = count;
    return SSG_OK;
}

enum ssg_err ssg_param_set(struct ssg_param_table table, int index, void *params,
                           const struct ssg_value *v, const char *owner,
                           struct ssg_diags *diags)
{
    const struct ssg_param_desc *p = &table.params[index];
    enum ssg_err e;
    switch (p->type) {
    case SSG_P_FLOAT:
        e = check_number(p, v, 0, owner, diags);
        if (!e)
            *FIELD(params, p, float) = (float)v->number;
        return e;
    case SSG_P_INT:
        e = check_number(p, v, 1, owner, diags);
        if (!e)
            *FIELD(params, p, int) = (int)v->number;
        return e;
    case SSG_P_BOOL: return set_bool(p, FIELD(params, p, int), v, owner, diags);
    case SSG_P_ENUM: return set_enum(p, FIELD(params, p, int), v, owner, diags);
    case SSG_P_STRING:
        return set_text(p, FIELD(params, p, char), SSG_STR_MAX, v, SSG_V_STRING, owner, diags);
    case SSG_P_NAME:
        return set_text(p, FIELD(params, p, char), SSG_NAME_MAX, v, SSG_V_IDENT, owner, diags);
    case SSG_P_VEC3: return set_vec3(p, FIELD(params, p, float), v, owner, diags);
    case SSG_P_INTS: return set_ints(p, FIELD(params, p, struct ssg_ints), v, owner, diags);
    case SSG_P_MAT3: break; /* a constant's row: no file sets it */
    }
    return SSG_E_VALUE;
}

void ssg_param_names(struct ssg_param_table table, char *buf, size_t len)
{
    size_t n = 0;
    buf[0] = 0;
    for (int i = 0; i < table.count && n < len; i++)
        n += (size_t)snprintf(buf + n, len - n, "%s%s", i ? ", " : "", table.params[i].name);
    if (table.count == 0)
        snprintf(buf, len, "(none)");
}

enum ssg_err ssg_param_set_text(struct ssg_param_table table, void *params, const char *text,
                                const char *origin, const char *owner, struct ssg_diags *diags)
{
    struct ssg_arena arena = {0};
    struct ssg_source src = {origin, text, strlen(text)};
    struct ssg_loc at = {&src, text};
    const char *eq = strchr(text, '=');
    enum ssg_err e = SSG_OK;
    size_t name_len = eq ? (size_t)(eq - text) : 0;
    while (name_len && text[name_len - 1] == ' ')
        name_len--;
    int index = eq ? ssg_param_find(table, text, name_len) : -1;
    if ((e = ssg_line_check(&src, diags))) {
        /* reported before the text is named in any other message */
    } else if (!eq) {
        ssg_diag_at(diags, e = SSG_E_SYNTAX, at, "expected parameter=value, found '%s'", text);
    } else if (index < 0) {
        char names[512];
        ssg_param_names(table, names, sizeof names);
        ssg_diag_at(diags, e = SSG_E_UNKNOWN_PARAM, at, "unknown parameter '%.*s' for '%s' "
                    "(expected one of: %s)", (int)name_len, text, owner, names);
    } else {
        struct ssg_value value;
        e = ssg_parse_value(&arena, &src, eq + 1, &value, diags);
        if (!e)
            e = ssg_param_set(table, index, params, &value, owner, diags);
    }
    ssg_arena_free(&arena);
    return e;
}

const char *ssg_param_type_name(const struct ssg_param_desc *p)
{
    static const char *const names[] = {"float", "int", "bool", "enum", "string", "vec3",
                                        "int list", "name", "mat3"};
    return names[p->type];
}

/* A string as a graph file writes it: quoted, with the four escapes the lexer reads (\", \\,
   \n, \t), so that a formatted value pasted into a file (a viewer's variant, a history) is
   one line that reads back the same. A value cut by len is cut before an escape, never in it. */
static void format_string(const char *s, char *buf, size_t len)
{
    static const char plain[] = "\"\\\n\t", coded[] = "\"\\nt";
    size_t n = 0;
    if (len < 3) {
        if (len)
            buf[0] = '\0';
        return;
    }
    buf[n++] = '"';
    for (; *s; s++) {
        const char *esc = strchr(plain, *s);
        size_t need = esc ? 2 : 1;
        if (n + need + 1 >= len) /* room for the closing quote and the NUL */
            break;
        if (esc)
            buf[n++] = '\\';
        buf[n++] = esc ? coded[esc - plain] : *s;
    }
    buf[n++] = '"';
    buf[n] = '\0';
}

void ssg_param_format(const struct ssg_param_desc *p, const void *params, char *buf, size_t len)
{
    switch (p->type) {
    case SSG_P_FLOAT: snprintf(buf, len, "%g", *CFIELD(params, p, float)); break;
    case SSG_P_INT: snprintf(buf, len, "%d", *CFIELD(params, p, int)); break;
    case SSG_P_BOOL:
        snprintf(buf, len, "%s", *CFIELD(params, p, int) ? "true" : "false");
        break;
    case SSG_P_ENUM: snprintf(buf, len, "%s", p->choices[*CFIELD(params, p, int)]); break;
    case SSG_P_STRING: format_string(CFIELD(params, p, char), buf, len); break;
    case SSG_P_NAME: snprintf(buf, len, "%s", CFIELD(params, p, char)); break;
    case SSG_P_VEC3: {
        const float *f = CFIELD(params, p, float);
        snprintf(buf, len, "[%g, %g, %g]", f[0], f[1], f[2]);
        break;
    }
    case SSG_P_INTS: {
        const struct ssg_ints *v = CFIELD(params, p, struct ssg_ints);
        size_t n = (size_t)snprintf(buf, len, "[");
        for (int i = 0; i < v->count && n < len; i++)
            n += (size_t)snprintf(buf + n, len - n, "%s%d", i ? ", " : "", v->v[i]);
        if (n < len)
            snprintf(buf + n, len - n, "]");
        break;
    }
    case SSG_P_MAT3: {
        const float *m = CFIELD(params, p, float);
        snprintf(buf, len, "[%g, %g, %g; %g, %g, %g; %g, %g, %g]", m[0], m[1], m[2], m[3],
                 m[4], m[5], m[6], m[7], m[8]);
        break;
    }
    }
}

/* The default as text, made by formatting a defaults-filled scratch struct. */
static void default_text(const struct ssg_param_desc *p, char *buf, size_t len)
{
    union {
        float f[3];
        int i;
        char s[SSG_STR_MAX];
        struct ssg_ints ints;
    } scratch;
    struct ssg_param_desc at_zero = *p;
    at_zero.offset = 0;
    struct ssg_param_table one = {&at_zero, 1};
    if (p->required) {
        snprintf(buf, len, "(required)");
        return;
    }
    ssg_params_defaults(one, &scratch);
    ssg_param_format(&at_zero, &scratch, buf, len);
}

/* What `describe` and the docs say a value may be: the valid range, then the useful one
   the viewer's slider spans ("a number in [1e-06, 1e+06] scene units, slider [0.05, 5]"). */
static void range_text(const struct ssg_param_desc *p, char *buf, size_t len)
{
    expected_text(p, buf, len);
    size_t n = strlen(buf);
    if (ssg_param_has_soft(p) && n < len)
        snprintf(buf + n, len - n, ", slider [%g, %g]", p->soft_min, p->soft_max);
}

int ssg_param_has_soft(const struct ssg_param_desc *p)
{
    return (p->type == SSG_P_FLOAT || p->type == SSG_P_INT) && p->soft_max > p->soft_min;
}

void ssg_param_describe(const struct ssg_param_desc *p, FILE *stream)
{
    char def[128], expected[300];
    default_text(p, def, sizeof def);
    range_text(p, expected, sizeof expected);
    fprintf(stream, "  %-18s %-8s default %-14s %s\n  %18s %s\n", p->name, ssg_param_type_name(p), def,
            expected, "", p->help ? p->help : "");
}

void ssg_param_markdown(const struct ssg_param_desc *p, FILE *stream)
{
    char def[128], expected[300];
    default_text(p, def, sizeof def);
    range_text(p, expected, sizeof expected);
    fprintf(stream, "| `%s` | %s | `%s` | %s | %s |\n", p->name, ssg_param_type_name(p), def, expected,
            p->help ? p->help : "");
}
