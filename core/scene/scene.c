/* scene.c - scene files: statements to validated entities (scene_build.h), then the scene.
 *
 * Each entity kind (camera, material, lights, environment, plane, box, sphere, mesh) is a
 * parameter table, so arguments are parsed, range-checked, defaulted and documented the
 * same way as node parameters. Positional arguments fill parameters in table order
 * (mesh("bunny.gltf") sets `file`); `name = kind(...)` names an entity, materials are
 * referred to by name from anywhere in the file; `set name.arg = value` overrides an
 * argument of an entity defined above it. Every problem is reported with its location;
 * assets are loaded only when the whole file is valid. */
#include <errno.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "scene/distance.h"
#include "scene/env.h"
#include "scene/proxy.h"
#include "scene/rt.h"
#include "scene/scene_build.h"
#include "scene/scene_shapes.h"

/* ---- helpers shared with scene_build.c ---- */

void ssg_scene_fail(struct scene_loader *l, enum ssg_err e)
{
    if (!l->first)
        l->first = e;
}

void ssg_scene_path(const struct scene_entity *e, const char *rel, char *out, size_t len)
{
    ssg_path_resolve(e->stmt->callee_loc.src->path, rel, out, len);
}

static void kind_names(char *buf, size_t len)
{
    size_t n = 0;
    for (int k = 0; k < SK_COUNT && n < len; k++)
        n += (size_t)snprintf(buf + n, len - n, "%s%s", k ? ", " : "", ssg_scene_kinds[k].name);
}

static const char *entity_name(const struct scene_entity *e)
{
    return ssg_scene_kinds[e->kind].name;
}

/* ---- binding arguments ---- */

static void bind_arg(struct scene_loader *l, struct scene_entity *e, int index,
                     const struct ssg_value *v)
{
    const struct scene_kind_desc *k = &ssg_scene_kinds[e->kind];
    enum ssg_err err = ssg_param_set(k->table, index, e->args, v, k->name, l->diags);
    if (err)
        ssg_scene_fail(l, err);
    else
        e->at[index] = v->loc;
}

static void bind_named(struct scene_loader *l, struct scene_entity *e, const struct ssg_arg *a)
{
    const struct scene_kind_desc *k = &ssg_scene_kinds[e->kind];
    int index = ssg_param_find(k->table, a->key, a->key_len);
    if (index >= 0) {
        bind_arg(l, e, index, &a->value);
        return;
    }
    char names[256];
    ssg_param_names(k->table, names, sizeof names);
    ssg_diag_at(l->diags, SSG_E_UNKNOWN_PARAM, a->key_loc, "unknown argument '%.*s' for '%s' "
                "(expected one of: %s)", (int)a->key_len, a->key, k->name, names);
    ssg_scene_fail(l, SSG_E_UNKNOWN_PARAM);
}

static void bind_call(struct scene_loader *l, struct scene_entity *e)
{
    const struct ssg_stmt *st = e->stmt;
    int next = 0, named = 0;
    for (int i = 0; i < st->arg_count; i++) {
        const struct ssg_arg *a = &st->args[i];
        if (a->key) {
            named = 1;
            bind_named(l, e, a);
        } else if (named) {
            ssg_diag_at(l->diags, SSG_E_SYNTAX, a->value.loc, "positional argument after a "
                        "named one (expected name=value)");
            ssg_scene_fail(l, SSG_E_SYNTAX);
        } else if (next < ssg_scene_kinds[e->kind].table.count) {
            bind_arg(l, e, next++, &a->value);
        } else {
            ssg_diag_at(l->diags, SSG_E_VALUE, a->value.loc, "too many positional arguments "
                        "for '%s' (it has %d arguments)", entity_name(e),
                        ssg_scene_kinds[e->kind].table.count);
            ssg_scene_fail(l, SSG_E_VALUE);
        }
    }
}

