/* scene_info.c - the summary `ssgraph check FILE.scene` prints (scene_info.h). The library
 * returns the loaded scene (scene/scene.h); the printing is here. */
#include "scene_info.h"

#include "scene/scene.h"

static void print_vec(FILE *out, const char *label, const float v[3])
{
    fprintf(out, "%s(%g, %g, %g)", label, (double)v[0], (double)v[1], (double)v[2]);
}

static void print_triangles(FILE *out, const struct ssg_scene *s)
{
    long long total = 0, in_models = 0;
    for (int i = 0; i < s->mesh_count; i++)
        total += s->meshes[i].triangle_count;
    fprintf(out, "  triangles: %lld\n", total);
    for (int i = 0; i < s->model_count; i++) {
        const struct ssg_scene_model *m = &s->models[i];
        fprintf(out, "    %s:%d:%d: mesh \"%s\": %lld triangles in %d mesh%s\n", s->path,
                m->line, m->column, m->file, m->triangles, m->mesh_count,
                m->mesh_count == 1 ? "" : "es");
        in_models += m->triangles;
    }
    if (total > in_models)
        fprintf(out, "    plane, box and sphere lines: %lld triangles\n", total - in_models);
}

static void print_lights(FILE *out, const struct ssg_scene *s)
{
    const struct ssg_environment *env = &s->environment;
    int has_env = env->image >= 0 || env->color[0] > 0 || env->color[1] > 0 || env->color[2] > 0;
    fprintf(out, "  lights: %d%s\n", s->light_count, has_env ? " and an environment" : "");
    for (int i = 0; i < s->light_count; i++) {
        const struct ssg_light *li = &s->lights[i];
        int point = li->kind == SSG_LIGHT_POINT;
        fprintf(out, "    %s ", point ? "point_light" : "directional_light");
        print_vec(out, point ? "position " : "direction ", point ? li->position : li->direction);
        print_vec(out, " color ", li->color);
        fprintf(out, " intensity %g\n", (double)li->intensity);
    }
    if (has_env) {
        print_vec(out, "    environment color ", env->color);
        fprintf(out, " intensity %g%s\n", (double)env->intensity,
                env->image >= 0 ? " with an image" : "");
    }
}

/* What a model needing `scale` was probably written in. */
static const char *unit_guess(float scale)
{
    return scale <= 0.002f ? "millimetres" : scale < 1.0f ? "centimetres" : "kilometres";
}

/* Far smaller or larger than the AO radius: a model in millimetres renders as if every
   surface were open (or the whole scene as one crease). */
static void print_scale_hint(FILE *out, const struct ssg_scene *s)
{
    float diagonal;
    float scale = ssg_scene_scale_hint(s, SSG_CLI_DEFAULT_AO_RADIUS, &diagonal);
    if (scale == 0.0f)
        return;
    fprintf(out, "  note: the models' bounding-box diagonal is %g scene units, %g times the "
            "AO radius %g of graphs/ssdo.graph: a model in %s? Add scale=%g to its mesh line",
            (double)diagonal, (double)(diagonal / SSG_CLI_DEFAULT_AO_RADIUS),
            (double)SSG_CLI_DEFAULT_AO_RADIUS, unit_guess(scale), (double)scale);
    for (int i = 0; i < s->model_count; i++)
        fprintf(out, "%s%s:%d", i ? ", " : " (", s->path, s->models[i].line);
    fprintf(out, "), or set the AO radius to match\n");
}

enum ssg_err ssg_cli_check_scene(const char *path, FILE *out, struct ssg_diags *diags)
{
    struct ssg_scene *s = NULL;
    enum ssg_err e = ssg_scene_load(path, 1, &s, diags);
    if (e)
        return e;
    float lo[3], hi[3];
    ssg_scene_bounds(s, lo, hi);
    fprintf(out, "%s: ok\n", path);
    if (lo[0] <= hi[0]) {
        print_vec(out, "  bounds: min ", lo);
        print_vec(out, " max ", hi);
        fputc('\n', out);
    } else {
        fprintf(out, "  bounds: empty (no geometry)\n");
    }
    print_triangles(out, s);
    const struct ssg_camera *c = &s->camera;
    print_vec(out, "  camera: position ", c->position);
    print_vec(out, " target ", c->target);
    fprintf(out, " fov %g degrees%s\n", (double)c->fov_y,
            s->has_camera ? "" : " (none given: framing the bounds)");
    print_lights(out, s);
    print_scale_hint(out, s);
    ssg_scene_destroy(&s);
    return SSG_OK;
}
