/* exec.c - output shapes and the timed execution of one node (exec.h). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "graph/exec.h"
#include "graph/gl_backend.h"
#include "graph/image.h"
#include "lang/parse.h"

enum ssg_err ssg_node_fail(const struct ssg_node_ctx *ctx, enum ssg_err code, const char *fmt,
                           ...)
{
    char what[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    ssg_diag_at(ctx->diags, code, (struct ssg_loc){0}, "%s '%s': %s",
                ctx->desc ? ctx->desc->name : "node", ctx->instance ? ctx->instance : "", what);
    return code;
}

double ssg_now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static void default_shape(const struct ssg_node_desc *desc, int port,
                          const struct ssg_frame *frame, const struct ssg_shape *in,
                          struct ssg_shape *out)
{
    const struct ssg_port_desc *p = &desc->outputs[port];
    if (p->same_as) {
        int src =
            ssg_port_find(desc->inputs, desc->input_count, p->same_as, strlen(p->same_as));
        if (src >= 0) {
            *out = in[src];
            return;
        }
    }
    out->width = ssg_frame_full_width(frame);
    out->height = ssg_frame_full_height(frame);
    out->channels = ssg_type_channels(p->types);
    out->type = p->types;
}

enum ssg_err ssg_shapes_infer(const struct ssg_node_desc *desc, const void *params,
                              const struct ssg_frame *frame, const struct ssg_shape *in,
                              struct ssg_shape *out, char *why, size_t why_len)
{
    why[0] = 0;
    for (int i = 0; i < desc->output_count; i++)
        default_shape(desc, i, frame, in, &out[i]);
    if (desc->check) {
        enum ssg_err e = desc->check(params, frame, in, out, why, why_len);
        if (e)
            return e;
    }
    for (int i = 0; i < desc->output_count; i++) {
        if (!ssg_image_size_ok(out[i].width, out[i].height, out[i].channels)) {
            snprintf(
                why, why_len,
                "output '%s' would be %dx%d with %d channels (at most "
                "%dx%d, %d pixels, 1-4 channels; a frame needs a size or a frame-sized input)",
                desc->outputs[i].name, out[i].width, out[i].height, out[i].channels,
                SSG_IMAGE_MAX_SIDE, SSG_IMAGE_MAX_SIDE, SSG_IMAGE_MAX_PIXELS);
            return SSG_E_SIZE;
        }
    }
    return SSG_OK;
}

const char *ssg_backend_name(enum ssg_backend b)
{
    return b == SSG_BACKEND_CPU ? "cpu" : b == SSG_BACKEND_GL ? "gl" : "default";
}

int ssg_backend_parse(const char *text, size_t len, enum ssg_backend *out)
{
    if (len == 3 && !strncmp(text, "cpu", 3))
        *out = SSG_BACKEND_CPU;
    else if (len == 2 && !strncmp(text, "gl", 2))
        *out = SSG_BACKEND_GL;
    else
        return 0;
    return 1;
}

/* Makes every input current where the node runs; the transfers' time goes to *ms. */
static enum ssg_err move_inputs(const struct ssg_node_desc *desc, const struct ssg_io *io,
                                int on_gl, double *ms, struct ssg_diags *diags)
{
    enum ssg_err e = SSG_OK;
    for (int i = 0; i < desc->input_count && !e; i++)
        if (io->in[i])
            e = on_gl ? ssg_gl_to_gpu(io->in[i], ms, diags)
                      : ssg_gl_to_cpu(io->in[i], ms, diags);
    for (int i = 0; i < io->extra_count && !e; i++)
        e = on_gl ? ssg_gl_to_gpu(io->extra_in[i], ms, diags)
                  : ssg_gl_to_cpu(io->extra_in[i], ms, diags);
    return e;
}

static enum ssg_err run_backend(const struct ssg_node_desc *desc,
                                const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io, int on_gl, struct ssg_node_timing *t)
{
    enum ssg_err e = move_inputs(desc, io, on_gl, &t->transfer_ms, ctx->diags);
    if (e)
        return e;
    if (!on_gl)
        e = desc->run_cpu(ctx, consts, io);
    else {
        ssg_gl_timer_begin();
        e = desc->run_gl(ctx, consts, io);
        t->gpu_ms = ssg_gl_timer_end();
    }
    for (int i = 0; i < desc->output_count; i++)
        if (io->out[i]) /* an on_demand output nothing reads is not bound */
            ssg_gl_mark_written(io->out[i], on_gl);
    return e;
}

enum ssg_err ssg_node_prepare(const struct ssg_node_desc *desc, const struct ssg_node_ctx *ctx,
                              const void *params, void **consts)
{
    *consts = NULL;
    size_t bytes = desc->consts_size_of ? desc->consts_size_of(params, ctx->in_shape)
                                        : desc->consts_size;
    if (!bytes)
        return SSG_OK;
    *consts = calloc(1, bytes);
    if (!*consts) {
        ssg_diag_file(ctx->diags, SSG_E_NOMEM, NULL, "out of memory preparing '%s'",
                      ctx->instance);
        return SSG_E_NOMEM;
    }
    return desc->prepare ? desc->prepare(ctx, params, *consts) : SSG_OK;
}

