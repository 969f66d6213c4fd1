/* graph_build.c - from statements to nodes (graph.h). Includes are expanded in place;
 * node calls are collected first and bound afterwards, so a node may name one defined
 * later; `set` lines then override arguments, and command-line --set last of all.
 *
 * Argument rules: a positional node.port fills the next input port in declared order, a
 * positional literal the next parameter; `key=value` names a port or a parameter; nodes
 * with extra inputs take unknown `key=node.port` as a named extra input. */
#include <stdio.h>
#include <string.h>

#include "graph/graph_files.h"

/* What one graph may ask of the builder, each refused with a message: includes nest at
   most MAX_INCLUDE_DEPTH deep; at most MAX_FILES_READ file reads in all (the same file
   included twice counts twice, so 15 levels of 8 includes of one file stop early rather
   than reading 8^15 copies); at most MAX_STATEMENTS statements in all. */
enum { MAX_INCLUDE_DEPTH = 16, MAX_FILES_READ = 1024, MAX_STATEMENTS = 200000 };

struct builder {
    struct ssg_graph *g;
    struct ssg_diags *diags;
    const struct ssg_stmt **sets; /* set lines in file order, applied after every call */
    int set_count, set_cap;
    const char *stack[MAX_INCLUDE_DEPTH]; /* files being read, for include cycles */
    int depth;
    int files_read, statements;         /* against the limits above */
    int limit_hit;                        /* 1 = a limit was reported: read nothing more */
    int anonymous;
    int in_set;                           /* 1 = binding a set line or --set */
    const char *set_origin;               /* the source name of a caller's set, NULL =
                                             "<command line --set>" */
    enum ssg_err first;
};

/* Keeps the first error; 1 when e is one, so that a caller can stop in the same line. */
static int fail(struct builder *b, enum ssg_err e)
{
    if (e && !b->first)
        b->first = e;
    return e != SSG_OK;
}

static struct gnode *add_node(struct builder *b, const struct ssg_stmt *st)
{
    struct ssg_graph *g = b->g;
    const struct ssg_node_desc *desc = ssg_node_find(st->callee, st->callee_len);
    if (!desc) {
        char names[512];
        ssg_node_names(names, sizeof names);
        ssg_diag_at(b->diags, SSG_E_UNKNOWN_NODE, st->callee_loc,
                    "unknown node '%.*s' (expected one of: %s)", (int)st->callee_len,
                    st->callee, names);
        fail(b, SSG_E_UNKNOWN_NODE);
        return NULL;
    }
    if (st->name && ssg_graph_find(g, st->name, st->name_len) >= 0) {
        ssg_diag_at(b->diags, SSG_E_DUPLICATE, st->name_loc, "node '%.*s' is defined twice "
                    "(use 'set %.*s.param = value' to change it)", (int)st->name_len, st->name,
                    (int)st->name_len, st->name);
        fail(b, SSG_E_DUPLICATE);
        return NULL;
    }
    if (g->count == g->cap) {
        int cap = g->cap ? g->cap * 2 : 16;
        struct gnode *nodes = ssg_arena_alloc(&g->arena, (size_t)cap * sizeof *nodes);
        if (!nodes)
            return NULL;
        if (g->count)
            memcpy(nodes, g->nodes, (size_t)g->count * sizeof *nodes);
        g->nodes = nodes;
        g->cap = cap;
    }
    struct gnode *n = &g->nodes[g->count++];
    memset(n, 0, sizeof *n);
    n->desc = desc;
    n->stmt = st;
    n->loc = st->callee_loc;
    if (st->name) {
        n->name = ssg_arena_strndup(&g->arena, st->name, st->name_len);
    } else {
        char anon[96];
        snprintf(anon, sizeof anon, "%s_%d", desc->name, ++b->anonymous);
        n->name = ssg_arena_strndup(&g->arena, anon, strlen(anon));
    }
    if (!n->name || !ssg_graph_name_add(g, g->count - 1)) {
        g->count--;
        fail(b, SSG_E_NOMEM);
        return NULL;
    }
    n->params = ssg_arena_alloc(&g->arena, desc->params_size ? desc->params_size : 1);
    if (n->params)
        ssg_params_defaults(desc->params, n->params);
    for (int i = 0; i < SSG_MAX_PORTS; i++)
        n->in[i].node = -1;
    return n;
}