static int find_entity(const struct scene_loader *l, const char *name, size_t len)
{
    for (int i = 0; i < l->count; i++) {
        const struct ssg_stmt *st = l->ents[i].stmt;
        if (st->name && st->name_len == len && memcmp(st->name, name, len) == 0)
            return i;
    }
    return -1;
}

/* Room for twice as many entities (the arena keeps the old array: a scene has few). */
static int grow_entities(struct scene_loader *l)
{
    int cap = l->ent_cap ? 2 * l->ent_cap : 64;
    struct scene_entity *grown = ssg_arena_alloc(&l->arena, sizeof *grown * (size_t)cap);
    if (!grown) {
        ssg_scene_fail(l, SSG_E_NOMEM);
        return 0;
    }
    if (l->count)
        memcpy(grown, l->ents, sizeof *grown * (size_t)l->count);
    l->ents = grown;
    l->ent_cap = cap;
    return 1;
}

static void add_entity(struct scene_loader *l, const struct ssg_stmt *st)
{
    int kind = 0;
    while (kind < SK_COUNT && !ssg_tok_eq(st->callee, st->callee_len, ssg_scene_kinds[kind].name))
        kind++;
    if (kind == SK_COUNT) {
        char names[256];
        kind_names(names, sizeof names);
        ssg_diag_at(l->diags, SSG_E_UNKNOWN_NODE, st->callee_loc, "unknown scene entity '%.*s' "
                    "(expected one of: %s)", (int)st->callee_len, st->callee, names);
        ssg_scene_fail(l, SSG_E_UNKNOWN_NODE);
        return;
    }
    if (st->name && find_entity(l, st->name, st->name_len) >= 0) {
        ssg_diag_at(l->diags, SSG_E_DUPLICATE, st->name_loc, "'%.*s' is defined twice",
                    (int)st->name_len, st->name);
        ssg_scene_fail(l, SSG_E_DUPLICATE);
        return;
    }
    if (l->count == l->ent_cap && !grow_entities(l))
        return;
    struct scene_entity *e = &l->ents[l->count];
    e->depth = l->depth;
    e->args = ssg_arena_alloc(&l->arena, ssg_scene_kinds[kind].size);
    if (!e->args) {
        ssg_scene_fail(l, SSG_E_NOMEM);
        return;
    }
    l->count++;
    e->kind = (enum scene_kind)kind;
    e->stmt = st;
    e->material = -1;
    ssg_params_defaults(ssg_scene_kinds[kind].table, e->args);
    bind_call(l, e);
}

static void apply_set(struct scene_loader *l, const struct ssg_stmt *st)
{
    int i = find_entity(l, st->name, st->name_len);
    if (i < 0) {
        ssg_diag_at(l->diags, SSG_E_UNKNOWN_NAME, st->name_loc, "'set' names '%.*s', which is "
                    "not defined above (define it with %.*s = kind(...))", (int)st->name_len,
                    st->name, (int)st->name_len, st->name);
        ssg_scene_fail(l, SSG_E_UNKNOWN_NAME);
        return;
    }
    bind_named(l, &l->ents[i], &st->args[0]);
}

static void read_file_entities(struct scene_loader *l, const char *path, int lights_only);

/* `include "other.scene"`: its entities join the scene as if written here. */
static void include_file(struct scene_loader *l, const struct ssg_stmt *st)
{
    char path[1024];
    if (!ssg_scene_include_path(l, st, path, sizeof path))
        return;
    l->depth++;
    read_file_entities(l, path, 0);
    l->depth--;
}