/* The scratch of runs without a slot of their own (node.h): one block a thread, kept for
   the process (reachable through the thread's storage, so no leak checker minds). */
static _Thread_local struct ssg_scratch thread_scratch;

void *ssg_node_scratch(const struct ssg_node_ctx *ctx, size_t bytes)
{
    struct ssg_scratch *s = ctx->scratch ? ctx->scratch : &thread_scratch;
    if (s->data && s->bytes >= bytes)
        return s->data;
    size_t rounded = (bytes + 63) / 64 * 64; /* aligned_alloc wants a multiple */
    void *p = aligned_alloc(64, rounded ? rounded : 64);
    if (!p)
        return NULL;
    free(s->data);
    *s = (struct ssg_scratch){p, rounded};
    return p;
}

void ssg_scratch_free(struct ssg_scratch *s)
{
    free(s->data);
    *s = (struct ssg_scratch){0};
}

static double shape_bytes(const struct ssg_shape *s)
{
    return (double)s->width * (double)s->height * (double)s->channels * sizeof(float);
}

void ssg_node_cost_of(const struct ssg_node_desc *desc, const struct ssg_node_ctx *ctx,
                      const void *consts, int extra_count, struct ssg_node_cost *cost)
{
    cost->bytes = 0.0;
    for (int i = 0; i < desc->input_count; i++)
        cost->bytes += shape_bytes(&ctx->in_shape[i]); /* unconnected: 0 channels */
    for (int i = 0; i < desc->output_count; i++)
        cost->bytes += shape_bytes(&ctx->out_shape[i]);
    for (int i = 0; ctx->extra_shape && i < extra_count; i++)
        cost->bytes += shape_bytes(&ctx->extra_shape[i]);
    cost->flops = -1.0;
    if (desc->flops_per_pixel && desc->output_count > 0)
        cost->flops = desc->flops_per_pixel(consts, ctx->in_shape) *
                      (double)ctx->out_shape[0].width * (double)ctx->out_shape[0].height;
}

/* "96x64 with 3 channels", or "unconnected". */
static void shape_text(int width, int height, int channels, char *buf, size_t len)
{
    if (channels == 0)
        snprintf(buf, len, "unconnected");
    else
        snprintf(buf, len, "%dx%d with %d channel%s", width, height, channels,
                 channels == 1 ? "" : "s");
}

/* One bound image against the shape it was checked with; SSG_OK or a reported error. */
static enum ssg_err verify_one(const struct ssg_node_ctx *ctx, const char *side,
                               const char *port, const struct ssg_image *im,
                               const struct ssg_shape *want)
{
    int w = im ? im->width : 0, h = im ? im->height : 0, c = im ? im->channels : 0;
    if (w == want->width && h == want->height && c == want->channels)
        return SSG_OK;
    if (!im && want->channels == 0)
        return SSG_OK;
    char got[64], expected[64];
    shape_text(w, h, c, got, sizeof got);
    shape_text(want->width, want->height, want->channels, expected, sizeof expected);
    enum ssg_err code = c != want->channels ? SSG_E_CHANNELS : SSG_E_SIZE;
    ssg_diag_at(ctx->diags, code, (struct ssg_loc){0}, "node '%s' (%s): %s '%s' is %s, "
                "expected %s (the shape the graph was checked with)",
                ctx->instance ? ctx->instance : "", ctx->desc->name, side, port,
                im ? got : "missing", expected);
    return code;
}

/* A bound input's type must be one its port accepts (a graph types every edge; shapes
   read off hand-bound images carry type 0 when the channels fit none). */
static enum ssg_err verify_type(const struct ssg_node_ctx *ctx,
                                const struct ssg_port_desc *port, const struct ssg_shape *shape)
{
    if (shape->type & port->types)
        return SSG_OK;
    char want[64];
    ssg_type_names(port->types, want, sizeof want);
    ssg_diag_at(ctx->diags, SSG_E_CHANNELS, (struct ssg_loc){0}, "node '%s' (%s): input '%s' "
                "has %d channels, which fits none of its types (%s)",
                ctx->instance ? ctx->instance : "", ctx->desc->name, port->name,
                shape->channels, want);
    return SSG_E_CHANNELS;
}

