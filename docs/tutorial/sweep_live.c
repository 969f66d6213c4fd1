/* sweep_live.c - the tutorial's live-graph example: one load, then a radius sweep in which
 * only the changed node and what follows it run again (ssg_graph_keep, ssg_graph_set,
 * ssg_graph_output). Build: cc sweep_live.c $(pkg-config --cflags --libs ssgraph) */
#include <stdio.h>

#include <ssgraph/ssgraph.h>

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: %s GRAPH\n", argv[0]);
        return 2;
    }
    struct ssg_overrides overrides = {.width = 320, .height = 180, .seed = -1};
    struct ssg_diags diags = {0};
    struct ssg_graph *graph = NULL;
    int ok = ssg_graph_load(argv[1], &overrides, &graph, &diags) == SSG_OK &&
             ssg_graph_keep(graph, 0, &diags) == SSG_OK; /* keep every node's output */
    const char *radii[] = {"0.125", "0.25", "0.5", "1"};
    for (int i = 0; ok && i < 4; i++) {
        struct ssg_run_stats stats = {0};
        struct ssg_run_options options = {.out_dir = "out/sweep", .stats = &stats};
        struct ssg_image *ao = NULL;
        ok = ssg_graph_set(graph, "ao.radius", radii[i], &diags) == SSG_OK &&
             ssg_graph_run(graph, &options, &diags) == SSG_OK &&
             ssg_graph_output(graph, "ao.out", &ao, &diags) == SSG_OK;
        int ran = 0;
        for (int n = 0; n < stats.node_count; n++)
            ran += stats.nodes[n].calls > 0;
        double sum = 0.0;
        for (int p = 0; ok && p < ao->width * ao->height; p++)
            sum += ao->data[p];
        if (ok)
            printf("radius %-5s mean ambient occlusion %.3f (%d of %d nodes ran)\n",
                   radii[i], sum / (ao->width * ao->height), ran, stats.node_count);
        ssg_image_destroy(&ao);
        ssg_run_stats_free(&stats);
    }
    if (!ok)
        ssg_diags_print(&diags, stderr); /* file:line:column: error: ... */
    ssg_graph_destroy(&graph);
    return ok ? 0 : 1;
}
