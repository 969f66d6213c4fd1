/* session.c - the state of `ssgraph view` between requests (session.h). */
#define _GNU_SOURCE /* open_memstream, asprintf */
#include "session.h"

#include "../watch.h"
#include "reference.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

enum { KEEP_BYTES = 1u << 30 }; /* images a graph keeps between runs, at most */

char *view_diags_text(const struct ssg_diags *diags, enum ssg_err e)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (!f)
        return NULL;
    ssg_diags_print(diags, f);
    if (e && diags->count == 0)
        fprintf(f, "error: %s\n", ssg_err_text(e));
    fclose(f);
    return text;
}

enum ssg_err view_fail(struct ssg_diags *d, enum ssg_err code, const char *fmt, ...)
{
    d->total++;
    if (d->count == SSG_DIAGS_MAX)
        return code;
    struct ssg_diag *item = &d->items[d->count++];
    *item = (struct ssg_diag){.code = code};
    snprintf(item->file, sizeof item->file, "<view>");
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(item->message, sizeof item->message, fmt, ap);
    va_end(ap);
    return code;
}

static void set_error(struct view_session *s, const struct ssg_diags *d, enum ssg_err e)
{
    free(s->error);
    s->error = e ? view_diags_text(d, e) : NULL;
}

/* Runs graph g (the full or the preview one) into the session's statistics. */
static enum ssg_err run_graph(struct view_session *s, struct ssg_graph *g, int preview,
                              struct ssg_diags *d)
{
    ssg_run_stats_free(&s->stats);
    struct ssg_run_options ro = {.out_dir = s->args->out_dir, .threads = s->args->threads,
                                 .stats = &s->stats, .no_files = 1};
    enum ssg_err e = ssg_graph_run(g, &ro, d);
    if (preview)
        s->preview_stale = 0;
    else
        s->full_stale = 0;
    s->last_preview = preview;
    s->generation++;
    set_error(s, d, e);
    return e;
}

/* The frame size a graph loaded with these overrides has. */
static void frame_size(const struct ssg_graph *g, int *w, int *h)
{
    struct ssg_frame frame;
    ssg_graph_frame(g, &frame);
    *w = frame.width;
    *h = frame.height;
}

/* 1 when the node of "node.param" is in g. */
static int set_node_exists(const struct ssg_graph *g, const char *key)
{
    char node[VIEW_KEY_MAX];
    snprintf(node, sizeof node, "%.*s", (int)strcspn(key, "."), key);
    return ssg_graph_node_index(g, node) >= 0;
}

/* Loads the graph at width x height (0: its own) with the session's changes and camera,
 * kept between runs. */
static enum ssg_err load(struct view_session *s, int width, int height, struct ssg_graph **out,
                         struct ssg_diags *d)
{
    struct ssg_overrides ov = s->args->ov;
    if (width) {
        ov.width = width;
        ov.height = height;
    }
    struct ssg_graph *g = NULL;
    const char *path = s->args->files[0];
    enum ssg_err e = s->text ? ssg_graph_load_text(path, s->text, &ov, &g, d)
                             : ssg_graph_load(path, &ov, &g, d);
    if (!e)
        e = ssg_graph_keep(g, KEEP_BYTES, d);
    for (int i = 0; !e && i < s->set_count; i++)
        if (set_node_exists(g, s->sets[i].key)) /* an edit may have removed it */
            e = ssg_graph_set(g, s->sets[i].key, s->sets[i].value, d);
    if (!e && s->frame)
        e = ssg_graph_set_frame(g, s->frame, d);
    if (!e && s->camera_changed)
        e = ssg_graph_set_view(g, &s->camera, d);
    if (e)
        ssg_graph_destroy(&g);
    *out = g;
    return e;
}

/* Takes the freshly loaded graph g as the session's full graph. */
static void adopt(struct view_session *s, struct ssg_graph *g)
{
    struct ssg_diags ignored = {0};
    ssg_graph_destroy(&s->g);
    ssg_graph_destroy(&s->preview); /* loaded again on the next drag */
    s->g = g;
    frame_size(g, &s->width, &s->height);
    s->preview_width = s->width / 2 > 16 ? s->width / 2 : s->width;
    s->preview_height = s->width / 2 > 16 ? s->height / 2 : s->height;
    if (s->preview_height < 1)
        s->preview_height = 1;
    if (!s->camera_changed)
        s->has_camera = ssg_graph_view(g, &s->camera, &ignored) == SSG_OK;
}

static void watch_files(struct view_session *s, const struct ssg_graph *g);

