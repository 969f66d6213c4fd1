/* fuzz_graph.c - libFuzzer target for the graph format: the input is loaded as a graph
 * file (lexer, parser, includes, build, validation; the scene it names is checked without
 * its assets). See fuzz_input.h for how the targets are built and replayed. */
#define _DEFAULT_SOURCE /* mkstemps */
#include "fuzz_input.h"
#include "ssgraph.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[4096];
    if (!fuzz_write_temp(data, size, ".graph", path))
        return 0;
    struct ssg_diags diags = {0};
    ssg_graph_check(path, NULL, &diags);
    unlink(path);
    return 0;
}