static void connect(struct builder *b, struct gconn *c, const struct ssg_value *v)
{
    c->node = -1; /* resolved by ssg_graph_validate once every node exists */
    c->value = *v;
    char ref[160];
    snprintf(ref, sizeof ref, v->prev ? "prev(%.*s.%.*s)" : "%.*s.%.*s", (int)v->len, v->text,
             (int)v->member_len, v->member); /* prev(): graph_history.h */
    c->ref = ssg_arena_strndup(&b->g->arena, ref, strlen(ref));
}

static void bind_input(struct builder *b, struct gnode *n, int port, const struct ssg_value *v)
{
    if (v->kind != SSG_V_REF) {
        char types[64];
        ssg_type_names(n->desc->inputs[port].types, types, sizeof types);
        ssg_diag_at(b->diags, SSG_E_TYPE, v->loc, "input '%s' of node '%s' expects a port "
                    "reference node.port (%s), got %s", n->desc->inputs[port].name, n->name,
                    types, ssg_value_kind_text(v->kind));
        fail(b, SSG_E_TYPE);
        return;
    }
    connect(b, &n->in[port], v);
}

static void bind_param(struct builder *b, struct gnode *n, int index, const struct ssg_value *v)
{
    if (v->kind == SSG_V_REF) {
        ssg_diag_at(b->diags, SSG_E_TYPE, v->loc, "parameter '%s' of node '%s' takes a value, "
                    "not a port reference", n->desc->params.params[index].name, n->name);
        fail(b, SSG_E_TYPE);
        return;
    }
    enum ssg_err e = ssg_param_set(n->desc->params, index, n->params, v, n->name, b->diags);
    if (e)
        fail(b, e);
    else if (index < (int)sizeof n->param_set)
        n->param_set[index] = 1;
}

static void bind_extra(struct builder *b, struct gnode *n, const struct ssg_arg *a)
{
    for (int i = 0; i < n->extra_count; i++) {
        if (ssg_tok_eq(a->key, a->key_len, n->extra_names[i])) {
            connect(b, &n->extra[i], &a->value);
            return;
        }
    }
    if (b->in_set) { /* set changes what the call defines and never adds to it */
        fail(b, ssg_graph_set_adds(b->diags, n, a->key, a->key_len, a->key_loc));
        return;
    }
    if (n->extra_count == SSG_MAX_EXTRA) {
        ssg_diag_at(b->diags, SSG_E_RANGE, a->key_loc, "too many extra inputs for node '%s' "
                    "(at most %d)", n->name, SSG_MAX_EXTRA);
        fail(b, SSG_E_RANGE);
        return;
    }
    n->extra_names[n->extra_count] = ssg_arena_strndup(&b->g->arena, a->key, a->key_len);
    connect(b, &n->extra[n->extra_count++], &a->value);
}

/* backend=cpu|gl on any node: where it runs (graph.h). An identifier, like enum values. */
static void bind_backend(struct builder *b, struct gnode *n, const struct ssg_value *v)
{
    enum ssg_backend backend;
    if ((v->kind != SSG_V_IDENT && v->kind != SSG_V_STRING) ||
        !ssg_backend_parse(v->text, v->len, &backend)) {
        ssg_diag_at(b->diags, SSG_E_VALUE, v->loc, "backend of node '%s' must be cpu or gl",
                    n->name);
        fail(b, SSG_E_VALUE);
        return;
    }
    n->backend = backend;
    n->backend_loc = v->loc;
}

/* One key=value (from the call, a set line or the command line). */
static void bind_named(struct builder *b, struct gnode *n, const struct ssg_arg *a)
{
    const struct ssg_node_desc *d = n->desc;
    if (ssg_tok_eq(a->key, a->key_len, "backend") &&
        ssg_param_find(d->params, a->key, a->key_len) < 0) {
        bind_backend(b, n, &a->value);
        return;
    }
    int port = ssg_port_find(d->inputs, d->input_count, a->key, a->key_len);
    int param = port < 0 ? ssg_param_find(d->params, a->key, a->key_len) : -1;
    if (port >= 0)
        bind_input(b, n, port, &a->value);
    else if (param >= 0)
        bind_param(b, n, param, &a->value);
    else if (d->extra_inputs && a->value.kind == SSG_V_REF)
        bind_extra(b, n, a);
    else
        fail(b, ssg_graph_unknown_key(b->diags, n, a->key, a->key_len, a->key_loc));
}

