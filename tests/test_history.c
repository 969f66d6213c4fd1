/* test_history.c - prev(node.port) inputs (docs/time.md, "History across frames";
 * core/graph/graph_history.c): the errors of the graph language, and the images a node
 * reads through prev() over several frames, on the CPU and on GL, in one multi-frame run
 * and in a kept graph's one-frame runs, where a set of the port's node and a new camera
 * start the history afresh; the bytes do not depend on the thread count.
 *
 * The accumulator is combine with the ambient term off: out = direct + M * environment,
 * so with direct = a (the G-buffer's albedo), M = m (a supplied scalar image) and
 * environment = prev(c.out), frame f gives c_f = a (1 - m^(f+1)) / (1 - m), a closed form
 * the test checks per pixel and frame. */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "graph/graph.h"
#include "graph/graph_history.h"
#include "graph/image.h"
#include "ssgraph.h"

enum { W = 16, H = 12 };

static char dir[1024];   /* the test's scratch folder */
static char scene[1200]; /* the Cornell box, by absolute path */

/* Writes a graph file under dir; returns its path (a static buffer per name). */
static const char *graph_file(const char *name, const char *body)
{
    static char paths[8][1400];
    static int used;
    char *path = paths[used++ % 8];
    snprintf(path, 1400, "%s/%s.graph", dir, name);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (f) {
        fprintf(f, "scene \"%s\"\nsize %d %d\n%s", scene, W, H, body);
        fclose(f);
    }
    return path;
}

/* ---- errors ---- */

/* Loading `body` fails with `code` at line:column of the graph file (the two header
   lines count: body line 1 is file line 3). */
static void expect_error(const char *body, enum ssg_err code, int line, int column)
{
    struct ssg_diags d = {0};
    struct ssg_overrides ov = {.seed = -1};
    CHECK_EQ(ssg_graph_check(graph_file("bad", body), &ov, &d), code);
    const struct ssg_diag none = {0}, *first = d.count ? &d.items[0] : &none;
    int ok = first->code == code && first->line == line && first->column == column;
    CHECK(ok);
    if (!ok) {
        fprintf(stderr, "  expected code %d at %d:%d in:\n%s", (int)code, line, column, body);
        ssg_diags_print(&d, stderr);
    }
}

#define ACC "c = combine(direct=g.albedo, albedo=g.albedo, ambient=0, darken_direct=false, "
#define TAIL "write(c.out, \"x\")\n"

static void errors(void)
{
    /* an unknown node, an unknown port, a sink's (no outputs): located inside prev() */
    expect_error("g = gbuffer()\n" ACC "environment=prev(nosuch.out))\n" TAIL,
                 SSG_E_UNKNOWN_NAME, 4, 96);
    expect_error("g = gbuffer()\n" ACC "environment=prev(c.nosuch))\n" TAIL,
                 SSG_E_UNKNOWN_PORT, 4, 98);
    expect_error("g = gbuffer()\n" ACC "environment=prev(w.out))\nw = write(c.out, \"x\")\n",
                 SSG_E_UNKNOWN_PORT, 4, 98);
    /* prev(prev(x)) is refused (no history of a history is kept), so is prev(3) */
    expect_error("g = gbuffer()\n" ACC "environment=prev(prev(c.out)))\n" TAIL, SSG_E_SYNTAX,
                 4, 91);
    expect_error("g = gbuffer()\n" ACC "environment=prev(3))\n" TAIL, SSG_E_SYNTAX, 4, 91);
    /* a parameter takes no port reference, prev() or not */
    expect_error("g = gbuffer()\nc = combine(direct=g.albedo, albedo=g.albedo, "
                 "ambient=prev(c.out))\n" TAIL, SSG_E_TYPE, 4, 60);
    /* an output whose shape would come from its own prev() has no shape to start from */
    expect_error("g = gbuffer()\nx = downsample(depth=prev(x.depth))\nwrite(x.depth, \"x\")\n",
                 SSG_E_SIZE, 4, 27);
    /* a plain self-reference is still a cycle; prev() of it is not */
    expect_error("g = gbuffer()\n" ACC "environment=c.out)\n" TAIL, SSG_E_CYCLE, 4, 5);
    struct ssg_diags d = {0};
    struct ssg_overrides ov = {.seed = -1};
    CHECK_EQ(ssg_graph_check(graph_file("ok", "g = gbuffer()\n" ACC
                                              "environment=prev(c.out))\n" TAIL),
                             &ov, &d),
             SSG_OK);
    ssg_diags_print(&d, stderr);
    /* a requested output is this frame's image: prev() is refused there */
    const char *outputs[] = {"prev(c.out)"};
    ov.outputs = outputs, ov.output_count = 1;
    struct ssg_diags d2 = {0};
    CHECK_EQ(ssg_graph_check(graph_file("ok2", "g = gbuffer()\n" ACC
                                               "environment=prev(c.out))\n" TAIL),
                             &ov, &d2),
             SSG_E_USAGE);
}

