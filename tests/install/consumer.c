/* consumer.c - a user's program built against an INSTALLED ssgraph (tests/test_install.sh
 * compiles it with pkg-config and with find_package): it includes only the installed
 * header, runs a graph through the public interface and checks what comes back.
 *
 * usage: consumer GRAPH  - runs GRAPH at 64x48, takes back the filtered AO and checks it is
 * a plausible occlusion image of the Cornell box (every value in [0, 1], the open middle
 * bright, some corner dark), then checks that a missing graph file is reported with its
 * name. Prints "consumer: ok" and exits 0, else says what was wrong and exits 1. */
#include <ssgraph/ssgraph.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

static int fail(const char *what, const struct ssg_diags *diags)
{
    fprintf(stderr, "consumer: %s\n", what);
    if (diags)
        ssg_diags_print(diags, stderr);
    return 1;
}

/* The AO image's range, mean and darkest value; 1 when every value is a finite [0, 1]. */
static int ao_summary(const struct ssg_image *ao, double *mean, float *darkest)
{
    size_t n = (size_t)ao->width * (size_t)ao->height;
    double sum = 0.0;
    *darkest = 1.0f;
    for (size_t i = 0; i < n; i++) {
        float v = ao->data[i];
        if (!isfinite(v) || v < 0.0f || v > 1.0f)
            return 0;
        sum += v;
        if (v < *darkest)
            *darkest = v;
    }
    *mean = sum / (double)n;
    return 1;
}

static int run_graph(const char *path)
{
    const char *wanted[] = {"b.out"};
    struct ssg_overrides overrides = {.width = 64, .height = 48, .seed = -1,
                                      .outputs = wanted, .output_count = 1};
    struct ssg_diags diags = {0};
    struct ssg_graph *graph = NULL;
    if (ssg_graph_load(path, &overrides, &graph, &diags) != SSG_OK)
        return fail("the graph did not load", &diags);
    struct ssg_image *ao = NULL;
    struct ssg_run_options options = {.threads = 2, .outputs = &ao};
    enum ssg_err err = ssg_graph_run(graph, &options, &diags);
    ssg_graph_destroy(&graph);
    if (err != SSG_OK || !ao)
        return fail("the graph did not run", &diags);
    double mean = 0.0;
    float darkest = 1.0f;
    int ok = ao->width == 64 && ao->height == 48 && ao->channels == 1 &&
             ao_summary(ao, &mean, &darkest);
    printf("consumer: ao %dx%d, mean %.3f, darkest %.3f\n", ao->width, ao->height, mean,
           darkest);
    ssg_image_destroy(&ao);
    if (!ok)
        return fail("the AO image is not 64x48, one channel, all in [0, 1]", NULL);
    /* the Cornell box: open walls mostly lit, its corners and box edges occluded */
    if (mean < 0.5 || mean > 0.99 || darkest > 0.8f)
        return fail("the AO image does not look like the Cornell box's", NULL);
    return 0;
}

static int missing_graph_reported(void)
{
    struct ssg_diags diags = {0};
    struct ssg_graph *graph = NULL;
    enum ssg_err err = ssg_graph_load("no_such.graph", NULL, &graph, &diags);
    if (err == SSG_OK || graph || diags.count < 1 ||
        !strstr(diags.items[0].file, "no_such.graph"))
        return fail("a missing graph file was not reported with its name", &diags);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: consumer GRAPH\n");
        return 2;
    }
    printf("consumer: ssgraph %s, %d nodes\n", SSG_VERSION, ssg_node_count());
    if (run_graph(argv[1]) || missing_graph_reported())
        return 1;
    printf("consumer: ok\n");
    return 0;
}