static void bind_call(struct builder *b, struct gnode *n)
{
    const struct ssg_stmt *st = n->stmt;
    int next_port = 0, next_param = 0, named = 0;
    for (int i = 0; i < st->arg_count; i++) {
        const struct ssg_arg *a = &st->args[i];
        if (a->key) {
            named = 1;
            bind_named(b, n, a);
            continue;
        }
        if (named) {
            ssg_diag_at(b->diags, SSG_E_SYNTAX, a->value.loc, "positional argument after a "
                        "named one (expected name=value)");
            fail(b, SSG_E_SYNTAX);
        } else if (a->value.kind == SSG_V_REF && next_port < n->desc->input_count) {
            bind_input(b, n, next_port++, &a->value);
        } else if (a->value.kind != SSG_V_REF && next_param < n->desc->params.count) {
            bind_param(b, n, next_param++, &a->value);
        } else {
            ssg_diag_at(b->diags, SSG_E_VALUE, a->value.loc, "too many positional arguments "
                        "for node '%s' (it has %d inputs and %d parameters)", n->name,
                        n->desc->input_count, n->desc->params.count);
            fail(b, SSG_E_VALUE);
        }
    }
}

/* ---- directives ---- */

static int directive_int(struct builder *b, const struct ssg_stmt *st, int i, long long lo,
                         long long hi, long long *out)
{
    if (i >= st->arg_count || st->args[i].value.kind != SSG_V_NUMBER ||
        !st->args[i].value.is_integer) {
        struct ssg_loc at = i < st->arg_count ? st->args[i].value.loc : st->name_loc;
        ssg_diag_at(b->diags, SSG_E_TYPE, at, "'%.*s' expects an integer here",
                    (int)st->name_len, st->name);
        fail(b, SSG_E_TYPE);
        return 0;
    }
    double v = st->args[i].value.number;
    if (v < (double)lo || v > (double)hi) {
        ssg_diag_at(b->diags, SSG_E_SIZE, st->args[i].value.loc, "'%.*s' value %g is out of "
                    "range (expected %lld to %lld)", (int)st->name_len, st->name, v, lo, hi);
        fail(b, SSG_E_SIZE);
        return 0;
    }
    *out = (long long)v;
    return 1;
}

static const char *directive_string(struct builder *b, const struct ssg_stmt *st)
{
    if (st->arg_count != 1 || st->args[0].value.kind != SSG_V_STRING) {
        ssg_diag_at(b->diags, SSG_E_TYPE, st->arg_count ? st->args[0].value.loc : st->name_loc,
                    "'%.*s' expects one quoted path, e.g. %.*s \"file\"", (int)st->name_len,
                    st->name, (int)st->name_len, st->name);
        fail(b, SSG_E_TYPE);
        return NULL;
    }
    return st->args[0].value.text;
}

static void read_file(struct builder *b, const char *path, struct ssg_loc from);

static void directive_size(struct builder *b, const struct ssg_stmt *st)
{
    long long w, h;
    if (st->arg_count != 2) {
        ssg_diag_at(b->diags, SSG_E_SYNTAX, st->name_loc, "'size' expects a width and a "
                    "height in pixels, e.g. size 1280 720");
        fail(b, SSG_E_SYNTAX);
        return;
    }
    if (directive_int(b, st, 0, 1, 16384, &w) && directive_int(b, st, 1, 1, 16384, &h))
        b->g->width = (int)w, b->g->height = (int)h, b->g->size_loc = st->args[0].value.loc;
}

/* One integer in [lo, hi] after the keyword (guard G, jitter N); `what` completes "expects
   one ..." when more are given. 1 when *out was set. */
static int directive_one(struct builder *b, const struct ssg_stmt *st, long long lo,
                         long long hi, const char *what, long long *out)
{
    if (st->arg_count <= 1)
        return directive_int(b, st, 0, lo, hi, out);
    ssg_diag_at(b->diags, SSG_E_SYNTAX, st->args[1].value.loc, "'%.*s' expects one %s",
                (int)st->name_len, st->name, what);
    fail(b, SSG_E_SYNTAX);
    return 0;
}

/* backend cpu|gl: where nodes without their own backend= run. */
static void directive_backend(struct builder *b, const struct ssg_stmt *st)
{
    const struct ssg_value *v = st->arg_count == 1 ? &st->args[0].value : NULL;
    enum ssg_backend backend;
    if (!v || v->kind != SSG_V_IDENT || !ssg_backend_parse(v->text, v->len, &backend)) {
        ssg_diag_at(b->diags, SSG_E_SYNTAX, v ? v->loc : st->name_loc,
                    "'backend' expects cpu or gl, e.g. backend gl");
        fail(b, SSG_E_SYNTAX);
        return;
    }
    b->g->backend = backend;
}

