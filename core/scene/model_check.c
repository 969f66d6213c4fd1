/* model_check.c - ssg_model_precheck_bytes (model.h): what is cheap to check in a model
 * file before Assimp sees it, because Assimp itself does not. Each check answers one way
 * a small hostile file takes the importer down (issue 28):
 *   - XML (DAE, X3D, AMF, ...) nested 100,000 deep overflows the stack of its recursive
 *     readers, and so do deep braces in glTF 1.0 (rapidjson), ASCII FBX, .x and .ase;
 *   - a PLY header without end_header spins forever, and its element counts (and the list
 *     counts in its data) are allocated before a byte of data is read: 219 bytes claiming
 *     2e9 faces cost 15 GB (model_check_ply.c);
 *   - a binary STL's 32-bit triangle count is multiplied in 32 bits, so a wrapped product
 *     passes Assimp's own size check;
 *   - a 3DS chunk's size must fit in its parent;
 *   - a COLLADA index list with a stray character, or a count beyond the file's size, has
 *     the COLLADA reader allocate without end (model_check_dae.c).
 * A linear pass over bytes the caller has in memory (or mapped); no allocation. */
#include <ctype.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "scene/model.h"
#include "scene/model_check.h"

void ssg_check_line_col(const struct ssg_check *s, size_t at, int *line, int *column)
{
    *line = 1;
    size_t start = 0;
    for (size_t i = 0; i < at && i < s->len; i++)
        if (s->data[i] == '\n')
            (*line)++, start = i + 1;
    *column = (int)(at - start) + 1;
}

/* The reason into s->why after its prefix ("file:line:col: " or "file: "). */
static enum ssg_err vrefuse(const struct ssg_check *s, int n, const char *fmt, va_list ap)
{
    if (n >= 0 && (size_t)n < s->why_len)
        vsnprintf(s->why + n, s->why_len - (size_t)n, fmt, ap);
    return SSG_E_GLTF;
}

enum ssg_err ssg_check_refuse_at(const struct ssg_check *s, size_t at, const char *fmt, ...)
{
    int line, column;
    ssg_check_line_col(s, at, &line, &column);
    int n = snprintf(s->why, s->why_len, "%s:%d:%d: ", s->path, line, column);
    va_list ap;
    va_start(ap, fmt);
    enum ssg_err e = vrefuse(s, n, fmt, ap);
    va_end(ap);
    return e;
}

enum ssg_err ssg_check_refuse(const struct ssg_check *s, const char *fmt, ...)
{
    int n = snprintf(s->why, s->why_len, "%s: ", s->path);
    va_list ap;
    va_start(ap, fmt);
    enum ssg_err e = vrefuse(s, n, fmt, ap);
    va_end(ap);
    return e;
}

/* 1 when the bytes at i are text. */
static int starts(const struct ssg_check *s, size_t i, const char *text)
{
    size_t n = strlen(text);
    return i + n <= s->len && memcmp(s->data + i, text, n) == 0;
}

size_t ssg_check_find(const struct ssg_check *s, size_t from, size_t to, const char *text)
{
    size_t n = strlen(text);
    for (size_t i = from; i + n <= to; i++) {
        const char *hit = memchr(s->data + i, text[0], to - i);
        if (!hit)
            break;
        i = (size_t)(hit - s->data);
        if (i + n <= to && !memcmp(s->data + i, text, n))
            return i;
    }
    return to;
}

/* Index just past the first `end` at or after i; len when there is none. */
static size_t skip_past(const struct ssg_check *s, size_t i, const char *end)
{
    size_t at = ssg_check_find(s, i, s->len, end);
    return at < s->len ? at + strlen(end) : s->len;
}

/* Past the tag opening at i, quoted attribute values honoured (they may hold '>');
   *closed: it ends in "/>" (or the file ends inside it). */
static size_t skip_tag(const struct ssg_check *s, size_t i, int *closed)
{
    char quote = 0, last = 0;
    for (i++; i < s->len; i++) {
        char c = s->data[i];
        if (quote) {
            quote = c == quote ? 0 : quote;
            continue;
        }
        if (c == '>') {
            *closed = last == '/';
            return i + 1;
        }
        if (c == '"' || c == '\'')
            quote = c;
        if (!isspace((unsigned char)c))
            last = c;
    }
    *closed = 1;
    return s->len;
}

/* Past a <!DOCTYPE ...> (its internal subset in [...] may hold '>'). */
static size_t skip_declaration(const struct ssg_check *s, size_t i)
{
    int brackets = 0;
    for (i += 2; i < s->len; i++) {
        char c = s->data[i];
        brackets += (c == '[') - (c == ']');
        if (c == '>' && brackets <= 0)
            return i + 1;
    }
    return s->len;
}

