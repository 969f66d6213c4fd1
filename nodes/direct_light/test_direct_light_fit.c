/* test_direct_light_fit.c - a direct_light builds its maps' faces itself (lightmap.h), so
 * its `fit` and `tiles` must be those of the lightmaps node that made the maps: no node
 * sees its producer's parameters, so nothing refuses a fit mismatch when a graph loads, and
 * it shows a wrong shadow without an error (tiles apart change the face count, which a
 * scene with a directional light refuses, test_lightmap_tiles.c; one without does not).
 * This checks every shipped graph (graphs/, each .graph file): each direct_light whose maps
 * come from a lightmaps node has its fit and tiles, and gi.graph's do fit the view. A
 * hand-written graph with the two fits apart is counted as one mismatch, so the check
 * itself can fail. */
#include <dirent.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "direct_light/direct_light.h"
#include "graph/graph.h"
#include "lightmaps/lightmaps.h"

/* Direct_light nodes of g whose fit differs from their maps' producer's; *checked counts
   those compared, *view those that fit the view. */
static int mismatches(const struct ssg_graph *g, int *checked, int *view)
{
    int bad = 0;
    for (int i = 0; i < g->count; i++) {
        const struct gnode *n = &g->nodes[i];
        const struct gconn *c = &n->in[SSG_DIRECT_LIGHT_IN_MAPS];
        if (n->desc != &ssg_node_direct_light || c->node < 0 ||
            g->nodes[c->node].desc != &ssg_node_lightmaps)
            continue;
        const struct ssg_direct_light_params *d = n->params;
        const struct ssg_lightmaps_params *m = g->nodes[c->node].params;
        (*checked)++;
        *view += d->fit == SSG_LIGHTMAP_FIT_VIEW;
        if (d->fit != m->fit || d->tiles != m->tiles) {
            fprintf(stderr, "direct_light '%s' has fit %d and tiles %d, its maps' node '%s' "
                    "fit %d and tiles %d\n", n->name, d->fit, d->tiles,
                    g->nodes[c->node].name, m->fit, m->tiles);
            bad++;
        }
    }
    return bad;
}

static struct ssg_graph *load(const char *path)
{
    struct ssg_overrides ov = {.width = 16, .height = 16, .seed = -1};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_load(path, &ov, &g, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    return g;
}

static void shipped_graphs(void)
{
    DIR *dir = opendir("graphs");
    CHECK(dir != NULL);
    int checked = 0, view = 0;
    for (struct dirent *e; dir && (e = readdir(dir));) {
        size_t len = strlen(e->d_name);
        if (len < 7 || strcmp(e->d_name + len - 6, ".graph"))
            continue;
        char path[512];
        snprintf(path, sizeof path, "graphs/%s", e->d_name);
        struct ssg_graph *g = load(path);
        if (g)
            CHECK_EQ(mismatches(g, &checked, &view), 0);
        ssg_graph_destroy(&g);
    }
    if (dir)
        closedir(dir);
    fprintf(stderr, "%d direct_light nodes checked, %d fit the view\n", checked, view);
    CHECK(checked >= 2); /* gi.graph's and direct_light.graph's at least */
    CHECK(view >= 1);    /* gi.graph's */
}

static void a_mismatch(void)
{
    const char *path = CHECK_TMP_ROOT "/ssg_test_direct_light_fit.graph";
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f)
        return;
    fputs("scene \"" SSG_SOURCE_DIR "/examples/table.scene\"\n"
          "g  = gbuffer()\n"
          "lm = lightmaps(resolution=64, fit=view)\n"
          "dl = direct_light(g.position, g.normal, g.albedo, lm.depth)\n"
          "write(dl.out, \"dl\")\n", f);
    fclose(f);
    struct ssg_graph *g = load(path);
    int checked = 0, view = 0;
    CHECK(g && mismatches(g, &checked, &view) == 1 && checked == 1 && view == 0);
    ssg_graph_destroy(&g);
    remove(path);
}

int main(void)
{
    shipped_graphs();
    a_mismatch();
    return check_report();
}
