/* exr_guard.c - see exr_guard.h. The layout read here is OpenEXR's file format ("The
 * OpenEXR File Layout"): magic 76 2f 31 01, a 4-byte version with flags (0x200 tiled,
 * 0x800 non-image, 0x1000 multi-part), then headers of attributes (name NUL, type NUL,
 * int32 size, value) ended by an empty name, then the chunk offset tables (8 bytes a
 * chunk), then the chunks. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/exr_guard.h"

enum { HEAD_BYTES = 1 << 20 }; /* headers are read from this much of the file */

struct reader {
    const unsigned char *d;
    size_t n, at;     /* bytes read in, position */
    long long file;   /* bytes in the whole file */
};

/* A NUL-terminated name of at most 255 bytes at the position; NULL past the bytes read. */
static const char *name_at(struct reader *r)
{
    const char *s = (const char *)r->d + r->at;
    const void *nul = r->at < r->n ? memchr(s, 0, r->n - r->at < 256 ? r->n - r->at : 256)
                                   : NULL;
    if (!nul)
        return NULL;
    r->at += (size_t)((const char *)nul - s) + 1;
    return s;
}

static int32_t le32(const unsigned char *p)
{
    return (int32_t)((uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
                     (uint32_t)p[3] << 24);
}

/* Scan-lines per chunk of each compression (OpenEXR's Compression enum order). */
static int lines_per_chunk(int compression)
{
    static const int lines[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
    return compression >= 0 && compression < 10 ? lines[compression] : 1;
}

/* What one header says about the chunks the file must index. */
struct header {
    int have_window, compression, tile_w, tile_h;
    int32_t x0, y0, x1, y1;
};

static void note_attribute(struct header *h, const char *name, const unsigned char *v,
                           int32_t size)
{
    if (!strcmp(name, "dataWindow") && size == 16) {
        h->x0 = le32(v), h->y0 = le32(v + 4), h->x1 = le32(v + 8), h->y1 = le32(v + 12);
        h->have_window = 1;
    } else if (!strcmp(name, "compression") && size == 1) {
        h->compression = v[0];
    } else if (!strcmp(name, "tiles") && size >= 8) {
        h->tile_w = le32(v), h->tile_h = le32(v + 4);
    }
}

/* Reads one header's attributes; 0 with a reason when one claims more than the file. */
static int read_header(struct reader *r, struct header *h, char *why, size_t why_len)
{
    memset(h, 0, sizeof *h);
    h->compression = -1;
    for (;;) {
        const char *name = name_at(r);
        if (!name)
            return 1; /* past what was read in: OpenEXR judges the rest */
        if (!*name)
            return 1;
        if (!name_at(r) || r->at + 4 > r->n)
            return 1;
        int32_t size = le32(r->d + r->at);
        r->at += 4;
        if (size < 0 || (long long)r->at + size > r->file) {
            snprintf(why, why_len, "OpenEXR attribute '%.64s' claims %ld bytes, but the file "
                     "has %lld after it (truncated or forged)", name, (long)size,
                     r->file - (long long)r->at);
            return 0;
        }
        if (r->at + (size_t)size <= r->n)
            note_attribute(h, name, r->d + r->at, size);
        r->at += (size_t)size;
    }
}

/* Chunks the header's data window implies (its offset table has 8 bytes each). */
static long long chunks_of(const struct header *h)
{
    long long w = (long long)h->x1 - h->x0 + 1, ht = (long long)h->y1 - h->y0 + 1;
    if (!h->have_window || w <= 0 || ht <= 0)
        return 0;
    if (h->tile_w > 0 && h->tile_h > 0) /* level 0 alone: a lower bound */
        return ((w + h->tile_w - 1) / h->tile_w) * ((ht + h->tile_h - 1) / h->tile_h);
    int lines = lines_per_chunk(h->compression);
    return (ht + lines - 1) / lines;
}

/* The headers in buf (the first n bytes of a file of `file` bytes) against its size. */
static int header_fits(const unsigned char *buf, size_t n, long long file, char *why,
                       size_t why_len)
{
    struct reader r = {buf, n, 8, file};
    int flags = buf[5];
    int multipart = flags & 0x10, deep = flags & 0x08;
    long long chunks = 0;
    for (int part = 0; part < 1024; part++) {
        struct header h;
        if (!read_header(&r, &h, why, why_len))
            return 0;
        chunks += chunks_of(&h);
        if (!multipart || r.at >= r.n || r.d[r.at] == 0)
            break;
    }
    /* Deep and multi-part files have per-part chunk counts in their headers; their tables
       are still at least 8 bytes a chunk of level 0. */
    if (!deep && chunks > 0 && (long long)r.at + 8 * chunks > r.file) {
        snprintf(why, why_len, "OpenEXR header declares %lld chunks, but the file ends after "
                 "%lld bytes, before their offset table (truncated or forged)", chunks, r.file);
        return 0;
    }
    return 1;
}

int ssg_exr_guard(int fd, char *why, size_t why_len)
{
    static const unsigned char magic[4] = {0x76, 0x2f, 0x31, 0x01};
    struct stat st;
    unsigned char *buf = fstat(fd, &st) == 0 ? malloc(HEAD_BYTES) : NULL;
    ssize_t got = buf ? pread(fd, buf, HEAD_BYTES, 0) : -1;
    int ok = got < 8 || memcmp(buf, magic, 4) != 0 || header_fits(buf, (size_t)got,
                                                                 (long long)st.st_size, why,
                                                                 why_len);
    free(buf);
    return ok;
}
