/* arena.h - a bump allocator: everything parsed from a graph or scene file lives in one
 * arena and is freed in one call. Not thread-safe; one owner. */
#ifndef SSG_ARENA_H
#define SSG_ARENA_H

#include <stddef.h>

struct ssg_arena_block;
struct ssg_arena {
    struct ssg_arena_block *head; /* newest block; NULL when empty */
};

/* Zeroed, 16-byte aligned memory; NULL when out of memory. */
void *ssg_arena_alloc(struct ssg_arena *arena, size_t size);
/* Copies len bytes and a terminating NUL. */
char *ssg_arena_strndup(struct ssg_arena *arena, const char *s, size_t len);
void ssg_arena_free(struct ssg_arena *arena);

#endif
