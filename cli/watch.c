/* watch.c - the polling file watcher (watch.h): snapshots of the files a graph depends on,
 * compared with the disk on each poll. */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "watch.h"

/* What a file looked like: a change in any field is a change of the file. */
struct snapshot {
    int exists;
    long long mtime_ns, size;
    unsigned long long dev, ino; /* a file replaced by a rename has another inode */
};

struct record {
    char *path;
    struct snapshot seen;
};

struct ssg_cli_watch {
    char *top;
    struct record *files;
    int count;
};

static struct snapshot take(const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0)
        return (struct snapshot){0};
    return (struct snapshot){
        .exists = 1, .mtime_ns = (long long)st.st_mtim.tv_sec * 1000000000LL + st.st_mtim.tv_nsec,
        .size = (long long)st.st_size, .dev = (unsigned long long)st.st_dev,
        .ino = (unsigned long long)st.st_ino};
}

static int same(const struct snapshot *a, const struct snapshot *b)
{
    return a->exists == b->exists && a->mtime_ns == b->mtime_ns && a->size == b->size &&
           a->dev == b->dev && a->ino == b->ino;
}

static void free_records(struct record *r, int count)
{
    for (int i = 0; i < count; i++)
        free(r[i].path);
    free(r);
}

/* The watcher's snapshot of path, or NULL when it has none. */
static const struct snapshot *known(const struct ssg_cli_watch *w, const char *path)
{
    for (int i = 0; i < w->count; i++)
        if (strcmp(w->files[i].path, path) == 0)
            return &w->files[i].seen;
    return NULL;
}

/* Makes paths[0..count-1] the watched set: a file watched before keeps its snapshot, a
   new one is taken now. 0, or -1 when out of memory (nothing changed then). */
static int watch_paths(struct ssg_cli_watch *w, const char *const *paths, int count)
{
    struct record *r = calloc((size_t)count + 1, sizeof *r);
    if (!r)
        return -1;
    for (int i = 0; i < count; i++) {
        const struct snapshot *old = known(w, paths[i]);
        r[i].seen = old ? *old : take(paths[i]);
        if (!(r[i].path = strdup(paths[i]))) {
            free_records(r, i);
            return -1;
        }
    }
    free_records(w->files, w->count);
    w->files = r;
    w->count = count;
    return 0;
}

struct ssg_cli_watch *ssg_cli_watch_new(const char *top)
{
    struct ssg_cli_watch *w = calloc(1, sizeof *w);
    if (w && (w->top = strdup(top)) && watch_paths(w, (const char *const *)&w->top, 1) == 0)
        return w;
    ssg_cli_watch_free(&w);
    return NULL;
}

void ssg_cli_watch_free(struct ssg_cli_watch **w)
{
    if (!w || !*w)
        return;
    free_records((*w)->files, (*w)->count);
    free((*w)->top);
    free(*w);
    *w = NULL;
}

/* The list a function of the ssg_graph_files kind fills, in a malloc'd array; *count its
   entries (0 with NULL when there are none or memory ran out). */
static struct ssg_graph_file *list_graph(const struct ssg_graph *g, int *count)
{
    int n = ssg_graph_files(g, NULL, 0);
    struct ssg_graph_file *f = n > 0 ? malloc((size_t)n * sizeof *f) : NULL;
    *count = f ? ssg_graph_files(g, f, n) : 0;
    return f;
}

static struct ssg_graph_file *list_scene(const char *scene, const char *lights, int *count)
{
    int n = ssg_scene_files(scene, lights, NULL, 0);
    struct ssg_graph_file *f = n > 0 ? malloc((size_t)n * sizeof *f) : NULL;
    *count = f ? ssg_scene_files(scene, lights, f, n) : 0;
    return f;
}

/* A failed load: the graph files ssg_graph_parse reads (as far as it gets), then the
   scene and lights the load would have used (the overrides win over the graph's lines)
   with what they name. */
static struct ssg_graph_file *list_failed(const char *top, const struct ssg_overrides *ov,
                                          int *count)
{
    struct ssg_diags *d = calloc(1, sizeof *d); /* the failed load has told its errors */
    struct ssg_graph *g = NULL;
    if (d)
        ssg_graph_parse(top, &g, d);
    free(d);
    int n = 0, m = 0;
    struct ssg_graph_file *f = list_graph(g, &n);
    struct ssg_graph_info info = {.scene = "", .lights = ""};
    if (g)
        ssg_graph_inspect(g, &info);
    const char *scene = ov && ov->scene ? ov->scene : info.scene;
    const char *lights = ov && ov->lights ? ov->lights : info.lights;
    struct ssg_graph_file *s = list_scene(scene, lights, &m);
    int graph_files = 0;
    while (graph_files < n && f[graph_files].kind == SSG_GRAPH_FILE_GRAPH)
        graph_files++;
    int total = graph_files + m;
    struct ssg_graph_file *all = total ? malloc(sizeof *all * (size_t)total) : NULL;
    if (all) {
        memcpy(all, f, sizeof *all * (size_t)graph_files);
        memcpy(all + graph_files, s, sizeof *all * (size_t)m);
    }
    *count = all ? total : 0;
    free(f);
    free(s);
    ssg_graph_destroy(&g);
    return all;
}

int ssg_cli_watch_load(struct ssg_cli_watch *w, const struct ssg_graph *graph,
                       const struct ssg_overrides *ov)
{
    int n = 0;
    struct ssg_graph_file *f = graph ? list_graph(graph, &n) : list_failed(w->top, ov, &n);
    const char **paths = malloc(sizeof *paths * (size_t)(n + 1));
    if (!paths) {
        free(f);
        return -1;
    }
    int count = 0, has_top = 0;
    for (int i = 0; i < n; i++)
        has_top |= strcmp(f[i].path, w->top) == 0;
    if (!has_top) /* the graph as given is watched whatever its load made of it */
        paths[count++] = w->top;
    for (int i = 0; i < n; i++)
        if (f[i].path[0])
            paths[count++] = f[i].path;
    int rc = watch_paths(w, paths, count);
    free(paths);
    free(f);
    return rc;
}

const char *ssg_cli_watch_changed(struct ssg_cli_watch *w)
{
    const char *first = NULL;
    for (int i = 0; i < w->count; i++) {
        struct snapshot now = take(w->files[i].path);
        if (same(&now, &w->files[i].seen))
            continue;
        w->files[i].seen = now;
        if (!first)
            first = w->files[i].path;
    }
    return first;
}

int ssg_cli_watch_count(const struct ssg_cli_watch *w)
{
    return w ? w->count : 0;
}

const char *ssg_cli_watch_file(const struct ssg_cli_watch *w, int i)
{
    return w && i >= 0 && i < w->count ? w->files[i].path : NULL;
}
