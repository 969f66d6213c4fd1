/* fuzz_input.h - what the fuzz targets share: the input bytes written to a temporary file
 * (every loader under test reads files, as ssgraph does), removed after the call.
 *
 * Each target (fuzz_graph.c, fuzz_scene.c, fuzz_gltf.c, fuzz_image.c) defines
 * LLVMFuzzerTestOneInput. Built with -DSSG_FUZZ=ON and clang it links libFuzzer (the
 * `fuzz_<name>` programs, run by fuzz/run.sh); in every build, `fuzz_replay_<name>` links
 * fuzz_replay.c instead and ctest runs it over the seeds and the fixtures of past findings,
 * so a fixed crash stays fixed under the sanitizer build too. Any crash, hang, leak or
 * sanitizer report is a bug; an error returned by the loader is the expected outcome. */
#ifndef SSG_FUZZ_INPUT_H
#define SSG_FUZZ_INPUT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Writes data to a new file <tmpdir>/ssg_fuzz_XXXXXX<suffix>; its path into path (at least
   4096 bytes). 0 when it could not. */
static inline int fuzz_write_temp(const uint8_t *data, size_t size, const char *suffix, char *path)
{
    const char *dir = getenv("TMPDIR");
    snprintf(path, 4096, "%s/ssg_fuzz_XXXXXX%s", dir && dir[0] ? dir : P_tmpdir, suffix);
    int fd = mkstemps(path, (int)strlen(suffix));
    if (fd < 0)
        return 0;
    int ok = write(fd, data, size) == (ssize_t)size;
    close(fd);
    if (!ok)
        unlink(path);
    return ok;
}

/* Writes data to a temporary file with the given suffix, calls use(path), removes it. */
static inline void fuzz_on_file(const uint8_t *data, size_t size, const char *suffix,
                                void (*use)(const char *path))
{
    char path[4096];
    if (!fuzz_write_temp(data, size, suffix, path))
        return;
    /* SSG_FUZZ_LAST=FILE keeps a copy of the input being run: when valgrind stops the
       fuzzer at the first bad write (--exit-on-first-error), FILE is the culprit. */
    const char *last = getenv("SSG_FUZZ_LAST");
    FILE *keep = last && last[0] ? fopen(last, "wb") : NULL;
    if (keep) {
        fwrite(data, 1, size, keep);
        fclose(keep);
    }
    use(path);
    unlink(path);
}

/* 1 when data starts with the given magic bytes. */
static inline int fuzz_has_magic(const uint8_t *data, size_t size, const char *magic, size_t len)
{
    return size >= len && memcmp(data, magic, len) == 0;
}

#endif
