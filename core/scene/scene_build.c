/* scene_build.c - turns the validated entities of a scene file into a struct ssg_scene:
 * materials and their textures, lights, the environment, tessellated primitives, glTF
 * meshes placed by their transform, the camera, and finally the Embree scene.
 *
 * Textures: images come through ssg_image_read, which linearises files OpenImageIO reports
 * as sRGB (8-bit PNG, JPEG) and leaves EXR/HDR as they are, so no colour conversion
 * happens here; glTF base-colour textures are linearised by the glTF adapter. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene/distance.h"
#include "scene/env.h"
#include <errno.h>
#include <unistd.h>

#include "scene/model.h"
#include "scene/rt.h"
#include "scene/coverage.h"
#include "scene/scene_build.h"
#include "scene/scene_shapes.h"

/* The array, grown when needed to hold count + 1 items of `size` bytes; NULL (the
 * array left as it was) when out of memory. */
void *ssg_scene_reserve(struct scene_loader *l, void *array, int count, int *cap, size_t size)
{
    if (count < *cap)
        return array;
    int want = *cap ? 2 * *cap : 16;
    void *p = realloc(array, (size_t)want * size);
    if (!p) {
        ssg_diag_at(l->diags, SSG_E_NOMEM, (struct ssg_loc){0},
                    "out of memory loading the scene");
        ssg_scene_fail(l, SSG_E_NOMEM);
        return NULL;
    }
    *cap = want;
    return p;
}

static struct ssg_material *new_material(struct scene_loader *l, const char *name)
{
    struct ssg_scene *s = l->scene;
    struct ssg_material *grown = ssg_scene_reserve(l, s->materials, s->material_count, &l->material_cap,
                                         sizeof *s->materials);
    if (!grown)
        return NULL;
    s->materials = grown;
    struct ssg_material *m = &s->materials[s->material_count++];
    memset(m, 0, sizeof *m);
    snprintf(m->name, sizeof m->name, "%s", name);
    m->shininess = 32.0f;
    m->texture = -1;
    m->alpha_mode = SSG_ALPHA_OPAQUE;
    m->alpha_cutoff = 0.5f; /* glTF's default */
    m->opacity = 1.0f;
    m->normal_texture = -1;
    m->normal_scale = 1.0f;
    m->emission_texture = -1;
    return m;
}

/* The white 0.8 material of everything that names none; made when first needed. */
static int default_material(struct scene_loader *l)
{
    if (l->default_material < 0) {
        struct ssg_material *m = new_material(l, "default");
        if (!m)
            return -1; /* l->first is set: the scene is discarded */
        m->albedo[0] = m->albedo[1] = m->albedo[2] = 0.8f;
        l->default_material = l->scene->material_count - 1;
    }
    return l->default_material;
}

static void build_material(struct scene_loader *l, int ent)
{
    const struct scene_entity *e = &l->ents[ent];
    const struct material_args *a = e->args;
    char name[SSG_NAME_MAX];
    snprintf(name, sizeof name, "%.*s", (int)(e->stmt->name ? e->stmt->name_len : 0),
             e->stmt->name ? e->stmt->name : "");
    struct ssg_material *m = new_material(l, name);
    if (!m)
        return;
    memcpy(m->albedo, a->albedo, sizeof m->albedo);
    memcpy(m->specular, a->specular, sizeof m->specular);
    m->shininess = a->shininess;
    m->alpha_mode = (enum ssg_alpha_mode)a->alpha_mode;
    m->alpha_cutoff = m->alpha_mode == SSG_ALPHA_BLEND ? 0.5f : a->alpha_cutoff;
    m->opacity = a->opacity;
    memcpy(m->emission, a->emission, sizeof m->emission);
    m->normal_scale = a->normal_scale;
    l->material_of[ent] = l->scene->material_count - 1;
    if (a->texture[0])
        m->texture = ssg_scene_load_texture(l, e, a->texture, 1, ssg_material_masked(m));
    if (a->normal_map[0])
        m->normal_texture = ssg_scene_load_normal_map(l, e, a->normal_map);
}