static void read_statements(struct scene_loader *l, const struct ssg_file *file)
{
    for (int i = 0; i < file->count; i++) {
        const struct ssg_stmt *st = &file->stmts[i];
        if (st->kind == SSG_S_CALL) {
            add_entity(l, st);
        } else if (st->kind == SSG_S_SET && !st->adds) {
            apply_set(l, st);
        } else if (st->kind == SSG_S_DIRECTIVE && ssg_tok_eq(st->name, st->name_len, "include")) {
            include_file(l, st);
        } else {
            char names[256];
            kind_names(names, sizeof names);
            ssg_diag_at(l->diags, SSG_E_SYNTAX, st->name_loc, "unknown statement '%.*s' in a "
                        "scene (expected an entity call: %s; set name.arg = value; or include \"file\")",
                        (int)st->name_len, st->name, names);
            ssg_scene_fail(l, SSG_E_SYNTAX);
        }
    }
}

/* ---- validation ---- */

static int param_index(const struct scene_entity *e, const char *name)
{
    return ssg_param_find(ssg_scene_kinds[e->kind].table, name, strlen(name));
}

/* Where to point at for a problem with argument `name`: its value, else the call. */
static struct ssg_loc arg_loc(const struct scene_entity *e, const char *name)
{
    int i = param_index(e, name);
    return i >= 0 && e->at[i].src ? e->at[i] : e->stmt->callee_loc;
}

static void problem(struct scene_loader *l, const struct scene_entity *e, const char *arg,
                    enum ssg_err code, const char *what)
{
    ssg_diag_at(l->diags, code, arg_loc(e, arg), "'%s' argument '%s': %s", entity_name(e), arg,
                what);
    ssg_scene_fail(l, code);
}

static void check_required(struct scene_loader *l, const struct scene_entity *e)
{
    const struct ssg_param_table t = ssg_scene_kinds[e->kind].table;
    for (int i = 0; i < t.count; i++)
        if (t.params[i].required && !e->at[i].src) {
            ssg_diag_at(l->diags, SSG_E_MISSING_INPUT, e->stmt->callee_loc,
                        "'%s' needs "
                        "argument '%s' (%s)",
                        entity_name(e), t.params[i].name, t.params[i].help);
            ssg_scene_fail(l, SSG_E_MISSING_INPUT);
        }
}

/* A spot light's inner cone may not be wider than its outer one. */
static void check_cone(struct scene_loader *l, const struct scene_entity *e)
{
    const struct light_args *a = e->args;
    if (a->inner_angle <= a->outer_angle)
        return;
    char what[160];
    snprintf(what, sizeof what, "inner_angle %g is wider than outer_angle %g (the "
             "full-intensity cone lies inside the lit one)", a->inner_angle, a->outer_angle);
    problem(l, e, "inner_angle", SSG_E_VALUE, what);
}

static int is_zero3(const float v[3])
{
    return v[0] == 0.0f && v[1] == 0.0f && v[2] == 0.0f;
}

/* A referenced file must be readable; checked without opening it (check mode opens
 * nothing but the scene file). */
static void check_file(struct scene_loader *l, const struct scene_entity *e, const char *arg,
                       const char *rel)
{
    char path[1024], what[1200];
    if (!rel[0])
        return;
    ssg_scene_path(e, rel, path, sizeof path);
    if (access(path, R_OK) == 0)
        return;
    snprintf(what, sizeof what, "cannot read '%s' (%s)", path, strerror(errno));
    problem(l, e, arg, SSG_E_IO, what);
}

static void check_material_ref(struct scene_loader *l, struct scene_entity *e, const char *name)
{
    if (!name[0])
        return;
    int i = find_entity(l, name, strlen(name));
    if (i >= 0 && l->ents[i].kind == SK_MATERIAL) {
        e->material = i;
        return;
    }
    char names[512] = "";
    size_t n = 0;
    for (int k = 0; k < l->count && n < sizeof names; k++)
        if (l->ents[k].kind == SK_MATERIAL && l->ents[k].stmt->name)
            n += (size_t)snprintf(names + n, sizeof names - n, "%s%.*s", n ? ", " : "",
                                  (int)l->ents[k].stmt->name_len, l->ents[k].stmt->name);
    char what[800];
    snprintf(what, sizeof what, "%s '%s' (expected a material: %s)",
             i >= 0 ? "not a material:" : "no material named", name,
             n ? names : "none defined");
    problem(l, e, "material", i >= 0 ? SSG_E_TYPE : SSG_E_UNKNOWN_NAME, what);
}

