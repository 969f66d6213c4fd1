/* model_check_dae.c - the COLLADA part of the model pre-checks (model_check.h), for two
 * ways a few changed bytes of a .dae make Assimp's COLLADA reader eat all memory (both
 * found by fuzz/fuzz_model.c):
 *   - it reads the indices of a <p> with `while (*text) { push_back(strtol10(...)); skip
 *     spaces; }`, so one character that is neither a digit nor a space stops both from
 *     advancing and the vector grows until the allocation fails (6 GB under the fuzzer);
 *   - it reserves each count="N" attribute's worth of values (a float_array's, a polylist's
 *     vcount) before reading one.
 * So the index lists may hold only digits, signs and white space, and no count may exceed
 * the file's size in bytes (every value counted takes at least one). A third, also found by
 * the fuzzer (under valgrind): a primitive (<triangles>, <polylist>, ...) without the
 * <input semantic="VERTEX"> the COLLADA specification requires of it has the reader index
 * before its input array, so each primitive with content must have one. A fourth (fuzzed,
 * a null read): a data array (<float_array>, <int_array>, ...) without its required count
 * attribute. A fifth (issue 42): an <accessor> is trusted to stay inside the array its
 * source names, so count x stride + offset (and its <param>s) must fit in that array's
 * count, and its numbers be plain decimals (the XML reader takes "-1" and "0x7fffffff"
 * too), and its stride be no less than its <param>s; and <p>, <vcount> and <h> hold no
 * negative number and none past INT_MAX (an index or a count: the reader's int would take
 * -1 for 0, or for 4 billion, and 4294967298 for 2). */
#include <ctype.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/model_check.h"

/* The elements whose text is a list of integers; those of them that may not hold a
   negative one (a <v>'s -1 is the bind shape, an int_array holds data). */
static const char *const INDEX_LISTS[] = {"p", "vcount", "v", "h", "int_array", NULL};
static const char *const UNSIGNED_LISTS[] = {"p", "vcount", "h", NULL};

/* A data array as pass 0 records it: its id's hash and where the id is, its count. */
struct ssg_dae_array {
    uint64_t hash;          /* FNV-1a of the id */
    size_t order;           /* the array's place in the file (the last of an id counts) */
    size_t id_at, id_len;   /* the id's bytes */
    unsigned long long count;
};

/* The tag name's length at at ("<name ..."). */
static size_t name_length(const struct ssg_check *s, size_t at, size_t end)
{
    size_t i = at + 1;
    while (i < end && !isspace((unsigned char)s->data[i]) && s->data[i] != '/' &&
           s->data[i] != '>')
        i++;
    return i - at - 1;
}

/* The data arrays, whose count attribute the specification requires. */
static const char *const ARRAYS[] = {"float_array", "int_array", "bool_array", "Name_array",
                                     "IDREF_array", "SIDREF_array", "token_array", NULL};

/* The elements that hold primitives, each with inputs and index lists. */
static const char *const PRIMITIVES[] = {"triangles", "polylist", "polygons", "lines",
                                         "linestrips", "trifans", "tristrips", NULL};

static int name_in(const struct ssg_check *s, size_t at, size_t n, const char *const *list)
{
    for (const char *const *name = list; *name; name++)
        if (strlen(*name) == n && !memcmp(s->data + at + 1, *name, n))
            return 1;
    return 0;
}

static int is_index_list(const struct ssg_check *s, size_t at, size_t n)
{
    return name_in(s, at, n, INDEX_LISTS);
}

/* The value of the tag [at, end)'s attribute `name` (white space before it, then '=',
   white space allowed around it, then a quoted value), outside quoted values: 1 with the
   value's bytes [*value, *value + *len), 0 when it has none. */
