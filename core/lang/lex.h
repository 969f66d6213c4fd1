/* lex.h - private to core/lang: the tokens of graph and scene files, made by lex.c and
 * read by the statement parser in parse.c. The two halves meet only here, so the parser
 * never looks at characters and the lexer never knows what a statement is.
 *
 * Tokens point into the source text (nothing is copied); the token array lives in the
 * lexer's arena. One lexer per text being parsed; not shared between threads. */
#ifndef SSG_LEX_H
#define SSG_LEX_H

#include <stdarg.h>
#include <stddef.h>

#include "lang/arena.h"
#include "lang/diag.h"

enum tok_kind {
    T_EOF,
    T_NEWLINE,
    T_IDENT,
    T_NUMBER,
    T_STRING,
    T_LPAREN,
    T_RPAREN,
    T_LBRACK,
    T_RBRACK,
    T_COMMA,
    T_EQ,
    T_DOT,
};

struct token {
    enum tok_kind kind;
    const char *at; /* first byte in the source text */
    size_t len;     /* bytes, quotes included for a string */
};

struct lexer {
    struct ssg_arena *arena;      /* holds the token array */
    const struct ssg_source *src; /* the text tokens point into, for locations */
    struct ssg_diags *diags;      /* where syntax errors go */
    struct token *toks;           /* count tokens; a tokenised text ends NEWLINE, EOF */
    int count, cap;
    int errors; /* syntax errors reported so far, by the lexer and by its parser */
};

/* Tokenises [p, end) into lx->toks, reporting bad characters, unterminated strings and
   overlong lines as it goes. Newlines inside (...) or [...] are dropped, so long calls
   may wrap. Returns 0 only when out of memory. */
int ssg_lex(struct lexer *lx, const char *p, const char *end);

/* How a token kind reads in a message: "a name", "')'", "end of line", ... */
const char *ssg_tok_text(enum tok_kind kind);

/* Reports a syntax error at `at` (a pointer into lx->src) and counts it. */
void ssg_syntax_verror(struct lexer *lx, const char *at, const char *fmt, va_list ap);

#endif
