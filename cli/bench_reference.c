/* bench_reference.c - `bench --reference NODE.PORT --image NODE.PORT`: each cell's image
 * scored against a reference that is rendered once per machine and reused.
 *
 * A reference (a 256-ray reference_ao, a path-traced reference_gi) costs far more than the
 * method it scores, and in a sweep most cells share it: it depends only on what the
 * reference output reads. Its key is the text of everything that decides it: ssgraph's
 * version, the output's name, the resolved frame (size, guard, seed, camera fov, near,
 * far), the scene and lights files with hashes of their bytes, the stereo eye offset, and
 * the backend and every parameter of each node the reference output needs (the graph
 * loaded with only that output, so a swept parameter of the method leaves it alone and one
 * of the G-buffer does not). Meshes, textures and probes named by the scene are not
 * hashed: edit one and clear the cache.
 *
 * The cache is a folder of <hash>.exr (the image) and <hash>.key (the key, then the
 * image's size and a hash of its pixels): $SSGRAPH_CACHE/references, else
 * $XDG_CACHE_HOME/ssgraph/references, else ~/.cache/ssgraph/references. A file is used only
 * when its key is the same text and its pixels hash to what the key file says; anything
 * else (missing, stale, truncated, corrupt) is rendered again and rewritten, each file
 * through a temporary and a rename. A cache that cannot be written is left alone.
 *
 * A cell then runs only what --image and --mask need (the graph's own sinks do not run:
 * its frame time is the method's alone) and its metrics are a `compare` of the image with
 * the reference, reported as node bench_reference. */
#define _DEFAULT_SOURCE /* open_memstream, realpath */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench_cells.h"
#include "graph_info.h"

/* A file's fingerprint for the key; 0 for none or one that cannot be read (the scene's
   load then reports it). */
static uint64_t file_hash(const char *path)
{
    char why[256];
    uint64_t h = 0;
    return path[0] && ssg_bench_file_fnv1a(path, &h, why, sizeof why) ? h : 0;
}

static uint64_t pixels_hash(const struct ssg_image *im)
{
    return ssg_bench_fnv1a(im->data, (size_t)im->width * (size_t)im->height *
                                         (size_t)im->channels * sizeof(float));
}

/* The cache folder ("" when there is no home to put it in). */
static void cache_dir(char *dir, size_t len)
{
    const char *own = getenv("SSGRAPH_CACHE"), *xdg = getenv("XDG_CACHE_HOME");
    const char *home = getenv("HOME");
    if (own && own[0])
        snprintf(dir, len, "%s/references", own);
    else if (xdg && xdg[0])
        snprintf(dir, len, "%s/ssgraph/references", xdg);
    else if (home && home[0])
        snprintf(dir, len, "%s/.cache/ssgraph/references", home);
    else
        dir[0] = '\0';
}

/* The key text of the reference of a graph loaded with only that output. */
static char *reference_key(const struct ssg_graph *g, const struct ssg_bench_request *q,
                           float eye_offset)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (!f)
        return NULL;
    fprintf(f, "ssgraph %s bench reference\noutput %s\neye_offset %.9g\n", SSG_VERSION,
            q->reference, (double)eye_offset);
    /* files by their real paths: graphs/../examples/x.scene and examples/x.scene agree */
    struct ssg_graph_info info;
    ssg_graph_inspect(g, &info);
    char scene[4096] = "", lights[4096] = "";
    if (info.scene[0] && !realpath(info.scene, scene))
        snprintf(scene, sizeof scene, "%s", info.scene);
    if (info.lights[0] && !realpath(info.lights, lights))
        snprintf(lights, sizeof lights, "%s", info.lights);
    const struct ssg_frame *fr = &info.frame;
    fprintf(f, "scene %s %016" PRIx64 "\nlights %s %016" PRIx64 "\n", scene,
            file_hash(info.scene), lights, file_hash(info.lights));
    fprintf(f, "frame %dx%d guard %d seed %" PRIu64 " fov %.9g near %.9g far %.9g\n",
            fr->width, fr->height, fr->guard, fr->seed, (double)fr->fov_y, (double)fr->near_z,
            (double)fr->far_z);
    ssg_cli_print_node_params(g, f);
    return fclose(f) == 0 ? text : (free(text), NULL);
}

/* The cached image of key, or NULL when it is not there or cannot be trusted. */
static struct ssg_image *cache_read(const char *base, const char *key)
{
    char path[4300], *stored = NULL, why[256];
    size_t len = 0, key_len = strlen(key);
    snprintf(path, sizeof path, "%s.key", base);
    if (ssg_input_read(path, 1 << 20, &stored, &len, why, sizeof why))
        return NULL;
    int w = 0, h = 0, c = 0;
    uint64_t want = 0;
    int ok = len > key_len && !memcmp(stored, key, key_len) &&
             sscanf(stored + key_len, "pixels %dx%dx%d %" SCNx64, &w, &h, &c, &want) == 4;
    free(stored);
    struct ssg_image *im = NULL;
    struct ssg_diags quiet = {0};
    snprintf(path, sizeof path, "%s.exr", base);
    if (ok && ssg_image_read(path, NULL, &im, &quiet) == SSG_OK && im->width == w &&
        im->height == h && im->channels == c && pixels_hash(im) == want)
        return im;
    ssg_image_destroy(&im);
    return NULL;
}

struct key_file {
    const char *key;
    const struct ssg_image *im;
};

