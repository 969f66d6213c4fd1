/* api_graph_files.c - the files a graph depends on, for file watchers (ssgraph_tools.h:
 * ssg_graph_files, ssg_scene_files; graph_files.h). The graph files are recorded by the
 * builder as it reads them; the scene's own files (models, textures, the environment
 * image) are found by reading the scene and lights files again with the one statement
 * parser and each entity kind's parameter table, so that they are known whether or not the
 * scene loaded: a watcher must see a broken model file being fixed. */
#include <stdlib.h>
#include <string.h>

#include "graph/graph_files.h"
#include "scene/scene_build.h"

enum ssg_err ssg_graph_file_note(struct ssg_graph *g, const char *path)
{
    struct ssg_file_list *l = g->files;
    if (!l && !(l = g->files = ssg_arena_alloc(&g->arena, sizeof *l)))
        return SSG_E_NOMEM;
    for (int i = 0; i < l->count; i++)
        if (strcmp(l->paths[i], path) == 0)
            return SSG_OK;
    if (l->count == l->cap) { /* the arena keeps the old array: few files, little waste */
        int cap = l->cap ? 2 * l->cap : 8;
        const char **grown = ssg_arena_alloc(&g->arena, (size_t)cap * sizeof *grown);
        if (!grown)
            return SSG_E_NOMEM;
        if (l->count)
            memcpy(grown, l->paths, (size_t)l->count * sizeof *grown);
        l->paths = grown;
        l->cap = cap;
    }
    const char *copy = ssg_arena_strndup(&g->arena, path, strlen(path));
    if (!copy)
        return SSG_E_NOMEM;
    l->paths[l->count++] = copy;
    return SSG_OK;
}

/* The files found so far, each once: all of them are kept (not only the caller's max), so
   that a file named twice past max is still counted once. */
struct lister {
    struct ssg_graph_file *found;
    int count, cap; /* out of memory, the list stays short: a watcher watches less */
};

static void add(struct lister *l, const char *path, enum ssg_graph_file_kind kind)
{
    size_t len = path ? strlen(path) : 0;
    if (!len || len >= SSG_GRAPH_FILE_PATH_MAX) /* none, or one no caller could open */
        return;
    for (int i = 0; i < l->count; i++)
        if (strcmp(l->found[i].path, path) == 0)
            return;
    if (l->count == l->cap) {
        int cap = l->cap ? 2 * l->cap : 16;
        struct ssg_graph_file *grown = realloc(l->found, (size_t)cap * sizeof *grown);
        if (!grown)
            return;
        l->found = grown;
        l->cap = cap;
    }
    memcpy(l->found[l->count].path, path, len + 1);
    l->found[l->count++].kind = kind;
}

/* What a scene parameter names, by its name: a file of that kind, or -1 (not a file). */
static int file_kind(const char *param, size_t len)
{
    static const struct { const char *name; enum ssg_graph_file_kind kind; } names[] = {
        {"file", SSG_GRAPH_FILE_MODEL},
        {"texture", SSG_GRAPH_FILE_TEXTURE},
        {"image", SSG_GRAPH_FILE_ENVIRONMENT},
    };
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (strlen(names[i].name) == len && memcmp(names[i].name, param, len) == 0)
            return (int)names[i].kind;
    return -1;
}

/* A string value naming a file: resolved against the file it is written in, as the scene
   loader resolves it (ssg_scene_path). */
static void add_value(struct lister *l, int kind, const struct ssg_value *v)
{
    if (kind < 0 || v->kind != SSG_V_STRING)
        return;
    char path[SSG_GRAPH_FILE_PATH_MAX + 1];
    ssg_path_resolve(v->loc.src ? v->loc.src->path : NULL, v->text, path, sizeof path);
    add(l, path, (enum ssg_graph_file_kind)kind);
}

/* An entity call's file arguments, positional ones by their place in the kind's table.
   skip_lights: the scene file's environment, which a lights file replaces. */