static int attribute(const struct ssg_check *s, size_t at, size_t end, const char *name,
                     size_t *value, size_t *len)
{
    size_t n = strlen(name);
    char quote = 0;
    for (size_t i = at + 1; i + n < end; i++) {
        char c = s->data[i];
        if (quote) {
            quote = c == quote ? 0 : quote;
            continue;
        }
        if (c == '"' || c == '\'')
            quote = c;
        if (!isspace((unsigned char)c) || memcmp(s->data + i + 1, name, n))
            continue;
        size_t v = i + 1 + n;
        while (v < end && isspace((unsigned char)s->data[v]))
            v++;
        if (v >= end || s->data[v] != '=')
            continue;
        for (v++; v < end && isspace((unsigned char)s->data[v]);)
            v++;
        if (v >= end || (s->data[v] != '"' && s->data[v] != '\''))
            continue;
        const char *close = memchr(s->data + v + 1, s->data[v], end - v - 1);
        *value = v + 1;
        *len = close ? (size_t)(close - s->data) - v - 1 : end - v - 1;
        return 1;
    }
    return 0;
}

/* A value of plain decimal digits (white space around them allowed), at most `cap`
   (larger ones read as cap + 1): 1 with it in *out, 0 when it is anything else. */
static int decimal(const struct ssg_check *s, size_t at, size_t len, unsigned long long cap,
                   unsigned long long *out)
{
    size_t i = at, end = at + len;
    while (i < end && isspace((unsigned char)s->data[i]))
        i++;
    size_t digits = i;
    *out = 0;
    for (; i < end && isdigit((unsigned char)s->data[i]); i++)
        *out = *out > cap ? cap + 1 : *out * 10 + (unsigned)(s->data[i] - '0');
    int any = i > digits;
    while (i < end && isspace((unsigned char)s->data[i]))
        i++;
    *out = *out > cap ? cap + 1 : *out;
    return any && i == end;
}

/* How much of the len bytes at `at` a message quotes: the printable start, at most 40
   (a message stays one line). */
static int shown(const struct ssg_check *s, size_t at, size_t len)
{
    size_t n = 0;
    while (n < len && n < 40 && isprint((unsigned char)s->data[at + n]))
        n++;
    return (int)n;
}

/* The tag's attribute `name` as a plain decimal into *out (fallback when it has none);
   refused when it is anything else, "-1" or "0x10" included (the XML reader would take a
   negative number modulo 2^32, and hexadecimal too). */
static enum ssg_err number(const struct ssg_check *s, size_t at, size_t end, size_t n,
                           const char *name, unsigned long long fallback,
                           unsigned long long *out)
{
    size_t v, len;
    *out = fallback;
    if (!attribute(s, at, end, name, &v, &len) || decimal(s, v, len, s->len, out))
        return SSG_OK;
    int quoted = shown(s, v, len);
    return ssg_check_refuse_at(s, v, "%s=\"%.*s%s\" on <%.*s> is not a non-negative decimal "
                               "integer", name, quoted, s->data + v,
                               (size_t)quoted < len ? "..." : "", (int)n, s->data + at + 1);
}

/* 1 when the tag [at, end) has the attribute semantic="VERTEX" (either quote), its name
   after white space as an XML reader splits it. */
static int has_vertex_semantic(const struct ssg_check *s, size_t at, size_t end)
{
    static const char *const forms[] = {"semantic=\"VERTEX\"", "semantic='VERTEX'", NULL};
    for (const char *const *form = forms; *form; form++)
        for (size_t i = ssg_check_find(s, at, end, *form); i < end;
             i = ssg_check_find(s, i + 1, end, *form))
            if (isspace((unsigned char)s->data[i - 1]))
                return 1;
    return 0;
}

/* An open primitive's content, up to its closing tag: one <input> with the VERTEX
   semantic (primitives do not nest, so the first closing tag of its name ends it). */