/* ---- values over frames ---- */

/* c: the accumulator (reads its own output); z, defined first, reads prev(c.out) before c
   runs in a frame; e reads c.out and prev(c.out) after it; k reads prev(h.out), and
   nothing else reads h, so prev() alone makes h live. */
static const char *accumulator_graph(void)
{
    return graph_file("acc", "m = input(type=scalar)\n"
                             "g = gbuffer()\n"
                             "z = combine(direct=g.albedo, albedo=g.albedo, ambient=0, "
                             "environment=prev(c.out))\n" ACC
                             "modulation=m.out, environment=prev(c.out))\n"
                             "e = combine(direct=c.out, albedo=g.albedo, ambient=0, "
                             "environment=prev(c.out))\n"
                             "h = combine(direct=g.albedo, albedo=g.albedo, ambient=0)\n"
                             "k = combine(direct=g.albedo, albedo=g.albedo, ambient=0, "
                             "environment=prev(h.out))\n" TAIL);
}

static const char *const PORTS[] = {"g.albedo", "c.out", "z.out", "e.out", "k.out"};
enum { ALBEDO, C, Z, E, K, PORT_COUNT };

/* The per-pixel modulation in (0.2, 0.7): every pixel its own geometric series. */
static struct ssg_image *modulation(void)
{
    struct ssg_image *m = ssg_image_create(W, H, 1);
    for (int i = 0; m && i < W * H; i++)
        m->data[i] = 0.2f + 0.5f * (float)((i * 37) % 101) / 101.0f;
    return m;
}

static struct ssg_graph *load(const char *backend, int with_outputs)
{
    struct ssg_overrides ov = {.seed = -1, .backend = backend};
    if (with_outputs)
        ov.outputs = PORTS, ov.output_count = PORT_COUNT;
    struct ssg_graph *g = NULL;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_load(accumulator_graph(), &ov, &g, &d), SSG_OK);
    struct ssg_image *m = modulation();
    if (g)
        CHECK_EQ(ssg_graph_supply(g, "m", m, &d), SSG_OK);
    ssg_image_destroy(&m);
    ssg_diags_print(&d, stderr);
    return g;
}

/* c_f = a (1 - m^(f+1)) / (1 - m); c_(-1) = 0. */
static double series(double a, double m, int f)
{
    return f < 0 ? 0.0 : a * (1.0 - pow(m, f + 1)) / (1.0 - m);
}

/* The ports' images against their closed forms in frame f (counted from the last reset). */
static void expect_frame(struct ssg_image *const *im, int f, const char *what)
{
    struct ssg_image *m = modulation();
    int bad = 0;
    for (int i = 0; m && i < W * H * 3 && bad < 5; i++) {
        double a = im[ALBEDO]->data[i], mi = m->data[i % (W * H)];
        double want[PORT_COUNT] = {a, series(a, mi, f), a + series(a, mi, f - 1),
                                   series(a, mi, f) + series(a, mi, f - 1),
                                   a + (f > 0 ? a : 0.0)};
        for (int p = C; p < PORT_COUNT; p++) {
            double got = im[p]->data[i], tol = 1e-6 * (1.0 + fabs(want[p]));
            if (fabs(got - want[p]) > tol && bad++ < 5)
                fprintf(stderr, "%s frame %d %s[%d]: %.9g, expected %.9g\n", what, f,
                        PORTS[p], i, got, want[p]);
        }
    }
    CHECK_EQ(bad, 0);
    ssg_image_destroy(&m);
}

static void destroy_all(struct ssg_image **im)
{
    for (int p = 0; p < PORT_COUNT; p++)
        ssg_image_destroy(&im[p]);
}

