/* ssilvb.c - the `ssilvb` node's descriptor, check and prepare: screen-space indirect
 * lighting with a visibility bitmask. The method, its sources and conventions: README.md. */
#include <math.h>
#include <stdio.h>

#include "common/random.h"
#include "common/horizon.h"
#include "ssilvb.h"

static int color_like(const struct ssg_shape *s, const struct ssg_shape *pos)
{
    return s->channels == 3 && ssg_shape_same_size(s, pos);
}

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    (void)params, (void)frame;
    const struct ssg_shape *pos = &in[SSG_SSILVB_IN_POSITION], *nrm = &in[SSG_SSILVB_IN_NORMAL];
    if (pos->channels != 3 || !color_like(nrm, pos)) {
        snprintf(why, why_len, "position and normal must be 3-channel images of one size");
        return SSG_E_SIZE;
    }
    if (!color_like(&in[SSG_SSILVB_IN_LIGHT], pos) ||
        !color_like(&in[SSG_SSILVB_IN_ALBEDO], pos)) {
        snprintf(why, why_len, "light and albedo must be 3-channel images the size of "
                               "position");
        return SSG_E_SIZE;
    }
    const struct ssg_shape *back = &in[SSG_SSILVB_IN_BACK];
    if (back->channels != 0 && (back->channels != 1 || !ssg_shape_same_size(back, pos))) {
        snprintf(why, why_len, "back must be a 1-channel image the size of position");
        return SSG_E_SIZE;
    }
    struct ssg_shape none = {0};
    enum ssg_err e = ssg_sampling_check_inputs(pos, NULL, &none, &in[SSG_SSILVB_IN_DEPTH],
                                               NULL, why, why_len);
    if (e)
        return e;
    out[SSG_SSILVB_OUT_AO] = (struct ssg_shape){pos->width, pos->height, 1, SSG_T_SCALAR};
    out[SSG_SSILVB_OUT_BOUNCE] = (struct ssg_shape){pos->width, pos->height, 3, SSG_T_COLOR};
    return SSG_OK;
}

/* The seed's pattern offsets (whole pixels below 1024: the noise's float arithmetic
   stays as exact as at the origin) and the turn table; the slices are the frame's
   (ssg_ssilvb_frame_of). */
static void prepare_tables(const struct ssg_node_ctx *ctx, struct ssg_ssilvb_consts *c)
{
    uint64_t state = (ctx->frame ? ctx->frame->seed : 1) ^ 0xA54FF53A5F1D36F1ull;
    for (int i = 0; i < 4; i++)
        c->noise_off[i] = (float)(ssg_splitmix64(&state) % 1024u);
    for (int j = 0; j < SSG_SSILVB_TURNS; j++) {
        double a = M_PI * (j + 0.5) / (SSG_SSILVB_TURNS * (double)c->p.slices);
        c->turn_cos[j] = (float)cos(a);
        c->turn_sin[j] = (float)sin(a);
    }
}

void ssg_ssilvb_frame_of(const struct ssg_ssilvb_consts *c, int frame,
                         struct ssg_ssilvb_frame *f)
{
    /* Frame 0: turn 0 and shift 0, the single-frame slices pi k / slices and offsets. */
    ssg_horizon_angles(c->p.slices, M_PI, ssg_sampling_frame_turn(frame), f->slice_cos,
                           f->slice_sin);
    float shift = ssg_sampling_frame_shift(frame);
    for (int i = 0; i < 4; i++)
        f->noise_off[i] = c->noise_off[i] + shift;
}

/* The consts with e1 for the G-buffer's columns. */
static size_t consts_size_of(const void *params, const struct ssg_shape *in)
{
    return ssg_horizon_consts_size(sizeof(struct ssg_ssilvb_consts), &in[SSG_SSILVB_IN_POSITION]);
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_ssilvb_consts *c = consts;
    c->p = *(const struct ssg_ssilvb_params *)params;
    enum ssg_err e = ssg_horizon_frame(ctx, &ctx->in_shape[SSG_SSILVB_IN_POSITION], &c->proj,
                                       &c->invf, c->e1);
    if (e)
        return e;
    prepare_tables(ctx, c);
    return SSG_OK;
}

SSG_PARAMS_TABLE(params, ssg_ssilvb_params, SSG_SSILVB_PARAMS);
SSG_PORT_TABLE(inputs, SSG_SSILVB_IN);
SSG_PORT_TABLE(outputs, SSG_SSILVB_OUT);

/* Flops per pixel (node.h), by reading ssilvb_cpu.c: per slice about 60 (its frame, the
   open measure), per step of each side about 75 (two points, two arc measures with their
   acos polynomials, the bits, the sender), about 50 per pixel. */
static double ssilvb_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_ssilvb_consts *c = consts;
    (void)in;
    return 50.0 + c->p.slices * (60.0 + 2.0 * 75.0 * c->p.steps);
}

const struct ssg_node_desc ssg_node_ssilvb = {
    .name = "ssilvb",
    .summary = "screen-space indirect lighting and ambient occlusion with visibility "
               "bitmasks (GTAO slices, thick occluders)",
    .method = "Therrien, Levesque and Gilet, Screen Space Indirect Lighting with Visibility "
              "Bitmask (2023, arXiv 2301.11376), sec. 3: GTAO's slices with a 32-sector "
              "bitmask per slice, occluders of finite thickness, one bounce through the "
              "sectors a sample newly occludes; sectors of equal cosine-weighted measure",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_ssilvb_params),
    .consts_size_of = consts_size_of,
    /* its slices turn every frame (docs/time.md) */
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA | SSG_READS_FRAME,
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = ssilvb_flops,
    .run_cpu = ssg_ssilvb_run_cpu,
    .run_gl = ssg_ssilvb_run_gl,
    .parity = {.max = 1.4e-6, .mean = 1.4e-7}, /* test_gl_ssilvb.c: 3.6e-7, 3.4e-8 (pow): 4x */
};