static void directive(struct builder *b, const struct ssg_stmt *st)
{
    const char *path;
    long long seed, n;
    char resolved[512];
    if (ssg_tok_eq(st->name, st->name_len, "scene")) {
        if ((path = directive_string(b, st))) {
            ssg_path_resolve(st->loc.src->path, path, b->g->scene_path,
                             sizeof b->g->scene_path);
            b->g->scene_loc = st->args[0].value.loc;
        }
    } else if (ssg_tok_eq(st->name, st->name_len, "lights")) {
        if ((path = directive_string(b, st)))
            ssg_path_resolve(st->loc.src->path, path, b->g->lights_path,
                             sizeof b->g->lights_path);
    } else if (ssg_tok_eq(st->name, st->name_len, "size")) {
        directive_size(b, st);
    } else if (ssg_tok_eq(st->name, st->name_len, "guard")) { /* ssg_frame.guard */
        if (directive_one(b, st, 0, SSG_GUARD_MAX, "number of pixels, e.g. guard 32", &n))
            b->g->guard = (int)n, b->g->guard_loc = st->args[0].value.loc;
    } else if (ssg_tok_eq(st->name, st->name_len, "jitter")) { /* graph_time.c */
        if (directive_one(b, st, 0, SSG_JITTER_MAX, "number of phases, e.g. jitter 8", &n))
            b->g->jitter = (int)n;
    } else if (ssg_tok_eq(st->name, st->name_len, "seed")) {
        if (st->arg_count == 1 && directive_int(b, st, 0, 0, 2147483647LL, &seed))
            b->g->seed = seed;
    } else if (ssg_tok_eq(st->name, st->name_len, "backend")) {
        directive_backend(b, st);
    } else if (ssg_tok_eq(st->name, st->name_len, "include")) {
        if ((path = directive_string(b, st))) {
            ssg_path_resolve(st->loc.src->path, path, resolved, sizeof resolved);
            read_file(b, resolved, st->args[0].value.loc);
        }
    } else {
        ssg_diag_at(b->diags, SSG_E_SYNTAX, st->name_loc, "unknown statement '%.*s' (expected "
                    "name = node(...), set node.param = value, scene, lights, size, guard, "
                    "jitter, seed, backend or include)",
                    (int)st->name_len, st->name);
        fail(b, SSG_E_SYNTAX);
    }
}

/* "a.graph -> b.graph -> c.graph": the files being read, for messages. */
static void include_chain(const struct builder *b, char *buf, size_t len)
{
    size_t n = 0;
    buf[0] = 0;
    for (int i = 0; i < b->depth && n < len; i++)
        n += (size_t)snprintf(buf + n, len - n, "%s%s", i ? " -> " : "", b->stack[i]);
}

/* 0 with a message once the graph asks for more files or statements than allowed. */
static int within_limits(struct builder *b, struct ssg_loc from, int more_statements)
{
    if (b->limit_hit)
        return 0;
    const char *what = NULL;
    int limit = 0;
    if (b->files_read > MAX_FILES_READ)
        what = "files read (includes, counting repeats)", limit = MAX_FILES_READ;
    else if ((b->statements += more_statements) > MAX_STATEMENTS)
        what = "statements", limit = MAX_STATEMENTS;
    if (!what)
        return 1;
    char chain[1024];
    include_chain(b, chain, sizeof chain);
    ssg_diag_at(b->diags, SSG_E_INCLUDE, from, "the graph needs more than %d %s (expected a "
                "graph that includes fewer files; reading %s)", limit, what, chain);
    fail(b, SSG_E_INCLUDE);
    b->limit_hit = 1;
    return 0;
}

static void add_set(struct builder *b, const struct ssg_stmt *st)
{
    if (b->set_count == b->set_cap) {
        int cap = b->set_cap ? 2 * b->set_cap : 64;
        const struct ssg_stmt **sets = ssg_arena_alloc(&b->g->arena, cap * sizeof *sets);
        if (!sets) {
            fail(b, SSG_E_NOMEM);
            return;
        }
        if (b->set_count)
            memcpy(sets, b->sets, (size_t)b->set_count * sizeof *sets);
        b->sets = sets;
        b->set_cap = cap;
    }
    b->sets[b->set_count++] = st;
}

