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
 * attribute. */
#include <ctype.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>

#include "scene/model_check.h"

/* The elements whose text is a list of integers. */
static const char *const INDEX_LISTS[] = {"p", "vcount", "v", "h", "int_array", NULL};

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

/* 1 when the tag [at, end) has an attribute `name` (white space before it, then white
   space or '=' after it), outside its quoted values. */
static int has_attribute(const struct ssg_check *s, size_t at, size_t end, const char *name)
{
    size_t n = strlen(name);
    char quote = 0;
    for (size_t i = at + 1; i + n < end; i++) {
        char c = s->data[i];
        if (quote) {
            quote = c == quote ? 0 : quote;
        } else if (c == '"' || c == '\'') {
            quote = c;
        } else if (isspace((unsigned char)c) && !memcmp(s->data + i + 1, name, n)) {
            char after = s->data[i + 1 + n];
            if (after == '=' || isspace((unsigned char)after))
                return 1;
        }
    }
    return 0;
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

/* The tag's count="N" attribute, N at most the file's size. */
static enum ssg_err check_count(const struct ssg_check *s, size_t at, size_t end, size_t n)
{
    for (size_t i = at + 1 + n; i + 6 < end; i++) {
        if (!isspace((unsigned char)s->data[i]) || memcmp(s->data + i + 1, "count", 5))
            continue;
        size_t v = i + 6;
        while (v < end && (isspace((unsigned char)s->data[v]) || s->data[v] == '='))
            v++;
        if (v >= end || (s->data[v] != '"' && s->data[v] != '\''))
            continue;
        unsigned long long count = 0;
        size_t d = ++v;
        while (d < end && isdigit((unsigned char)s->data[d]) && count <= s->len)
            count = count * 10 + (unsigned)(s->data[d++] - '0');
        if (count > s->len)
            return ssg_check_refuse_at(s, v, "count on <%.*s> is more than a file of %zu "
                                       "bytes can hold (the importer would reserve them)",
                                       (int)n, s->data + at + 1, s->len);
    }
    return SSG_OK;
}

/* The text after an index list's tag, up to the next tag: integers only. */
static enum ssg_err check_indices(const struct ssg_check *s, size_t at, size_t end, size_t n)
{
    for (size_t i = end; i < s->len && s->data[i] != '<'; i++) {
        char c = s->data[i];
        if (!isdigit((unsigned char)c) && !isspace((unsigned char)c) && c != '-' && c != '+')
            return ssg_check_refuse_at(s, i, "<%.*s> holds a character that is no part of an "
                                       "integer (the importer would read it forever)", (int)n,
                                       s->data + at + 1);
    }
    return SSG_OK;
}

enum ssg_err ssg_check_dae_tag(const struct ssg_check *s, size_t at, size_t end, int closed)
{
    size_t n = name_length(s, at, end);
    enum ssg_err e = check_count(s, at, end, n);
    if (!e && !closed && is_index_list(s, at, n))
        e = check_indices(s, at, end, n);
    if (!e && !closed && name_in(s, at, n, PRIMITIVES))
        e = check_primitive(s, at, end, n);
    if (!e && name_in(s, at, n, ARRAYS) && !has_attribute(s, at, end, "count"))
        e = ssg_check_refuse_at(s, at, "<%.*s> without the count attribute it must have (the "
                                "importer would read through a null array)", (int)n,
                                s->data + at + 1);
    return e;
}
