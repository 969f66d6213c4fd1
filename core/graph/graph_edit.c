/* graph_edit.c - ssg_graph_text_edit (ssgraph_tools.h): edits a graph file's text the way
 * a person would, for `ssgraph view`'s editor. The edits are graph statements themselves:
 *   NAME = TYPE(args)        appended as a line of its own (a new node)
 *   set NAME.KEY = VALUE     the argument changed where it is written: the file's last
 *                            `set NAME.KEY` line, else the node's call (keyed, or the
 *                            positional argument that fills KEY), else `, KEY=VALUE` added
 *                            to the call; a node of an included file gets a set line
 *   add NAME.LAYER = N.PORT  appended (a new layer of a write)
 *   remove NAME              its call and its set lines deleted, whole lines with their
 *                            comments (on the line, and the comment lines right above);
 *                            refused where another statement reads it
 * Only the edited spans change: every other byte of the text stays as it was. Nothing here
 * checks the graph: the caller loads the result (ssg_graph_load_text), so every check and
 * message is the graph file's own, at the line of the edited text. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "graph/graph.h"
#include "lang/params.h"
#include "lang/parse.h"

enum { WRAP_COLUMN = 96 }; /* a call line that would pass it takes the new argument on a
                              line of its own, as the graphs in graphs/ are wrapped */

/* The text being edited: parsed, and the offsets of its statements. */
struct edit_text {
    const char *path;
    char *text; /* malloc'd */
    struct ssg_file file;
};

static size_t off(const struct edit_text *t, const char *at)
{
    return (size_t)(at - t->file.src->text);
}

/* Replaces bytes [from, to) of t->text with `with` (len bytes). */
static enum ssg_err splice(struct edit_text *t, size_t from, size_t to, const char *with,
                           size_t len)
{
    size_t old = strlen(t->text);
    char *out = malloc(old - (to - from) + len + 1);
    if (!out)
        return SSG_E_NOMEM;
    memcpy(out, t->text, from);
    memcpy(out + from, with, len);
    memcpy(out + from + len, t->text + to, old - to + 1);
    free(t->text);
    t->text = out;
    return SSG_OK;
}

static enum ssg_err append_line(struct edit_text *t, const char *line, size_t len)
{
    size_t n = strlen(t->text);
    int newline = n && t->text[n - 1] != '\n';
    char *add = malloc(len + 3);
    if (!add)
        return SSG_E_NOMEM;
    size_t k = 0;
    if (newline)
        add[k++] = '\n';
    memcpy(add + k, line, len);
    add[k + len] = '\n';
    enum ssg_err e = splice(t, n, n, add, k + len + 1);
    free(add);
    return e;
}

/* The top file's call that defines `name`, or NULL. */
static const struct ssg_stmt *find_call(const struct ssg_file *f, const char *name, size_t len)
{
    for (int i = 0; i < f->count; i++)
        if (f->stmts[i].kind == SSG_S_CALL && f->stmts[i].name &&
            f->stmts[i].name_len == len && !memcmp(f->stmts[i].name, name, len))
            return &f->stmts[i];
    return NULL;
}

/* The argument of call st that gives `key`: keyed, or the positional one that fills it
   (graph_build.c's rule: positional references fill the inputs in order, positional
   values the parameters); NULL when the call leaves it out. */
static const struct ssg_arg *find_arg(const struct ssg_stmt *st, const char *key, size_t len)
{
    const struct ssg_node_desc *d = ssg_node_find(st->callee, st->callee_len);
    int port = d ? ssg_port_find(d->inputs, d->input_count, key, len) : -1;
    int param = d && port < 0 ? ssg_param_find(d->params, key, len) : -1;
    int next_port = 0, next_param = 0;
    for (int i = 0; i < st->arg_count; i++) {
        const struct ssg_arg *a = &st->args[i];
        if (a->key && a->key_len == len && !memcmp(a->key, key, len))
            return a;
        if (a->key)
            continue;
        int is_ref = a->value.kind == SSG_V_REF;
        if ((is_ref && next_port++ == port) || (!is_ref && next_param++ == param))
            return a;
    }
    return NULL;
}

/* The column (0-based) of `at` in its line. */
static size_t column(const char *text, const char *at)
{
    const char *p = at;
    while (p > text && p[-1] != '\n')
        p--;
    return (size_t)(at - p);
}

/* `key=value` added to call st: after its last argument (wrapped onto a new line aligned
   with the first when the line would grow past WRAP_COLUMN), or inside its empty (). */
