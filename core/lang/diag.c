/* diag.c - error codes and the diagnostics list. Messages are formatted like a compiler's:
 * `file:line:column: error: message`. Locations are computed from a token pointer only
 * here, when a message is made (see diag.h). */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "lang/diag.h"

static const char *const err_names[] = {
#define X(code, text) #code,
#include "errors.def"
#undef X
};

static const char *const err_texts[] = {
#define X(code, text) text,
#include "errors.def"
#undef X
};

const char *ssg_err_name(enum ssg_err code)
{
    return (unsigned)code < SSG_ERR_COUNT ? err_names[code] : "SSG_E_UNKNOWN";
}

const char *ssg_err_text(enum ssg_err code)
{
    return (unsigned)code < SSG_ERR_COUNT ? err_texts[code] : "unknown error";
}

void ssg_loc_linecol(struct ssg_loc loc, int *line, int *column)
{
    *line = 0;
    *column = 0;
    if (!loc.src || !loc.at)
        return;
    int l = 1, c = 1;
    for (const char *p = loc.src->text; p < loc.at && *p; p++) {
        if (*p == '\n') {
            l++;
            c = 1;
        } else {
            c++;
        }
    }
    *line = l;
    *column = c;
}

/* Takes the next slot, or only counts when the list is full. */
static struct ssg_diag *diag_slot(struct ssg_diags *diags, enum ssg_err code)
{
    if (!diags)
        return NULL;
    diags->total++;
    if (diags->count >= SSG_DIAGS_MAX)
        return NULL;
    struct ssg_diag *d = &diags->items[diags->count++];
    memset(d, 0, sizeof *d);
    d->code = code;
    return d;
}

void ssg_diag_vat(struct ssg_diags *diags, enum ssg_err code, struct ssg_loc loc,
                  const char *fmt, va_list ap)
{
    struct ssg_diag *d = diag_slot(diags, code);
    if (!d)
        return;
    if (loc.src)
        snprintf(d->file, sizeof d->file, "%s", loc.src->path);
    ssg_loc_linecol(loc, &d->line, &d->column);
    vsnprintf(d->message, sizeof d->message, fmt, ap);
}

void ssg_diag_at(struct ssg_diags *diags, enum ssg_err code, struct ssg_loc loc,
                 const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    ssg_diag_vat(diags, code, loc, fmt, ap);
    va_end(ap);
}

void ssg_diag_warn(struct ssg_diags *diags, enum ssg_err code, struct ssg_loc loc,
                   const char *fmt, ...)
{
    if (!diags || diags->warning_count >= SSG_WARNINGS_MAX)
        return;
    struct ssg_diag *d = &diags->warnings[diags->warning_count++];
    memset(d, 0, sizeof *d);
    d->code = code;
    if (loc.src)
        snprintf(d->file, sizeof d->file, "%s", loc.src->path);
    ssg_loc_linecol(loc, &d->line, &d->column);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(d->message, sizeof d->message, fmt, ap);
    va_end(ap);
}

void ssg_diag_file(struct ssg_diags *diags, enum ssg_err code, const char *file,
                   const char *fmt, ...)
{
    struct ssg_diag *d = diag_slot(diags, code);
    if (!d)
        return;
    snprintf(d->file, sizeof d->file, "%s", file ? file : "");
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(d->message, sizeof d->message, fmt, ap);
    va_end(ap);
}

static void print_one(const struct ssg_diag *d, const char *severity, FILE *stream)
{
    if (d->file[0] && d->line > 0)
        fprintf(stream, "%s:%d:%d: %s: %s\n", d->file, d->line, d->column, severity,
                d->message);
    else if (d->file[0])
        fprintf(stream, "%s: %s: %s\n", d->file, severity, d->message);
    else
        fprintf(stream, "ssgraph: %s: %s\n", severity, d->message);
}

int ssg_api_null(struct ssg_diags *diags, const char *function, const char *names, int count,
                 ...)
{
    va_list ap;
    va_start(ap, count);
    int missing = -1;
    for (int i = 0; i < count; i++)
        if (!va_arg(ap, const void *) && missing < 0)
            missing = i;
    va_end(ap);
    if (missing < 0)
        return 0;
    const char *name = names; /* the missing one's entry of "a, b, c" */
    for (int i = 0; i < missing && strchr(name, ','); i++)
        name = strchr(name, ',') + 1;
    name += strspn(name, " ");
    ssg_diag_file(diags, SSG_E_USAGE, NULL, "%s: %.*s is NULL (expected a valid pointer)",
                  function, (int)strcspn(name, ","), name);
    return 1;
}

void ssg_diags_print(const struct ssg_diags *diags, FILE *stream)
{
    if (!diags || !stream)
        return;
    for (int i = 0; i < diags->warning_count && i < SSG_WARNINGS_MAX; i++)
        print_one(&diags->warnings[i], "warning", stream);
    for (int i = 0; i < diags->count; i++)
        print_one(&diags->items[i], "error", stream);
    if (diags->total > diags->count)
        fprintf(stream, "ssgraph: %d more errors not shown\n", diags->total - diags->count);
}

enum ssg_err ssg_diags_first(const struct ssg_diags *diags)
{
    return diags && diags->count ? diags->items[0].code : SSG_OK;
}