/* Element nesting of an XML file: comments, CDATA, processing instructions and
   declarations open nothing; the deepest open tag is reported where it starts. A COLLADA
   file's tags are checked one by one too (model_check_dae.c), with dae (else NULL). */
static enum ssg_err walk_xml(const struct ssg_check *s, struct ssg_dae_scan *dae)
{
    int depth = 0;
    for (size_t i = 0; i < s->len;) {
        const char *lt = memchr(s->data + i, '<', s->len - i);
        if (!lt)
            break;
        i = (size_t)(lt - s->data);
        if (starts(s, i, "<!--"))
            i = skip_past(s, i + 4, "-->");
        else if (starts(s, i, "<![CDATA["))
            i = skip_past(s, i + 9, "]]>");
        else if (starts(s, i, "<?"))
            i = skip_past(s, i + 2, "?>");
        else if (starts(s, i, "<!"))
            i = skip_declaration(s, i);
        else if (starts(s, i, "</")) {
            depth -= depth > 0;
            i = skip_past(s, i, ">");
        } else {
            int closed;
            size_t at = i;
            i = skip_tag(s, i, &closed);
            if (!closed && ++depth > SSG_MODEL_MAX_NESTING)
                return ssg_check_refuse_at(s, at, "XML elements nested deeper than %d levels "
                                           "(the importer would overflow its stack)",
                                           SSG_MODEL_MAX_NESTING);
            enum ssg_err e = dae ? ssg_check_dae_tag(s, dae, at, i, closed) : SSG_OK;
            if (e)
                return e;
        }
    }
    return SSG_OK;
}

/* An XML file's walk; a COLLADA file's twice (model_check.h, struct ssg_dae_scan). */
static enum ssg_err check_xml(const struct ssg_check *s, int collada)
{
    if (!collada)
        return walk_xml(s, NULL);
    struct ssg_dae_scan dae = {0};
    enum ssg_err e = walk_xml(s, &dae);
    if (!e) {
        ssg_check_dae_sort(&dae);
        dae.pass = 1;
        e = walk_xml(s, &dae);
    }
    ssg_check_dae_free(&dae);
    return e;
}

/* Nesting of { and [ outside "strings": JSON, ASCII FBX, DirectX .x, ASE. */
static enum ssg_err check_braces(const struct ssg_check *s)
{
    int depth = 0, in_string = 0;
    for (size_t i = 0; i < s->len; i++) {
        char c = s->data[i];
        if (in_string) {
            i += c == '\\'; /* an escaped quote does not end the string */
            in_string = c != '"';
        } else if (c == '"') {
            in_string = 1;
        } else if (c == '{' || c == '[') {
            if (++depth > SSG_MODEL_MAX_NESTING)
                return ssg_check_refuse_at(s, i, "'%c' nested deeper than %d levels (the "
                                           "importer would overflow its stack)", c,
                                           SSG_MODEL_MAX_NESTING);
        } else if (c == '}' || c == ']') {
            depth -= depth > 0;
        }
    }
    return SSG_OK;
}

/* The first byte that is not white space (or a UTF-8 byte order mark). */
static char first_char(const struct ssg_check *s)
{
    size_t i = starts(s, 0, "\xEF\xBB\xBF") ? 3 : 0;
    while (i < s->len && isspace((unsigned char)s->data[i]))
        i++;
    return i < s->len ? s->data[i] : 0;
}

static int one_of(const char *ext, const char *const *list)
{
    for (; *list; list++)
        if (!strcmp(ext, *list))
            return 1;
    return 0;
}

static uint32_t le32(const char *p)
{
    const unsigned char *u = (const unsigned char *)p;
    return u[0] | (uint32_t)u[1] << 8 | (uint32_t)u[2] << 16 | (uint32_t)u[3] << 24;
}

/* Assimp takes a file for binary STL when 84 + 50 n equals its size, computed in 32 bits
   (so a wrapped product of a count near 2^31 passes and is allocated); ASCII STL starts
   with "solid" (binary ones may too, so binary is asked first, as Assimp does). */
static enum ssg_err check_stl(const struct ssg_check *s)
{
    uint32_t n = s->len >= 84 ? le32(s->data + 80) : 0;
    unsigned long long want = 84ull + 50ull * n;
    if (s->len >= 84 && (uint32_t)want == (uint32_t)s->len && want != s->len)
        return ssg_check_refuse(s, "a binary STL claiming %lu triangles (%llu bytes) in %zu "
                                "bytes", (unsigned long)n, want, s->len);
    if (s->len >= 84 && want == s->len)
        return SSG_OK;
    size_t i = 0;
    while (i < s->len && isspace((unsigned char)s->data[i]))
        i++;
    if (starts(s, i, "solid"))
        return SSG_OK; /* ASCII: Assimp counts facets as it reads them */
    if (s->len < 84)
        return ssg_check_refuse(s, "neither ASCII STL (no 'solid') nor binary STL (%zu bytes, "
                                "under the 84 of a binary header)", s->len);
    return ssg_check_refuse(s, "a binary STL claiming %lu triangles needs 84 + 50 x %lu = "
                            "%llu bytes, but the file has %zu", (unsigned long)n,
                            (unsigned long)n, want, s->len);
}

