/* lex.c - the lexer shared by graph and scene files (lex.h): turns a source text into
 * tokens that point into it. It is separate from the statement parser (parse.c) because it
 * works on characters where the parser works on tokens; the two share only lex.h. Errors
 * (a stray byte, an unterminated string, an overlong line) are reported and lexing goes
 * on, so one run reports every problem in a file. */
#include <stdio.h>
#include <string.h>

#include "lang/lex.h"
#include "lang/parse.h"

/* A text may not ask the lexer for more than this, refused with a located message; no real
   file comes near it. */
enum {
    MAX_LINE_BYTES = 65536, /* bytes in one physical line */
};

static const char *const tok_texts[] = {
    "end of file", "end of line", "a name", "a number", "a string", "'('", "')'", "'['",
    "']'", "','", "'='", "'.'",
};

const char *ssg_tok_text(enum tok_kind kind)
{
    return tok_texts[kind];
}

int ssg_tok_eq(const char *tok, size_t len, const char *s)
{
    return tok && strlen(s) == len && memcmp(tok, s, len) == 0;
}

void ssg_syntax_verror(struct lexer *lx, const char *at, const char *fmt, va_list ap)
{
    struct ssg_loc loc = {lx->src, at};
    ssg_diag_vat(lx->diags, SSG_E_SYNTAX, loc, fmt, ap);
    lx->errors++;
}

static void error_at(struct lexer *lx, const char *at, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static void error_at(struct lexer *lx, const char *at, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    ssg_syntax_verror(lx, at, fmt, ap);
    va_end(ap);
}

static int is_ident_start(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

static int is_digit(char c)
{
    return c >= '0' && c <= '9';
}

static int push_token(struct lexer *lx, enum tok_kind kind, const char *at, size_t len)
{
    if (lx->count == lx->cap) {
        int cap = lx->cap ? lx->cap * 2 : 256;
        struct token *t = ssg_arena_alloc(lx->arena, (size_t)cap * sizeof *t);
        if (!t)
            return 0;
        if (lx->count)
            memcpy(t, lx->toks, (size_t)lx->count * sizeof *t);
        lx->toks = t;
        lx->cap = cap;
    }
    lx->toks[lx->count++] = (struct token){kind, at, len};
    return 1;
}

/* Length of a number at p (sign, digits, fraction, exponent), 0 if none. */
static size_t number_length(const char *p)
{
    const char *s = p;
    if (*s == '-' || *s == '+')
        s++;
    const char *digits = s;
    while (is_digit(*s))
        s++;
    if (*s == '.' && is_digit(s[1])) {
        s++;
        while (is_digit(*s))
            s++;
    }
    if (s == digits)
        return 0;
    if ((*s == 'e' || *s == 'E') &&
        (is_digit(s[1]) || ((s[1] == '-' || s[1] == '+') && is_digit(s[2])))) {
        s += 2;
        while (is_digit(*s))
            s++;
    }
    return (size_t)(s - p);
}

/* Bytes below 0x20 and 0x7f: never part of a value (a string spells them \\n, \\t). */
static int is_control(char c)
{
    return (unsigned char)c < 0x20 || c == 0x7f;
}

/* How a message names control byte c: "a newline (0x0a)". */
static void control_text(char c, char *buf, size_t len)
{
    static const struct {
        char c;
        const char *name;
    } names[] = {{'\n', "a newline"}, {'\r', "a carriage return"}, {'\t', "a tab"},
                 {0x1b, "an escape"}, {0x7f, "a delete"}};
    const char *name = "a control character";
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (names[i].c == c)
            name = names[i].name;
    snprintf(buf, len, "%s (0x%02x)", name, (unsigned char)c);
}

/* A raw control byte inside a string: its first is reported (files are text; a tab or an
   escape sequence pasted into a name would be written back raw by whoever saves it). */
static size_t string_length(struct lexer *lx, const char *p)
{
    const char *s = p + 1, *control = NULL;
    while (*s && *s != '"' && *s != '\n') {
        if (*s == '\\' && s[1] && !is_control(s[1]))
            s++;
        else if (is_control(*s) && !control)
            control = s;
        s++;
    }
    if (control) {
        char what[48];
        control_text(*control, what, sizeof what);
        error_at(lx, control, "%s in a string (expected printable text; write a newline "
                 "or a tab as \\n or \\t)", what);
    }
    if (*s != '"') {
        error_at(lx, p, "unterminated string (expected a closing '\"' on the same line)");
        return (size_t)(s - p);
    }
    return (size_t)(s - p) + 1;
}

static enum tok_kind punct_kind(char c)
{
    switch (c) {
    case '(': return T_LPAREN;
    case ')': return T_RPAREN;
    case '[': return T_LBRACK;
    case ']': return T_RBRACK;
    case ',': return T_COMMA;
    case '=': return T_EQ;
    case '.': return T_DOT;
    default: return T_EOF;
    }
}

/* Newlines inside (...) or [...] do not end a statement, so long calls may wrap. */
int ssg_lex(struct lexer *lx, const char *p, const char *end)
{
    int depth = 0;
    const char *line = p;
    while (p < end) {
        char c = *p;
        size_t n;
        if (p - line > MAX_LINE_BYTES) {
            error_at(lx, line, "line longer than %d bytes (expected a text file of "
                     "statements)", MAX_LINE_BYTES);
            break; /* reported: the rest of such a file is not worth reading */
        }
        if (c == ' ' || c == '\t' || c == '\r') {
            p++;
        } else if (c == '#') {
            while (p < end && *p != '\n')
                p++;
        } else if (c == '\n') {
            if (depth == 0 && !push_token(lx, T_NEWLINE, p, 1))
                return 0;
            p++;
            line = p;
        } else if (is_ident_start(c)) {
            const char *s = p;
            while (is_ident_start(*p) || is_digit(*p))
                p++;
            if (!push_token(lx, T_IDENT, s, (size_t)(p - s)))
                return 0;
        } else if ((n = number_length(p)) > 0) {
            if (!push_token(lx, T_NUMBER, p, n))
                return 0;
            p += n;
        } else if (c == '"') {
            n = string_length(lx, p);
            if (!push_token(lx, T_STRING, p, n))
                return 0;
            p += n;
        } else if (punct_kind(c) != T_EOF) {
            enum tok_kind k = punct_kind(c);
            depth += (k == T_LPAREN || k == T_LBRACK) - (k == T_RPAREN || k == T_RBRACK);
            if (depth < 0)
                depth = 0;
            if (!push_token(lx, k, p, 1))
                return 0;
            p++;
        } else {
            if ((unsigned char)c >= 32 && (unsigned char)c < 127)
                error_at(lx, p, "unexpected character '%c'", c);
            else
                error_at(lx, p, "unexpected byte 0x%02x (is this a text file?)",
                         (unsigned char)c);
            p++;
        }
    }
    return push_token(lx, T_NEWLINE, end, 0) && push_token(lx, T_EOF, end, 0);
}

enum ssg_err ssg_line_check(const struct ssg_source *src, struct ssg_diags *diags)
{
    for (const char *s = src->text; s < src->text + src->len; s++) {
        if (!is_control(*s))
            continue;
        char what[48];
        control_text(*s, what, sizeof what);
        ssg_diag_at(diags, SSG_E_SYNTAX, (struct ssg_loc){src, s}, "%s in a setting "
                    "given as one line (expected printable text: a value ends at the end "
                    "of its text; write a newline or a tab in a string as \\n or \\t)",
                    what);
        return SSG_E_SYNTAX;
    }
    return SSG_OK;
}