static void build_light(struct scene_loader *l, const struct scene_entity *e)
{
    const struct light_args *a = e->args;
    struct ssg_light *li = &l->scene->lights[l->scene->light_count++];
    memset(li, 0, sizeof *li);
    li->kind = e->kind == SK_POINT_LIGHT ? SSG_LIGHT_POINT
               : e->kind == SK_SPOT_LIGHT ? SSG_LIGHT_SPOT : SSG_LIGHT_DIRECTIONAL;
    ssg_light_set_cone(li, a->inner_angle, a->outer_angle);
    memcpy(li->position, a->position, sizeof li->position);
    memcpy(li->color, a->color, sizeof li->color);
    li->intensity = a->intensity;
    float len = sqrtf(a->direction[0] * a->direction[0] + a->direction[1] * a->direction[1] +
                      a->direction[2] * a->direction[2]);
    for (int i = 0; i < 3 && len > 0.0f; i++)
        li->direction[i] = a->direction[i] / len;
}

/* The model's own lights (glTF KHR_lights_punctual), placed by the mesh line's transform
   as its triangles are (a position scaled, turned and moved; a direction scaled and turned),
   after the scene's light lines. Dropped with `lights=false`, and when a lights file
   relights the scene. */
static void import_lights(struct scene_loader *l, const struct scene_entity *e,
                          const struct ssg_gltf *g)
{
    const struct mesh_args *a = e->args;
    struct ssg_scene *s = l->scene;
    if (!a->lights || s->lights_path[0])
        return;
    float r[9];
    ssg_euler_matrix(a->rotate, r);
    for (int k = 0; k < g->light_count; k++) {
        struct ssg_light *grown = ssg_scene_reserve(l, s->lights, s->light_count, &l->light_cap,
                                          sizeof *s->lights);
        if (!grown)
            return;
        s->lights = grown;
        struct ssg_light *li = &s->lights[s->light_count++];
        *li = g->lights[k];
        float p[3], d[3], len = 0.0f;
        for (int i = 0; i < 3; i++)
            p[i] = li->position[i] * a->scale[i], d[i] = li->direction[i] * a->scale[i];
        for (int i = 0; i < 3; i++) {
            li->position[i] = r[3 * i] * p[0] + r[3 * i + 1] * p[1] + r[3 * i + 2] * p[2] +
                              a->translate[i];
            li->direction[i] = r[3 * i] * d[0] + r[3 * i + 1] * d[1] + r[3 * i + 2] * d[2];
            len += li->direction[i] * li->direction[i];
        }
        for (int i = 0; i < 3 && len > 0.0f; i++)
            li->direction[i] /= sqrtf(len);
    }
}

/* Appends a mesh (taking over its arrays); frees them when the scene cannot grow. */
static void add_mesh(struct scene_loader *l, struct ssg_mesh *mesh)
{
    struct ssg_scene *s = l->scene;
    struct ssg_mesh *grown =
        ssg_scene_reserve(l, s->meshes, s->mesh_count, &l->mesh_cap, sizeof *s->meshes);
    if (!grown) {
        ssg_mesh_free(mesh);
        return;
    }
    s->meshes = grown;
    s->meshes[s->mesh_count++] = *mesh;
}

/* Records a mesh line for ssgraph check; its meshes follow as they are added. */
static struct ssg_scene_model *add_model(struct scene_loader *l, const struct scene_entity *e,
                                         long long triangles)
{
    struct ssg_scene *s = l->scene;
    struct ssg_scene_model *grown = ssg_scene_reserve(l, s->models, s->model_count, &l->model_cap,
                                            sizeof *s->models);
    if (!grown)
        return NULL;
    s->models = grown;
    struct ssg_scene_model *m = &s->models[s->model_count++];
    memset(m, 0, sizeof *m);
    snprintf(m->file, sizeof m->file, "%s", ((const struct mesh_args *)e->args)->file);
    ssg_scene_path(e, m->file, m->path, sizeof m->path);
    ssg_loc_linecol(e->at[0], &m->line, &m->column);
    snprintf(m->scene_file, sizeof m->scene_file, "%s", e->stmt->callee_loc.src->path);
    m->first_mesh = s->mesh_count;
    m->triangles = triangles;
    return m;
}

/* One warning a model that uses what ssgraph does not read (the features, without the
   materials: `ssgraph check` lists those), so a run says its picture leaves them out. */