static void put_key(FILE *f, const void *user)
{
    const struct key_file *k = user;
    fprintf(f, "%spixels %dx%dx%d %016" PRIx64 "\n", k->key, k->im->width, k->im->height,
            k->im->channels, pixels_hash(k->im));
}

/* The image first, its key last: a key names only a complete image. A cache that cannot
   be written (a full disk, a FIFO planted at a name: refused, never opened) is left alone,
   with a warning unless quiet: the bench goes on without it. */
static void cache_write(const char *dir, const char *base, const char *key,
                        const struct ssg_image *im, int quiet)
{
    char path[4300];
    struct ssg_diags d = {0};
    struct key_file k = {key, im};
    snprintf(path, sizeof path, "%s.exr", base);
    enum ssg_err e = ssg_make_dirs(dir, &d);
    if (!e)
        e = ssg_image_write(path, im, &d);
    snprintf(path, sizeof path, "%s.key", base);
    if (!e)
        e = ssg_write_text_file(path, "reference cache key", put_key, &k, &d);
    if (e && !quiet)
        fprintf(stderr, "ssgraph: warning: the reference was not cached (%s): %s\n",
                d.count ? d.items[0].file : dir, d.count ? d.items[0].message
                                                         : ssg_err_text(e));
}

/* The graph with only `outputs` loaded: their images after `frames` frames. */
static enum ssg_err run_outputs(const struct bench *b, const struct ssg_overrides *cell,
                                const char *const *outputs, int count, int frames,
                                struct ssg_image **images, struct ssg_run_stats *stats,
                                struct ssg_graph **kept, struct ssg_diags *d)
{
    struct ssg_overrides ov = *cell;
    ov.outputs = outputs;
    ov.output_count = count;
    struct ssg_graph *g = NULL;
    enum ssg_err e = ssg_graph_load(b->req->graph, &ov, &g, d);
    struct ssg_run_options ro = {.threads = b->req->threads, .frames = frames, .stats = stats,
                                 .outputs = images};
    if (!e)
        e = ssg_graph_run(g, &ro, d);
    if (kept && !e)
        *kept = g;
    else
        ssg_graph_destroy(&g);
    return e;
}

/* The reference of a cell's overrides: from the cache, else rendered (and cached). */
static enum ssg_err reference_image(const struct bench *b, const struct ssg_overrides *cell,
                                    struct ssg_image **ref, struct ssg_diags *d)
{
    struct ssg_overrides ov = *cell;
    const char *outputs[] = {b->req->reference};
    ov.outputs = outputs;
    ov.output_count = 1;
    struct ssg_graph *g = NULL;
    enum ssg_err e = ssg_graph_load(b->req->graph, &ov, &g, d);
    char *key = e ? NULL : reference_key(g, b->req, cell->eye_offset);
    char dir[4096], base[4200];
    cache_dir(dir, sizeof dir);
    snprintf(base, sizeof base, "%s/%016" PRIx64, dir,
             key ? ssg_bench_fnv1a(key, strlen(key)) : 0);
    *ref = key && dir[0] ? cache_read(base, key) : NULL;
    if (!e && !*ref) {
        struct ssg_run_options ro = {.threads = b->req->threads, .frames = 1, .outputs = ref};
        e = ssg_graph_run(g, &ro, d);
        if (!e && key && dir[0])
            cache_write(dir, base, key, *ref, b->req->quiet);
    }
    free(key);
    ssg_graph_destroy(&g);
    return e;
}

/* The compare node's metrics appended to the cell's, as node bench_reference. */
static enum ssg_err add_metrics(struct ssg_run_stats *st, const struct ssg_outputs *out)
{
    struct ssg_run_metric *m =
        realloc(st->metrics, (size_t)(st->metric_count + out->metric_count) * sizeof *m + 1);
    if (!m)
        return SSG_E_NOMEM;
    st->metrics = m;
    for (int i = 0; i < out->metric_count; i++) {
        struct ssg_run_metric *to = &m[st->metric_count++];
        snprintf(to->node, sizeof to->node, "bench_reference");
        snprintf(to->name, sizeof to->name, "%s", out->metric_names[i]);
        to->value = out->metric_values[i];
    }
    return SSG_OK;
}

enum ssg_err ssg_bench_run_compared(const struct bench *b, const struct ssg_overrides *cell,
                                    int frames, struct ssg_run_stats *stats,
                                    struct ssg_diags *d)
{
    const struct ssg_bench_request *q = b->req;
    struct ssg_image *ref = NULL, *im[2] = {NULL, NULL};
    struct ssg_graph *g = NULL;
    const char *outputs[] = {q->image, q->mask};
    enum ssg_err e = reference_image(b, cell, &ref, d);
    if (!e)
        e = run_outputs(b, cell, outputs, q->mask ? 2 : 1, frames, im, stats, &g, d);
    struct ssg_outputs out = {0};
    if (!e) {
        struct ssg_binding bind[] = {{"a", im[0]}, {"b", ref}, {"mask", im[1]}};
        struct ssg_graph_info info;
        ssg_graph_inspect(g, &info);
        e = ssg_node_run("compare", bind, q->mask ? 3 : 2, NULL, 0, &info.frame, &out, d);
    }
    if (!e)
        e = add_metrics(stats, &out);
    ssg_outputs_release(&out);
    ssg_graph_destroy(&g);
    for (int i = 0; i < 2; i++)
        ssg_image_destroy(&im[i]);
    ssg_image_destroy(&ref);
    return e;
}
