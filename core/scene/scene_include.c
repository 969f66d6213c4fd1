/* scene_include.c - `include "other.scene"` in a scene file (scene_build.h): the other
 * file's entities join the scene as if written at the include, each of its paths still
 * resolved against its own folder (ssg_scene_path reads the file of each statement). A
 * file's own camera, camera path, environment and frame rate replace those of the files it
 * includes, so a scene that is "that scene with this camera path" (what the viewer's
 * "save path" writes) loads with its own path and no other. */
#include "scene/scene_build.h"

/* Which kinds a file's own line replaces in the files it includes: a camera the camera, a
   camera path (camera_key lines or an orbit) the path, and each other one-only kind its
   own; 0 for kinds that add up (shapes, lights, materials). */
static int replace_class(enum scene_kind k)
{
    switch (k) {
    case SK_CAMERA: return 1;
    case SK_CAMERA_KEY:
    case SK_ORBIT: return 2;
    case SK_ENVIRONMENT: return 3;
    case SK_FRAME_RATE: return 4;
    default: return 0;
    }
}

void ssg_scene_replace_included(struct scene_loader *l, int first)
{
    int own[5] = {0};
    for (int i = first; i < l->count; i++)
        if (l->ents[i].depth == l->depth)
            own[replace_class(l->ents[i].kind)] = 1;
    int kept = first;
    for (int i = first; i < l->count; i++) {
        const struct scene_entity *e = &l->ents[i];
        int c = replace_class(e->kind);
        if (e->depth == l->depth || !c || !own[c])
            l->ents[kept++] = *e;
    }
    l->count = kept;
}

int ssg_scene_include_path(struct scene_loader *l, const struct ssg_stmt *st, char *path,
                           size_t len)
{
    if (st->arg_count != 1 || st->args[0].value.kind != SSG_V_STRING) {
        ssg_diag_at(l->diags, SSG_E_SYNTAX, st->name_loc, "include takes one file name in "
                    "quotes: include \"other.scene\"");
        ssg_scene_fail(l, SSG_E_SYNTAX);
        return 0;
    }
    if (l->depth >= SSG_SCENE_MAX_INCLUDE) {
        ssg_diag_at(l->diags, SSG_E_SYNTAX, st->args[0].value.loc, "scene files included "
                    "more than %d deep: does a file include itself?", SSG_SCENE_MAX_INCLUDE);
        ssg_scene_fail(l, SSG_E_SYNTAX);
        return 0;
    }
    ssg_path_resolve(st->loc.src->path, st->args[0].value.text, path, len);
    return 1;
}