static int include_cycle(struct builder *b, const char *path, struct ssg_loc from)
{
    for (int i = 0; i < b->depth; i++) {
        if (strcmp(b->stack[i], path) == 0) {
            ssg_diag_at(b->diags, SSG_E_INCLUDE, from, "'%s' includes itself (through %s)",
                        path, b->stack[b->depth - 1]);
            return 1;
        }
    }
    if (b->depth == MAX_INCLUDE_DEPTH) {
        ssg_diag_at(b->diags, SSG_E_INCLUDE, from, "includes nested deeper than %d",
                    MAX_INCLUDE_DEPTH);
        return 1;
    }
    return 0;
}

static void read_file(struct builder *b, const char *path, struct ssg_loc from)
{
    if (include_cycle(b, path, from)) {
        fail(b, SSG_E_INCLUDE);
        return;
    }
    b->files_read++;
    if (!within_limits(b, from, 0))
        return;
    fail(b, ssg_graph_file_note(b->g, path)); /* for file watchers (api_graph_files.c) */
    struct ssg_file file;
    enum ssg_err e = ssg_graph_read(b->g, path, from, !b->depth, &file, b->diags);
    if (e)
        fail(b, e);
    if (!file.src)
        return;
    b->stack[b->depth++] = file.src->path;
    if (within_limits(b, from, file.count)) {
        for (int i = 0; i < file.count && !b->limit_hit; i++) {
            const struct ssg_stmt *st = &file.stmts[i];
            if (st->kind == SSG_S_DIRECTIVE)
                directive(b, st);
            else if (st->kind == SSG_S_CALL)
                add_node(b, st);
            else
                add_set(b, st);
        }
    }
    b->depth--;
}

/* ---- set lines and overrides ---- */

/* `add node.name = node.port`: a new named input (a layer of a write node) on top of
   what the node's call defines; a name the node has already is refused (set changes it). */
static void add_extra(struct builder *b, struct gnode *n, const struct ssg_arg *a)
{
    const struct ssg_node_desc *d = n->desc;
    int known = ssg_port_find(d->inputs, d->input_count, a->key, a->key_len) >= 0 ||
                ssg_param_find(d->params, a->key, a->key_len) >= 0;
    for (int i = 0; i < n->extra_count && !known; i++)
        known = ssg_tok_eq(a->key, a->key_len, n->extra_names[i]);
    if (!d->extra_inputs || known || a->value.kind != SSG_V_REF) {
        ssg_diag_at(b->diags, SSG_E_VALUE, a->key_loc, "'add' makes a new named input "
                    "node.port: node '%s' (%s) %s", n->name, d->name,
                    !d->extra_inputs ? "takes no named inputs (expected set, which changes "
                                       "an input or parameter)"
                    : known ? "has that name already (expected set, which changes it)"
                            : "takes only port references here (expected node.port)");
        fail(b, SSG_E_VALUE);
        return;
    }
    bind_extra(b, n, a);
}

static void apply_set(struct builder *b, const struct ssg_stmt *st)
{
    int i = ssg_graph_find(b->g, st->name, st->name_len);
    if (i < 0) {
        ssg_diag_at(b->diags, SSG_E_UNKNOWN_NAME, st->name_loc, "'set' names node '%.*s', "
                    "which is not defined (define it with %.*s = node(...))", (int)st->name_len,
                    st->name, (int)st->name_len, st->name);
        fail(b, SSG_E_UNKNOWN_NAME);
        return;
    }
    if (st->adds) {
        add_extra(b, &b->g->nodes[i], &st->args[0]);
        return;
    }
    b->in_set = 1;
    bind_named(b, &b->g->nodes[i], &st->args[0]);
    b->in_set = 0;
}

/* A caller's string as a source of its own, so messages point at a column of it. */
static struct ssg_source *caller_source(struct builder *b, const char *path, const char *text)
{
    struct ssg_source *src = ssg_arena_alloc(&b->g->arena, sizeof *src);
    const char *copy = ssg_arena_strndup(&b->g->arena, text, strlen(text));
    if (!src || !copy)
        return NULL;
    *src = (struct ssg_source){.path = path, .text = copy, .len = strlen(text)};
    return src;
}