enum ssg_err ssg_node_verify_io(const struct ssg_node_ctx *ctx, const struct ssg_io *io)
{
    const struct ssg_node_desc *d = ctx->desc;
    if (!ctx->in_shape || !ctx->out_shape || (io->extra_count && !ctx->extra_shape)) {
        ssg_diag_at(ctx->diags, SSG_E_RUN, (struct ssg_loc){0}, "node '%s' (%s): run "
                    "without the shapes it was checked with",
                    ctx->instance ? ctx->instance : "", d->name);
        return SSG_E_RUN;
    }
    enum ssg_err e = SSG_OK;
    for (int i = 0; i < d->input_count && !e; i++) {
        e = verify_one(ctx, "input", d->inputs[i].name, io->in[i], &ctx->in_shape[i]);
        if (!e && io->in[i])
            e = verify_type(ctx, &d->inputs[i], &ctx->in_shape[i]);
    }
    for (int i = 0; i < d->output_count && !e; i++)
        if (io->out[i] || !d->outputs[i].on_demand) /* unread on_demand: may be unbound */
            e = verify_one(ctx, "output", d->outputs[i].name, io->out[i], &ctx->out_shape[i]);
    for (int i = 0; i < io->extra_count && !e; i++)
        e = verify_one(ctx, "input", io->extra_names[i], io->extra_in[i], &ctx->extra_shape[i]);
    return e;
}

void ssg_io_shapes_of(const struct ssg_node_desc *desc, const struct ssg_io *io,
                      struct ssg_io_shapes *s)
{
    memset(s, 0, sizeof *s);
    for (int i = 0; i < desc->input_count; i++)
        if (io->in[i])
            s->in[i] = ssg_shape_of_image(io->in[i], desc->inputs[i].types);
    for (int i = 0; i < desc->output_count; i++)
        if (io->out[i])
            s->out[i] = ssg_shape_of_image(io->out[i], desc->outputs[i].types);
    for (int i = 0; i < io->extra_count && i < SSG_MAX_EXTRA; i++)
        s->extra[i] = ssg_shape_of_image(io->extra_in[i], SSG_T_IMAGE);
}

void ssg_node_ctx_set_shapes(struct ssg_node_ctx *ctx, const struct ssg_io_shapes *s)
{
    ctx->in_shape = s->in;
    ctx->out_shape = s->out;
    ctx->extra_shape = s->extra;
}

struct ssg_shape ssg_shape_of_image(const struct ssg_image *image, unsigned accepted)
{
    unsigned type = ssg_type_of_image(accepted, image);
    return (struct ssg_shape){image->width, image->height, image->channels, type};
}

enum ssg_err ssg_node_run_prepared(const struct ssg_node_desc *desc,
                                   const struct ssg_node_ctx *ctx, const void *params,
                                   const void *consts, const struct ssg_io *io,
                                   enum ssg_backend backend, struct ssg_node_timing *timing)
{
    double t0 = ssg_now_ms();
    *timing = (struct ssg_node_timing){0};
    int on_gl = backend == SSG_BACKEND_GL && desc->run_gl;
    struct ssg_node_ctx run_ctx = *ctx;
    run_ctx.params = params; /* what a GL pass binds by the tables (gl.h) */
    run_ctx.consts = consts;
    struct ssg_gl_shared own = {0}; /* a node run alone shares with nobody */
    if (!run_ctx.gl_shared)
        run_ctx.gl_shared = &own;
    enum ssg_err e = ssg_node_verify_io(&run_ctx, io);
    if (!e)
        e = run_backend(desc, &run_ctx, consts ? consts : params, io, on_gl, timing);
    ssg_gl_shared_clear(&own);
    timing->ms = ssg_now_ms() - t0 - timing->transfer_ms;
    return e;
}

enum ssg_err ssg_node_execute(const struct ssg_node_desc *desc, const struct ssg_node_ctx *ctx,
                              const void *params, const struct ssg_io *io,
                              enum ssg_backend backend, struct ssg_node_timing *timing)
{
    double t0 = ssg_now_ms();
    void *consts = NULL;
    *timing = (struct ssg_node_timing){0};
    enum ssg_err e = ssg_node_prepare(desc, ctx, params, &consts);
    double prepare_ms = ssg_now_ms() - t0;
    if (!e)
        e = ssg_node_run_prepared(desc, ctx, params, consts, io, backend, timing);
    free(consts);
    timing->ms += prepare_ms;
    return e;
}

unsigned ssg_type_of_image(unsigned accepted, const struct ssg_image *image)
{
    if (image->channels == 1 && (accepted & SSG_T_SCALAR))
        return SSG_T_SCALAR;
    if (image->channels == 3 && (accepted & SSG_T_VECTOR))
        return SSG_T_VECTOR;
    if (image->channels == 3 && (accepted & SSG_T_COLOR))
        return SSG_T_COLOR;
    if (image->channels == 3 && image->height == 1 && (accepted & SSG_T_KERNEL))
        return SSG_T_KERNEL;
    /* A pattern's optional channels 3 and 4: the length shift (halton lengths=shifted). */
    if ((image->channels == 2 || (image->channels == 4 && image->width == image->height)) &&
        (accepted & SSG_T_PATTERN))
        return SSG_T_PATTERN;
    if (image->channels == 3 && image->height == 2 && (accepted & SSG_T_LIGHTS))
        return SSG_T_LIGHTS;
    if (image->width == image->height && (accepted & SSG_T_SHADOWMAPS))
        return SSG_T_SHADOWMAPS;
    if (image->width == image->height && (accepted & SSG_T_LIGHTMAPS))
        return SSG_T_LIGHTMAPS;
    return 0;
}
