/* temporal_test.h - what the `temporal` node's two tests share (test_temporal.c, the
 * method on hand-made inputs; test_temporal_parity.c, CPU/GL parity and thread counts):
 * one frame's input images, and a runner that, unlike ssg_node_run, sets
 * ctx->history_reset (a graph's executor sets it; a single-node run has no frames).
 * Header-only, for tests. */
#ifndef SSG_TEMPORAL_TEST_H
#define SSG_TEMPORAL_TEST_H

#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "scene_node.h" /* node_params, node_execute_on */
#include "temporal.h"

/* One frame's inputs (NULL = unconnected optional port) and the three outputs. */
struct tframe {
    struct ssg_image *in, *in2, *hist, *hist2, *len, *motion, *depth, *normal, *pdepth,
        *pnormal;
};
struct tresult {
    struct ssg_image *out, *out2, *length;
};

static struct ssg_image *tfilled(int w, int h, int ch, float v)
{
    struct ssg_image *im = ssg_image_create(w, h, ch);
    for (size_t i = 0; i < (size_t)w * (size_t)h * (size_t)ch; i++)
        im->data[i] = v;
    return im;
}

/* A static camera's frame: depth 2 now and before, motion (0, 0, 2), history 0, length 0,
   in 0; with normals, (0, 0, 1) now and before; with in2, 3 channels of 0. */
static struct tframe tframe_make(int w, int h, int ch, int in2, int normals)
{
    struct tframe f = {.in = tfilled(w, h, ch, 0), .hist = tfilled(w, h, ch, 0),
                       .len = tfilled(w, h, 1, 0), .motion = tfilled(w, h, 3, 0),
                       .depth = tfilled(w, h, 1, 2), .pdepth = tfilled(w, h, 1, 2)};
    float *mz = ssg_image_plane(f.motion, 2);
    for (size_t i = 0; i < (size_t)w * (size_t)h; i++)
        mz[i] = 2.0f;
    if (in2) {
        f.in2 = tfilled(w, h, 3, 0);
        f.hist2 = tfilled(w, h, 3, 0);
    }
    if (normals) {
        f.normal = tfilled(w, h, 3, 0);
        f.pnormal = tfilled(w, h, 3, 0);
        for (size_t i = 0; i < (size_t)w * (size_t)h; i++)
            ssg_image_plane(f.normal, 2)[i] = ssg_image_plane(f.pnormal, 2)[i] = 1.0f;
    }
    return f;
}

static void tframe_free(struct tframe *f)
{
    struct ssg_image **all[] = {&f->in, &f->in2, &f->hist, &f->hist2, &f->len, &f->motion,
                                &f->depth, &f->normal, &f->pdepth, &f->pnormal};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++)
        ssg_image_destroy(all[i]);
}

static void tresult_free(struct tresult *r)
{
    ssg_image_destroy(&r->out);
    ssg_image_destroy(&r->out2);
    ssg_image_destroy(&r->length);
}

/* Runs the node on f with the "param=value" sets, history_reset as given, on the CPU or
   GL, into r (owned); returns 0 on success. As noderun.c's run_single, with the reset. */
static int trun(const struct tframe *f, const char *const *sets, int n, int reset, int gl,
                struct tresult *r)
{
    const struct ssg_node_desc *d = &ssg_node_temporal;
    struct ssg_temporal_params *params = node_params(d, sets, n);
    struct ssg_diags diags = {0};
    enum ssg_err e = SSG_OK;
    const struct ssg_image *in[SSG_TEMPORAL_INPUTS] = {
        f->in, f->in2, f->hist, f->hist2, f->len, f->motion, f->depth, f->normal, f->pdepth,
        f->pnormal};
    struct ssg_shape ins[SSG_MAX_PORTS] = {{0}}, outs[SSG_MAX_PORTS];
    for (int i = 0; i < SSG_TEMPORAL_INPUTS; i++)
        if (in[i])
            ins[i] = ssg_shape_of_image(in[i], d->inputs[i].types);
    struct ssg_frame frame = SSG_FRAME_DEFAULTS;
    frame.width = f->in->width, frame.height = f->in->height;
    char why[256] = "";
    if (!e)
        e = ssg_shapes_infer(d, params, &frame, ins, outs, why, sizeof why);
    memset(r, 0, sizeof *r);
    struct ssg_image *out[SSG_TEMPORAL_OUTPUTS] = {NULL};
    for (int i = 0; i < SSG_TEMPORAL_OUTPUTS && !e; i++)
        out[i] = ssg_image_create(outs[i].width, outs[i].height, outs[i].channels);
    struct ssg_io io = {.in = in, .out = out};
    struct ssg_node_ctx ctx = {.desc = d, .instance = "t", .frame = &frame, .diags = &diags,
                               .in_shape = ins, .out_shape = outs, .history_reset = reset};
    if (!e)
        e = node_execute_on(d, &ctx, params, &io, gl ? SSG_BACKEND_GL : SSG_BACKEND_CPU);
    free(params);
    if (e) {
        fprintf(stderr, "temporal run failed (%s): %s\n", gl ? "gl" : "cpu", why);
        ssg_diags_print(&diags, stderr);
    }
    CHECK_EQ(e, SSG_OK);
    r->out = out[0], r->out2 = out[1], r->length = out[2];
    if (e)
        tresult_free(r);
    return e != SSG_OK;
}

/* A reproducible value in [0, 1) for (a, b, c) (an integer hash). */
static float thash(uint32_t a, uint32_t b, uint32_t c)
{
    uint32_t h = a * 0x9E3779B1u ^ (b + 0x7F4A7C15u) * 0x85EBCA77u ^ (c + 1u) * 0xC2B2AE3Du;
    h ^= h >> 15, h *= 0x2C1B3C6Du, h ^= h >> 12, h *= 0x297A2D39u, h ^= h >> 15;
    return (float)(h >> 8) / 16777216.0f;
}

#endif
