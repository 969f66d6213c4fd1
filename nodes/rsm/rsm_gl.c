/* rsm_gl.c - GL side of the `rsm` node (method in README.md): the maps never leave the GPU. Four
 * passes: the slots of every cell (rsm_cells.glsl, one invocation a cell), the list with
 * its CDF and count (rsm_list.glsl, one invocation: a running sum), the draws of each
 * cell of the offset tile (rsm_picks.glsl, one invocation a draw) and the gather
 * (rsm.glsl), which with visibility on also reads the scene's distance field, bound from
 * the run's copy of the scene (gl_scene.h). The list walk and an exact gather are split into dispatches of at most
 * SSG_RSM_GL_ITERATIONS loop iterations, their state in scratch images between them:
 * llvmpipe silently ends a loop after 65535 iterations. The faces and the offset tile are
 * the CPU's floats from prepare(), in storage buffers, and so is the slot grid's shape.
 * Ports, parameters and prepare()'s constants are bound by the descriptor's tables, each
 * in the shaders its row's .gl_in names (rsm.h); what is bound here by hand is the
 * scratch images between the passes and the dispatches' loop values. Known cost: the list walk is one
 * thread's work (about 0.5 s on llvmpipe for a point light's cube at 512 with cell 4;
 * a two-level prefix sum, row by row, would make it parallel). */
#include "gl/gl.h"
#include "gl/gl_scene.h"
#include <stdlib.h>

#include "rsm.h"

static void cells_pass(const struct ssg_node_ctx *ctx, const struct ssg_rsm_consts *c,
                       const struct ssg_io *io, struct ssg_image *cells, struct ssg_gl_pass *p)
{
    ssg_gl_pass_begin(p, ctx, "rsm_cells.glsl", NULL);
    ssg_gl_ports(p, io); /* the maps */
    ssg_gl_output(p, "cells", cells);
    ssg_gl_buffer(p, 0, c->face, sizeof(float) * 16 * (size_t)c->faces);
    ssg_gl_dispatch(p, c->cells, c->grid_h);
}

/* One invocation walks the slots, at most SSG_RSM_GL_ITERATIONS a dispatch (rsm.h). */
static void list_pass(const struct ssg_node_ctx *ctx, const struct ssg_rsm_consts *c,
                      const struct ssg_image *cells, struct ssg_image *list,
                      struct ssg_image *state, struct ssg_gl_pass *p)
{
    int rows = c->gl_list_rows;
    ssg_gl_pass_begin(p, ctx, "rsm_list.glsl", NULL);
    ssg_gl_input(p, "cells", cells);
    ssg_gl_output(p, "list", list);
    ssg_gl_output(p, "state", state);
    for (int row0 = 0; row0 < c->grid_h; row0 += rows) {
        ssg_gl_int(p, "row0", row0);
        ssg_gl_dispatch(p, 1, 1);
    }
}

static void picks_pass(const struct ssg_node_ctx *ctx, const struct ssg_rsm_consts *c,
                       const struct ssg_image *list, const struct ssg_image *count,
                       struct ssg_image *pick, struct ssg_gl_pass *p)
{
    ssg_gl_pass_begin(p, ctx, "rsm_picks.glsl", NULL);
    ssg_gl_input(p, "list", list);
    ssg_gl_input(p, "count", count);
    ssg_gl_output(p, "pick", pick);
    ssg_gl_buffer(p, 1, c->offset, sizeof c->offset);
    ssg_gl_dispatch(p, c->p.samples, SSG_RSM_TILE * SSG_RSM_TILE);
}

static void gather_pass(const struct ssg_node_ctx *ctx, const struct ssg_rsm_consts *c,
                        const struct ssg_io *io, const struct ssg_image *list,
                        const struct ssg_image *count, const struct ssg_image *pick,
                        struct ssg_image *acc, struct ssg_gl_pass *p)
{
    const struct ssg_image *pos = io->in[SSG_RSM_IN_POSITION];
    ssg_gl_pass_begin(p, ctx, "rsm.glsl", NULL);
    ssg_gl_ports(p, io); /* position, normal, albedo, out */
    ssg_gl_input(p, "list", list);
    ssg_gl_input(p, "count", count);
    ssg_gl_input(p, "pick", pick);
    ssg_gl_output(p, "acc", acc);
    if (c->vis) { /* the field went up with the scene, once a run (gl_scene.h) */
        ssg_gl_scene_bind_distance(p, SSG_GL_SCENE_BINDING + SSG_GL_SCENE_BUFFERS);
        ssg_gl_buffer(p, 1, c->vis_phase, sizeof c->vis_phase);
    }
    /* An exact sum walks the VPLs in dispatches of SSG_RSM_GL_ITERATIONS (rsm.h), the
       running sums kept in acc between them; the count is on the GPU, so every dispatch
       the slots could need is made (those past the count add nothing). A sampled run is
       done in the first. */
    int vpls = SSG_RSM_GL_ITERATIONS;
    for (int vpl0 = 0; vpl0 < c->slots; vpl0 += vpls) {
        ssg_gl_int(p, "vpl0", vpl0);
        ssg_gl_int(p, "vpls", vpls);
        ssg_gl_int(p, "first", vpl0 == 0);
        ssg_gl_int(p, "last", vpl0 + vpls >= c->slots);
        ssg_gl_dispatch(p, pos->width, pos->height);
    }
}

/* The passes of one run with the frame's constants (ssg_rsm_run_frame). */
static enum ssg_err run(const struct ssg_node_ctx *ctx, const struct ssg_rsm_consts *c,
                        const struct ssg_io *io)
{
    int gw = c->grid_w, gh = c->grid_h;
    struct ssg_image *cells = ssg_gl_scratch(ctx, gw, gh, SSG_RSM_CELL_FLOATS);
    struct ssg_image *list = ssg_gl_scratch(ctx, gw, gh, SSG_RSM_SLOT);
    struct ssg_image *count = ssg_gl_scratch(ctx, 1, 1, 2);
    const struct ssg_image *pos = io->in[SSG_RSM_IN_POSITION];
    struct ssg_image *acc = ssg_gl_scratch(ctx, pos->width, pos->height, 3);
    int draws = c->p.samples > 0 ? c->p.samples : 1;
    struct ssg_image *pick = ssg_gl_scratch(ctx, draws, SSG_RSM_TILE * SSG_RSM_TILE, 1);
    enum ssg_err e = SSG_E_NOMEM;
    struct ssg_gl_pass p;
    if (cells && list && count && pick && acc) {
        cells_pass(ctx, c, io, cells, &p);
        if (!(e = ssg_gl_pass_end(&p))) {
            list_pass(ctx, c, cells, list, count, &p);
            e = ssg_gl_pass_end(&p);
        }
        if (!e && c->p.samples > 0) {
            picks_pass(ctx, c, list, count, pick, &p);
            e = ssg_gl_pass_end(&p);
        }
        if (!e) {
            gather_pass(ctx, c, io, list, count, pick, acc, &p);
            e = ssg_gl_pass_end(&p);
        }
    } else {
        ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory");
    }
    ssg_gl_scratch_release(&cells);
    ssg_gl_scratch_release(&list);
    ssg_gl_scratch_release(&count);
    ssg_gl_scratch_release(&pick);
    ssg_gl_scratch_release(&acc);
    return e;
}

enum ssg_err ssg_rsm_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                            const struct ssg_io *io)
{
    return ssg_rsm_run_frame(ctx, consts, io, run);
}