static enum ssg_err check_primitive(const struct ssg_check *s, size_t at, size_t end, size_t n)
{
    char close[16];
    snprintf(close, sizeof close, "</%.*s", (int)n, s->data + at + 1);
    size_t stop = ssg_check_find(s, end, s->len, close);
    for (size_t i = ssg_check_find(s, end, stop, "<input"); i < stop;
         i = ssg_check_find(s, i + 1, stop, "<input")) {
        size_t tag_end = ssg_check_find(s, i, stop, ">");
        if (has_vertex_semantic(s, i, tag_end))
            return SSG_OK;
    }
    return ssg_check_refuse_at(s, at, "<%.*s> without an <input semantic=\"VERTEX\"> (the "
                               "importer would read before its inputs)", (int)n,
                               s->data + at + 1);
}

/* The tag's count="N" attribute: a plain decimal, at most the file's size. */
static enum ssg_err check_count(const struct ssg_check *s, size_t at, size_t end, size_t n)
{
    unsigned long long count;
    enum ssg_err e = number(s, at, end, n, "count", 0, &count);
    size_t v, len;
    if (!e && count > s->len && attribute(s, at, end, "count", &v, &len))
        return ssg_check_refuse_at(s, v, "count on <%.*s> is more than a file of %zu "
                                   "bytes can hold (the importer would reserve them)",
                                   (int)n, s->data + at + 1, s->len);
    return e;
}

/* The number at i of an index or count list ('+' and digits): refused when it does not
   fit a non-negative int (the importer's strtol10 wraps 4294967298 to 2 and 2^31 to 0);
   *last: its last byte. */
static enum ssg_err check_index(const struct ssg_check *s, size_t at, size_t n, size_t i,
                                size_t *last)
{
    unsigned long long value = 0;
    size_t j = i + (s->data[i] == '+');
    for (; j < s->len && isdigit((unsigned char)s->data[j]); j++)
        value = value > INT_MAX ? value : value * 10 + (unsigned)(s->data[j] - '0');
    *last = j - 1;
    if (value <= INT_MAX)
        return SSG_OK;
    int quoted = shown(s, i, j - i);
    return ssg_check_refuse_at(s, i, "<%.*s> holds %.*s%s, more than an index or a count can "
                               "be (%d; the importer would wrap it to a small one)", (int)n,
                               s->data + at + 1, quoted, s->data + i,
                               (size_t)quoted < j - i ? "..." : "", INT_MAX);
}

/* The text after an index list's tag, up to the next tag: integers only, and where it is
   an index or a count, none negative or past INT_MAX. */
static enum ssg_err check_indices(const struct ssg_check *s, size_t at, size_t end, size_t n)
{
    int is_unsigned = name_in(s, at, n, UNSIGNED_LISTS);
    for (size_t i = end; i < s->len && s->data[i] != '<'; i++) {
        char c = s->data[i];
        if (is_unsigned && (c == '+' || isdigit((unsigned char)c))) {
            enum ssg_err e = check_index(s, at, n, i, &i);
            if (e)
                return e;
            continue;
        }
        if (c == '-' && is_unsigned)
            return ssg_check_refuse_at(s, i, "<%.*s> holds a negative number (indices and "
                                       "counts start at 0; the importer would take -1 for "
                                       "0 or for 4294967295)", (int)n, s->data + at + 1);
        if (!isdigit((unsigned char)c) && !isspace((unsigned char)c) && c != '-' && c != '+')
            return ssg_check_refuse_at(s, i, "<%.*s> holds a character that is no part of an "
                                       "integer (the importer would read it forever)", (int)n,
                                       s->data + at + 1);
    }
    return SSG_OK;
}

static uint64_t fnv1a(const char *p, size_t n)
{
    uint64_t h = 14695981039346656037ull;
    for (size_t i = 0; i < n; i++)
        h = (h ^ (unsigned char)p[i]) * 1099511628211ull;
    return h;
}

/* Pass 0: a data array's id and count, for the accessors of pass 1 (an array without an
   id cannot be named by one). */