static void warn_ignored(struct scene_loader *l, const struct scene_entity *e,
                         const char *file, const char *ignored)
{
    char features[400] = "";
    size_t n = 0;
    for (const char *line = ignored; *line && n + 4 < sizeof features;) {
        const char *end = strchr(line, '\n'), *colon = strstr(line, ": ");
        size_t len = (size_t)((colon && (!end || colon < end) ? colon : end ? end : line +
                               strlen(line)) - line);
        n += (size_t)snprintf(features + n, sizeof features - n, "%s%.*s", n ? "; " : "",
                              (int)len, line);
        line = end ? end + 1 : line + strlen(line);
    }
    if (features[0])
        ssg_diag_warn(l->diags, SSG_E_VALUE, e->at[0], "%s uses what ssgraph does not read "
                      "yet, and the picture leaves it out: %s (`ssgraph check` lists where; "
                      "docs/scenes.md, \"Model file features\")", file, features);
}

static int material_for(struct scene_loader *l, const struct scene_entity *e)
{
    return e->material >= 0 ? l->material_of[e->material] : default_material(l);
}

/* 0 with a message at `at` when `more` triangles would take the scene past its limit. */
static int triangles_fit(struct scene_loader *l, struct ssg_loc at, long long more,
                         const char *what)
{
    if (l->triangles + more <= SSG_SCENE_MAX_TRIANGLES) {
        l->triangles += more;
        return 1;
    }
    ssg_diag_at(l->diags, SSG_E_SIZE, at, "%s has %lld triangles, which takes the scene past "
                "its limit of %lld (expected fewer subdivisions or a lighter model)", what,
                more, SSG_SCENE_MAX_TRIANGLES);
    ssg_scene_fail(l, SSG_E_SIZE);
    return 0;
}

static void build_shape(struct scene_loader *l, const struct scene_entity *e)
{
    const struct shape_args *a = e->args;
    struct ssg_mesh mesh;
    enum ssg_err err;
    long long tris = e->kind == SK_SPHERE ? 4LL * a->subdivisions * (a->subdivisions - 1) : 12;
    if (!triangles_fit(l, e->stmt->callee_loc, tris, "this shape"))
        return;
    if (e->kind == SK_PLANE)
        err = ssg_shape_plane(a->center, a->size, a->normal, &mesh);
    else if (e->kind == SK_BOX)
        err = ssg_shape_box(a->center, a->size, a->rotate, &mesh);
    else
        err = ssg_shape_sphere(a->center, a->radius, a->subdivisions, &mesh);
    if (err) {
        ssg_diag_at(l->diags, err, e->stmt->callee_loc, "out of memory tessellating '%.*s'",
                    (int)e->stmt->callee_len, e->stmt->callee);
        ssg_scene_fail(l, err);
        return;
    }
    mesh.material = material_for(l, e);
    add_mesh(l, &mesh);
}

/* Brings the model's materials and textures into the scene; returns the scene index of its
 * material 0 (materials keep their order). */
static int import_gltf_materials(struct scene_loader *l, const struct scene_entity *e,
                                 struct ssg_gltf *g, const char *model)
{
    const char *file = ((const struct mesh_args *)e->args)->file;
    int first_texture = l->scene->texture_count, first = l->scene->material_count;
    for (int i = 0; i < g->texture_count; i++) {
        ssg_scene_add_texture(l, g->textures[i].width, g->textures[i].height, g->textures[i].rgb,
                    g->textures[i].alpha);
        g->textures[i].rgb = g->textures[i].alpha = NULL; /* now the scene's */
    }
    for (int i = 0; i < g->material_count; i++) {
        const struct ssg_gltf_material *gm = &g->materials[i];
        char name[SSG_NAME_MAX];
        snprintf(name, sizeof name, "%.63s", gm->name[0] ? gm->name : file);
        struct ssg_material *m = new_material(l, name);
        if (!m)
            return first;
        memcpy(m->albedo, gm->base_color, sizeof m->albedo);
        m->opacity = gm->base_color[3];
        m->alpha_mode = (enum ssg_alpha_mode)gm->alpha_mode;
        m->alpha_cutoff = gm->alpha_cutoff;
        if (m->alpha_mode == SSG_ALPHA_BLEND)
            ssg_diag_warn(l->diags, SSG_E_VALUE, e->at[0], "%s: material '%s' has alphaMode "
                          "BLEND, drawn as MASK at cutoff 0.5 (no pass of ssgraph blends; "
                          "docs/scenes.md)", model, name);
        m->texture = gm->texture >= 0 ? first_texture + gm->texture : -1;
        m->normal_texture = gm->normal_texture >= 0 ? first_texture + gm->normal_texture : -1;
        m->normal_scale = gm->normal_scale;
        memcpy(m->emission, gm->emission, sizeof m->emission);
        m->emission_texture =
            gm->emission_texture >= 0 ? first_texture + gm->emission_texture : -1;
        if (gm->texture < 0 && gm->texture_file[0])
            m->texture = ssg_scene_model_texture(l, e, model, gm);
        if (gm->emission_texture < 0 && gm->emission_file[0])
            m->emission_texture = ssg_scene_model_emission(l, e, model, gm);
        if (gm->opacity_file[0])
            m->texture = ssg_scene_model_opacity(l, e, model, gm, m->texture);
        if (gm->normal_texture < 0 && gm->normal_file[0])
            m->normal_texture = ssg_scene_model_normal_map(l, e, model, gm);
    }
    return first;
}

