/* model_check_ply.c - the PLY pre-check (model_check.h). Assimp's PLY reader looks for
 * end_header without a bound (a 22-byte header without it spins forever), resizes a vector
 * to each element's count in the header, and to each list's count in the data, before it
 * reads a single entry: 219 bytes claiming 2e9 faces cost a minute and 15 GB. So the
 * header must end within SSG_PLY_MAX_HEADER bytes and hold no NUL byte (which hangs it as
 * well), and every count must fit in the bytes that follow: binary, each entry's smallest
 * size times the count (and every list's entries) within what is left; ASCII, two
 * characters a value (a digit and a space), each list within its line. The data are walked
 * once, in order, never allocated. */
#include <ctype.h>
#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "scene/model_check.h"

/* Beyond these an element or a file is not walked (its counts are still checked against
   the size): 3D Gaussian splats have 62 properties a vertex, real files a few elements. */
enum { MAX_ELEMENTS = 16, MAX_PROPS = 128, MAX_WORDS = 6 };
enum ply_format { PLY_UNKNOWN, PLY_ASCII, PLY_LITTLE, PLY_BIG };

struct ply_prop {
    int list;         /* 1 = a list: a count, then that many entries */
    int size;         /* bytes of a scalar, or of each entry of a list; 0 = unknown type */
    int count_size;   /* a list: bytes of its count; 0 = unknown type */
    int count_signed; /* the list's count type is signed (a negative count is absurd) */
};

struct ply_element {
    char name[32];
    size_t name_at, name_len; /* the whole name in the file, for duplicates */
    unsigned long long count; /* entries, as the header claims */
    size_t at;                /* its header line, for messages */
    size_t min_bytes;         /* a binary entry's smallest size (lists empty, unknown types
                                 0 bytes): a lower bound */
    int values;               /* values an ASCII entry has at least (a list: its count) */
    int prop_count;           /* properties in props */
    int complete;             /* every property is in props (none past MAX_PROPS) */
    int sized;                /* complete, and every type's size is known */
    int has_list;
    struct ply_prop props[MAX_PROPS];
};

struct ply_header {
    enum ply_format format;
    int element_count;
    struct ply_element elements[MAX_ELEMENTS];
    size_t data; /* first byte after the end_header line */
};

/* One header line split into words. */
struct ply_line {
    size_t at, end; /* [at, end): the line without its end */
    int words;
    size_t word[MAX_WORDS], word_len[MAX_WORDS];
};

static size_t line_end(const struct ssg_check *s, size_t at, size_t limit)
{
    while (at < limit && s->data[at] != '\n' && s->data[at] != '\r')
        at++;
    return at;
}

static void split_line(const struct ssg_check *s, size_t at, size_t end, struct ply_line *l)
{
    l->at = at, l->end = end, l->words = 0;
    for (size_t i = at; i < end && l->words < MAX_WORDS;) {
        while (i < end && isspace((unsigned char)s->data[i]))
            i++;
        size_t w = i;
        while (i < end && !isspace((unsigned char)s->data[i]))
            i++;
        if (i > w)
            l->word[l->words] = w, l->word_len[l->words++] = i - w;
    }
}

static int word_is(const struct ssg_check *s, const struct ply_line *l, int k, const char *text)
{
    return k < l->words && l->word_len[k] == strlen(text) &&
           !memcmp(s->data + l->word[k], text, l->word_len[k]);
}

/* Bytes of a PLY scalar type (both spellings), 0 when unknown; *is_signed for counts. */
static int type_size(const struct ssg_check *s, const struct ply_line *l, int k, int *is_signed)
{
    static const struct { const char *name; int size, is_signed; } types[] = {
        {"char", 1, 1},  {"int8", 1, 1},   {"uchar", 1, 0},  {"uint8", 1, 0},
        {"short", 2, 1}, {"int16", 2, 1},  {"ushort", 2, 0}, {"uint16", 2, 0},
        {"int", 4, 1},   {"int32", 4, 1},  {"uint", 4, 0},   {"uint32", 4, 0},
        {"float", 4, 1}, {"float32", 4, 1}, {"double", 8, 1}, {"float64", 8, 1}};
    for (size_t i = 0; i < sizeof types / sizeof types[0]; i++)
        if (word_is(s, l, k, types[i].name)) {
            *is_signed = types[i].is_signed;
            return types[i].size;
        }
    *is_signed = 0;
    return 0;
}