static unsigned le16(const char *p)
{
    const unsigned char *u = (const unsigned char *)p;
    return u[0] | (unsigned)u[1] << 8;
}

/* A 3DS array chunk (points, faces, texture coordinates): a 16-bit count of entries of
   `entry` bytes must fit in the chunk's body [at, end). */
static enum ssg_err check_3ds_array(const struct ssg_check *s, size_t at, size_t end,
                                    unsigned id, size_t entry)
{
    if (end - at < 2)
        return ssg_check_refuse(s, "3DS chunk 0x%04X at byte %zu has no room for its count",
                                id, at - 6);
    size_t n = le16(s->data + at);
    if (n * entry > end - at - 2)
        return ssg_check_refuse(s, "3DS chunk 0x%04X at byte %zu claims %zu entries of %zu "
                                "bytes in %zu bytes", id, at - 6, n, entry, end - at - 2);
    return SSG_OK;
}

static int is_3ds_container(unsigned id)
{
    return id == 0x4D4D || id == 0x3D3D || id == 0x4000 || id == 0x4100 || id == 0xAFFF ||
           id == 0xB000;
}

static enum ssg_err check_3ds_chunks(const struct ssg_check *s, size_t at, size_t end,
                                     int depth);

/* The body [body, end) of one chunk: its arrays' counts, and the chunks inside it. */
static enum ssg_err check_3ds_body(const struct ssg_check *s, unsigned id, size_t body,
                                   size_t end, int depth)
{
    if (id == 0x4110)
        return check_3ds_array(s, body, end, id, 12);
    if (id == 0x4140)
        return check_3ds_array(s, body, end, id, 8);
    if (id == 0x4120) { /* faces, then their material and smoothing chunks */
        enum ssg_err e = check_3ds_array(s, body, end, id, 8);
        return e ? e : check_3ds_chunks(s, body + 2 + 8 * (size_t)le16(s->data + body), end,
                                        depth + 1);
    }
    if (id == 0x4000) { /* a named object: a C string, then its chunks */
        const char *nul = memchr(s->data + body, 0, end - body);
        body = nul ? (size_t)(nul - s->data) + 1 : end;
    }
    return is_3ds_container(id) && depth < 8 ? check_3ds_chunks(s, body, end, depth + 1)
                                             : SSG_OK;
}

/* The chunks in [at, end), each 6 bytes of id and size (the header included) and no
   larger than what is left of its parent; the containers Assimp reads meshes from are
   walked into (five levels in a real file). */
static enum ssg_err check_3ds_chunks(const struct ssg_check *s, size_t at, size_t end,
                                     int depth)
{
    while (end - at >= 6) {
        unsigned id = le16(s->data + at);
        size_t size = le32(s->data + at + 2);
        if (size < 6 || size > end - at)
            return ssg_check_refuse(s, "3DS chunk 0x%04X at byte %zu claims %zu bytes, but "
                                    "%zu are left in %s", id, at, size, end - at,
                                    depth ? "its parent chunk" : "the file");
        enum ssg_err e = check_3ds_body(s, id, at + 6, at + size, depth);
        if (e)
            return e;
        at += size;
        if (depth == 0)
            break; /* the main chunk is the file; bytes after it are not read */
    }
    return SSG_OK;
}

enum ssg_err ssg_model_precheck_bytes(const char *path, const char *ext, const char *data,
                                      size_t len, char *why, size_t why_len)
{
    static const char *const braced[] = {".gltf", ".fbx", ".x", ".ase", ".ask", NULL};
    const struct ssg_check s = {path, data, len, why, why_len};
    char first = first_char(&s);
    enum ssg_err e = SSG_OK;
    if (first == '<') /* XML, whatever the extension: Assimp's XML readers all recurse */
        e = check_xml(&s, !strcmp(ext, ".dae"));
    else if (one_of(ext, braced) && !starts(&s, 0, "Kaydara FBX Binary"))
        e = check_braces(&s);
    if (!e && !strcmp(ext, ".ply"))
        e = ssg_check_ply(&s);
    if (!e && !strcmp(ext, ".stl"))
        e = check_stl(&s);
    if (!e && (!strcmp(ext, ".3ds") || !strcmp(ext, ".prj")))
        e = check_3ds_chunks(&s, 0, len, 0);
    return e;
}