static enum ssg_err record_array(const struct ssg_check *s, struct ssg_dae_scan *scan,
                                 size_t at, size_t end, size_t n)
{
    size_t id, id_len;
    struct ssg_dae_array a = {0};
    enum ssg_err e = number(s, at, end, n, "count", 0, &a.count);
    if (e || !attribute(s, at, end, "id", &id, &id_len))
        return e;
    if (scan->array_count == scan->array_cap) {
        size_t cap = scan->array_cap ? 2 * scan->array_cap : 64;
        struct ssg_dae_array *grown = realloc(scan->arrays, cap * sizeof *grown);
        if (!grown) {
            snprintf(s->why, s->why_len, "%s: out of memory checking its data arrays", s->path);
            return SSG_E_NOMEM;
        }
        scan->arrays = grown, scan->array_cap = cap;
    }
    a.hash = fnv1a(s->data + id, id_len);
    a.order = scan->array_count;
    a.id_at = id, a.id_len = id_len;
    scan->arrays[scan->array_count++] = a;
    return SSG_OK;
}

static int by_hash_then_order(const void *pa, const void *pb)
{
    const struct ssg_dae_array *a = pa, *b = pb;
    if (a->hash != b->hash)
        return a->hash < b->hash ? -1 : 1;
    return (a->order > b->order) - (a->order < b->order);
}

void ssg_check_dae_sort(struct ssg_dae_scan *scan)
{
    if (scan->array_count)
        qsort(scan->arrays, scan->array_count, sizeof *scan->arrays, by_hash_then_order);
}

void ssg_check_dae_free(struct ssg_dae_scan *scan)
{
    free(scan->arrays);
    *scan = (struct ssg_dae_scan){0};
}

/* The last data array in the file whose id is the n bytes at ref (the one the importer
   keeps), or NULL. */
static const struct ssg_dae_array *find_array(const struct ssg_check *s,
                                              const struct ssg_dae_scan *scan, size_t ref,
                                              size_t n)
{
    uint64_t h = fnv1a(s->data + ref, n);
    size_t lo = 0, hi = scan->array_count;
    while (lo < hi) { /* the first entry of hash > h */
        size_t mid = lo + (hi - lo) / 2;
        if (scan->arrays[mid].hash <= h)
            lo = mid + 1;
        else
            hi = mid;
    }
    for (size_t i = lo; i-- > 0 && scan->arrays[i].hash == h;)
        if (scan->arrays[i].id_len == n && !memcmp(s->data + scan->arrays[i].id_at,
                                                   s->data + ref, n))
            return &scan->arrays[i];
    return NULL;
}

/* The <param> elements of an open accessor: the tags from i on while they are <param> or
   </param> (text between them skipped), so each accessor's scan ends at its own content. */
static unsigned long long count_params(const struct ssg_check *s, size_t i)
{
    unsigned long long params = 0;
    for (;;) {
        const char *lt = memchr(s->data + i, '<', s->len - i);
        if (!lt)
            return params;
        i = (size_t)(lt - s->data);
        size_t left = s->len - i;
        if (left >= 7 && !memcmp(lt, "</param", 7)) {
            i += 7;
            continue;
        }
        char after = left > 6 ? lt[6] : '>';
        if (left < 6 || memcmp(lt, "<param", 6) ||
            !(isspace((unsigned char)after) || after == '/' || after == '>'))
            return params;
        params++;
        i += 6;
    }
}

/* The tag's attribute `name` as written, its white space trimmed (a decimal number() has
   passed, so printable), at most 40 bytes; fallback when it has none. */
static const char *written(const struct ssg_check *s, size_t at, size_t end, const char *name,
                           const char *fallback, char out[48])
{
    size_t v, len;
    if (!attribute(s, at, end, name, &v, &len))
        return fallback;
    for (; len && isspace((unsigned char)s->data[v]); v++)
        len--;
    while (len && isspace((unsigned char)s->data[v + len - 1]))
        len--;
    int quoted = shown(s, v, len);
    snprintf(out, 48, "%.*s%s", quoted, s->data + v, (size_t)quoted < len ? "..." : "");
    return out;
}

