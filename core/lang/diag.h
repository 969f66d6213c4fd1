/* diag.h - where a message points and how it is recorded: sources (a loaded text), places
 * in them, and the diagnostics every layer appends to a struct ssg_diags (ssgraph.h), with
 * file:line:column worked out only when a message is made (diag.c). Shared by the parser,
 * the graph and scene builders, the executor, the nodes, the image and file I/O and the
 * CLI, none of which needs the parser for it.
 *
 * Ownership: a source's text belongs to whoever loaded it (an arena); diagnostics copy
 * what they keep. Thread safety: appending to one struct ssg_diags is not thread-safe;
 * nodes report from their own thread, never from inside row bands. */
#ifndef SSG_DIAG_H
#define SSG_DIAG_H

#include <stdarg.h>
#include <stddef.h>

#include "ssgraph.h"

/* One loaded text: a file, or a command-line string. */
struct ssg_source {
    const char *path; /* as given (for messages), NUL-terminated */
    const char *text; /* NUL-terminated contents */
    size_t len;       /* bytes of text */
};

/* A place in a source. `at` points into src->text. */
struct ssg_loc {
    const struct ssg_source *src;
    const char *at;
};

/* 1-based line and column of loc (column counts bytes). Both 0 when loc.src is NULL. */
void ssg_loc_linecol(struct ssg_loc loc, int *line, int *column);

/* Appends a diagnostic at loc (or without location when loc.src is NULL). */
void ssg_diag_at(struct ssg_diags *diags, enum ssg_err code, struct ssg_loc loc,
                 const char *fmt, ...) __attribute__((format(printf, 4, 5)));
void ssg_diag_vat(struct ssg_diags *diags, enum ssg_err code, struct ssg_loc loc,
                  const char *fmt, va_list ap);
/* Appends a warning (struct ssg_diags) at a location of a source; dropped past
 * SSG_WARNINGS_MAX. */
void ssg_diag_warn(struct ssg_diags *diags, enum ssg_err code, struct ssg_loc loc,
                   const char *fmt, ...) __attribute__((format(printf, 4, 5)));
/* Appends a diagnostic naming a file but no line (I/O errors, image errors). */
/* For the public API's entry points: 1 when any of the `count` pointers is NULL, after an
 * SSG_E_USAGE diagnostic "FUNCTION: ARGUMENT is NULL" naming the first. names is a
 * comma-separated list of the arguments in the order of the pointers. A NULL diags is
 * allowed everywhere (nothing is recorded), so it is never one of them. */
int ssg_api_null(struct ssg_diags *diags, const char *function, const char *names, int count,
                 ...);

void ssg_diag_file(struct ssg_diags *diags, enum ssg_err code, const char *file,
                   const char *fmt, ...) __attribute__((format(printf, 4, 5)));

#endif
