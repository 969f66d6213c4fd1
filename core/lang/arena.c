#include "lang/arena.h"

#include <stdlib.h>
#include <string.h>

struct ssg_arena_block {
    struct ssg_arena_block *prev;
    size_t used, size;
    _Alignas(16) unsigned char data[];
};

enum { BLOCK_SIZE = 64 * 1024 };

void *ssg_arena_alloc(struct ssg_arena *arena, size_t size)
{
    size = (size + 15) & ~(size_t)15;
    struct ssg_arena_block *b = arena->head;
    if (!b || b->size - b->used < size) {
        size_t want = size > BLOCK_SIZE ? size : BLOCK_SIZE;
        b = malloc(sizeof *b + want);
        if (!b)
            return NULL;
        b->prev = arena->head;
        b->used = 0;
        b->size = want;
        arena->head = b;
    }
    void *p = b->data + b->used;
    b->used += size;
    memset(p, 0, size);
    return p;
}

char *ssg_arena_strndup(struct ssg_arena *arena, const char *s, size_t len)
{
    char *p = ssg_arena_alloc(arena, len + 1);
    if (p)
        memcpy(p, s, len);
    return p;
}

void ssg_arena_free(struct ssg_arena *arena)
{
    struct ssg_arena_block *b = arena->head;
    while (b) {
        struct ssg_arena_block *prev = b->prev;
        free(b);
        b = prev;
    }
    arena->head = NULL;
}