struct ssg_camera ssg_scene_camera_of(const struct camera_args *a)
{
    struct ssg_camera c = {.fov_y = a->fov, .near_z = a->near_z, .far_z = a->far_z};
    memcpy(c.position, a->position, sizeof c.position);
    memcpy(c.target, a->target, sizeof c.target);
    memcpy(c.up, a->up, sizeof c.up);
    return c;
}

static void check_camera(struct scene_loader *l, const struct scene_entity *e)
{
    struct ssg_camera c = ssg_scene_camera_of(e->args);
    enum ssg_camera_part part;
    const char *why = ssg_camera_fault(&c, &part);
    if (why)
        problem(l, e, ssg_camera_part_arg(part),
                part == SSG_CAMERA_PLANES ? SSG_E_RANGE : SSG_E_VALUE, why);
}

static void check_plane(struct scene_loader *l, struct scene_entity *e)
{
    const struct shape_args *s = e->args;
    if (is_zero3(s->normal))
        problem(l, e, "normal", SSG_E_VALUE, "the normal is zero");
    if (s->size[0] <= 0.0f || s->size[2] <= 0.0f)
        problem(l, e, "size", SSG_E_RANGE, "width (size[0]) and depth (size[2]) must be > 0");
}

static void check_entity(struct scene_loader *l, struct scene_entity *e)
{
    check_required(l, e);
    switch (e->kind) {
    case SK_CAMERA: check_camera(l, e); break;
    case SK_MATERIAL:
        check_file(l, e, "texture", ((const struct material_args *)e->args)->texture);
        check_file(l, e, "normal_map", ((const struct material_args *)e->args)->normal_map);
        if (((const struct material_args *)e->args)->alpha_mode == SSG_ALPHA_BLEND)
            ssg_diag_warn(l->diags, SSG_E_VALUE, arg_loc(e, "alpha_mode"), "material '%.*s': "
                          "alpha_mode=blend is drawn as mask at cutoff 0.5 (no pass of ssgraph "
                          "blends; docs/scenes.md)", (int)(e->stmt->name ? e->stmt->name_len : 0),
                          e->stmt->name ? e->stmt->name : "");
        break;
    case SK_POINT_LIGHT:
    case SK_CAMERA_KEY:
    case SK_ORBIT:
    case SK_FRAME_RATE: break;
    case SK_DIRECTIONAL_LIGHT:
    case SK_SPOT_LIGHT:
        if (e->at[param_index(e, "direction")].src &&
            is_zero3(((const struct light_args *)e->args)->direction))
            problem(l, e, "direction", SSG_E_VALUE, "the direction is zero");
        if (e->kind == SK_SPOT_LIGHT)
            check_cone(l, e);
        break;
    case SK_ENVIRONMENT:
        check_file(l, e, "image", ((const struct environment_args *)e->args)->image);
        break;
    case SK_PLANE:
    case SK_BOX:
    case SK_SPHERE:
        if (e->kind == SK_PLANE)
            check_plane(l, e);
        check_material_ref(l, e, ((const struct shape_args *)e->args)->material);
        break;
    case SK_MESH:
        check_file(l, e, "file", ((const struct mesh_args *)e->args)->file);
        check_material_ref(l, e, ((const struct mesh_args *)e->args)->material);
        break;
    case SK_COUNT: break;
    }
}

