/* parse.c - the statement parser shared by graph and scene files (see parse.h), over the
 * tokens of lex.c (lex.h). The whole text is tokenised first, then statements are read with
 * one token of lookahead. After an error the parser skips to the end of the statement and
 * goes on, so every problem in a file is reported in one run. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lang/lex.h"
#include "lang/parse.h"

/* Limits on what a text may ask of the parser, each refused with a located message: lists
   are parsed recursively with a 64-value frame on the stack, so nesting is bounded; no real
   file comes near either limit. */
enum {
    MAX_FILE_BYTES = SSG_GRAPH_FILE_MAX_BYTES,
    MAX_LIST_NESTING = 16,   /* [[...]] levels in one value */
};

struct parser {
    struct lexer lex;          /* the tokens, and the error count both halves add to */
    struct ssg_arena *values;  /* what the parse returns (strings, lists, arguments); the
                                  tokens may live in another, shorter-lived arena */
    int pos;
    int nesting;  /* lists open around the value being parsed */
};

const char *ssg_value_kind_text(enum ssg_value_kind kind)
{
    switch (kind) {
    case SSG_V_NUMBER: return "a number";
    case SSG_V_STRING: return "a string";
    case SSG_V_IDENT: return "a name";
    case SSG_V_REF: return "a port reference (node.port)";
    case SSG_V_LIST: return "a list";
    }
    return "a value";
}

static struct ssg_loc loc_of(const struct parser *ps, const char *at)
{
    struct ssg_loc loc = {ps->lex.src, at};
    return loc;
}

