/* fuzz_graph.c - libFuzzer target for the graph format: the input is loaded as a graph
 * file (lexer, parser, includes, build, validation; the scene it names is checked without
 * its assets). See fuzz_input.h for how the targets are built and replayed. */
#define _DEFAULT_SOURCE /* mkstemps */
#include "fuzz_input.h"
#include "ssgraph.h"

static void check_graph(const char *path)
{
    struct ssg_diags diags = {0};
    ssg_graph_check(path, NULL, &diags);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_on_file(data, size, ".graph", check_graph);
    return 0;
}