static enum ssg_err add_arg(struct edit_text *t, const struct ssg_stmt *st, const char *key,
                            size_t key_len, const char *value, size_t value_len)
{
    const char *src = t->file.src->text;
    const char *at = st->arg_count ? st->args[st->arg_count - 1].value.end : st->end - 1;
    const char *first = st->arg_count ? (st->args[0].key ? st->args[0].key
                                                         : st->args[0].value.start) : at;
    size_t lead = column(src, first), len = key_len + value_len + 1;
    const char *eol = strchr(at, '\n');
    size_t line_end = column(src, at) + (eol ? (size_t)(eol - at) : strlen(at));
    int wrap = st->arg_count && line_end + len + 2 > WRAP_COLUMN;
    size_t sep = !st->arg_count ? 0 : wrap ? 2 + lead : 2;
    char *with = malloc(sep + len + 1);
    if (!with)
        return SSG_E_NOMEM;
    if (sep) {
        with[0] = ',';
        memset(with + 1, ' ', sep - 1);
        if (wrap)
            with[1] = '\n';
    }
    memcpy(with + sep, key, key_len);
    with[sep + key_len] = '=';
    memcpy(with + sep + key_len + 1, value, value_len);
    size_t at_off = off(t, at);
    enum ssg_err e = splice(t, at_off, at_off, with, sep + len);
    free(with);
    return e;
}

/* set NAME.KEY = VALUE (see the top of the file). */
static enum ssg_err edit_set(struct edit_text *t, const struct ssg_stmt *ed)
{
    const struct ssg_value *v = &ed->args[0].value;
    size_t value_len = (size_t)(v->end - v->start);
    const struct ssg_file *f = &t->file;
    for (int i = f->count - 1; i >= 0; i--) {
        const struct ssg_stmt *st = &f->stmts[i];
        if (st->kind == SSG_S_SET && st->name_len == ed->name_len &&
            !memcmp(st->name, ed->name, ed->name_len) && st->callee_len == ed->callee_len &&
            !memcmp(st->callee, ed->callee, ed->callee_len))
            return splice(t, off(t, st->args[0].value.start), off(t, st->args[0].value.end),
                          v->start, value_len);
    }
    const struct ssg_stmt *call = find_call(f, ed->name, ed->name_len);
    if (!call) /* a node of an included file, or none: the load says which */
        return append_line(t, ed->loc.at, (size_t)(ed->end - ed->loc.at));
    const struct ssg_arg *a = find_arg(call, ed->callee, ed->callee_len);
    if (a)
        return splice(t, off(t, a->value.start), off(t, a->value.end), v->start, value_len);
    return add_arg(t, call, ed->callee, ed->callee_len, v->start, value_len);
}

/* 1 when value v (a list's items too) reads node `name`. */
static int reads(const struct ssg_value *v, const char *name, size_t len,
                 struct ssg_loc *where)
{
    if (v->kind == SSG_V_REF && v->len == len && !memcmp(v->text, name, len)) {
        *where = v->loc;
        return 1;
    }
    for (int i = 0; v->kind == SSG_V_LIST && i < v->count; i++)
        if (reads(&v->items[i], name, len, where))
            return 1;
    return 0;
}

/* The statement of the node itself, or one of its own set lines. */
static int own(const struct ssg_stmt *st, const char *name, size_t len)
{
    return (st->kind == SSG_S_CALL || st->kind == SSG_S_SET) && st->name &&
           st->name_len == len && !memcmp(st->name, name, len);
}

/* Each statement that reads node `name`, reported where it does; the count. */
static int readers(const struct edit_text *t, const char *name, size_t len,
                   struct ssg_diags *d)
{
    int found = 0;
    for (int i = 0; i < t->file.count; i++) {
        const struct ssg_stmt *st = &t->file.stmts[i];
        struct ssg_loc at;
        for (int k = 0; !own(st, name, len) && k < st->arg_count; k++) {
            if (!reads(&st->args[k].value, name, len, &at))
                continue;
            char who[96] = "a statement";
            if (st->name)
                snprintf(who, sizeof who, "node '%.*s'", (int)st->name_len, st->name);
            ssg_diag_at(d, SSG_E_UNKNOWN_NAME, at, "cannot remove node '%.*s': %s reads it "
                        "here (expected that input connected to another output first, or "
                        "the reader removed first)", (int)len, name, who);
            found++;
            break;
        }
    }
    return found;
}

/* The start of the comment lines right above line start `a` (no blank line between: they
   speak of that statement), or a itself. */
static const char *comment_above(const char *src, const char *a)
{
    while (a > src) {
        const char *line = a - 1; /* the '\n' that ends the line above */
        while (line > src && line[-1] != '\n')
            line--;
        const char *p = line + strspn(line, " \t");
        if (*p != '#')
            break;
        a = line;
    }
    return a;
}

/* The span of statement st widened to whole lines when nothing else is on its line: the
   comment lines right above it and its indentation, and after it the blanks, a comment
   and the newline. */
