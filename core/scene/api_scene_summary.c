/* api_scene_summary.c - what `ssgraph check FILE.scene` and `ssgraph check MODEL` print
 * (ssgraph.h, ssg_scene_summary and ssg_model_summary): a scene loaded with its meshes, or
 * a model file alone, as a newcomer needs to see it before the first render. The loaded
 * scene (scene/scene.h) or model (scene/model.h) and the model's up axis are read here;
 * the advice built on them (the up-axis hint, the scale hint, a scene to paste) too.
 * Writes to the stream the caller gives; reads the files only. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lang/diag.h"
#include "lang/parse.h"
#include "scene/model.h"
#include "scene/scene.h"

/* The AO radius of the default graph (graphs/ssdo.graph's ssdo radius), scene units: the
   scale the hint compares the scene's bounding-box diagonal with. */
#define DEFAULT_AO_RADIUS 0.5f

/* Mesh lines listed one by one up to this many meshes (a model of thousands would bury
   the rest of the summary). */
enum { MAX_LISTED_MESHES = 12 };

static void print_vec(FILE *out, const char *label, const float v[3])
{
    fprintf(out, "%s(%g, %g, %g)", label, (double)v[0], (double)v[1], (double)v[2]);
}

/* The box of `count` meshes; lo > hi when they hold no vertex. */
static void meshes_bounds(const struct ssg_mesh *meshes, int count, float lo[3], float hi[3])
{
    for (int i = 0; i < 3; i++)
        lo[i] = HUGE_VALF, hi[i] = -HUGE_VALF;
    for (int m = 0; m < count; m++)
        for (size_t v = 0; v < 3 * (size_t)meshes[m].vertex_count; v++) {
            float p = meshes[m].positions[v];
            lo[v % 3] = fminf(lo[v % 3], p);
            hi[v % 3] = fmaxf(hi[v % 3], p);
        }
}

/* One line per mesh, "INDENTmesh N: T triangles[, material 'M'], bounds min (..) max (..)",
   the first MAX_LISTED_MESHES of them. */
static void print_meshes(FILE *out, const char *indent, const struct ssg_mesh *meshes,
                         int count, const struct ssg_gltf_material *materials)
{
    for (int i = 0; i < count && i < MAX_LISTED_MESHES; i++) {
        float lo[3], hi[3];
        meshes_bounds(&meshes[i], 1, lo, hi);
        fprintf(out, "%smesh %d: %d triangles", indent, i, meshes[i].triangle_count);
        if (materials && meshes[i].material >= 0 && materials[meshes[i].material].name[0])
            fprintf(out, ", material '%s'", materials[meshes[i].material].name);
        print_vec(out, ", bounds min ", lo);
        print_vec(out, " max ", hi);
        fputc('\n', out);
    }
    if (count > MAX_LISTED_MESHES)
        fprintf(out, "%s(%d more meshes)\n", indent, count - MAX_LISTED_MESHES);
}