enum ssg_err view_session_open(struct view_session *s, const struct ssg_cli_args *args)
{
    *s = (struct view_session){.args = args};
    struct ssg_diags d = {0};
    struct ssg_graph *g;
    /* The watcher snapshots the files before the load reads them: an edit during the
       load is seen by the first poll. */
    s->watch = ssg_cli_watch_new(args->files[0]);
    enum ssg_err e = load(s, 0, 0, &g, &d);
    if (!e)
        watch_files(s, g);
    if (!e) {
        adopt(s, g);
        e = run_graph(s, s->g, 0, &d);
    }
    if (!e && args->reference)
        e = view_reference_open(s, args->reference, &d);
    if (e) {
        ssg_diags_print(&d, stderr);
        view_session_close(s);
    }
    return e;
}

void view_session_close(struct view_session *s)
{
    ssg_graph_destroy(&s->g);
    ssg_graph_destroy(&s->preview);
    ssg_run_stats_free(&s->stats);
    ssg_cli_watch_free(&s->watch);
    view_reference_close(s);
    free(s->error);
    s->error = NULL;
    free(s->text);
    s->text = NULL;
}

/* The slot of key among this session's changes: its own, or the next free one
 * (VIEW_MAX_SETS when there is none). */
static int set_slot(const struct view_session *s, const char *key)
{
    int i = 0;
    while (i < s->set_count && strcmp(s->sets[i].key, key))
        i++;
    return i;
}

enum ssg_err view_session_set(struct view_session *s, const char *assignment,
                              struct ssg_diags *d)
{
    const char *eq = strchr(assignment, '=');
    char key[VIEW_KEY_MAX];
    if (!eq || eq == assignment || (size_t)(eq - assignment) >= sizeof key ||
        strlen(eq + 1) >= VIEW_VALUE_MAX)
        return view_fail(d, SSG_E_USAGE, "expected NODE.PARAM=VALUE (a key under %d bytes, "
                         "a value under %d), got '%.200s'", VIEW_KEY_MAX, VIEW_VALUE_MAX,
                         assignment);
    snprintf(key, sizeof key, "%.*s", (int)(eq - assignment), assignment);
    const char *value = eq + 1;
    /* Refused before anything is applied: a change the session cannot remember would be
       in the graphs but lost at the next reload and missing from a saved variant. */
    int slot = set_slot(s, key);
    if (slot == VIEW_MAX_SETS)
        return view_fail(d, SSG_E_USAGE, "more than %d parameters changed in one session "
                         "(save a variant and open it to go on)", VIEW_MAX_SETS);
    enum ssg_err e = ssg_graph_set(s->g, key, value, d);
    if (!e && s->preview)
        e = ssg_graph_set(s->preview, key, value, d); /* the same checks: it passes */
    if (e)
        return e;
    snprintf(s->sets[slot].key, sizeof s->sets[slot].key, "%s", key);
    snprintf(s->sets[slot].value, sizeof s->sets[slot].value, "%s", value);
    if (slot == s->set_count)
        s->set_count++;
    s->preview_stale = 1;
    return run_graph(s, s->g, 0, d);
}

enum ssg_err view_session_camera(struct view_session *s, const struct ssg_view *camera,
                                 int preview, struct ssg_diags *d)
{
    enum ssg_err e = ssg_graph_set_view(s->g, camera, d);
    if (e)
        return e;
    s->camera = *camera;
    s->camera_changed = 1;
    if (preview && !s->preview)
        e = load(s, s->preview_width, s->preview_height, &s->preview, d);
    else if (s->preview)
        e = ssg_graph_set_view(s->preview, camera, d);
    if (e)
        return e;
    s->full_stale = preview;
    s->preview_stale = !preview;
    return run_graph(s, preview ? s->preview : s->g, preview, d);
}

enum ssg_err view_session_frame(struct view_session *s, int frame, struct ssg_diags *d)
{
    enum ssg_err e = ssg_graph_set_frame(s->g, frame, d);
    if (!e && s->preview)
        e = ssg_graph_set_frame(s->preview, frame, d);
    if (e)
        return e;
    struct ssg_diags ignored = {0};
    s->frame = frame;
    s->camera_changed = 0; /* the path's camera from now on */
    s->preview_stale = 1;
    e = run_graph(s, s->g, 0, d);
    if (!e)
        s->has_camera = ssg_graph_view(s->g, &s->camera, &ignored) == SSG_OK;
    return e;
}

