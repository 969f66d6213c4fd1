/* scene_path.c - the camera path of a scene file (docs/time.md): the camera_key, orbit and
 * frame_rate lines checked together, then made into scene->camera_path. Each line's own
 * arguments are range-checked by its table (scene_tables.c); what needs several lines is here: keys
 * at one time, a lone key, keys beside an orbit, a cut on the first key. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene/camera_path.h"
#include "scene/scene_build.h"

/* Where argument `name` of e was written, else its call. */
static struct ssg_loc written_at(const struct scene_entity *e, const char *name)
{
    int i = ssg_param_find(ssg_scene_kinds[e->kind].table, name, strlen(name));
    return i >= 0 && e->at[i].src ? e->at[i] : e->stmt->callee_loc;
}

/* 1 when argument `name` of e was written (not its default). */
static int given(const struct scene_entity *e, const char *name)
{
    int i = ssg_param_find(ssg_scene_kinds[e->kind].table, name, strlen(name));
    return i >= 0 && e->at[i].src != NULL;
}

static int line_of(const struct scene_entity *e)
{
    int line, col;
    ssg_loc_linecol(e->stmt->callee_loc, &line, &col);
    return line;
}

static const struct scene_loader *sort_loader; /* qsort has no user pointer in C11 */

static int by_time(const void *a, const void *b)
{
    int i = *(const int *)a, j = *(const int *)b;
    float ti = ((const struct camera_key_args *)sort_loader->ents[i].args)->time;
    float tj = ((const struct camera_key_args *)sort_loader->ents[j].args)->time;
    return ti < tj ? -1 : ti > tj ? 1 : i - j;
}

/* The key entities sorted by time into `index` (l->count ints); returns how many. */
static int sorted_keys(const struct scene_loader *l, int *index)
{
    int n = 0;
    for (int i = 0; i < l->count; i++)
        if (l->ents[i].kind == SK_CAMERA_KEY)
            index[n++] = i;
    sort_loader = l;
    qsort(index, (size_t)n, sizeof *index, by_time);
    sort_loader = NULL;
    return n;
}

static void fail_at(struct scene_loader *l, enum ssg_err code, struct ssg_loc at,
                    const char *fmt, double value, int line)
{
    ssg_diag_at(l->diags, code, at, fmt, value, line);
    ssg_scene_fail(l, code);
}

/* The up a key gets: its own, else the camera line's (else the table's default). */
static const float *key_up(const struct scene_loader *l, const struct scene_entity *e)
{
    if (given(e, "up"))
        return ((const struct camera_key_args *)e->args)->up;
    for (int i = 0; i < l->count; i++)
        if (l->ents[i].kind == SK_CAMERA)
            return ((const struct camera_args *)l->ents[i].args)->up;
    return ((const struct camera_key_args *)e->args)->up;
}

/* A key's view must be a camera as a camera line's must (ssg_camera_fault); its planes
   are the camera line's, checked there. */
static void check_key_view(struct scene_loader *l, const struct scene_entity *e)
{
    const struct camera_key_args *k = e->args;
    struct camera_args planes;
    ssg_params_defaults(ssg_scene_kinds[SK_CAMERA].table, &planes);
    struct camera_args args = {.fov = k->fov, .near_z = planes.near_z, .far_z = planes.far_z};
    memcpy(args.position, k->position, sizeof args.position);
    memcpy(args.target, k->target, sizeof args.target);
    memcpy(args.up, key_up(l, e), sizeof args.up);
    struct ssg_camera c = ssg_scene_camera_of(&args);
    enum ssg_camera_part part;
    const char *why = ssg_camera_fault(&c, &part);
    if (!why)
        return;
    const char *arg = ssg_camera_part_arg(part);
    ssg_diag_at(l->diags, SSG_E_VALUE, written_at(e, arg), "'camera_key' argument '%s': %s "
                "(at time %g; line %d)", arg, why, (double)k->time, line_of(e));
    ssg_scene_fail(l, SSG_E_VALUE);
}

static void check_keys(struct scene_loader *l, const int *index, int n)
{
    if (n == 1)
        fail_at(l, SSG_E_VALUE, l->ents[index[0]].stmt->callee_loc, "a camera path needs "
                "at least two camera_key lines (this one at time %g, line %d, is alone; for "
                "a still camera write camera(...))",
                ((const struct camera_key_args *)l->ents[index[0]].args)->time,
                line_of(&l->ents[index[0]]));
    for (int k = 0; k < n; k++) {
        const struct scene_entity *e = &l->ents[index[k]];
        const struct camera_key_args *a = e->args;
        check_key_view(l, e);
        if (k == 0 && a->cut && n > 1)
            fail_at(l, SSG_E_VALUE, written_at(e, "cut"), "'camera_key' argument 'cut': the "
                    "first key (time %g, line %d) has no key before it to cut from", a->time,
                    line_of(e));
        const struct scene_entity *before = k ? &l->ents[index[k - 1]] : NULL;
        if (before && ((const struct camera_key_args *)before->args)->time == a->time) {
            const struct scene_entity *later = index[k] > index[k - 1] ? e : before;
            fail_at(l, SSG_E_DUPLICATE, written_at(later, "time"), "two camera keys at "
                    "time %g (the other is on line %d; expected one key a time)", a->time,
                    line_of(later == e ? before : e));
        }
    }
}

