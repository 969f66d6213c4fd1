/* scenes.h - for the tests of nodes that trace the scene: a scene written from text into
 * $SSG_TMP (or /tmp) and loaded with its assets, so Embree rays are built; a run of a node
 * with that scene the way the executor runs it (prepare, then run_cpu); and the size
 * checks of a node's check(). Header-only, shared by test_reference_ao.c,
 * test_reference_gi.c and, through scene_node.h, the hybrid AO's tests.
 *
 * Ownership: the returned scene and images are the caller's (ssg_scene_destroy,
 * ssg_image_destroy); the scene file stays in the scratch folder for inspection.
 * Single-threaded, like the tests; load failures count as CHECK failures and print the
 * loader's diagnostics. */
#ifndef SSG_TEST_SCENES_H
#define SSG_TEST_SCENES_H

#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

#include "check.h"
#include "graph/exec.h"
#include "graph/node.h"
#include "scene/scene.h"

/* Writes text to <SSG_TMP>/<name>.scene and loads it with its assets; NULL when the file
   cannot be written (or, with a failed CHECK, when the scene does not load). */
static inline struct ssg_scene *scene_from_text(const char *name, const char *text)
{
    const char *dir = getenv("SSG_TMP");
    char path[600];
    dir = dir && dir[0] ? dir : "/tmp";
    mkdir(dir, 0755);
    snprintf(path, sizeof path, "%s/%s.scene", dir, name);
    FILE *f = fopen(path, "w");
    if (!f)
        return NULL;
    fputs(text, f);
    fclose(f);
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load(path, 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    return s;
}

/* check() of desc on the input shapes `in` (all of one size w x h, input `bad` one row
   taller): SSG_E_SIZE; with `bad` set right, SSG_OK and every one of `outputs` outputs
   w x h with `channels` channels. */
static inline void check_sizes(const struct ssg_node_desc *desc, struct ssg_shape *in, int bad,
                        int outputs, int channels)
{
    const int w = in[0].width, h = in[0].height;
    struct ssg_shape o[8] = {{0}};
    struct ssg_frame frame = {w, h, 50, 0.05f, 100, 1, 0, 0, 0};
    char why[200];
    in[bad].height = h + 1;
    CHECK_EQ(desc->check(NULL, &frame, in, o, why, sizeof why), SSG_E_SIZE);
    in[bad].height = h;
    CHECK_EQ(desc->check(NULL, &frame, in, o, why, sizeof why), SSG_OK);
    for (int i = 0; i < outputs && i < 8; i++)
        CHECK_EQ(o[i].width * 1000 + o[i].height * 10 + o[i].channels,
                 w * 1000 + h * 10 + channels);
}

/* An output image as the executor hands it over: contents undefined (here -123, so a
   pixel the node forgets to write shows). */
static inline struct ssg_image *undefined_image(int width, int height, int channels)
{
    struct ssg_image *im = ssg_image_create(width, height, channels);
    for (size_t i = 0; im && i < (size_t)width * height * channels; i++)
        im->data[i] = -123.0f;
    return im;
}

/* Runs desc on in -> out with scene s as the executor does: prepare() into calloc'd
   constants of the descriptor's size (or consts_size_of), then run_cpu; diagnostics go to
   stderr. */
static inline enum ssg_err run_prepared(const struct ssg_node_desc *desc,
                                        const struct ssg_scene *s,
                                        const struct ssg_frame *frame, const void *params,
                                        const struct ssg_image *const *in,
                                        struct ssg_image **out)
{
    struct ssg_diags d = {0};
    struct ssg_node_ctx ctx = {.desc = desc, .instance = desc->name, .frame = frame,
                               .scene = s, .out_dir = ".", .diags = &d};
    struct ssg_io io = {.in = in, .out = out};
    struct ssg_io_shapes shapes;
    ssg_io_shapes_of(desc, &io, &shapes);
    ssg_node_ctx_set_shapes(&ctx, &shapes);
    void *c = calloc(1, desc->consts_size_of ? desc->consts_size_of(params, shapes.in)
                                             : desc->consts_size);
    enum ssg_err e = c ? desc->prepare(&ctx, params, c) : SSG_E_NOMEM;
    if (!e)
        e = desc->run_cpu(&ctx, c, &io);
    ssg_diags_print(&d, stderr);
    free(c);
    return e;
}

/* prepare() of desc alone, on input shapes `in` (port order) with scene s and a 16 x 16
   frame of seed 1, into consts: for the tests of the constants both backends read (a slip
   there passes every CPU/GL parity test). Returns its error; diagnostics go to stderr. */
static inline enum ssg_err prepare_on(const struct ssg_node_desc *desc,
                                      const struct ssg_scene *s, const struct ssg_shape *in,
                                      const void *params, void *consts)
{
    struct ssg_frame frame = {16, 16, 45, 0.05f, 100, 1, 0, 0, 0};
    struct ssg_diags d = {0};
    struct ssg_node_ctx ctx = {.desc = desc, .instance = desc->name, .frame = &frame,
                               .scene = s, .out_dir = ".", .diags = &d, .in_shape = in};
    enum ssg_err e = desc->prepare(&ctx, params, consts);
    ssg_diags_print(&d, stderr);
    return e;
}

#endif
