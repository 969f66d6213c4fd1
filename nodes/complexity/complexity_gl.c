/* complexity_gl.c - GL side of the `complexity` node (method and mapping in README.md, CPU
 * kernel complexity_cpu.c). The CPU's three steps as passes: per grid the cell means
 * (complexity_means.glsl, into two scratch images) and the cell weights
 * (complexity_weight.glsl, one small scratch image per grid, the thresholds and gains
 * bound from the table), then per pixel the max over the grids and the level
 * (complexity_count.glsl): 2 resolutions + 1 dispatches. The grids' layout and the
 * projection are prepare()'s, as on the CPU. Ports, parameters and the projection are
 * bound by the tables (each in the shaders its row's .gl_in names, complexity.h); by hand
 * only the scratch images of each grid and the side of the grid a pass is for. */
#include "complexity.h"
#include "gl/gl.h"

/* The scratch images of one grid: means (normal + depth, point) and weights. */
struct grid {
    struct ssg_image *nd, *pt, *t;
};

static void release_grid(struct grid *g)
{
    ssg_gl_scratch_release(&g->nd);
    ssg_gl_scratch_release(&g->pt);
    ssg_gl_scratch_release(&g->t);
}

/* Means then weights of one grid; its mean images go back to the scratch pool after. */
static enum ssg_err grid_passes(const struct ssg_node_ctx *ctx,
                                const struct ssg_complexity_consts *c, const struct ssg_io *io,
                                const struct ssg_complexity_grid *cells, struct grid *g)
{
    g->nd = ssg_gl_scratch(ctx, cells->gw, cells->gh, 4);
    g->pt = g->nd ? ssg_gl_scratch(ctx, cells->gw, cells->gh, 3) : NULL;
    g->t = g->pt ? ssg_gl_scratch(ctx, cells->gw, cells->gh, 1) : NULL;
    if (!g->t)
        return SSG_E_NOMEM;
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "complexity_means.glsl", NULL);
    ssg_gl_ports(&p, io); /* depth, normal */
    ssg_gl_output(&p, "nd", g->nd);
    ssg_gl_output(&p, "pt", g->pt);
    ssg_gl_int(&p, "side", cells->side);
    ssg_gl_dispatch(&p, cells->gw, cells->gh);
    enum ssg_err e = ssg_gl_pass_end(&p);
    if (e == SSG_OK) {
        ssg_gl_pass_begin(&p, ctx, "complexity_weight.glsl", NULL);
        ssg_gl_input(&p, "nd", g->nd);
        ssg_gl_input(&p, "pt", g->pt);
        ssg_gl_output(&p, "weight", g->t);
        ssg_gl_dispatch(&p, cells->gw, cells->gh);
        e = ssg_gl_pass_end(&p);
    }
    ssg_gl_scratch_release(&g->nd);
    ssg_gl_scratch_release(&g->pt);
    return e;
}

static enum ssg_err count_pass(const struct ssg_node_ctx *ctx,
                               const struct ssg_complexity_consts *c, const struct ssg_io *io,
                               const struct grid *g)
{
    static const char *const names[SSG_COMPLEXITY_MAX_RESOLUTIONS] = {"t0", "t1", "t2", "t3"};
    struct ssg_image *out = io->out[0];
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "complexity_count.glsl", NULL);
    ssg_gl_ports(&p, io);
    for (int r = 0; r < SSG_COMPLEXITY_MAX_RESOLUTIONS; r++)
        ssg_gl_input(&p, names[r], r < c->grids ? g[r].t : NULL);
    ssg_gl_dispatch(&p, out->width, out->height);
    return ssg_gl_pass_end(&p);
}

enum ssg_err ssg_complexity_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                   const struct ssg_io *io)
{
    const struct ssg_complexity_consts *c = consts;
    struct grid g[SSG_COMPLEXITY_MAX_RESOLUTIONS] = {{0}};
    enum ssg_err e = SSG_OK;
    for (int r = 0; e == SSG_OK && r < c->grids; r++)
        e = grid_passes(ctx, c, io, &c->grid[r], &g[r]);
    if (e == SSG_OK)
        e = count_pass(ctx, c, io, g);
    for (int r = 0; r < c->grids; r++)
        release_grid(&g[r]);
    return e;
}
