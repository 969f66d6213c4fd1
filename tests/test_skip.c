/* test_skip.c - skipping the passes whose work nothing uses (core/graph/graph_skip.h), on
 * gi.graph, whose far field lights the scene from its environment.
 *
 * On the Cornell box (no environment: lightprobe missing=dark gives lights that carry
 * nothing) a run skips the lights' shadow maps, the half-resolution G-buffer, the probe's
 * light, its filter and its upsampling: their light is all zero, and the visibility they also make only scales that
 * zero in combine. The images are the bytes of a kept graph's run, which skips nothing (a
 * live graph's every output may be looked at). Asking for the visibility the branch makes
 * (glob.out2) makes all five run again, and under a sky nothing is skipped. On a still
 * camera the skipped nodes are kept after frame 0, as runs are. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "ssgraph.h"

#define GRAPH "graphs/gi.graph"

static const char *const sets[] = {"lm.resolution=64", "lb.resolution=32", "sm.resolution=64",
                                   "lp.count=48"};
static const char *const branch[] = {"sm", "h", "hp", "hpf", "glob"};
static char out_dir[1024];

/* gi.graph at 64 x 40 under `lights` (NULL = the scene's own), with the outputs `want`
   handed out (count of them), kept as a live graph when `keep`. */
static struct ssg_graph *load(const char *lights, const char *const *want, int count, int keep)
{
    struct ssg_overrides ov = {.width = 64, .height = 40, .seed = -1, .sets = sets,
                               .set_count = 4, .lights = lights, .outputs = want,
                               .output_count = count};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_load(GRAPH, &ov, &g, &d), SSG_OK);
    if (g && keep)
        CHECK_EQ(ssg_graph_keep(g, 0, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    return g;
}

static int run(struct ssg_graph *g, struct ssg_run_stats *stats, struct ssg_image **outputs)
{
    struct ssg_diags d = {0};
    struct ssg_run_options opt = {.out_dir = out_dir, .threads = 2, .stats = stats,
                                  .outputs = outputs};
    enum ssg_err e = ssg_graph_run(g, &opt, &d);
    ssg_diags_print(&d, stderr);
    CHECK_EQ(e, SSG_OK);
    return e == SSG_OK;
}

static const char *why_of(const struct ssg_run_stats *s, const char *name)
{
    for (int i = 0; i < s->node_count; i++)
        if (!strcmp(s->nodes[i].name, name))
            return s->nodes[i].why ? s->nodes[i].why : "(none)";
    return "(not in the run)";
}

static int same_image(const struct ssg_image *a, const struct ssg_image *b)
{
    return a && b && a->width == b->width && a->height == b->height &&
           a->channels == b->channels &&
           !memcmp(a->data, b->data,
                   sizeof(float) * (size_t)a->width * (size_t)a->height * (size_t)a->channels);
}

/* A fresh run with the outputs `want`: the branch's nodes say `branch_why`, and each
   output has the bytes of a kept graph's. */
static void check_case(const char *label, const char *lights, const char *const *want,
                       int count, const char *branch_why)
{
    struct ssg_graph *fresh = load(lights, want, count, 0), *kept = load(lights, NULL, 0, 1);
    struct ssg_run_stats s = {0}, unused = {0};
    struct ssg_image *got[4] = {0};
    if (fresh && kept && run(fresh, &s, got) && run(kept, &unused, NULL)) {
        for (int k = 0; k < (int)(sizeof branch / sizeof branch[0]); k++) {
            const char *why = why_of(&s, branch[k]);
            if (strcmp(why, branch_why))
                fprintf(stderr, "%s: node %s says '%s', expected '%s'\n", label, branch[k],
                        why, branch_why);
            CHECK(!strcmp(why, branch_why));
        }
        for (int k = 0; k < count; k++) {
            struct ssg_diags d = {0};
            struct ssg_image *ref = NULL;
            CHECK_EQ(ssg_graph_output(kept, want[k], &ref, &d), SSG_OK);
            int same = same_image(got[k], ref);
            if (!same)
                fprintf(stderr, "%s: %s differs from the kept graph's\n", label, want[k]);
            CHECK(same);
            ssg_image_destroy(&ref);
        }
    }
    for (int k = 0; k < count; k++)
        ssg_image_destroy(&got[k]);
    ssg_run_stats_free(&s);
    ssg_run_stats_free(&unused);
    ssg_graph_destroy(&fresh);
    ssg_graph_destroy(&kept);
}

/* Three frames of a still camera: the branch is skipped once and then kept like any
   run's outputs, and so is what reads it (glit): a sequence pays nothing for it after
   frame 0. */
static void still_sequence(void)
{
    struct ssg_graph *g = load(NULL, NULL, 0, 0);
    struct ssg_run_stats s = {0};
    struct ssg_diags d = {0};
    struct ssg_run_options opt = {.out_dir = out_dir, .threads = 2, .stats = &s, .frames = 3};
    if (g && ssg_graph_run(g, &opt, &d) == SSG_OK) {
        for (int k = 0; k < (int)(sizeof branch / sizeof branch[0]); k++)
            CHECK(!strcmp(why_of(&s, branch[k]), "skipped: zero or unused, kept x2"));
        const char *glit = why_of(&s, "glit");
        if (strcmp(glit, "first run, kept x2"))
            fprintf(stderr, "still camera: glit says '%s'\n", glit);
        CHECK(!strcmp(glit, "first run, kept x2"));
    }
    ssg_diags_print(&d, stderr);
    ssg_run_stats_free(&s);
    ssg_graph_destroy(&g);
}

int main(void)
{
    const char *tmp = getenv("SSG_TMP");
    snprintf(out_dir, sizeof out_dir, "%s", tmp ? tmp : CHECK_TMP_ROOT "/ssg_test_skip");
    static const char *const frame[] = {"gi.out", "glob.out", "glit.out"};
    check_case("Cornell box", NULL, frame, 3, "skipped: zero or unused");
    static const char *const visibility[] = {"gi.out", "glob.out2"};
    check_case("its visibility asked for", NULL, visibility, 2, "first run");
    check_case("under a sky", "examples/lights/sky.scene", frame, 3, "first run");
    still_sequence();
    return check_report();
}