static void call_files(struct lister *l, const struct ssg_stmt *st, int skip_lights)
{
    for (int k = 0; k < SK_COUNT; k++) {
        const struct scene_kind_desc *d = &ssg_scene_kinds[k];
        if (strlen(d->name) != st->callee_len || memcmp(d->name, st->callee, st->callee_len))
            continue;
        if (skip_lights && k == SK_ENVIRONMENT)
            return;
        for (int i = 0, next = 0; i < st->arg_count; i++) {
            const struct ssg_arg *a = &st->args[i];
            int index = a->key ? ssg_param_find(d->table, a->key, a->key_len) : next++;
            if (index < 0 || index >= d->table.count)
                continue;
            const char *name = d->table.params[index].name;
            add_value(l, file_kind(name, strlen(name)), &a->value);
        }
        return;
    }
}

static void scene_assets(struct lister *l, const char *path, int skip_lights, int depth);

/* A scene file another includes (scene_include.c), and what it names in turn. */
static void included_scene(struct lister *l, const struct ssg_value *v, int skip_lights,
                           int depth)
{
    if (v->kind != SSG_V_STRING)
        return;
    char path[SSG_GRAPH_FILE_PATH_MAX + 1];
    ssg_path_resolve(v->loc.src ? v->loc.src->path : NULL, v->text, path, sizeof path);
    add(l, path, SSG_GRAPH_FILE_SCENE);
    scene_assets(l, path, skip_lights, depth);
}

/* The files a scene (or lights) file names, from the statements that parse; `set
   name.file = "..."` lines count as well (a superset of what loads is harmless here). */
static void scene_assets(struct lister *l, const char *path, int skip_lights, int depth)
{
    struct ssg_arena arena = {0};
    struct ssg_diags *diags = calloc(1, sizeof *diags); /* its errors are the load's to tell */
    struct ssg_file file = {0};
    if (diags)
        ssg_parse_file(&arena, path, (struct ssg_loc){0}, &file, diags);
    for (int i = 0; file.src && i < file.count; i++) {
        const struct ssg_stmt *st = &file.stmts[i];
        if (st->kind == SSG_S_CALL)
            call_files(l, st, skip_lights);
        else if (st->kind == SSG_S_SET && st->arg_count == 1)
            add_value(l, file_kind(st->callee, st->callee_len), &st->args[0].value);
        else if (st->kind == SSG_S_DIRECTIVE && ssg_tok_eq(st->name, st->name_len, "include") &&
                 st->arg_count == 1 && depth < SSG_SCENE_MAX_INCLUDE)
            included_scene(l, &st->args[0].value, skip_lights, depth + 1);
    }
    free(diags);
    ssg_arena_free(&arena);
}

static void scene_files(struct lister *l, const char *scene, const char *lights)
{
    int has_lights = lights && lights[0];
    add(l, scene, SSG_GRAPH_FILE_SCENE);
    if (has_lights)
        add(l, lights, SSG_GRAPH_FILE_LIGHTS);
    if (scene && scene[0])
        scene_assets(l, scene, has_lights, 0);
    if (has_lights)
        scene_assets(l, lights, 0, 0);
}

/* Copies at most max into files and frees the list; the count found. */
static int hand_out(struct lister *l, struct ssg_graph_file *files, int max)
{
    for (int i = 0; files && i < l->count && i < max; i++)
        files[i] = l->found[i];
    free(l->found);
    return l->count;
}

int ssg_graph_files(const struct ssg_graph *g, struct ssg_graph_file *files, int max)
{
    if (!g)
        return 0;
    struct lister l = {0};
    if (g->files)
        for (int i = 0; i < g->files->count; i++)
            add(&l, g->files->paths[i], SSG_GRAPH_FILE_GRAPH);
    else
        add(&l, g->path, SSG_GRAPH_FILE_GRAPH); /* built before it could record any */
    scene_files(&l, g->scene_path, g->lights_path);
    return hand_out(&l, files, max);
}

int ssg_scene_files(const char *scene, const char *lights, struct ssg_graph_file *files,
                    int max)
{
    struct lister l = {0};
    scene_files(&l, scene, lights);
    return hand_out(&l, files, max);
}
