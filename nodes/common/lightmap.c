/* lightmap.c - the faces of lightmap.h, built from the scene's lights alone. */
#include <math.h>
#include <stdio.h>

#include "scene/scene.h"
#include "common/lightmap.h"
#include "common/sampling.h"
#include "common/env_lights.h"

/* The cube's faces: look axis, then u and v, with u x v = axis. */
static const float CUBE[SSG_LIGHTMAP_CUBE_FACES][3][3] = {
    {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
    {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
    {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},   {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
};

static int tiles_of(int tiles)
{
    return tiles > 1 ? tiles : 1;
}

int ssg_lightmap_light_faces(const struct ssg_light *light, int tiles)
{
    if (light->kind == SSG_LIGHT_DIRECTIONAL)
        return tiles_of(tiles) * tiles_of(tiles);
    if (light->kind == SSG_LIGHT_SPOT && light->cos_outer >= SSG_LIGHTMAP_SPOT_FACE_COS)
        return 1;
    return SSG_LIGHTMAP_CUBE_FACES;
}

/* Faces of the scene's own lights alone: at least 1. */
static int own_face_count(const struct ssg_scene *scene, int tiles)
{
    int n = 0;
    for (int i = 0; scene && i < scene->light_count; i++)
        n += ssg_lightmap_light_faces(&scene->lights[i], tiles);
    return n > 0 ? n : 1;
}

enum ssg_err ssg_lightmap_sources_check(struct ssg_lightmap_sources src, char *why,
                                        size_t why_len)
{
    if (src.own || src.environment > 0)
        return SSG_OK;
    snprintf(why, why_len, "own=false and environment=0 leave no light to map: keep the own "
             "lights or give the environment a light count (rsm: the lightmaps node's values)");
    return SSG_E_VALUE;
}

int ssg_lightmap_face_count(const struct ssg_scene *scene, struct ssg_lightmap_sources src)
{
    return (src.own ? own_face_count(scene, src.tiles) : 0) + src.environment;
}

void ssg_lightmap_env_directions(const struct ssg_scene *scene, int count, float *dirs)
{
    const struct ssg_env *env = scene ? scene->env : NULL;
    if (env && env->has_light)
        ssg_env_lights_importance(env, count, SSG_LIGHTMAP_ENV_UNIFORM_SHARE, dirs);
    else
        ssg_env_lights_fibonacci(count, dirs);
}

/* An orthographic face over the bounding sphere, looking along -l (l towards the light). */
static void directional_face(const struct ssg_bounding_sphere *sphere, const float l[3],
                             struct ssg_lightmap_face *f)
{
    struct ssg_shadow_frame frame = ssg_shadow_frame_make(sphere, l);
    f->ortho = 1;
    f->half = frame.radius;
    for (int k = 0; k < 3; k++) {
        f->origin[k] = frame.origin[k];
        f->u[k] = frame.u[k];
        f->v[k] = frame.v[k];
        f->axis[k] = -l[k];
    }
}

static void cube_face(const struct ssg_light *light, int side, struct ssg_lightmap_face *f)
{
    f->ortho = 0;
    f->half = 1.0f;
    for (int k = 0; k < 3; k++) {
        f->origin[k] = light->position[k];
        f->axis[k] = CUBE[side][0][k];
        f->u[k] = CUBE[side][1][k];
        f->v[k] = CUBE[side][2][k];
    }
}

/* A spot light's one face: along its axis, u and v the orthonormal frame about it with
   u x v = axis (ssg_sampling_basis), as wide as its outer cone. */
static void spot_face(const struct ssg_light *light, struct ssg_lightmap_face *f)
{
    const float *a = light->direction;
    float s = sqrtf(fmaxf(0.0f, 1.0f - light->cos_outer * light->cos_outer));
    f->ortho = 0;
    f->half = s / light->cos_outer;
    ssg_sampling_basis(a[0], a[1], a[2], f->u, f->v);
    for (int k = 0; k < 3; k++) {
        f->origin[k] = light->position[k];
        f->axis[k] = a[k];
    }
}

const char *const ssg_lightmap_fit_choices[] = {"scene", "view", NULL};

/* The own lights' faces into faces[0 ..]; returns how many. */
static int own_faces(const struct ssg_scene *scene, const struct ssg_bounding_sphere *sphere,
                     struct ssg_lightmap_face *faces)
{
    if (!scene || scene->light_count == 0) {
        faces[0] = (struct ssg_lightmap_face){.light = -1, .ortho = 1, .half = 1.0f,
                                              .u = {1, 0, 0}, .v = {0, 1, 0},
                                              .axis = {0, 0, 1}};
        return 1;
    }
    int n = 0;
    for (int i = 0; i < scene->light_count; i++) {
        const struct ssg_light *light = &scene->lights[i];
        if (light->kind == SSG_LIGHT_DIRECTIONAL) {
            float l[3] = {-light->direction[0], -light->direction[1], -light->direction[2]};
            faces[n] = (struct ssg_lightmap_face){.light = i};
            directional_face(sphere, l, &faces[n++]);
            continue;
        }
        if (ssg_lightmap_light_faces(light, 1) == 1) {
            faces[n] = (struct ssg_lightmap_face){.light = i};
            spot_face(light, &faces[n++]);
            continue;
        }
        for (int side = 0; side < SSG_LIGHTMAP_CUBE_FACES; side++) {
            faces[n] = (struct ssg_lightmap_face){.light = i};
            cube_face(light, side, &faces[n++]);
        }
    }
    return n;
}

/* The own directional lights' faces (after own_faces) fitted to the view; their maps'
   side is tiles x the resolution (the padding is in their texels). */
static void fit_to_view(const struct ssg_scene *scene, const struct ssg_lightmap_view *view,
                        int tiles, struct ssg_lightmap_face *faces, int n)
{
    float lo[3], hi[3];
    ssg_scene_bounds(scene, lo, hi);
    struct ssg_lightmap_view whole = *view;
    whole.res = view->res * tiles;
    for (int i = 0; i < n; i++)
        if (faces[i].light >= 0 && faces[i].ortho)
            ssg_lightmap_fit_view(&whole, lo, hi, &faces[i]);
}

/* Cuts the own directional lights' faces (faces[0 .. n - 1]) into tiles x tiles faces
   each, in place; returns the new count. Tile (tx, ty) covers [-1 + 2 tx / T, -1 + 2 (tx
   + 1) / T] of its map's a (same for b), so its origin moves within the plane and its
   half shrinks by T: the depth along the axis stays the map's. */
static int cut_tiles(struct ssg_lightmap_face *faces, int n, int tiles)
{
    int t2 = tiles * tiles, extra = 0;
    for (int i = 0; i < n; i++)
        extra += faces[i].light >= 0 && faces[i].ortho ? t2 - 1 : 0;
    for (int i = n - 1, o = n + extra - 1; i >= 0; i--) {
        struct ssg_lightmap_face f = faces[i];
        if (!(f.light >= 0 && f.ortho)) {
            faces[o--] = f;
            continue;
        }
        for (int t = t2 - 1; t >= 0; t--, o--) {
            float a = (2.0f * (float)(t % tiles) + 1.0f) / (float)tiles - 1.0f;
            float b = (2.0f * (float)(t / tiles) + 1.0f) / (float)tiles - 1.0f;
            faces[o] = f;
            faces[o].half = f.half / (float)tiles;
            for (int k = 0; k < 3; k++)
                faces[o].origin[k] += f.half * (a * f.u[k] + b * f.v[k]);
        }
    }
    return n + extra;
}

int ssg_lightmap_faces(const struct ssg_scene *scene, struct ssg_lightmap_sources src,
                       struct ssg_lightmap_face *faces, int max)
{
    return ssg_lightmap_faces_fit(scene, src, SSG_LIGHTMAP_FIT_SCENE, NULL, faces, max);
}

int ssg_lightmap_faces_fit(const struct ssg_scene *scene, struct ssg_lightmap_sources src,
                           enum ssg_lightmap_fit fit, const struct ssg_lightmap_view *view,
                           struct ssg_lightmap_face *faces, int max)
{
    int count = ssg_lightmap_face_count(scene, src);
    if (count > max || src.environment < 0 || src.environment > SSG_LIGHTMAP_ENV_MAX)
        return -1;
    struct ssg_bounding_sphere sphere = {{0, 0, 0}, 1.0f};
    if (scene)
        sphere = ssg_scene_bounding_sphere(scene);
    int n = src.own ? own_faces(scene, &sphere, faces) : 0, tiles = tiles_of(src.tiles);
    if (fit == SSG_LIGHTMAP_FIT_VIEW && scene && view)
        fit_to_view(scene, view, tiles, faces, n);
    if (tiles > 1)
        n = cut_tiles(faces, n, tiles);
    float dirs[3 * SSG_LIGHTMAP_ENV_MAX];
    ssg_lightmap_env_directions(scene, src.environment, dirs);
    for (int k = 0; k < src.environment; k++) {
        faces[n] = (struct ssg_lightmap_face){.light = SSG_LIGHTMAP_ENV_LIGHT(k)};
        directional_face(&sphere, dirs + 3 * k, &faces[n++]);
    }
    return n;
}
