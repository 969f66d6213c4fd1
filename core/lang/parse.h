/* parse.h - the one lexer and statement parser behind both text formats (graphs, scenes).
 *
 * A file is a list of line-oriented statements; `#` starts a comment; newlines end a
 * statement except inside (...) or [...]. Three statement shapes:
 *   [name =] callee(arg, key=value, ...)     a call: a graph node or a scene entity
 *   set name.member = value                  an override of an earlier call's argument
 *   keyword value value ...                  a directive: scene "x", size 640 480, include "y"
 * Values: numbers (12, -0.5, 1e-3), strings ("..." with \" and \\), identifiers (true,
 * cosine, white), references (node.port, or prev(node.port): that port's image in the
 * previous frame) and lists ([2, 3]).
 *
 * Tokens point into the source text; line and column are worked out only when a message is
 * printed. Everything parsed lives in the caller's arena. */
#ifndef SSG_PARSE_H
#define SSG_PARSE_H

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

#include "lang/arena.h"
#include "lang/diag.h"
#include "lang/files.h"
#include "ssgraph.h"

enum ssg_value_kind {
    SSG_V_NUMBER,
    SSG_V_STRING,
    SSG_V_IDENT,
    SSG_V_REF,
    SSG_V_LIST,
};

struct ssg_value {
    enum ssg_value_kind kind;
    struct ssg_loc loc;        /* first character of the value */
    double number;             /* NUMBER */
    int is_integer;            /* NUMBER written without '.', 'e' */
    const char *text;          /* STRING (unescaped, NUL-terminated), IDENT, REF: node name */
    size_t len;                /* bytes of text */
    const char *member;        /* REF: the port after the dot */
    size_t member_len;
    struct ssg_loc member_loc; /* REF: where the port name starts */
    int prev;                  /* REF written prev(node.port): the image the port had in
                                  the previous frame (loc: the node name inside) */
    struct ssg_value *items;   /* LIST */
    int count;                 /* LIST */
    const char *start, *end;   /* its first character as written (prev( included: loc
                                  points inside) and one past its last (its ']' or ')'):
                                  the span a text edit replaces (graph_edit.c) */
};

struct ssg_arg {
    const char *key;        /* NULL for a positional argument */
    size_t key_len;
    struct ssg_loc key_loc;
    struct ssg_value value;
};

enum ssg_stmt_kind {
    SSG_S_CALL,
    SSG_S_SET,
    SSG_S_DIRECTIVE,
};

struct ssg_stmt {
    enum ssg_stmt_kind kind;
    struct ssg_loc loc;        /* first token of the statement */
    /* CALL: the assigned name (NULL when anonymous); SET: the target name;
       DIRECTIVE: the keyword */
    const char *name;
    size_t name_len;
    struct ssg_loc name_loc;
    /* CALL: callee; SET: the member after the dot */
    const char *callee;
    size_t callee_len;
    struct ssg_loc callee_loc;
    /* CALL: arguments; DIRECTIVE: its values as positional arguments;
       SET: one argument, keyed by the member */
    struct ssg_arg *args;
    int arg_count;
    int adds;                  /* SET: 1 = written `add node.name = value`: a new named
                                  input (a write layer), where `set` only changes */
    const char *end;           /* one past its last token (a call's ')'), before any
                                  comment: the span a text edit removes */
};

struct ssg_file {
    const struct ssg_source *src;
    struct ssg_stmt *stmts;
    int count;
};

/* Reads and parses a file. A missing file is reported at `from` (an include or scene
 * statement) or without location. Syntax errors are all reported; returns the first code. */
enum ssg_err ssg_parse_file(struct ssg_arena *arena, const char *path, struct ssg_loc from,
                            struct ssg_file *out, struct ssg_diags *diags);
/* Parses text already in memory (copied into the arena) under the name `origin`. */
enum ssg_err ssg_parse_text(struct ssg_arena *arena, const char *origin, const char *text,
                            struct ssg_file *out, struct ssg_diags *diags);
/* 0 when a caller's one-line text (a --set, an ssg_graph_set key and value, an output
 * name: all of src) holds no control character (a byte below 0x20, tab included, or 0x7f);
 * else SSG_E_SYNTAX, reported at the first, named ("a newline (0x0a)"). Such a text is
 * refused whole, never cut at the newline: what follows it would be dropped, or written
 * as a line of its own by whoever saves the setting. */
enum ssg_err ssg_line_check(const struct ssg_source *src, struct ssg_diags *diags);
/* Parses a single value, e.g. the right side of a command-line `--set a.b=VALUE`. src is
 * the caller's whole one-line text (key included), refused by ssg_line_check first. */
enum ssg_err ssg_parse_value(struct ssg_arena *arena, const struct ssg_source *src,
                             const char *start, struct ssg_value *out, struct ssg_diags *diags);

/* Compares a (pointer, length) token with a C string. */
int ssg_tok_eq(const char *tok, size_t len, const char *s);

/* Human name of a value kind for messages: "a number", "a string", ... */
const char *ssg_value_kind_text(enum ssg_value_kind kind);

/* Resolves `rel` against the directory of `base_file` into out (absolute paths kept). */
void ssg_path_resolve(const char *base_file, const char *rel, char *out, size_t len);

#endif