/* At most one camera and one environment: a second one is surely a mistake. */
static void check_unique(struct scene_loader *l, enum scene_kind kind)
{
    int seen = -1;
    for (int i = 0; i < l->count; i++) {
        if (l->ents[i].kind != kind)
            continue;
        if (seen >= 0) {
            int line, col;
            ssg_loc_linecol(l->ents[seen].stmt->callee_loc, &line, &col);
            ssg_diag_at(l->diags, SSG_E_DUPLICATE, l->ents[i].stmt->callee_loc, "a second "
                        "'%s' (the first is on line %d; a scene has at most one)",
                        ssg_scene_kinds[kind].name, line);
            ssg_scene_fail(l, SSG_E_DUPLICATE);
        }
        seen = i;
    }
}

/* ---- public API ---- */

static int is_light_kind(enum scene_kind k)
{
    return scene_kind_is_own_light(k) || k == SK_ENVIRONMENT;
}

/* Parses one file and appends its entities. With lights_only, a statement that is not a
   light or the environment is an error (a lights file relights a scene, nothing else). */
static void read_file_entities(struct scene_loader *l, const char *path, int lights_only)
{
    struct ssg_file file;
    enum ssg_err e = ssg_parse_file(&l->arena, path, (struct ssg_loc){0}, &file, l->diags);
    if (e)
        ssg_scene_fail(l, e);
    if (!file.src)
        return;
    int first = l->count;
    read_statements(l, &file);
    ssg_scene_replace_included(l, first);
    for (int i = first; lights_only && i < l->count; i++) {
        if (is_light_kind(l->ents[i].kind))
            continue;
        ssg_diag_at(l->diags, SSG_E_SYNTAX, l->ents[i].stmt->callee_loc, "a lights file holds "
                    "only point_light, directional_light, spot_light and environment (got '%s'; it "
                    "replaces the lights of the scene, whose geometry stays)",
                    entity_name(&l->ents[i]));
        ssg_scene_fail(l, SSG_E_SYNTAX);
    }
}

/* Drops the scene file's lights and environment before a lights file adds its own. */
static void drop_lights(struct scene_loader *l)
{
    int kept = 0;
    for (int i = 0; i < l->count; i++)
        if (!is_light_kind(l->ents[i].kind))
            l->ents[kept++] = l->ents[i];
    l->count = kept;
}

static enum ssg_err read_scene(struct scene_loader *l, const char *path, const char *lights)
{
    read_file_entities(l, path, 0);
    if (lights) {
        drop_lights(l);
        read_file_entities(l, lights, 1);
    }
    for (int i = 0; i < l->count; i++)
        check_entity(l, &l->ents[i]);
    check_unique(l, SK_CAMERA);
    check_unique(l, SK_ENVIRONMENT);
    check_unique(l, SK_ORBIT);
    check_unique(l, SK_FRAME_RATE);
    if (!l->first)
        ssg_scene_path_check(l);
    return l->first;
}

/* What a scene holds before any asset is loaded: the file's camera and environment. */
static void scene_defaults(struct ssg_scene *s, struct scene_loader *l)
{
    struct camera_args c;
    ssg_params_defaults(ssg_scene_kinds[SK_CAMERA].table, &c);
    s->environment.intensity = 1.0f; /* color 0: no environment light unless one is given */
    s->environment.image = -1;
    for (int i = 0; i < l->count; i++) {
        const struct scene_entity *e = &l->ents[i];
        if (scene_kind_is_own_light(e->kind))
            s->light_lines++;
        if (e->kind == SK_CAMERA) {
            c = *(const struct camera_args *)e->args;
            s->has_camera = 1;
        } else if (e->kind == SK_ENVIRONMENT) {
            const struct environment_args *env = e->args;
            memcpy(s->environment.color, env->color, sizeof env->color);
            s->environment.intensity = env->intensity;
        }
    }
    s->camera = ssg_scene_camera_of(&c);
    ssg_scene_path_fill(l, &c);
}

enum ssg_err ssg_scene_load(const char *path, int load_assets, struct ssg_scene **out,
                            struct ssg_diags *diags)
{
    return ssg_scene_load_lit(path, NULL, load_assets, out, diags);
}