/* A decimal count, saturating at ULLONG_MAX; a sign or any other character is absurd
   for a count and saturates too. */
static unsigned long long parse_count(const char *p, size_t n)
{
    unsigned long long v = 0;
    for (size_t i = 0; i < n; i++) {
        if (p[i] < '0' || p[i] > '9' || v > (ULLONG_MAX - 9) / 10)
            return ULLONG_MAX;
        v = v * 10 + (unsigned)(p[i] - '0');
    }
    return n ? v : ULLONG_MAX;
}

static enum ssg_err add_element(const struct ssg_check *s, const struct ply_line *l,
                                struct ply_header *h)
{
    if (l->words < 3)
        return ssg_check_refuse_at(s, l->at, "a PLY element line needs a name and a count");
    if (h->element_count == MAX_ELEMENTS)
        return ssg_check_refuse_at(s, l->at, "a PLY header with over %d elements",
                                   MAX_ELEMENTS);
    if (isdigit((unsigned char)s->data[l->word[1]])) /* found by fuzz/fuzz_model.c */
        return ssg_check_refuse_at(s, l->word[1], "a PLY element name starting with a digit "
                                   "(Assimp reads an unknown name's digits as its count)");
    for (int i = 0; i < h->element_count; i++) /* found by fuzz/fuzz_model.c */
        if (h->elements[i].name_len == l->word_len[1] &&
            !memcmp(s->data + h->elements[i].name_at, s->data + l->word[1], l->word_len[1]))
            return ssg_check_refuse_at(s, l->word[1], "a second PLY element '%.*s' (Assimp "
                                       "sizes its arrays by the first and overruns them)",
                                       (int)l->word_len[1], s->data + l->word[1]);
    struct ply_element *e = &h->elements[h->element_count++];
    memset(e, 0, sizeof *e);
    size_t n = l->word_len[1] < sizeof e->name ? l->word_len[1] : sizeof e->name - 1;
    memcpy(e->name, s->data + l->word[1], n);
    e->name_at = l->word[1], e->name_len = l->word_len[1];
    e->count = parse_count(s->data + l->word[2], l->word_len[2]);
    e->at = l->word[2];
    e->complete = e->sized = 1;
    return SSG_OK;
}

static void add_property(const struct ssg_check *s, const struct ply_line *l,
                         struct ply_header *h)
{
    if (!h->element_count)
        return; /* before any element: Assimp's concern */
    struct ply_element *e = &h->elements[h->element_count - 1];
    struct ply_prop p = {.list = word_is(s, l, 1, "list")};
    int is_signed;
    if (p.list) {
        p.count_size = type_size(s, l, 2, &p.count_signed);
        p.size = type_size(s, l, 3, &is_signed);
    } else {
        p.size = type_size(s, l, 1, &is_signed);
    }
    e->min_bytes += p.list ? (size_t)p.count_size : (size_t)p.size;
    e->values++;
    e->has_list |= p.list;
    if (!p.size || (p.list && !p.count_size))
        e->sized = 0;
    if (e->prop_count < MAX_PROPS)
        e->props[e->prop_count++] = p;
    else
        e->complete = e->sized = 0;
}

static enum ssg_err header_line(const struct ssg_check *s, const struct ply_line *l,
                                struct ply_header *h)
{
    if (word_is(s, l, 0, "format"))
        h->format = word_is(s, l, 1, "ascii")                  ? PLY_ASCII
                    : word_is(s, l, 1, "binary_little_endian") ? PLY_LITTLE
                    : word_is(s, l, 1, "binary_big_endian")    ? PLY_BIG
                                                               : PLY_UNKNOWN;
    else if (word_is(s, l, 0, "element"))
        return add_element(s, l, h);
    else if (word_is(s, l, 0, "property"))
        add_property(s, l, h);
    return SSG_OK;
}

static int is_line_end(char c)
{
    return c == '\r' || c == '\n' || c == '\f' || c == 0;
}

/* The next header line from at as Assimp's IOStreamBuffer::getNextLine cuts it: a line
   ends at \r, \n, \f or NUL, of which one character is consumed; a line starting on such a
   character first skips past the next \n. So "\n\rend_header\n" hides end_header from it,
   and it reads on forever (found by fuzz/fuzz_model.c). Returns the line's end; its start
   into *start. */