/* An orbit is the whole path: keys beside it are a mistake (first_key: the earliest of
   them, NULL = none); its up must give it a plane to circle in. */
static void check_orbit(struct scene_loader *l, const struct scene_entity *e, int keys,
                        const struct scene_entity *first_key)
{
    const struct orbit_args *o = e->args;
    if (keys) {
        ssg_diag_at(l->diags, SSG_E_DUPLICATE, e->stmt->callee_loc, "an orbit beside %d "
                    "camera_key lines (one on line %d): a scene has one camera path, keys "
                    "or an orbit", keys, line_of(first_key));
        ssg_scene_fail(l, SSG_E_DUPLICATE);
    }
    if (o->up[0] == 0 && o->up[1] == 0 && o->up[2] == 0) {
        ssg_diag_at(l->diags, SSG_E_VALUE, written_at(e, "up"), "'orbit' argument 'up': "
                    "the up direction is zero (expected the axis to circle about)");
        ssg_scene_fail(l, SSG_E_VALUE);
    }
}

void ssg_scene_path_check(struct scene_loader *l)
{
    int *index = ssg_arena_alloc(&l->arena, sizeof(int) * (size_t)(l->count + 1));
    if (!index) {
        ssg_scene_fail(l, SSG_E_NOMEM);
        return;
    }
    int n = sorted_keys(l, index);
    check_keys(l, index, n);
    for (int i = 0; i < l->count; i++)
        if (l->ents[i].kind == SK_ORBIT)
            check_orbit(l, &l->ents[i], n, n ? &l->ents[index[0]] : NULL);
}

/* The keys, sorted, into the scene; up and fov that a key leaves out are the camera's. */
static int fill_keys(struct scene_loader *l, const struct camera_args *camera)
{
    struct ssg_camera_path *path = &l->scene->camera_path;
    int *index = ssg_arena_alloc(&l->arena, sizeof(int) * (size_t)(l->count + 1));
    int n = index ? sorted_keys(l, index) : 0;
    if (!index || (n && !(path->keys = calloc((size_t)n, sizeof *path->keys))))
        return 0;
    for (int k = 0; k < n; k++) {
        const struct scene_entity *e = &l->ents[index[k]];
        const struct camera_key_args *a = e->args;
        struct ssg_camera_key *key = &path->keys[k];
        key->time = a->time;
        memcpy(key->position, a->position, sizeof key->position);
        memcpy(key->target, a->target, sizeof key->target);
        memcpy(key->up, given(e, "up") ? a->up : camera->up, sizeof key->up);
        key->fov_y = given(e, "fov") ? a->fov : camera->fov;
        key->cut = a->cut;
    }
    path->key_count = n;
    return 1;
}

static void fill_orbit(struct scene_loader *l, const struct scene_entity *e,
                       const struct camera_args *camera)
{
    const struct orbit_args *a = e->args;
    struct ssg_orbit *o = &l->scene->camera_path.orbit;
    double len = sqrt((double)a->up[0] * a->up[0] + (double)a->up[1] * a->up[1] +
                      (double)a->up[2] * a->up[2]);
    for (int i = 0; i < 3; i++) {
        o->target[i] = a->target[i];
        o->up[i] = (float)(a->up[i] / len);
    }
    o->radius = a->radius, o->height = a->height;
    o->period = a->period, o->start = a->start;
    o->fov_y = given(e, "fov") ? a->fov : camera->fov;
    l->scene->camera_path.has_orbit = 1;
}

void ssg_scene_path_fill(struct scene_loader *l, const struct camera_args *camera)
{
    struct ssg_camera_path *path = &l->scene->camera_path;
    path->fps = 30.0;
    path->near_z = camera->near_z;
    path->far_z = camera->far_z;
    for (int i = 0; i < l->count; i++) {
        if (l->ents[i].kind == SK_FRAME_RATE)
            path->fps = ((const struct frame_rate_args *)l->ents[i].args)->fps;
        else if (l->ents[i].kind == SK_ORBIT)
            fill_orbit(l, &l->ents[i], camera);
    }
    if (!fill_keys(l, camera)) {
        ssg_scene_fail(l, SSG_E_NOMEM);
        return;
    }
    if (ssg_camera_path_active(path)) { /* the path is the camera: a glTF's gives way */
        ssg_camera_path_eval(path, 0.0, &l->scene->camera);
        l->scene->has_camera = 1;
    }
}
