/* scene_textures.c - the scene's textures as scene_build.c loads them (scene_build.h):
 * image files read into interleaved linear RGB (with the alpha plane a masked material cuts
 * by), normal maps read as data, the textures an Assimp material names. Every problem is a
 * message naming the file, and the scene fails. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "lang/files.h"
#include "scene/coverage.h"
#include "scene/gltf.h"
#include "scene/scene_build.h"

/* Adds a texture; takes ownership of rgb and alpha (NULL = opaque). Returns its index or
   -1. */
int ssg_scene_add_texture(struct scene_loader *l, int width, int height, float *rgb, float *alpha)
{
    struct ssg_scene *s = l->scene;
    struct ssg_texture *grown = ssg_scene_reserve(l, s->textures, s->texture_count, &l->texture_cap,
                                        sizeof *s->textures);
    if (!grown) {
        free(rgb);
        free(alpha);
        return -1;
    }
    s->textures = grown;
    s->textures[s->texture_count] = (struct ssg_texture){width, height, rgb, alpha};
    return s->texture_count++;
}

/* A texture with a NaN or infinite pixel would put NaN into every image it shades: it is
   refused with the file and the first such pixel. */
static int texture_finite(struct scene_loader *l, const char *path, const struct ssg_image *im)
{
    size_t px = (size_t)im->width * (size_t)im->height;
    for (int c = 0; c < im->channels; c++) {
        const float *plane = ssg_image_plane(im, c);
        for (size_t i = 0; i < px; i++) {
            if (isfinite(plane[i]))
                continue;
            ssg_diag_file(l->diags, SSG_E_IMAGE, path, "pixel (%zu, %zu) channel %d is %s "
                          "(expected finite colours)", i % (size_t)im->width,
                          i / (size_t)im->width, c, isnan(plane[i]) ? "NaN" : "infinite");
            ssg_scene_fail(l, SSG_E_IMAGE);
            return 0;
        }
    }
    return 1;
}

/* 1 when the image has an alpha channel (gray + alpha, RGBA: its last). */
static int has_alpha(const struct ssg_image *im)
{
    return im->channels == 2 || im->channels == 4;
}

/* Channel c of an image as coverages, clamped to [0, 1] (malloc'd); NULL when out of
   memory. */
static float *coverage_plane(const struct ssg_image *im, int c)
{
    size_t px = (size_t)im->width * (size_t)im->height;
    float *alpha = malloc(px * sizeof(float));
    const float *plane = ssg_image_plane(im, c);
    for (size_t i = 0; alpha && i < px; i++)
        alpha[i] = plane[i] > 0.0f ? (plane[i] < 1.0f ? plane[i] : 1.0f) : 0.0f;
    return alpha;
}

/* The alpha plane of an image with one, clamped to [0, 1]; NULL without one, or out of
   memory (*nomem set). */
static float *alpha_plane(const struct ssg_image *im, int *nomem)
{
    if (!has_alpha(im))
        return NULL;
    float *alpha = coverage_plane(im, im->channels - 1);
    *nomem = !alpha;
    return alpha;
}

/* Reads an image file into an interleaved RGB texture; gray images fill all three. A
   material texture must be finite here; a probe is checked by core/scene/env.c (finite_only 0),
   which names its own rules. keep_alpha: a masked material's texture keeps its alpha
   channel as the coverage plane. */
int ssg_scene_load_texture_file(struct scene_loader *l, const char *path, int finite_only,
                             int keep_alpha)
{
    struct ssg_image *im = NULL;
    enum ssg_err e = ssg_image_read(path, NULL, &im, l->diags);
    if (e) {
        ssg_scene_fail(l, e);
        return -1;
    }
    if (finite_only && !texture_finite(l, path, im)) {
        ssg_image_destroy(&im);
        return -1;
    }
    size_t px = (size_t)im->width * (size_t)im->height;
    float *rgb = malloc(px * 3 * sizeof(float));
    int nomem = 0;
    float *alpha = keep_alpha ? alpha_plane(im, &nomem) : NULL;
    if (!rgb || nomem) {
        free(rgb);
        ssg_image_destroy(&im);
        ssg_scene_fail(l, SSG_E_NOMEM);
        return -1;
    }
    for (int c = 0; c < 3; c++) {
        const float *plane = ssg_image_plane(im, im->channels >= 3 ? c : 0);
        for (size_t i = 0; i < px; i++)
            rgb[3 * i + (size_t)c] = plane[i];
    }
    int width = im->width, height = im->height;
    ssg_image_destroy(&im);
    return ssg_scene_add_texture(l, width, height, rgb, alpha);
}

/* A normal map file: its values as stored, not sRGB-decoded (ssg_image_read_data), its
   first three channels. */
static int load_normal_map_file(struct scene_loader *l, const char *path)
{
    struct ssg_image *im = NULL;
    enum ssg_err e = ssg_image_read_data(path, &im, l->diags);
    if (!e && !texture_finite(l, path, im))
        e = SSG_E_IMAGE;
    if (!e && im->channels < 3) {
        ssg_diag_file(l->diags, SSG_E_CHANNELS, path, "a normal map needs three channels "
                      "(x, y, z), this image has %d", im->channels);
        e = SSG_E_CHANNELS;
    }
    size_t px = im ? (size_t)im->width * (size_t)im->height : 0;
    float *rgb = e ? NULL : malloc(px * 3 * sizeof(float));
    if (!e && !rgb)
        e = SSG_E_NOMEM;
    for (size_t i = 0; rgb && i < px; i++)
        for (int c = 0; c < 3; c++)
            rgb[3 * i + (size_t)c] = ssg_image_plane(im, c)[i];
    int width = im ? im->width : 0, height = im ? im->height : 0;
    ssg_image_destroy(&im);
    if (e) {
        ssg_scene_fail(l, e);
        return -1;
    }
    return ssg_scene_add_texture(l, width, height, rgb, NULL);
}