enum ssg_err ssg_scene_load_lit(const char *path, const char *lights, int load_assets,
                                struct ssg_scene **out, struct ssg_diags *diags)
{
    *out = NULL;
    struct scene_loader l = {.diags = diags, .default_material = -1};
    struct ssg_scene *s = calloc(1, sizeof *s);
    if (s)
        s->proxies = ssg_scene_proxies_new();
    if (!s || !s->proxies) {
        free(s);
        return SSG_E_NOMEM;
    }
    snprintf(s->path, sizeof s->path, "%s", path);
    snprintf(s->lights_path, sizeof s->lights_path, "%s", lights ? lights : "");
    l.scene = s;
    if (read_scene(&l, path, lights) == SSG_OK) {
        scene_defaults(s, &l);
        if (load_assets && !l.first)
            ssg_scene_build(&l);
    }
    ssg_arena_free(&l.arena);
    if (l.first) {
        ssg_scene_destroy(&s);
        return l.first;
    }
    *out = s;
    return SSG_OK;
}

#define SWAP(type, x, y) do { type t_ = (x); (x) = (y); (y) = t_; } while (0)

void ssg_scene_swap_lights(struct ssg_scene *a, struct ssg_scene *b)
{
    char path[sizeof a->lights_path];
    memcpy(path, a->lights_path, sizeof path);
    memcpy(a->lights_path, b->lights_path, sizeof path);
    memcpy(b->lights_path, path, sizeof path);
    SWAP(struct ssg_light *, a->lights, b->lights);
    SWAP(int, a->light_count, b->light_count);
    SWAP(int, a->light_lines, b->light_lines);
    SWAP(struct ssg_environment, a->environment, b->environment);
    SWAP(struct ssg_env *, a->env, b->env);
}

void ssg_light_set_cone(struct ssg_light *l, float inner_deg, float outer_deg)
{
    l->cone_scale = 0.0f, l->cone_offset = 1.0f;
    l->cos_inner = l->cos_outer = -1.0f;
    if (l->kind != SSG_LIGHT_SPOT)
        return;
    const double rad = 0.017453292519943295; /* pi / 180 */
    l->cos_inner = (float)cos(inner_deg * rad), l->cos_outer = (float)cos(outer_deg * rad);
    /* glTF's lightAngleScale and lightAngleOffset; a hard edge when inner = outer */
    float span = l->cos_inner - l->cos_outer;
    l->cone_scale = 1.0f / (span > 1e-3f ? span : 1e-3f);
    l->cone_offset = -l->cos_outer * l->cone_scale;
}

int ssg_material_emits(const struct ssg_material *m)
{
    return m->emission[0] > 0.0f || m->emission[1] > 0.0f || m->emission[2] > 0.0f;
}

int ssg_scene_has_emission(const struct ssg_scene *s)
{
    for (int i = 0; i < s->material_count; i++)
        if (ssg_material_emits(&s->materials[i]))
            return 1;
    return 0;
}

int ssg_scene_environment_lit(const struct ssg_scene *s)
{
    const struct ssg_environment *env = &s->environment;
    return env->intensity > 0 && (env->color[0] > 0 || env->color[1] > 0 || env->color[2] > 0);
}

void ssg_scene_destroy(struct ssg_scene **scene)
{
    if (!scene || !*scene)
        return;
    struct ssg_scene *s = *scene;
    ssg_scene_proxies_release(s);
    ssg_rt_destroy(&s->rt);
    ssg_distance_destroy(&s->distance);
    ssg_env_destroy(&s->env);
    for (int i = 0; i < s->mesh_count; i++)
        ssg_mesh_free(&s->meshes[i]);
    for (int i = 0; i < s->texture_count; i++) {
        free(s->textures[i].rgb);
        free(s->textures[i].alpha);
    }
    free(s->meshes);
    free(s->textures);
    free(s->materials);
    free(s->lights);
    free(s->models);
    free(s->camera_path.keys);
    free(s);
    *scene = NULL;
}