/* The axis along which the box is strictly the largest; -1 on a tie. */
static int largest_axis(const float lo[3], const float hi[3])
{
    float e[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
    for (int a = 0; a < 3; a++)
        if (e[a] > e[(a + 1) % 3] && e[a] > e[(a + 2) % 3])
            return a;
    return -1;
}

/* The mesh line's rotate (about x, then y, then z) that turns `sign` `axis` into +Y, the
   renderer's up; NULL when it is +Y already. */
static const char *rotate_to_y(int axis, int sign)
{
    static const char *const turn[3][2] = {{"[0, 0, -90]", "[0, 0, 90]"},
                                           {"[180, 0, 0]", NULL},
                                           {"[90, 0, 0]", "[-90, 0, 0]"}};
    return turn[axis][sign > 0];
}

/* The up-axis hint for a model whose box is lo..hi (`placed`: after its mesh line's
   transform). The reader's up axis when it knows one; else a guess from the box, said to
   be one. Returns the rotate it suggests, or NULL. */
static const char *print_up(FILE *out, const char *indent, const struct ssg_model_up *up,
                            const float lo[3], const float hi[3], int placed)
{
    static const char axes[] = "XYZ";
    int big = largest_axis(lo, hi);
    const char *where = placed ? "after the mesh line's transform, its box" : "its box";
    fprintf(out, "%sup: ", indent);
    if (up->axis >= 0) {
        const char *turn = rotate_to_y(up->axis, up->sign);
        fprintf(out, "%c%c, from %s: ", up->sign < 0 ? '-' : '+', axes[up->axis], up->basis);
        if (turn)
            fprintf(out, "rotate=%s on the mesh line stands it up (the renderer's up is +Y)",
                    turn);
        else if (up->alt_sign)
            fprintf(out, "upright as loaded if the file was made that way;\n%s    but the file "
                    "does not record which way it was made: one made with another up comes out "
                    "%c%c up, lying on its side,\n%s    and rotate=%s stands it up (render it "
                    "and look)", indent, up->alt_sign < 0 ? '-' : '+',
                    axes[up->alt_axis], indent, rotate_to_y(up->alt_axis, up->alt_sign));
        else
            fprintf(out, "upright as loaded, no rotate needed (a Z-up rotate would lay it on "
                    "its back)");
        if (placed && big >= 0)
            fprintf(out, "; %s is largest along %c", where, axes[big]);
        fputc('\n', out);
        return turn;
    }
    fprintf(out, "unknown (%s); %s is %g x %g x %g", up->basis, where, (double)(hi[0] - lo[0]),
            (double)(hi[1] - lo[1]), (double)(hi[2] - lo[2]));
    if (big == 2)
        fprintf(out, ", largest along Z: looks Z-up, try rotate=[-90, 0, 0] (a guess from "
                "the geometry)\n");
    else if (big == 1)
        fprintf(out, ", largest along Y, the renderer's up: looks upright (a guess from the "
                "geometry)\n");
    else
        fprintf(out, ": no guess from the geometry (rotate=[-90, 0, 0] stands a Z-up model "
                "up, rotate=[0, 0, 90] an X-up one)\n");
    return big == 2 ? "[-90, 0, 0]" : NULL;
}

/* What a mesh line of the scene holds: each mesh's box after the transform, and the up
   axis of its file (asked of the model reader again, for the up axis alone). */
static void print_model_line(FILE *out, const struct ssg_scene *s,
                             const struct ssg_scene_model *m)
{
    char why[1024];
    float lo[3], hi[3];
    struct ssg_model_up up;
    print_meshes(out, "      ", &s->meshes[m->first_mesh], m->mesh_count, NULL);
    meshes_bounds(&s->meshes[m->first_mesh], m->mesh_count, lo, hi);
    if (ssg_model_load_up(m->path, NULL, &up, why, sizeof why) == SSG_OK && lo[0] <= hi[0])
        print_up(out, "      ", &up, lo, hi, 1);
}

/* What a model file uses and no path reads (struct ssg_gltf's ignored), a line each. */
static void print_ignored(FILE *out, const char *indent, const char *ignored)
{
    for (const char *line = ignored; *line;) {
        const char *end = strchr(line, '\n');
        int len = (int)(end ? end - line : (long)strlen(line));
        fprintf(out, "%snot read: %.*s\n", indent, len, line);
        line = end ? end + 1 : line + len;
    }
}

static void print_triangles(FILE *out, const struct ssg_scene *s)
{
    long long total = 0, in_models = 0;
    for (int i = 0; i < s->mesh_count; i++)
        total += s->meshes[i].triangle_count;
    fprintf(out, "  triangles: %lld\n", total);
    for (int i = 0; i < s->model_count; i++) {
        const struct ssg_scene_model *m = &s->models[i];
        fprintf(out, "    %s:%d:%d: mesh \"%s\": %lld triangles in %d mesh%s\n", m->scene_file,
                m->line, m->column, m->file, m->triangles, m->mesh_count,
                m->mesh_count == 1 ? "" : "es");
        print_model_line(out, s, m);
        print_ignored(out, "      ", m->ignored);
        in_models += m->triangles;
    }
    if (total > in_models)
        fprintf(out, "    plane, box and sphere lines: %lld triangles\n", total - in_models);
}

static void print_lights(FILE *out, const struct ssg_scene *s)
{
    const double DEGREES = 57.29577951308232; /* per radian */
    const struct ssg_environment *env = &s->environment;
    int has_env = env->image >= 0 || env->color[0] > 0 || env->color[1] > 0 || env->color[2] > 0;
    fprintf(out, "  lights: %d%s\n", s->light_count, has_env ? " and an environment" : "");
    for (int i = 0; i < s->light_count; i++) {
        const struct ssg_light *li = &s->lights[i];
        static const char *const kind[] = {"point_light", "directional_light", "spot_light"};
        fprintf(out, "    %s ", kind[li->kind]);
        if (li->kind != SSG_LIGHT_DIRECTIONAL)
            print_vec(out, "position ", li->position);
        if (li->kind != SSG_LIGHT_POINT)
            print_vec(out, li->kind == SSG_LIGHT_SPOT ? " direction " : "direction ",
                      li->direction);
        if (li->kind == SSG_LIGHT_SPOT)
            fprintf(out, " cone %g..%g degrees", acos(li->cos_inner) * DEGREES,
                    acos(li->cos_outer) * DEGREES);
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
    float scale = ssg_scene_scale_hint(s, DEFAULT_AO_RADIUS, &diagonal);
    if (scale == 0.0f)
        return;
    fprintf(out, "  note: the models' bounding-box diagonal is %g scene units, %g times the "
            "AO radius %g of graphs/ssdo.graph: a model in %s? Add scale=%g to its mesh line",
            (double)diagonal, (double)(diagonal / DEFAULT_AO_RADIUS),
            (double)DEFAULT_AO_RADIUS, unit_guess(scale), (double)scale);
    for (int i = 0; i < s->model_count; i++)
        fprintf(out, "%s%s:%d", i ? ", " : " (", s->models[i].scene_file,
                s->models[i].line);
    fprintf(out, "), or set the AO radius to match\n");
}

enum ssg_err ssg_scene_summary(const char *path, FILE *out, struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_scene_summary", "path, out", 2, path, out))
        return SSG_E_USAGE;
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

/* The loader's message as a diagnostic: "PATH:LINE:COLUMN: text" keeps its place. */
static void model_diag(struct ssg_diags *d, enum ssg_err e, const char *path, const char *why)
{
    size_t n = strlen(path);
    int line = 0, column = 0, used = 0;
    if (!strncmp(why, path, n) && why[n] == ':') {
        if (sscanf(why + n, ":%d:%d: %n", &line, &column, &used) == 2 && used > 0)
            why += n + (size_t)used;
        else
            why += n + 1 + (why[n + 1] == ' ');
    }
    int before = d->count;
    ssg_diag_file(d, e, path, "%s", why);
    if (d->count > before && line > 0)
        d->items[before].line = line, d->items[before].column = column;
}

/* p turned by the mesh line's rotate (degrees, about x, then y, then z, world axes). */
static void turn(const float rot[3], const float p[3], float q[3])
{
    double v[3] = {p[0], p[1], p[2]};
    for (int a = 0; a < 3; a++) {
        double r = rot[a] * 3.14159265358979323846 / 180.0, c = cos(r), s = sin(r);
        c = fabs(c) < 1e-12 ? 0.0 : c; /* a quarter turn is exact, not 6e-17 */
        s = fabs(s) < 1e-12 ? 0.0 : s;
        int i = (a + 1) % 3, j = (a + 2) % 3;
        double vi = v[i] * c - v[j] * s, vj = v[i] * s + v[j] * c;
        v[i] = vi, v[j] = vj;
    }
    for (int a = 0; a < 3; a++)
        q[a] = (float)v[a];
}

/* The box lo..hi scaled and turned as the mesh line will, into plo..phi. */
static void place_box(const float lo[3], const float hi[3], const float rot[3], float scale,
                      float plo[3], float phi[3])
{
    for (int a = 0; a < 3; a++)
        plo[a] = HUGE_VALF, phi[a] = -HUGE_VALF;
    for (int k = 0; k < 8; k++) {
        float p[3], q[3];
        for (int a = 0; a < 3; a++)
            p[a] = ((k >> a) & 1 ? hi[a] : lo[a]) * scale;
        turn(rot, p, q);
        for (int a = 0; a < 3; a++)
            plo[a] = fminf(plo[a], q[a]), phi[a] = fmaxf(phi[a], q[a]);
    }
}

/* x as %g writes it, read back: what a scene file pasted from the printed line holds. */
static float as_printed(float x)
{
    char text[32];
    snprintf(text, sizeof text, "%g", (double)x);
    return strtof(text, NULL);
}

/* The camera line of the suggested scene: the placed model framed from the front, to the
   right and above (the default camera frames the floor, three times wider, and shows the
   model small), far enough to see the whole floor. A camera the scene reader would refuse
   as printed (a speck far from the origin: position and target round to one point) is
   left out, and the default camera frames the scene. */
static void print_camera(FILE *out, const float plo[3], const float phi[3], float width)
{
    const float front_right[3] = {0.42679f, 0.29875f, 0.85358f}; /* (0.5, 0.35, 1) normalised */
    struct ssg_camera c;
    enum ssg_camera_part part;
    if (!ssg_camera_frame_box(plo, phi, front_right, &c))
        return;
    c.far_z += width;
    for (int i = 0; i < 3; i++)
        c.position[i] = as_printed(c.position[i]), c.target[i] = as_printed(c.target[i]);
    c.near_z = as_printed(c.near_z), c.far_z = as_printed(c.far_z);
    if (ssg_camera_fault(&c, &part))
        return;
    fprintf(out, "    camera(position=[%g, %g, %g], target=[%g, %g, %g], near=%g, far=%g)\n",
            (double)c.position[0], (double)c.position[1], (double)c.position[2],
            (double)c.target[0], (double)c.target[1], (double)c.target[2], (double)c.near_z,
            (double)c.far_z);
}

/* The model's box once placed by its mesh line's rotate (NULL: none) and scale (0: none),
   and the width of a floor under it: three times the box's; for a point or an upright line
   (no area) three times its height, at least 1 and a thousandth of its distance (a floor
   float can place; a plane of size 0 is refused). 0 when the placed box overflows float. */
static float placed_floor(const float lo[3], const float hi[3], const char *rotate,
                          float scale, float plo[3], float phi[3])
{
    float rot[3] = {0, 0, 0};
    if (rotate)
        sscanf(rotate, "[%f, %f, %f]", &rot[0], &rot[1], &rot[2]);
    place_box(lo, hi, rot, scale > 0.0f ? scale : 1.0f, plo, phi);
    float width = 3.0f * fmaxf(phi[0] - plo[0], phi[2] - plo[2]);
    if (width == 0.0f) {
        float far = fmaxf(fmaxf(fabsf(plo[0]), fabsf(phi[0])),
                          fmaxf(fabsf(plo[2]), fabsf(phi[2])));
        width = fmaxf(3.0f * (phi[1] - plo[1]), fmaxf(1.0f, 1e-3f * far));
    }
    return isfinite(width) && isfinite(plo[0] + phi[0]) && isfinite(plo[2] + phi[2]) ? width
                                                                                      : 0.0f;
}

/* The mesh line and the floor under it, each line after `lead` ("    ", or "    # " for
   lines to use instead). */
static void print_model_and_floor(FILE *out, const char *lead, const char *name,
                                  const char *rotate, float scale, const float plo[3],
                                  const float phi[3], float width)
{
    fprintf(out, "%smesh(\"%s\"", lead, name);
    if (rotate)
        fprintf(out, ", rotate=%s", rotate);
    if (scale > 0.0f)
        fprintf(out, ", scale=%g", (double)scale);
    fprintf(out, ")\n%splane(center=[%g, %g, %g], size=[%g, 0, %g])\n", lead,
            (double)(plo[0] + phi[0]) / 2, (double)plo[1], (double)(plo[2] + phi[2]) / 2,
            (double)width, (double)width);
}

/* A scene to paste around the model: its mesh line with the suggested rotate and scale, a
   floor under it (occlusion needs something to land on) three times its width, a sun, a
   sky, and a camera framing the model; with alt_rotate (the other way a file of its format
   may come out), the two lines that stand it up that way instead, as comments. */
static void print_snippet(FILE *out, const char *path, const char *rotate,
                          const char *alt_rotate, float scale, const float lo[3],
                          const float hi[3])
{
    const char *slash = strrchr(path, '/'), *name = slash ? slash + 1 : path;
    const char *dot = strrchr(name, '.');
    int stem = (int)(dot ? dot - name : (long)strlen(name));
    float plo[3], phi[3], alo[3], ahi[3];
    float width = placed_floor(lo, hi, rotate, scale, plo, phi);
    if (width == 0.0f) {
        fprintf(out, "  no scene to suggest: the model's box overflows float once placed "
                "(scale it down on its mesh line)\n");
        return;
    }
    fprintf(out, "  a scene around it (docs/scenes.md), to save as %.*s.scene next to %s:\n",
            stem, name, name);
    print_model_and_floor(out, "    ", name, rotate, scale, plo, phi, width);
    float alt_width = alt_rotate ? placed_floor(lo, hi, alt_rotate, scale, alo, ahi) : 0.0f;
    if (alt_width > 0.0f) {
        fprintf(out, "    # lying on its side? these two lines stand it up instead:\n");
        print_model_and_floor(out, "    # ", name, alt_rotate, scale, alo, ahi, alt_width);
    }
    fprintf(out, "    directional_light(direction=[-0.4, -1, -0.6], intensity=2)\n"
                 "    environment(color=[0.6, 0.7, 0.9], intensity=0.5)\n");
    print_camera(out, plo, phi, width);
    fprintf(out, "  and render it: ssgraph run graphs/ssdo.graph --scene %.*s.scene\n", stem,
            name);
}

/* 1 when a triangle of the model has area (its edges' cross product, in double, is not 0). */
static int model_has_area(const struct ssg_gltf *g)
{
    for (int m = 0; m < g->mesh_count; m++) {
        const struct ssg_mesh *mesh = &g->meshes[m];
        for (size_t t = 0; t < (size_t)mesh->triangle_count; t++) {
            const uint32_t *k = &mesh->indices[3 * t];
            if (k[0] >= (uint32_t)mesh->vertex_count || k[1] >= (uint32_t)mesh->vertex_count ||
                k[2] >= (uint32_t)mesh->vertex_count)
                continue;
            const float *a = &mesh->positions[3 * (size_t)k[0]],
                        *b = &mesh->positions[3 * (size_t)k[1]],
                        *c = &mesh->positions[3 * (size_t)k[2]];
            double u[3], v[3];
            for (int i = 0; i < 3; i++)
                u[i] = (double)b[i] - a[i], v[i] = (double)c[i] - a[i];
            if (u[1] * v[2] != u[2] * v[1] || u[2] * v[0] != u[0] * v[2] ||
                u[0] * v[1] != u[1] * v[0])
                return 1;
        }
    }
    return 0;
}

/* The scale hint of a scene holding only this model (ssg_scene_scale_hint's rule). */
static float model_scale_hint(const struct ssg_gltf *g, float *diagonal)
{
    struct ssg_scene_model m = {.first_mesh = 0, .mesh_count = g->mesh_count};
    struct ssg_scene s = {.mesh_count = g->mesh_count, .meshes = g->meshes,
                          .model_count = 1, .models = &m};
    return ssg_scene_scale_hint(&s, DEFAULT_AO_RADIUS, diagonal);
}

/* Every vertex of the loaded model finite: the readers refuse NaN and infinity in the
   file, but a node's transform can still overflow float, and the bounds, the hints and
   the scene printed from them must never hold NaN or infinity. */
static enum ssg_err model_finite(const struct ssg_gltf *g, const char *path,
                                 struct ssg_diags *diags)
{
    for (int m = 0; m < g->mesh_count; m++)
        for (size_t v = 0; v < 3 * (size_t)g->meshes[m].vertex_count; v++) {
            const float *p = &g->meshes[m].positions[v - v % 3];
            if (isfinite(g->meshes[m].positions[v]))
                continue;
            ssg_diag_file(diags, SSG_E_VALUE, path, "mesh %d vertex %zu is at (%g, %g, %g) "
                          "after the file's node transforms (expected finite coordinates)",
                          m, v / 3, (double)p[0], (double)p[1], (double)p[2]);
            return SSG_E_VALUE;
        }
    return SSG_OK;
}

enum ssg_err ssg_model_summary(const char *path, FILE *out, struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_model_summary", "path, out", 2, path, out))
        return SSG_E_USAGE;
    struct ssg_gltf *g = NULL;
    struct ssg_model_up up;
    char why[1024];
    enum ssg_err e = ssg_model_load_up(path, &g, &up, why, sizeof why);
    if (e) {
        model_diag(diags, e, path, why);
        return e;
    }
    if ((e = model_finite(g, path, diags))) {
        ssg_gltf_destroy(&g);
        return e;
    }
    long long triangles = 0;
    float lo[3], hi[3], diagonal;
    for (int i = 0; i < g->mesh_count; i++)
        triangles += g->meshes[i].triangle_count;
    meshes_bounds(g->meshes, g->mesh_count, lo, hi);
    fprintf(out, "%s: ok (a model; a scene file places it: see below)\n", path);
    fprintf(out, "  triangles: %lld in %d mesh%s\n", triangles, g->mesh_count,
            g->mesh_count == 1 ? "" : "es");
    print_meshes(out, "    ", g->meshes, g->mesh_count, g->materials);
    print_vec(out, "  bounds: min ", lo);
    print_vec(out, " max ", hi);
    fputc('\n', out);
    const char *rotate = print_up(out, "  ", &up, lo, hi, 0);
    print_ignored(out, "  ", g->ignored);
    float scale = model_scale_hint(g, &diagonal);
    if (scale > 0.0f)
        fprintf(out, "  scale: the bounding-box diagonal is %g, %g times the AO radius %g of "
                "graphs/ssdo.graph: a model in %s? scale=%g fits it\n", (double)diagonal,
                (double)(diagonal / DEFAULT_AO_RADIUS),
                (double)DEFAULT_AO_RADIUS, unit_guess(scale), (double)scale);
    if (!model_has_area(g))
        fprintf(out, "  no area: every triangle's corners lie on one line or at one point, so "
                "the model renders as nothing\n");
    const char *alt_rotate =
        up.axis >= 0 && up.alt_sign ? rotate_to_y(up.alt_axis, up.alt_sign) : NULL;
    print_snippet(out, path, rotate, alt_rotate, scale, lo, hi);
    ssg_gltf_destroy(&g);
    return SSG_OK;
}