/* "node.param=value" from the command line, parsed as a set line of its own source. */
static void apply_override(struct builder *b, const char *text)
{
    struct ssg_source *src = caller_source(b, b->set_origin ? b->set_origin
                                                            : "<command line --set>", text);
    if (!src || fail(b, ssg_line_check(src, b->diags)))
        return;
    const char *dot = strchr(src->text, '.'), *eq = strchr(src->text, '=');
    struct ssg_loc at = {src, src->text};
    if (!dot || !eq || dot > eq) {
        ssg_diag_at(b->diags, SSG_E_USAGE, at, "expected --set node.param=value, got '%s'",
                    text);
        fail(b, SSG_E_USAGE);
        return;
    }
    /* The statement is a temporary (binding copies what it needs; a live graph's every
       ssg_graph_set comes here, so nothing of it may pile up in the graph's arena). */
    struct ssg_stmt set = {0}, *st = &set;
    struct ssg_arg one = {0}, *arg = &one;
    st->kind = SSG_S_SET;
    st->name = src->text;
    st->name_len = (size_t)(dot - src->text);
    st->name_loc = at;
    arg->key = dot + 1;
    arg->key_len = (size_t)(eq - dot - 1);
    arg->key_loc = (struct ssg_loc){src, dot + 1};
    if (fail(b, ssg_parse_value(&b->g->arena, src, eq + 1, &arg->value, b->diags)))
        return;
    st->args = arg;
    st->arg_count = 1;
    apply_set(b, st);
}

enum ssg_err ssg_graph_apply_set(struct ssg_graph *g, const char *text, struct ssg_diags *diags)
{
    struct builder b = {.g = g, .diags = diags, .set_origin = "<ssg_graph_set>"};
    return apply_override(&b, text), b.first;
}

/* A requested output "node.port": a port reference, resolved as any input's. */
static void want_output(struct builder *b, const char *text)
{
    struct ssg_source *src = caller_source(b, "<output>", text);
    struct ssg_value v = {0};
    enum ssg_err e = src ? ssg_parse_value(&b->g->arena, src, src->text, &v, b->diags)
                         : SSG_E_NOMEM;
    if (!e && (v.kind != SSG_V_REF || b->g->wanted_count == SSG_MAX_OUTPUTS)) {
        ssg_diag_at(b->diags, SSG_E_USAGE, v.loc, "expected at most %d outputs node.port, "
                    "got '%s'", SSG_MAX_OUTPUTS, text);
        e = SSG_E_USAGE;
    }
    if (e)
        fail(b, e);
    else
        connect(b, &b->g->wanted[b->g->wanted_count++], &v);
}

static void apply_overrides(struct builder *b, const struct ssg_overrides *ov)
{
    if (!ov)
        return;
    for (int i = 0; i < ov->output_count; i++)
        want_output(b, ov->outputs[i]);
    b->g->keep_sinks = ov->keep_sinks; /* the sinks run beside the requested outputs */
    for (int i = 0; i < ov->set_count; i++)
        apply_override(b, ov->sets[i]);
    if (ov->scene) {
        snprintf(b->g->scene_path, sizeof b->g->scene_path, "%s", ov->scene);
        b->g->scene_loc = (struct ssg_loc){0}; /* named on the command line, not a line */
    }
    if (ov->lights)
        snprintf(b->g->lights_path, sizeof b->g->lights_path, "%s", ov->lights);
    if (ov->width > 0 && ov->height > 0) {
        b->g->width = ov->width;
        b->g->height = ov->height;
    }
    if (ov->seed >= 0)
        b->g->seed = ov->seed;
    if (ov->guard_given)
        b->g->guard = ov->guard;
    if (ov->backend && !ssg_backend_parse(ov->backend, strlen(ov->backend), &b->g->forced)) {
        ssg_diag_at(b->diags, SSG_E_USAGE, (struct ssg_loc){0}, "--backend must be cpu or gl, "
                    "got '%s'", ov->backend);
        fail(b, SSG_E_USAGE);
    }
}

enum ssg_err ssg_graph_build(struct ssg_graph *g, const char *path,
                             const struct ssg_overrides *ov, struct ssg_diags *diags)
{
    struct builder *b = ssg_arena_alloc(&g->arena, sizeof *b);
    if (!b)
        return SSG_E_NOMEM;
    b->g = g;
    b->diags = diags;
    g->path = ssg_arena_strndup(&g->arena, path, strlen(path));
    g->width = 1280;
    g->height = 720;
    g->seed = 1;
    read_file(b, path, (struct ssg_loc){0});
    for (int i = 0; i < g->count; i++)
        bind_call(b, &g->nodes[i]);
    for (int i = 0; i < b->set_count; i++)
        apply_set(b, b->sets[i]);
    apply_overrides(b, ov);
    return b->first;
}
