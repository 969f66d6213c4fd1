/* model_check_dae.c - the COLLADA part of the model pre-checks (model_check.h), for two
 * ways a few changed bytes of a .dae make Assimp's COLLADA reader eat all memory (both
 * found by fuzz/fuzz_model.c):
 *   - it reads the indices of a <p> with `while (*text) { push_back(strtol10(...)); skip
 *     spaces; }`, so one character that is neither a digit nor a space stops both from
 *     advancing and the vector grows until the allocation fails (6 GB under the fuzzer);
 *   - it reserves each count="N" attribute's worth of values (a float_array's, a polylist's
 *     vcount) before reading one.
 * So the index lists may hold only digits, signs and white space, and no count may exceed
 * the file's size in bytes (every value counted takes at least one). */
#include <ctype.h>
#include <limits.h>
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

static int is_index_list(const struct ssg_check *s, size_t at, size_t n)
{
    for (const char *const *name = INDEX_LISTS; *name; name++)
        if (strlen(*name) == n && !memcmp(s->data + at + 1, *name, n))
            return 1;
    return 0;
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
    return e;
}