/* Pass 1: an <accessor> reads values offset + k x stride + j (k < count, j < its <param>s
   and at least j = 0) of the array its source="#id" names, without a bound: the last of
   them must lie inside that array. A source naming no array is the importer's to refuse.
   Its stride may not be less than its <param>s, nor 0 (its elements would overlap: stride
   0 reads the first values for every one). Messages print the numbers as written (the
   values read stop at the file's size). */
static enum ssg_err check_accessor(const struct ssg_check *s, const struct ssg_dae_scan *scan,
                                   size_t at, size_t end, int closed)
{
    size_t ref, ref_len;
    unsigned long long count, stride, offset;
    const size_t n = strlen("accessor");
    enum ssg_err e = number(s, at, end, n, "stride", 1, &stride);
    if (!e)
        e = number(s, at, end, n, "offset", 0, &offset);
    if (e || !attribute(s, at, end, "source", &ref, &ref_len) || ref_len < 2 ||
        s->data[ref] != '#')
        return e;
    const struct ssg_dae_array *a = find_array(s, scan, ref + 1, ref_len - 1);
    number(s, at, end, n, "count", 0, &count); /* checked in pass 0 */
    if (!a || count == 0)
        return SSG_OK;
    unsigned long long params = closed ? 0 : count_params(s, end);
    unsigned long long last = params > stride ? params : stride > 0 ? stride : 1;
    char stride_text[48], offset_text[48], count_text[48], last_text[48];
    const char *stride_is = written(s, at, end, "stride", "1", stride_text);
    /* offset + (count - 1) x stride + last <= the array's count, without a product that
       could wrap */
    unsigned long long room = a->count >= offset + last ? a->count - offset - last : 0;
    if (a->count >= offset + last && (stride == 0 || count - 1 <= room / stride))
        return stride >= params && stride > 0
                   ? SSG_OK
                   : ssg_check_refuse_at(s, at, "<accessor> has stride %s but %llu <param>s "
                                         "(its elements would overlap: the importer would "
                                         "read the same values for two of them)", stride_is,
                                         params);
    snprintf(last_text, sizeof last_text, "%llu", params);
    return ssg_check_refuse_at(s, at, "<accessor> reads past the end of its array '%.*s': "
                               "offset %s + (count %s - 1) x stride %s + %s values, but the "
                               "array holds %llu (the importer would read beyond it)",
                               shown(s, ref + 1, ref_len - 1), s->data + ref + 1,
                               written(s, at, end, "offset", "0", offset_text),
                               written(s, at, end, "count", "0", count_text), stride_is,
                               params > stride ? last_text : stride > 0 ? stride_is : "1",
                               a->count);
}

enum ssg_err ssg_check_dae_tag(const struct ssg_check *s, struct ssg_dae_scan *scan, size_t at,
                               size_t end, int closed)
{
    size_t n = name_length(s, at, end);
    if (scan->pass == 1)
        return n == 8 && !memcmp(s->data + at + 1, "accessor", 8)
                   ? check_accessor(s, scan, at, end, closed)
                   : SSG_OK;
    enum ssg_err e = check_count(s, at, end, n);
    if (!e && !closed && is_index_list(s, at, n))
        e = check_indices(s, at, end, n);
    if (!e && !closed && name_in(s, at, n, PRIMITIVES))
        e = check_primitive(s, at, end, n);
    size_t v, len;
    if (!e && name_in(s, at, n, ARRAYS) && !attribute(s, at, end, "count", &v, &len))
        e = ssg_check_refuse_at(s, at, "<%.*s> without the count attribute it must have (the "
                                "importer would read through a null array)", (int)n,
                                s->data + at + 1);
    if (!e && name_in(s, at, n, ARRAYS))
        e = record_array(s, scan, at, end, n);
    return e;
}