static void place_camera(struct ssg_camera *c, const struct mesh_args *a)
{
    float r[9];
    ssg_euler_matrix(a->rotate, r);
    float *pts[2] = {c->position, c->target};
    for (int k = 0; k < 2; k++) {
        float p[3] = {pts[k][0] * a->scale[0], pts[k][1] * a->scale[1],
                      pts[k][2] * a->scale[2]};
        for (int i = 0; i < 3; i++)
            pts[k][i] = r[3 * i] * p[0] + r[3 * i + 1] * p[1] + r[3 * i + 2] * p[2];
        for (int i = 0; i < 3; i++)
            pts[k][i] += a->translate[i];
    }
    float u[3] = {c->up[0], c->up[1], c->up[2]};
    for (int i = 0; i < 3; i++)
        c->up[i] = r[3 * i] * u[0] + r[3 * i + 1] * u[1] + r[3 * i + 2] * u[2];
}

/* Placed vertices must be finite and within +-SSG_PARAM_ABS_MAX, like every coordinate
   a scene file may write: past that, ray tracing and projection overflow. */
static int vertices_in_range(struct scene_loader *l, const struct scene_entity *e,
                             const struct ssg_mesh *m, int index)
{
    const struct mesh_args *a = e->args;
    for (size_t i = 0; i < 3 * (size_t)m->vertex_count; i++) {
        if (fabsf(m->positions[i]) <= SSG_PARAM_ABS_MAX)
            continue;
        ssg_diag_at(l->diags, SSG_E_VALUE, e->at[0], "%s: primitive %d vertex %zu is at "
                    "(%g, %g, %g) after translate, rotate and scale (expected finite "
                    "coordinates within +-%g)", a->file, index, i / 3,
                    (double)m->positions[i - i % 3], (double)m->positions[i - i % 3 + 1],
                    (double)m->positions[i - i % 3 + 2], SSG_PARAM_ABS_MAX);
        ssg_scene_fail(l, SSG_E_VALUE);
        return 0;
    }
    return 1;
}

static void build_mesh(struct scene_loader *l, const struct scene_entity *e, int *camera_set)
{
    const struct mesh_args *a = e->args;
    char path[1024], why[768];
    struct ssg_gltf *g = NULL;
    ssg_scene_path(e, a->file, path, sizeof path);
    enum ssg_err err = ssg_model_load(path, &g, why, sizeof why);
    if (err) {
        ssg_diag_at(l->diags, err, e->at[0], "%s", why);
        ssg_scene_fail(l, err);
        return;
    }
    long long tris = 0;
    for (int i = 0; i < g->mesh_count; i++)
        tris += g->meshes[i].triangle_count;
    if (!triangles_fit(l, e->at[0], tris, a->file)) {
        ssg_gltf_destroy(&g);
        return;
    }
    int first = e->material < 0 ? import_gltf_materials(l, e, g, path) : 0;
    struct ssg_scene_model *model = add_model(l, e, tris);
    if (model)
        snprintf(model->ignored, sizeof model->ignored, "%s", g->ignored);
    import_lights(l, e, g);
    warn_ignored(l, e, a->file, g->ignored);
    for (int i = 0; i < g->mesh_count && !l->first; i++) {
        struct ssg_mesh mesh = g->meshes[i];
        memset(&g->meshes[i], 0, sizeof g->meshes[i]); /* the arrays are now ours */
        ssg_mesh_place(&mesh, a->translate, a->rotate, a->scale);
        if (!vertices_in_range(l, e, &mesh, i)) {
            ssg_mesh_free(&mesh);
            break;
        }
        if (e->material >= 0)
            mesh.material = l->material_of[e->material];
        else
            mesh.material = mesh.material >= 0 ? first + mesh.material : default_material(l);
        add_mesh(l, &mesh);
        if (model)
            model->mesh_count++;
    }
    if (g->has_camera && !*camera_set && !l->first) {
        l->scene->camera = g->camera;
        place_camera(&l->scene->camera, a);
        *camera_set = 1;
        const struct ssg_camera *c = &l->scene->camera;
        enum ssg_camera_part part;
        const char *fault = ssg_camera_fault(c, &part);
        if (fault) {
            ssg_diag_at(l->diags, SSG_E_VALUE, e->at[0], "%s: its camera at (%g, %g, %g) "
                        "after translate, rotate and scale cannot be used: %s", a->file,
                        (double)c->position[0], (double)c->position[1],
                        (double)c->position[2], fault);
            ssg_scene_fail(l, SSG_E_VALUE);
        }
    }
    ssg_gltf_destroy(&g);
}