static void error_at(struct parser *ps, const char *at, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static void error_at(struct parser *ps, const char *at, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    ssg_syntax_verror(&ps->lex, at, fmt, ap);
    va_end(ap);
}

static const struct token *peek(const struct parser *ps, int ahead)
{
    int i = ps->pos + ahead;
    return &ps->lex.toks[i < ps->lex.count ? i : ps->lex.count - 1];
}

/* One past the last token read: where a value or statement just parsed ends. */
static const char *read_end(const struct parser *ps)
{
    const struct token *t = &ps->lex.toks[ps->pos ? ps->pos - 1 : 0];
    return t->at + t->len;
}

static const struct token *next(struct parser *ps)
{
    const struct token *t = peek(ps, 0);
    if (ps->pos < ps->lex.count - 1)
        ps->pos++;
    return t;
}

static int expect(struct parser *ps, enum tok_kind kind, const char *context)
{
    const struct token *t = peek(ps, 0);
    if (t->kind == kind) {
        next(ps);
        return 1;
    }
    error_at(ps, t->at, "expected %s %s, found %s", ssg_tok_text(kind), context,
             ssg_tok_text(t->kind));
    return 0;
}

/* Skips the rest of a statement after an error. */
static void recover(struct parser *ps)
{
    while (peek(ps, 0)->kind != T_NEWLINE && peek(ps, 0)->kind != T_EOF)
        next(ps);
}

static const char *unescape(struct parser *ps, const struct token *t, size_t *len)
{
    char *out = ssg_arena_alloc(ps->values, t->len + 1);
    if (!out)
        return NULL;
    size_t n = 0;
    const char *s = t->at + 1, *end = t->at + t->len - 1;
    for (; s < end; s++) {
        if (*s != '\\') {
            out[n++] = *s;
            continue;
        }
        s++;
        switch (*s) {
        case '"': out[n++] = '"'; break;
        case '\\': out[n++] = '\\'; break;
        case 'n': out[n++] = '\n'; break;
        case 't': out[n++] = '\t'; break;
        default:
            error_at(ps, s - 1, "unknown escape '\\%c' (expected \\\", \\\\, \\n or \\t)", *s);
        }
    }
    *len = n;
    return out;
}

static int parse_value(struct parser *ps, struct ssg_value *v);

/* The values of a list up to its ']' (left for the caller), at most 64. */
static int parse_items(struct parser *ps, struct ssg_value *items, int *count)
{
    while (peek(ps, 0)->kind != T_RBRACK) {
        if (*count == 64) {
            error_at(ps, peek(ps, 0)->at, "list too long (at most 64 values)");
            return 0;
        }
        if (!parse_value(ps, &items[(*count)++]))
            return 0;
        if (peek(ps, 0)->kind != T_COMMA)
            break;
        next(ps);
    }
    return 1;
}

static int parse_list(struct parser *ps, struct ssg_value *v)
{
    struct ssg_value items[64];
    int count = 0;
    if (ps->nesting == MAX_LIST_NESTING) {
        error_at(ps, peek(ps, 0)->at, "lists nested deeper than %d levels (expected a value "
                 "or a list of values)", MAX_LIST_NESTING);
        return 0;
    }
    next(ps); /* '[' */
    ps->nesting++;
    int ok = parse_items(ps, items, &count);
    ps->nesting--;
    if (!ok)
        return 0;
    if (!expect(ps, T_RBRACK, "to close the list"))
        return 0;
    v->kind = SSG_V_LIST;
    v->count = count;
    v->items = ssg_arena_alloc(ps->values, (size_t)(count ? count : 1) * sizeof *items);
    if (!v->items)
        return 0;
    memcpy(v->items, items, (size_t)count * sizeof *items);
    return 1;
}

/* prev(node.port): the image that port had in the previous frame (graph.h, docs/time.md).
   Only a plain reference may stand inside: prev(prev(x)) would ask for a history the
   executor does not keep, so it is refused here rather than given a meaning. */
static int parse_prev(struct parser *ps, struct ssg_value *v)
{
    const struct token *name = next(ps);
    next(ps); /* the '(' parse_value saw */
    if (!parse_value(ps, v))
        return 0;
    if (v->kind != SSG_V_REF || v->prev) {
        error_at(ps, name->at, "prev() takes one port reference, prev(node.port), not %s",
                 v->prev ? "prev() of prev()" : ssg_value_kind_text(v->kind));
        return 0;
    }
    v->prev = 1;
    return expect(ps, T_RPAREN, "to close prev(");
}

/* A number token read whole, however long (leading zeros, many digits): strtod needs it
   alone and NUL-terminated, and the source holds more after it. Past a double's range it
   is refused at its place, never cut to fit a buffer. */
static int parse_number(struct parser *ps, const struct token *t, struct ssg_value *v)
{
    char small[64], *buf = t->len < sizeof small ? small : malloc(t->len + 1);
    if (!buf) {
        error_at(ps, t->at, "out of memory reading a number of %zu characters", t->len);
        return 0;
    }
    memcpy(buf, t->at, t->len);
    buf[t->len] = 0;
    errno = 0;
    v->kind = SSG_V_NUMBER;
    v->number = strtod(buf, NULL);
    v->is_integer = strpbrk(buf, ".eE") == NULL;
    int out_of_range = errno == ERANGE;
    if (buf != small)
        free(buf);
    if (out_of_range)
        error_at(ps, t->at, "number '%.*s%s' (%zu characters) is out of the range of a "
                 "double", (int)(t->len < 40 ? t->len : 40), t->at, t->len > 40 ? "..." : "",
                 t->len);
    return !out_of_range;
}

static int parse_value_kind(struct parser *ps, struct ssg_value *v);

static int parse_value(struct parser *ps, struct ssg_value *v)
{
    const char *start = peek(ps, 0)->at;
    int ok = parse_value_kind(ps, v);
    v->start = start;
    v->end = read_end(ps);
    return ok;
}

static int parse_value_kind(struct parser *ps, struct ssg_value *v)
{
    const struct token *t = peek(ps, 0);
    memset(v, 0, sizeof *v);
    v->loc = loc_of(ps, t->at);
    switch (t->kind) {
    case T_NUMBER:
        next(ps);
        return parse_number(ps, t, v);
    case T_STRING:
        next(ps);
        v->kind = SSG_V_STRING;
        v->text = unescape(ps, t, &v->len);
        return v->text != NULL;
    case T_IDENT:
        if (ssg_tok_eq(t->at, t->len, "prev") && peek(ps, 1)->kind == T_LPAREN)
            return parse_prev(ps, v);
        next(ps);
        v->kind = SSG_V_IDENT;
        v->text = t->at;
        v->len = t->len;
        if (peek(ps, 0)->kind == T_DOT) {
            next(ps);
            const struct token *m = peek(ps, 0);
            if (m->kind != T_IDENT) {
                error_at(ps, m->at, "expected a port name after '%.*s.', found %s",
                         (int)t->len, t->at, ssg_tok_text(m->kind));
                return 0;
            }
            next(ps);
            v->kind = SSG_V_REF;
            v->member = m->at;
            v->member_len = m->len;
            v->member_loc = loc_of(ps, m->at);
        }
        return 1;
    case T_LBRACK:
        return parse_list(ps, v);
    default:
        error_at(ps, t->at, "expected a value (number, string, name, node.port or [list]), "
                            "found %s", ssg_tok_text(t->kind));
        return 0;
    }
}

static int parse_arg(struct parser *ps, struct ssg_arg *arg)
{
    memset(arg, 0, sizeof *arg);
    const struct token *t = peek(ps, 0);
    if (t->kind == T_IDENT && peek(ps, 1)->kind == T_EQ) {
        arg->key = t->at;
        arg->key_len = t->len;
        arg->key_loc = loc_of(ps, t->at);
        next(ps);
        next(ps);
    }
    return parse_value(ps, &arg->value);
}

static struct ssg_arg *copy_args(struct parser *ps, const struct ssg_arg *args, int count)
{
    struct ssg_arg *out = ssg_arena_alloc(ps->values, (size_t)(count ? count : 1) * sizeof *out);
    if (out && count)
        memcpy(out, args, (size_t)count * sizeof *out);
    return out;
}

enum { MAX_ARGS = 64 };

static int parse_call(struct parser *ps, struct ssg_stmt *st)
{
    struct ssg_arg args[MAX_ARGS];
    int count = 0;
    const struct token *callee = next(ps);
    st->kind = SSG_S_CALL;
    st->callee = callee->at;
    st->callee_len = callee->len;
    st->callee_loc = loc_of(ps, callee->at);
    const char *open = peek(ps, 0)->at;
    if (!expect(ps, T_LPAREN, "after the node or entity name"))
        return 0;
    while (peek(ps, 0)->kind != T_RPAREN) {
        if (count == MAX_ARGS) {
            error_at(ps, peek(ps, 0)->at, "too many arguments (at most %d)", MAX_ARGS);
            return 0;
        }
        if (!parse_arg(ps, &args[count++]))
            return 0;
        if (peek(ps, 0)->kind != T_COMMA)
            break;
        next(ps);
    }
    if (peek(ps, 0)->kind != T_RPAREN) {
        int line, column;
        ssg_loc_linecol(loc_of(ps, open), &line, &column);
        error_at(ps, peek(ps, 0)->at, "expected ')' to close the '(' of line %d, column %d, "
                 "found %s", line, column, ssg_tok_text(peek(ps, 0)->kind));
        return 0;
    }
    next(ps);
    st->args = copy_args(ps, args, count);
    st->arg_count = count;
    return st->args != NULL;
}

/* set NAME.MEMBER = VALUE, or add NAME.MEMBER = VALUE (st->adds) */
static int parse_set(struct parser *ps, struct ssg_stmt *st)
{
    st->kind = SSG_S_SET;
    st->adds = ssg_tok_eq(peek(ps, 0)->at, peek(ps, 0)->len, "add");
    const char *form = st->adds ? "(add node.input = node.port)"
                                : "(set node.parameter = value)";
    next(ps); /* set or add */
    const struct token *name = peek(ps, 0);
    char what[80];
    snprintf(what, sizeof what, "after '%s' %s", st->adds ? "add" : "set", form);
    if (!expect(ps, T_IDENT, what))
        return 0;
    st->name = name->at;
    st->name_len = name->len;
    st->name_loc = loc_of(ps, name->at);
    snprintf(what, sizeof what, "after the node name %s", form);
    if (!expect(ps, T_DOT, what))
        return 0;
    const struct token *member = peek(ps, 0);
    snprintf(what, sizeof what, "after '.' %s", form);
    if (!expect(ps, T_IDENT, what))
        return 0;
    st->callee = member->at;
    st->callee_len = member->len;
    st->callee_loc = loc_of(ps, member->at);
    snprintf(what, sizeof what, "after the parameter %s", form);
    if (!expect(ps, T_EQ, what))
        return 0;
    struct ssg_arg arg = {.key = member->at, .key_len = member->len,
                          .key_loc = loc_of(ps, member->at)};
    if (!parse_value(ps, &arg.value))
        return 0;
    st->args = copy_args(ps, &arg, 1);
    st->arg_count = 1;
    return st->args != NULL;
}

static int parse_directive(struct parser *ps, struct ssg_stmt *st)
{
    struct ssg_arg args[MAX_ARGS];
    int count = 0;
    st->kind = SSG_S_DIRECTIVE;
    next(ps); /* keyword */
    while (peek(ps, 0)->kind != T_NEWLINE && peek(ps, 0)->kind != T_EOF) {
        if (count == MAX_ARGS) {
            error_at(ps, peek(ps, 0)->at, "too many values (at most %d)", MAX_ARGS);
            return 0;
        }
        memset(&args[count], 0, sizeof args[count]);
        if (!parse_value(ps, &args[count++].value))
            return 0;
    }
    st->args = copy_args(ps, args, count);
    st->arg_count = count;
    return st->args != NULL;
}

static int parse_statement(struct parser *ps, struct ssg_stmt *st)
{
    const struct token *t = peek(ps, 0);
    memset(st, 0, sizeof *st);
    st->loc = loc_of(ps, t->at);
    if (t->kind != T_IDENT) {
        error_at(ps, t->at, "expected a statement (name = node(...), set a.b = value, or a "
                            "directive such as scene/size/include), found %s",
                 ssg_tok_text(t->kind));
        return 0;
    }
    st->name = t->at;
    st->name_len = t->len;
    st->name_loc = st->loc;
    enum tok_kind after = peek(ps, 1)->kind;
    int ok;
    if ((ssg_tok_eq(t->at, t->len, "set") || ssg_tok_eq(t->at, t->len, "add")) &&
        after == T_IDENT) {
        ok = parse_set(ps, st);
    } else if (after == T_EQ) {
        next(ps);
        next(ps);
        if (peek(ps, 0)->kind != T_IDENT) {
            error_at(ps, peek(ps, 0)->at, "expected a node or entity name after '=', found %s",
                     ssg_tok_text(peek(ps, 0)->kind));
            return 0;
        }
        ok = parse_call(ps, st);
    } else if (after == T_LPAREN) {
        st->name = NULL;
        st->name_len = 0;
        ok = parse_call(ps, st);
    } else {
        ok = parse_directive(ps, st);
    }
    if (ok && peek(ps, 0)->kind != T_NEWLINE && peek(ps, 0)->kind != T_EOF) {
        error_at(ps, peek(ps, 0)->at, "expected end of line after the statement, found %s",
                 ssg_tok_text(peek(ps, 0)->kind));
        ok = 0;
    }
    st->end = read_end(ps);
    return ok;
}

static enum ssg_err parse_source(struct ssg_arena *arena, const struct ssg_source *src,
                                 struct ssg_file *out, struct ssg_diags *diags)
{
    struct parser ps = {.lex = {.arena = arena, .src = src, .diags = diags}, .values = arena};
    memset(out, 0, sizeof *out);
    out->src = src;
    if (!ssg_lex(&ps.lex, src->text, src->text + src->len))
        return SSG_E_NOMEM;
    int cap = 16, count = 0;
    struct ssg_stmt *stmts = ssg_arena_alloc(arena, (size_t)cap * sizeof *stmts);
    while (stmts && peek(&ps, 0)->kind != T_EOF) {
        if (peek(&ps, 0)->kind == T_NEWLINE) {
            next(&ps);
            continue;
        }
        if (count == cap) {
            struct ssg_stmt *grown = ssg_arena_alloc(arena, (size_t)cap * 2 * sizeof *stmts);
            if (!grown)
                return SSG_E_NOMEM;
            memcpy(grown, stmts, (size_t)count * sizeof *stmts);
            stmts = grown;
            cap *= 2;
        }
        if (parse_statement(&ps, &stmts[count]))
            count++;
        else
            recover(&ps);
    }
    if (!stmts)
        return SSG_E_NOMEM;
    out->stmts = stmts;
    out->count = count;
    return ps.lex.errors ? SSG_E_SYNTAX : SSG_OK;
}

static struct ssg_source *make_source(struct ssg_arena *arena, const char *path,
                                      const char *text, size_t len)
{
    struct ssg_source *src = ssg_arena_alloc(arena, sizeof *src);
    if (!src)
        return NULL;
    src->path = ssg_arena_strndup(arena, path, strlen(path));
    src->text = ssg_arena_strndup(arena, text, len);
    src->len = len;
    return (src->path && src->text) ? src : NULL;
}

enum ssg_err ssg_parse_text(struct ssg_arena *arena, const char *origin, const char *text,
                            struct ssg_file *out, struct ssg_diags *diags)
{
    struct ssg_source *src = make_source(arena, origin, text, strlen(text));
    if (!src)
        return SSG_E_NOMEM;
    return parse_source(arena, src, out, diags);
}

/* Reads a whole file into the arena; reports at `from` when it cannot. Only a regular
   file of at most MAX_FILE_BYTES is read (files.h): a FIFO or /dev/zero is refused. */
static struct ssg_source *read_source(struct ssg_arena *arena, const char *path,
                                      struct ssg_loc from, struct ssg_diags *diags)
{
    char *buf = NULL, why[256];
    size_t len = 0;
    enum ssg_err e = ssg_input_read(path, MAX_FILE_BYTES, &buf, &len, why, sizeof why);
    struct ssg_source *src = NULL;
    if (e && from.src)
        ssg_diag_at(diags, e, from, "cannot read '%s': %s", path, why);
    else if (e)
        ssg_diag_file(diags, e, path, "cannot read file: %s", why);
    else if (memchr(buf, 0, len))
        ssg_diag_file(diags, SSG_E_SYNTAX, path, "file contains NUL bytes; expected text");
    else if (!(src = make_source(arena, path, buf, len)))
        ssg_diag_file(diags, SSG_E_NOMEM, path, "out of memory");
    free(buf);
    return src;
}

enum ssg_err ssg_parse_file(struct ssg_arena *arena, const char *path, struct ssg_loc from,
                            struct ssg_file *out, struct ssg_diags *diags)
{
    memset(out, 0, sizeof *out);
    struct ssg_source *src = read_source(arena, path, from, diags);
    if (!src)
        return ssg_diags_first(diags) ? ssg_diags_first(diags) : SSG_E_IO;
    return parse_source(arena, src, out, diags);
}

enum ssg_err ssg_parse_value(struct ssg_arena *arena, const struct ssg_source *src,
                             const char *start, struct ssg_value *out, struct ssg_diags *diags)
{
    /* Tokenise only the tail, keeping locations relative to the whole source. The tokens
       (6 KiB at least) are freed here: a live graph parses a value at every
       ssg_graph_set, and its arena would otherwise grow by them each time. */
    if (ssg_line_check(src, diags))
        return SSG_E_SYNTAX;
    struct ssg_arena tokens = {0};
    struct parser ps = {.lex = {.arena = &tokens, .src = src, .diags = diags}, .values = arena};
    if (!ssg_lex(&ps.lex, start, start + strlen(start))) {
        ssg_arena_free(&tokens);
        return SSG_E_NOMEM;
    }
    int ok = !ps.lex.errors && parse_value(&ps, out);
    if (ok && peek(&ps, 0)->kind != T_NEWLINE && peek(&ps, 0)->kind != T_EOF) {
        error_at(&ps, peek(&ps, 0)->at, "expected one value, found more after it");
        ok = 0;
    }
    ssg_arena_free(&tokens);
    return ok ? SSG_OK : SSG_E_SYNTAX;
}

void ssg_path_resolve(const char *base_file, const char *rel, char *out, size_t len)
{
    const char *slash = base_file ? strrchr(base_file, '/') : NULL;
    if (rel[0] == '/' || !slash)
        snprintf(out, len, "%s", rel);
    else
        snprintf(out, len, "%.*s/%s", (int)(slash - base_file), base_file, rel);
}