static size_t next_header_line(const struct ssg_check *s, size_t at, size_t limit,
                               size_t *start)
{
    if (at < limit && is_line_end(s->data[at])) {
        const char *nl = memchr(s->data + at, '\n', limit - at);
        at = nl ? (size_t)(nl - s->data) + 1 : limit;
    }
    *start = at;
    while (at < limit && !is_line_end(s->data[at]))
        at++;
    return at;
}

/* Reads the header up to end_header, line by line as Assimp does; h->data is where the
   data begin. */
static enum ssg_err read_header(const struct ssg_check *s, struct ply_header *h)
{
    size_t limit = s->len < SSG_PLY_MAX_HEADER ? s->len : SSG_PLY_MAX_HEADER, start;
    for (size_t at = 0; at < limit;) {
        struct ply_line l;
        size_t end = next_header_line(s, at, limit, &start);
        split_line(s, start, end, &l);
        at = end + 1;
        if (word_is(s, &l, 0, "end_header")) {
            const char *nul = memchr(s->data, 0, end); /* found by fuzz/fuzz_model.c */
            h->data = at + (at < s->len && s->data[end] == '\r' && s->data[at] == '\n');
            return nul ? ssg_check_refuse_at(s, (size_t)(nul - s->data), "a NUL byte in the "
                                             "PLY header (Assimp's reader loops forever on it)")
                       : SSG_OK;
        }
        enum ssg_err e = header_line(s, &l, h);
        if (e)
            return e;
    }
    if (limit < s->len)
        return ssg_check_refuse(s, "a PLY header with no end_header line in its first %d "
                                "bytes", SSG_PLY_MAX_HEADER);
    return ssg_check_refuse(s, "a PLY header with no end_header line Assimp would find (the "
                            "file ends after %zu bytes, or an empty line before end_header "
                            "hides it)", s->len);
}

static unsigned long long read_uint(const char *p, int size, int big, int is_signed)
{
    unsigned long long v = 0;
    for (int i = 0; i < size; i++)
        v |= (unsigned long long)(unsigned char)p[big ? size - 1 - i : i] << (8 * i);
    if (is_signed && (v >> (8 * size - 1)) & 1)
        return ULLONG_MAX; /* a negative count */
    return v;
}

/* One binary entry of e at *at: each list's entries must fit in what is left. */
static enum ssg_err walk_binary_entry(const struct ssg_check *s, const struct ply_header *h,
                                      const struct ply_element *e, unsigned long long k,
                                      size_t *at)
{
    for (int i = 0; i < e->prop_count; i++) {
        const struct ply_prop *p = &e->props[i];
        size_t n = p->list ? (size_t)p->count_size : (size_t)p->size;
        if (n > s->len - *at)
            return ssg_check_refuse(s, "the PLY data end inside %s %llu (byte %zu)", e->name,
                                    k, *at);
        if (!p->list) {
            *at += n;
            continue;
        }
        unsigned long long count =
            read_uint(s->data + *at, p->count_size, h->format == PLY_BIG, p->count_signed);
        *at += n;
        if (count > (s->len - *at) / (size_t)p->size)
            return ssg_check_refuse(s, "PLY %s %llu holds a list of %llu entries of %d bytes "
                                    "at byte %zu, but %zu bytes are left", e->name, k, count,
                                    p->size, *at - n, s->len - *at);
        *at += (size_t)count * (size_t)p->size;
    }
    return SSG_OK;
}

/* Once an element of unknown size has passed (or when the format itself is unknown:
   exact 0), `at` is only a lower bound of where the next begins: its count is still
   checked against the bytes left, but not walked. */
static enum ssg_err walk_binary(const struct ssg_check *s, const struct ply_header *h,
                                int exact)
{
    size_t at = h->data;
    for (int i = 0; i < h->element_count; i++) {
        const struct ply_element *e = &h->elements[i];
        size_t min = e->min_bytes ? e->min_bytes : 1;
        if (e->count > (s->len - at) / min)
            return ssg_check_refuse_at(s, e->at, "PLY element '%s' claims %llu entries (of "
                                       "%zu or more bytes each), but only %zu bytes of data "
                                       "follow", e->name, e->count, min, s->len - at);
        exact &= e->sized;
        if (!exact || !e->has_list) {
            at += (size_t)e->count * e->min_bytes;
            continue;
        }
        for (unsigned long long k = 0; k < e->count; k++) {
            enum ssg_err err = walk_binary_entry(s, h, e, k, &at);
            if (err)
                return err;
        }
    }
    return SSG_OK;
}