static void line_span(const struct edit_text *t, const struct ssg_stmt *st, size_t *from,
                      size_t *to)
{
    const char *src = t->file.src->text, *a = st->loc.at, *b = st->end;
    while (a > src && (a[-1] == ' ' || a[-1] == '\t'))
        a--;
    int alone = a == src || a[-1] == '\n';
    while (*b == ' ' || *b == '\t')
        b++;
    if (*b == '#')
        b += strcspn(b, "\n");
    if (alone && *b == '\n')
        b++;
    *from = off(t, alone ? comment_above(src, a) : st->loc.at);
    *to = off(t, alone ? b : st->end);
}

static enum ssg_err edit_remove(struct edit_text *t, const struct ssg_stmt *ed,
                                struct ssg_diags *d)
{
    const struct ssg_value *v = ed->arg_count == 1 ? &ed->args[0].value : NULL;
    if (!v || v->kind != SSG_V_IDENT) {
        ssg_diag_at(d, SSG_E_SYNTAX, v ? v->loc : ed->name_loc, "expected remove NAME (one "
                    "node of the graph)");
        return SSG_E_SYNTAX;
    }
    if (!find_call(&t->file, v->text, v->len)) {
        ssg_diag_at(d, SSG_E_UNKNOWN_NAME, v->loc, "no node '%.*s' is defined in %s (expected "
                    "a node of that file; one of an included file is removed there)",
                    (int)v->len, v->text, t->path);
        return SSG_E_UNKNOWN_NAME;
    }
    if (readers(t, v->text, v->len, d))
        return SSG_E_UNKNOWN_NAME;
    enum ssg_err e = SSG_OK;
    for (int i = t->file.count - 1; !e && i >= 0; i--) { /* from the end: offsets hold */
        size_t from, to;
        if (!own(&t->file.stmts[i], v->text, v->len))
            continue;
        line_span(t, &t->file.stmts[i], &from, &to);
        e = splice(t, from, to, "", 0);
    }
    return e;
}

/* A new node: NAME = TYPE(args), named (an anonymous one could be named by nothing else). */
static enum ssg_err edit_add(struct edit_text *t, const struct ssg_stmt *ed,
                             struct ssg_diags *d)
{
    if (!ed->name) {
        ssg_diag_at(d, SSG_E_SYNTAX, ed->loc, "a new node needs a name: NAME = %.*s(...)",
                    (int)ed->callee_len, ed->callee);
        return SSG_E_SYNTAX;
    }
    return append_line(t, ed->loc.at, (size_t)(ed->end - ed->loc.at));
}

static enum ssg_err edit_one(struct edit_text *t, const struct ssg_stmt *ed,
                             struct ssg_diags *d)
{
    if (ed->kind == SSG_S_CALL)
        return edit_add(t, ed, d);
    if (ed->kind == SSG_S_SET && ed->adds)
        return append_line(t, ed->loc.at, (size_t)(ed->end - ed->loc.at));
    if (ed->kind == SSG_S_SET)
        return edit_set(t, ed);
    if (ssg_tok_eq(ed->name, ed->name_len, "remove"))
        return edit_remove(t, ed, d);
    ssg_diag_at(d, SSG_E_SYNTAX, ed->name_loc, "unknown edit '%.*s' (expected NAME = "
                "TYPE(...), set NAME.INPUT = NODE.PORT, add NAME.LAYER = NODE.PORT or remove "
                "NAME)", (int)ed->name_len, ed->name);
    return SSG_E_SYNTAX;
}

enum ssg_err ssg_graph_text_edit(const char *path, const char *text, const char *edits,
                                 char **out, struct ssg_diags *diags)
{
    if (out)
        *out = NULL;
    if (ssg_api_null(diags, "ssg_graph_text_edit", "path, text, edits, out", 4, path, text,
                     edits, out))
        return SSG_E_USAGE;
    struct ssg_arena arena = {0};
    struct ssg_file list;
    struct edit_text t = {.path = path, .text = strdup(text)};
    enum ssg_err e = t.text ? ssg_parse_text(&arena, "<edit>", edits, &list, diags)
                            : SSG_E_NOMEM;
    /* Each edit sees the text the one before it left, parsed anew (each arena is
       freed with the next: the edit list keeps its own). */
    if (!e && !list.count) {
        ssg_diag_at(diags, SSG_E_SYNTAX, (struct ssg_loc){list.src, list.src->text}, "no edit "
                    "given (expected NAME = TYPE(...), set NAME.INPUT = NODE.PORT or remove "
                    "NAME)");
        e = SSG_E_SYNTAX;
    }
    for (int i = 0; !e && i < list.count; i++) {
        struct ssg_arena pass = {0};
        e = ssg_parse_text(&pass, path, t.text, &t.file, diags);
        if (!e)
            e = edit_one(&t, &list.stmts[i], diags);
        ssg_arena_free(&pass);
    }
    ssg_arena_free(&arena);
    if (e)
        free(t.text);
    else
        *out = t.text;
    return e;
}