/* One run of `frames` frames: the last frame's images. */
static void run_frames(const char *backend, int frames, int threads, struct ssg_image **im)
{
    struct ssg_graph *g = load(backend, 1);
    struct ssg_diags d = {0};
    struct ssg_run_options opt = {.out_dir = dir, .threads = threads, .frames = frames,
                                  .outputs = im};
    CHECK_EQ(ssg_graph_run(g, &opt, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

static void sequence(const char *backend)
{
    for (int frames = 1; frames <= 5; frames++) {
        struct ssg_image *im[PORT_COUNT] = {0};
        run_frames(backend, frames, 2, im);
        if (im[C])
            expect_frame(im, frames - 1, backend);
        destroy_all(im);
    }
}

static int same_bytes(const struct ssg_image *a, const struct ssg_image *b)
{
    return a && b && a->width == b->width && a->height == b->height &&
           a->channels == b->channels &&
           !memcmp(a->data, b->data, (size_t)a->width * a->height * a->channels * 4);
}

/* Frame 0 of a graph with prev() is today's run of it without the prev() inputs. */
static void first_frame_is_plain(const char *backend)
{
    struct ssg_image *im[PORT_COUNT] = {0};
    run_frames(backend, 1, 2, im);
    const char *plain = graph_file("plain", "g = gbuffer()\nc = combine(direct=g.albedo, "
                                            "albedo=g.albedo, ambient=0)\n" TAIL);
    const char *outputs[] = {"c.out"};
    struct ssg_overrides ov = {.seed = -1, .backend = backend, .outputs = outputs,
                               .output_count = 1};
    struct ssg_graph *g = NULL;
    struct ssg_diags d = {0};
    struct ssg_image *out[1] = {0};
    CHECK_EQ(ssg_graph_load(plain, &ov, &g, &d), SSG_OK);
    struct ssg_run_options opt = {.out_dir = dir, .threads = 2, .outputs = out};
    CHECK_EQ(ssg_graph_run(g, &opt, &d), SSG_OK);
    CHECK(same_bytes(out[0], im[C]));
    ssg_image_destroy(&out[0]);
    ssg_graph_destroy(&g);
    destroy_all(im);
}

static void deterministic(const char *backend)
{
    struct ssg_image *one[PORT_COUNT] = {0}, *three[PORT_COUNT] = {0};
    run_frames(backend, 4, 1, one);
    run_frames(backend, 4, 3, three);
    for (int p = 0; p < PORT_COUNT; p++)
        CHECK(same_bytes(one[p], three[p]));
    destroy_all(one);
    destroy_all(three);
}

/* ---- a kept graph ---- */

static void live_outputs(struct ssg_graph *g, struct ssg_image **im)
{
    struct ssg_diags d = {0};
    struct ssg_run_options opt = {.out_dir = dir, .threads = 2};
    CHECK_EQ(ssg_graph_run(g, &opt, &d), SSG_OK);
    for (int p = 0; p < PORT_COUNT; p++)
        CHECK_EQ(ssg_graph_output(g, PORTS[p], &im[p], &d), SSG_OK);
    ssg_diags_print(&d, stderr);
}

/* One one-frame run of a kept graph, checked as frame f since the last reset. */
static void live_step(struct ssg_graph *g, int f, const char *what)
{
    struct ssg_image *im[PORT_COUNT] = {0};
    live_outputs(g, im);
    if (im[C])
        expect_frame(im, f, what);
    destroy_all(im);
}

static void live(const char *backend)
{
    struct ssg_graph *g = load(backend, 1);
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_keep(g, 0, &d), SSG_OK);
    for (int f = 0; f < 4; f++)
        live_step(g, f, "kept");
    /* a set of the accumulator (a change that leaves its image alone) starts it afresh;
       h and k, which it does not feed, keep theirs */
    CHECK_EQ(ssg_graph_set(g, "c.darken_indirect", "false", &d), SSG_OK);
    struct ssg_image *im[PORT_COUNT] = {0};
    live_outputs(g, im);
    struct ssg_image *m = modulation();
    for (int i = 0; im[C] && i < W * H * 3; i++) {
        CHECK_NEAR(im[C]->data[i], im[ALBEDO]->data[i], 1e-6);
        CHECK_NEAR(im[K]->data[i], 2.0 * im[ALBEDO]->data[i], 2e-6);
    }
    destroy_all(im);
    live_step(g, 1, "after set");
    /* a set of another node keeps the history: g's normals do not change the albedo */
    CHECK_EQ(ssg_graph_set(g, "g.normals", "face", &d), SSG_OK);
    live_step(g, 2, "after another's set");
    /* a new camera is a cut */
    struct ssg_view v;
    CHECK_EQ(ssg_graph_view(g, &v, &d), SSG_OK);
    v.position[0] += 0.05f;
    CHECK_EQ(ssg_graph_set_view(g, &v, &d), SSG_OK);
    live_step(g, 0, "after camera");
    live_step(g, 1, "after camera");
    ssg_diags_print(&d, stderr);
    ssg_image_destroy(&m);
    ssg_graph_destroy(&g);
}

/* ---- the executor's side, step by step (graph_history.h) ---- */

static int all_zero(const struct ssg_image *im)
{
    for (size_t i = 0; im && i < (size_t)im->width * im->height * im->channels; i++)
        if (im->data[i] != 0.0f)
            return 0;
    return im != NULL;
}

/* Binds node `name`'s inputs; returns the reset flag, the environment input in *env. */
static int bind(struct ssg_graph *g, struct ssg_pool *pool, const char *name,
                const struct ssg_image **env)
{
    const struct gnode *n = &g->nodes[ssg_graph_find(g, name, strlen(name))];
    const struct ssg_image *in[SSG_MAX_PORTS] = {0}, *extra[SSG_MAX_EXTRA] = {0};
    int reset = 7;
    CHECK_EQ(ssg_history_bind(g, pool, n, in, extra, &reset), SSG_OK);
    int port = ssg_port_find(n->desc->inputs, n->desc->input_count, "environment", 11);
    *env = port >= 0 ? in[port] : NULL;
    return reset;
}

static void reset_flags(void)
{
    struct ssg_graph *g = load("cpu", 1);
    struct ssg_pool *pool = ssg_pool_create();
    struct gnode *c = &g->nodes[ssg_graph_find(g, "c", 1)];
    const struct ssg_image *env;
    CHECK_EQ(ssg_history_begin(g, pool), SSG_OK);
    ssg_history_frame(g, pool); /* frame 0: nothing before */
    CHECK_EQ(bind(g, pool, "g", &env), -1); /* reads nothing through prev() */
    CHECK_EQ(bind(g, pool, "c", &env), 1);
    CHECK(all_zero(env) && env->width == W && env->height == H && env->channels == 3);
    CHECK_EQ(ssg_history_keep(g, pool, c, 0), 1);
    c->out_img[0] = ssg_pool_acquire(pool, W, H, 3);
    c->out_img[0]->data[0] = 7.0f;
    CHECK_EQ(bind(g, pool, "e", &env), 1); /* after c in frame 0: still nothing */
    struct ssg_image *written = c->out_img[0];
    ssg_history_frame(g, pool); /* frame 1: c's frame-0 image, before and after c runs */
    CHECK_EQ(bind(g, pool, "z", &env), 0);
    CHECK(env == written);
    CHECK_EQ(ssg_history_keep(g, pool, c, 0), 1);
    CHECK(c->out_img[0] == NULL); /* handed over, not copied */
    c->out_img[0] = ssg_pool_acquire(pool, W, H, 3);
    CHECK(c->out_img[0] != written);
    CHECK_EQ(bind(g, pool, "e", &env), 0);
    CHECK(env == written && env->data[0] == 7.0f);
    ssg_history_cut(g);
    ssg_history_frame(g, pool); /* a cut: nothing before again */
    CHECK_EQ(bind(g, pool, "z", &env), 1);
    CHECK(all_zero(env));
    ssg_pool_release(pool, c->out_img[0]);
    c->out_img[0] = NULL;
    ssg_history_free(g, pool);
    ssg_pool_destroy(&pool);
    ssg_graph_destroy(&g);
}

int main(void)
{
    const char *tmp = getenv("SSG_TMP");
    snprintf(dir, sizeof dir, "%s", tmp ? tmp : CHECK_TMP_ROOT "/ssg_test_history");
    char cmd[1200];
    snprintf(cmd, sizeof cmd, "mkdir -p '%s'", dir);
    CHECK_EQ(system(cmd), 0);
    char cwd[1024];
    CHECK(getcwd(cwd, sizeof cwd) != NULL);
    snprintf(scene, sizeof scene, "%s/examples/cornell.scene", cwd);
    errors();
    reset_flags();
    const char *backends[] = {"cpu", "gl"};
    for (int b = 0; b < 2; b++) {
        sequence(backends[b]);
        first_frame_is_plain(backends[b]);
        deterministic(backends[b]);
        live(backends[b]);
    }
    return check_report();
}