/* No camera anywhere: look at the middle of the scene's bounds from the front (+z),
 * slightly above. */
static void default_camera(struct ssg_scene *s)
{
    float lo[3] = {HUGE_VALF, HUGE_VALF, HUGE_VALF},
          hi[3] = {-HUGE_VALF, -HUGE_VALF, -HUGE_VALF};
    for (int i = 0; i < s->mesh_count; i++)
        ssg_mesh_bounds(&s->meshes[i], lo, hi);
    const float front[3] = {0.0f, 0.24253563f, 0.97014250f}; /* (0, 1, 4) normalised */
    ssg_camera_frame_box(lo, hi, front, &s->camera); /* nothing to look at: the defaults */
}

static void build_geometry(struct scene_loader *l, int *camera_set)
{
    for (int i = 0; i < l->count && !l->first; i++) {
        const struct scene_entity *e = &l->ents[i];
        if (e->kind == SK_PLANE || e->kind == SK_BOX || e->kind == SK_SPHERE)
            build_shape(l, e);
        else if (e->kind == SK_MESH)
            build_mesh(l, e, camera_set);
    }
}

static void build_environment(struct scene_loader *l)
{
    char path[1024] = "";
    for (int i = 0; i < l->count; i++) {
        const struct environment_args *a = l->ents[i].args;
        if (l->ents[i].kind == SK_ENVIRONMENT && a->image[0]) {
            l->scene->environment.image = ssg_scene_load_texture(l, &l->ents[i], a->image, 0, 0);
            ssg_scene_path(&l->ents[i], a->image, path, sizeof path);
        }
    }
    if (l->first)
        return;
    enum ssg_err e = ssg_env_build(l->scene, path, &l->scene->env, l->diags);
    if (e)
        ssg_scene_fail(l, e);
}

void ssg_scene_build(struct scene_loader *l)
{
    struct ssg_scene *s = l->scene;
    l->material_of = ssg_arena_alloc(&l->arena, sizeof(int) * (size_t)(l->count + 1));
    s->lights = calloc((size_t)l->count + 1, sizeof *s->lights);
    l->light_cap = l->count + 1;
    if (!l->material_of || !s->lights) {
        ssg_scene_fail(l, SSG_E_NOMEM);
        return;
    }
    for (int i = 0; i < l->count; i++) {
        if (l->ents[i].kind == SK_MATERIAL)
            build_material(l, i);
        else if (scene_kind_is_own_light(l->ents[i].kind))
            build_light(l, &l->ents[i]);
    }
    build_environment(l);
    int camera_set = s->has_camera;
    build_geometry(l, &camera_set);
    if (l->first)
        return;
    if (!camera_set)
        default_camera(s);
    s->has_camera = camera_set;
    enum ssg_err e = SSG_OK;
    for (int i = 0; i < s->mesh_count && !e; i++) /* in world space, once placed */
        if (s->materials[s->meshes[i].material].normal_texture >= 0)
            e = ssg_mesh_tangents(&s->meshes[i]);
    if (e) {
        ssg_diag_file(l->diags, e, s->path, "out of memory for the meshes' tangents");
        ssg_scene_fail(l, e);
        return;
    }
    e = ssg_rt_build(s, &s->rt, l->diags);
    if (!e)
        e = ssg_distance_build(s->meshes, s->mesh_count, SSG_DISTANCE_RES, &s->distance);
    if (e == SSG_E_NOMEM)
        ssg_diag_file(l->diags, e, s->path, "out of memory for the scene's distance field");
    if (e)
        ssg_scene_fail(l, e);
}
