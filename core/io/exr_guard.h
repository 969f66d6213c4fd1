/* exr_guard.h - sanity checks on an OpenEXR file's bytes before OpenEXR reads it.
 *
 * OpenEXR 3.1 allocates what a header claims before it finds that the file ends: a 1 KB
 * file whose string attribute claims 2 GB takes seconds and gigabytes to refuse (found by
 * fuzz_image), and a header that declares 64 M pixels over a few bytes makes the reader
 * allocate the whole image first. These checks refuse such files from the sizes alone:
 * every header attribute must fit in the file, and the file must hold at least the chunk
 * offset table its data window and compression imply. They never reject a complete file.
 *
 * Thread-safe, no state; reads only through the descriptor given. */
#ifndef SSG_EXR_GUARD_H
#define SSG_EXR_GUARD_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* 1 when the file at fd is not an OpenEXR file (nothing to check) or its header is
 * consistent with its size; 0 with the reason in why otherwise. */
int ssg_exr_guard(int fd, char *why, size_t why_len);

#ifdef __cplusplus
}
#endif
#endif
