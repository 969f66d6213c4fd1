/* fuzz_parse.c - libFuzzer target for the text formats: the input is written to a file and
 * loaded as a graph (lexer, parser, build, validation) and as a scene (parse and checks,
 * no assets). Any crash, hang, leak or sanitizer report is a bug; error returns are fine.
 *
 *   cmake -S . -B build-fuzz -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DSSG_FUZZ=ON
 *   build-fuzz/fuzz_parse -max_len=4096 build-fuzz/corpus graphs examples tests/fixtures
 * Without SSG_FUZZ, fuzz_replay runs this entry point on every file given (ctest does, on
 * the bundled graphs, scenes and fixtures). */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "ssgraph.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[] = "/tmp/ssg_fuzz_XXXXXX";
    int fd = mkstemp(path);
    if (fd < 0)
        return 0;
    if (write(fd, data, size) != (ssize_t)size) {
        close(fd);
        unlink(path);
        return 0;
    }
    close(fd);
    struct ssg_diags graph_diags = {0}, scene_diags = {0};
    ssg_graph_check(path, NULL, &graph_diags);
    ssg_scene_check(path, &scene_diags);
    unlink(path);
    return 0;
}