/* The next data line at or after *at, blank lines skipped as Assimp skips them: [*at, end)
   on return; 0 at the end of the file. */
static int next_line(const struct ssg_check *s, size_t *at, size_t *end)
{
    while (*at < s->len && (s->data[*at] == '\n' || s->data[*at] == '\r'))
        (*at)++;
    *end = line_end(s, *at, s->len);
    return *at < s->len;
}

/* One ASCII entry on the line [at, end): a list's count must leave room on the line for
   its entries, a digit and a space each (Assimp reads an entry from one line). */
static enum ssg_err walk_ascii_entry(const struct ssg_check *s, const struct ply_element *e,
                                     size_t at, size_t end)
{
    for (int i = 0; i < e->prop_count; i++) {
        while (at < end && isspace((unsigned char)s->data[at]))
            at++;
        size_t w = at;
        while (at < end && !isspace((unsigned char)s->data[at]))
            at++;
        if (at == w)
            return SSG_OK; /* a short line: Assimp reads what is there */
        if (!e->props[i].list)
            continue;
        unsigned long long count = parse_count(s->data + w, at - w);
        if (count > (end - at + 1) / 2)
            return ssg_check_refuse_at(s, w, "PLY %s holds a list of %.*s entries on a line "
                                       "with room for %zu", e->name, (int)(at - w),
                                       s->data + w, (end - at + 1) / 2);
        for (unsigned long long k = 0; k < count; k++) { /* its entries */
            while (at < end && isspace((unsigned char)s->data[at]))
                at++;
            while (at < end && !isspace((unsigned char)s->data[at]))
                at++;
        }
    }
    return SSG_OK;
}

/* Digits a number of the ASCII data may have before its point or exponent: a double's
   precision and then some. Assimp's reader turns a longer run of digits (19 and more;
   fuzzed) into a request for tens of gigabytes. */
enum { MAX_INTEGER_DIGITS = 17 };

static enum ssg_err check_ascii_numbers(const struct ssg_check *s, size_t at)
{
    for (size_t i = at; i < s->len;) {
        size_t start = i + (s->data[i] == '-' || s->data[i] == '+');
        size_t d = start;
        while (d < s->len && isdigit((unsigned char)s->data[d]))
            d++;
        if (d - start > MAX_INTEGER_DIGITS)
            return ssg_check_refuse_at(s, i, "a number with %zu digits before its point in "
                                       "the PLY data (at most %d)", d - start,
                                       MAX_INTEGER_DIGITS);
        i = d > i ? d : i + 1;
        while (i < s->len && !isspace((unsigned char)s->data[i]))
            i++; /* the rest of this token */
        while (i < s->len && isspace((unsigned char)s->data[i]))
            i++;
    }
    return SSG_OK;
}

static enum ssg_err walk_ascii(const struct ssg_check *s, const struct ply_header *h)
{
    enum ssg_err numbers = check_ascii_numbers(s, h->data);
    if (numbers)
        return numbers;
    size_t at = h->data, end;
    for (int i = 0; i < h->element_count; i++) {
        const struct ply_element *e = &h->elements[i];
        size_t min = 2 * (size_t)(e->values ? e->values : 1); /* "0 0 0\n": 2 a value */
        if (e->count > (s->len - at + 1) / min)
            return ssg_check_refuse_at(s, e->at, "PLY element '%s' claims %llu entries (of "
                                       "%zu or more characters each), but only %zu characters "
                                       "of data follow", e->name, e->count, min, s->len - at);
        for (unsigned long long k = 0; k < e->count && next_line(s, &at, &end); k++) {
            enum ssg_err err =
                e->has_list && e->complete ? walk_ascii_entry(s, e, at, end) : SSG_OK;
            if (err)
                return err;
            at = end;
        }
    }
    return SSG_OK;
}

enum ssg_err ssg_check_ply(const struct ssg_check *s)
{
    if (s->len < 3 || memcmp(s->data, "ply", 3))
        return SSG_OK; /* not a PLY: Assimp says so */
    struct ply_header *h = calloc(1, sizeof *h);
    if (!h) {
        ssg_check_refuse(s, "out of memory");
        return SSG_E_NOMEM;
    }
    enum ssg_err e = read_header(s, h);
    if (!e && h->format == PLY_ASCII)
        e = walk_ascii(s, h);
    else if (!e) /* an unknown format still takes a byte or more an entry */
        e = walk_binary(s, h, h->format != PLY_UNKNOWN);
    free(h);
    return e;
}