int ssg_scene_load_normal_map(struct scene_loader *l, const struct scene_entity *from,
                              const char *rel)
{
    char path[1024];
    ssg_scene_path(from, rel, path, sizeof path);
    return load_normal_map_file(l, path);
}

/* The same for a path written in an entity, relative to its file. */
int ssg_scene_load_texture(struct scene_loader *l, const struct scene_entity *from,
                        const char *rel, int finite_only, int keep_alpha)
{
    char path[1024];
    ssg_scene_path(from, rel, path, sizeof path);
    return ssg_scene_load_texture_file(l, path, finite_only, keep_alpha);
}

/* The file `file` (a texture or normal map, `what`) an Assimp material names, resolved
   against the model into path; 0 with a message at the mesh line naming the model, the
   material and the file when it is embedded or cannot be read. */
static int model_file(struct scene_loader *l, const struct scene_entity *e, const char *model,
                      const struct ssg_gltf_material *gm, const char *file, const char *what,
                      char *path, size_t len)
{
    const char *problem = NULL;
    if (file[0] == '*') {
        problem = "is embedded in the model file (not supported: give the mesh a material=)";
    } else {
        ssg_path_resolve(model, file, path, len);
        if (access(path, R_OK) != 0)
            problem = strerror(errno);
    }
    if (problem) {
        ssg_diag_at(l->diags, SSG_E_IO, e->at[0], "%s: material '%s' names %s '%s', which "
                    "cannot be read (%s)", model, gm->name, what, file, problem);
        ssg_scene_fail(l, SSG_E_IO);
        return 0;
    }
    return 1;
}

int ssg_scene_model_texture(struct scene_loader *l, const struct scene_entity *e,
                            const char *model, const struct ssg_gltf_material *gm)
{
    char path[1024];
    if (!model_file(l, e, model, gm, gm->texture_file, "texture", path, sizeof path))
        return -1;
    /* a separate coverage map (opacity_file) replaces the texture's own alpha */
    return ssg_scene_load_texture_file(l, path, 1, gm->alpha_mode != SSG_ALPHA_OPAQUE &&
                                                       !gm->opacity_file[0]);
}

int ssg_scene_model_emission(struct scene_loader *l, const struct scene_entity *e,
                             const char *model, const struct ssg_gltf_material *gm)
{
    char path[1024];
    if (!model_file(l, e, model, gm, gm->emission_file, "emission map", path, sizeof path))
        return -1;
    return ssg_scene_load_texture_file(l, path, 1, 0);
}

int ssg_scene_model_normal_map(struct scene_loader *l, const struct scene_entity *e,
                               const char *model, const struct ssg_gltf_material *gm)
{
    char path[1024];
    if (!model_file(l, e, model, gm, gm->normal_file, "normal map", path, sizeof path))
        return -1;
    return load_normal_map_file(l, path);
}

/* The mask's coverage (its alpha channel when it has one, else its first) at the texel
   centres of a width x height texture: bilinear over the mask as the surface lookups read
   a texture (ssg_texture_bilinear), the same grid when the sizes agree. NULL when out of
   memory. */
static float *coverage_on(const struct ssg_image *mask, int width, int height)
{
    size_t px = (size_t)width * height;
    float *plane = coverage_plane(mask, has_alpha(mask) ? mask->channels - 1 : 0);
    float *alpha = malloc(px * sizeof(float));
    for (size_t i = 0; plane && alpha && i < px; i++) {
        float u = ((float)(i % (size_t)width) + 0.5f) / (float)width;
        float v = ((float)(i / (size_t)width) + 0.5f) / (float)height;
        ssg_texture_bilinear(plane, 1, mask->width, mask->height, u, v, &alpha[i]);
    }
    free(plane);
    if (!plane) {
        free(alpha);
        return NULL;
    }
    return alpha;
}

int ssg_scene_model_opacity(struct scene_loader *l, const struct scene_entity *e,
                            const char *model, const struct ssg_gltf_material *gm, int texture)
{
    char path[1024];
    struct ssg_image *mask = NULL;
    if (!model_file(l, e, model, gm, gm->opacity_file, "opacity map", path, sizeof path))
        return -1;
    enum ssg_err err = ssg_image_read_data(path, &mask, l->diags);
    if (!err && !texture_finite(l, path, mask))
        err = SSG_E_IMAGE;
    if (!err && texture < 0) { /* no diffuse texture: white, the albedo is the colour's */
        size_t px = (size_t)mask->width * mask->height;
        float *white = malloc(px * 3 * sizeof(float));
        for (size_t i = 0; white && i < 3 * px; i++)
            white[i] = 1.0f;
        texture = white ? ssg_scene_add_texture(l, mask->width, mask->height, white, NULL) : -1;
        err = texture < 0 ? SSG_E_NOMEM : SSG_OK;
    }
    struct ssg_texture *t = err ? NULL : &l->scene->textures[texture];
    float *alpha = t ? coverage_on(mask, t->width, t->height) : NULL;
    if (t && !alpha)
        err = SSG_E_NOMEM;
    ssg_image_destroy(&mask);
    if (err) {
        ssg_scene_fail(l, err);
        return -1;
    }
    free(t->alpha);
    t->alpha = alpha;
    return texture;
}
