/* hello.c - the tutorial's library example: run a graph from C and read back one image.
 *
 *   cc hello.c -o hello $(pkg-config --cflags --libs ssgraph)
 *   ./hello docs/tutorial/first.graph
 */
#include <ssgraph/ssgraph.h>

#include <stdio.h>

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: hello GRAPH\n");
        return 2;
    }
    /* Ask for the ssao node's output instead of running the graph's write node. */
    const char *wanted[] = {"ao.out"};
    struct ssg_overrides overrides = {.width = 320, .height = 180, .seed = -1,
                                      .outputs = wanted, .output_count = 1};
    struct ssg_diags diags = {0};
    struct ssg_graph *graph = NULL;
    struct ssg_image *ao = NULL;
    struct ssg_run_options options = {.outputs = &ao};
    if (ssg_graph_load(argv[1], &overrides, &graph, &diags) != SSG_OK ||
        ssg_graph_run(graph, &options, &diags) != SSG_OK) {
        ssg_diags_print(&diags, stderr); /* file:line:column: error: ... */
        ssg_graph_destroy(&graph);
        return 1;
    }
    double sum = 0.0;
    for (int i = 0; i < ao->width * ao->height; i++)
        sum += ao->data[i];
    printf("%dx%d, mean ambient occlusion %.3f\n", ao->width, ao->height,
           sum / (ao->width * ao->height));
    ssg_image_destroy(&ao);
    ssg_graph_destroy(&graph);
    return 0;
}