enum ssg_err view_session_image(struct view_session *s, const char *port, int preview,
                                struct ssg_image **out, struct ssg_diags *d)
{
    /* A preview asked for once the full graph has run for the same camera (a drag's last
       fetch, late behind the full-size run) gets the full image: running the preview again
       would replace the finer, newer picture with a coarse one, and every drag ended on the
       preview (issue 46). */
    if (preview && s->preview_stale && !s->full_stale)
        preview = 0;
    struct ssg_image *img = NULL, *copy = NULL;
    enum ssg_err e;
    if (view_reference_image(s, port, out, &e, d))
        return e;
    *out = NULL;
    struct ssg_graph *g = preview && s->preview ? s->preview : s->g;
    /* After a drag only the preview ran: the full graph runs when first asked for. */
    int stale = g == s->g ? s->full_stale : s->preview_stale;
    e = stale ? run_graph(s, g, g != s->g, d) : SSG_OK;
    if (!e)
        e = ssg_graph_output(g, port, &img, d);
    if (e)
        return e;
    struct ssg_frame frame;
    ssg_graph_frame(g, &frame);
    const struct ssg_image *framed = ssg_image_framed(&frame, img, &copy);
    if (!framed) {
        ssg_image_destroy(&img);
        return SSG_E_NOMEM;
    }
    if (copy) {
        ssg_image_destroy(&img);
        img = copy;
    }
    *out = img;
    return SSG_OK;
}

/* The files the graph reads, watched (watch.h); after a load, or a failed one (g NULL). */
static void watch_files(struct view_session *s, const struct ssg_graph *g)
{
    if (s->watch && ssg_cli_watch_load(s->watch, g, &s->args->ov))
        fprintf(stderr, "ssgraph: view: out of memory: the file watcher keeps its old files\n");
}

int view_session_poll(struct view_session *s)
{
    const char *file = s->watch ? ssg_cli_watch_changed(s->watch) : NULL;
    if (!file)
        return 0;
    if (s->text) { /* the page's edits are of the text it had: neither may silently win */
        printf("view: %s changed: not loaded while the page has edits of the graph\n", file);
        fflush(stdout);
        free(s->error);
        if (asprintf(&s->error, "%s changed on disk while the page holds edits of the "
                     "graph: the change is not loaded (save the edits as a new graph, or "
                     "discard them to load the file)\n", file) < 0)
            s->error = NULL;
        s->generation++;
        return 1;
    }
    printf("view: %s changed: reloading\n", file);
    fflush(stdout);
    struct ssg_diags d = {0};
    struct ssg_graph *g;
    enum ssg_err e = load(s, 0, 0, &g, &d);
    if (!e) {
        adopt(s, g);
        e = run_graph(s, s->g, 0, &d);
    } else {
        s->generation++;
        set_error(s, &d, e);
    }
    watch_files(s, e ? NULL : s->g);
    if (e)
        ssg_diags_print(&d, stderr);
    return 1;
}

/* The parameter changes of nodes g lacks dropped (a removed node's). */
static void prune_sets(struct view_session *s, const struct ssg_graph *g)
{
    int kept = 0;
    for (int i = 0; i < s->set_count; i++)
        if (set_node_exists(g, s->sets[i].key))
            s->sets[kept++] = s->sets[i];
    s->set_count = kept;
}

/* Loads the session's graph with text as the graph file's (NULL: the file) and adopts it;
   on failure the session keeps its text and graph. */
static enum ssg_err reload_with(struct view_session *s, char *text, struct ssg_diags *d)
{
    char *old = s->text;
    struct ssg_graph *g;
    s->text = text;
    enum ssg_err e = load(s, 0, 0, &g, d);
    if (e) {
        s->text = old;
        free(text);
        return e;
    }
    free(old);
    prune_sets(s, g);
    adopt(s, g);
    return SSG_OK;
}

enum ssg_err view_session_edit(struct view_session *s, const char *edits, struct ssg_diags *d)
{
    const char *path = s->args->files[0];
    char *base = s->text, *text = NULL, why[256];
    size_t len;
    enum ssg_err e = SSG_OK;
    if (!base && (e = ssg_input_read(path, SSG_GRAPH_FILE_MAX_BYTES, &base, &len, why,
                                     sizeof why)))
        return view_fail(d, e, "cannot read %s: %s", path, why);
    e = ssg_graph_text_edit(path, base, edits, &text, d);
    if (base != s->text)
        free(base);
    if (!e)
        e = reload_with(s, text, d);
    if (e)
        return e;
    s->edits++;
    return run_graph(s, s->g, 0, d);
}

enum ssg_err view_session_discard(struct view_session *s, struct ssg_diags *d)
{
    if (!s->text)
        return view_fail(d, SSG_E_USAGE, "the graph has no edits to discard");
    enum ssg_err e = reload_with(s, NULL, d); /* frees the edited text once the file loads */
    if (e)
        return e;
    s->edits = 0;
    watch_files(s, s->g); /* the file as it is now is the one shown */
    return run_graph(s, s->g, 0, d);
}
