/* model_check.h - private to the model pre-checks (model_check.c, model_check_ply.c,
 * model_check_dae.c): the
 * bytes under check and how a refusal is worded. Messages name the file and, in a text
 * format, the line and column: "cube.dae:3:18: XML elements nested deeper than 256
 * levels". No state beyond the struct the caller passes. */
#ifndef SSG_MODEL_CHECK_H
#define SSG_MODEL_CHECK_H

#include <stddef.h>

#include "ssgraph.h"

/* One file's bytes under check, and where its message goes. */
struct ssg_check {
    const char *path; /* for messages */
    const char *data; /* the whole file (not NUL-terminated) */
    size_t len;       /* bytes */
    char *why;        /* the message of a refusal */
    size_t why_len;
};

/* 1-based line and byte column of offset at. */
void ssg_check_line_col(const struct ssg_check *s, size_t at, int *line, int *column);

/* "PATH:LINE:COLUMN: message" (at: a byte offset) or "PATH: message" into why; both
   return SSG_E_GLTF. */
enum ssg_err ssg_check_refuse_at(const struct ssg_check *s, size_t at, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
enum ssg_err ssg_check_refuse(const struct ssg_check *s, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* Where `text` first occurs in [from, to); `to` when it does not. */
size_t ssg_check_find(const struct ssg_check *s, size_t from, size_t to, const char *text);

/* A PLY's header (ends in end_header within SSG_PLY_MAX_HEADER bytes) and its element
   and list counts against the bytes after it (model_check_ply.c). */
#define SSG_PLY_MAX_HEADER (1 << 20)
enum ssg_err ssg_check_ply(const struct ssg_check *s);

/* What the COLLADA checks carry from tag to tag (model_check_dae.c). The walk over the
   tags runs twice: pass 0 checks each tag alone and records every data array's id and
   count (the importer keeps the last array of an id, and so does `arrays`), pass 1 checks
   each <accessor> against the array it names. Zero-initialised; ssg_check_dae_free. */
struct ssg_dae_scan {
    int pass;                   /* 0 or 1 */
    struct ssg_dae_array *arrays; /* malloc'd, sorted by id once pass 0 ends */
    size_t array_count, array_cap;
};

/* One open tag [at, end) of a COLLADA file (closed: it ends in "/>"): in pass 0 its count
   attribute against the file's size, an index list's text, a data array's count; in pass
   1 an accessor's reach into its array. */
enum ssg_err ssg_check_dae_tag(const struct ssg_check *s, struct ssg_dae_scan *scan, size_t at,
                               size_t end, int closed);
/* Between the passes: the arrays sorted for lookup. */
void ssg_check_dae_sort(struct ssg_dae_scan *scan);
void ssg_check_dae_free(struct ssg_dae_scan *scan);

#endif
