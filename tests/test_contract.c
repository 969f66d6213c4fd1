/* test_contract.c - the node contract's shape guarantee, for every registered node: the
 * executor verifies each bound image against the shape the graph was checked with before
 * a node runs (ssg_node_verify_io, called by ssg_node_run_prepared), so no node checks its
 * own images. For each node, on both backends' path (the verification is the same call):
 *   - images of exactly the checked shapes pass;
 *   - each input in turn, and each output, bound one pixel wider (or with one channel
 *     more) is refused with SSG_E_SIZE (SSG_E_CHANNELS) and one message naming the node,
 *     the instance, the port, the actual and the expected shape; the node never runs
 *     (its kernel would read past the smaller image: ASan would say so);
 *   - an optional input bound although the graph left it unconnected is refused;
 *   - every port has a name and a type (the arrays are indexed by the port enumerators);
 *   - the method text is in one place: the folder's README.md (embedded) or the
 *     descriptor's doc, never both, never neither; and every README names a node.
 * Shapes: every input port gets a shape of its first accepted type on a 16x12 frame. */
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "graph/exec.h"
#include "graph/image.h"
#include "graph/node.h"

enum { W = 16, H = 12, LIGHTS = 4 };

/* A shape of the first type in `types`. */
static struct ssg_shape shape_of_type(unsigned types)
{
    if (types & SSG_T_SCALAR)
        return (struct ssg_shape){W, H, 1, SSG_T_SCALAR};
    if (types & SSG_T_VECTOR)
        return (struct ssg_shape){W, H, 3, SSG_T_VECTOR};
    if (types & SSG_T_COLOR)
        return (struct ssg_shape){W, H, 3, SSG_T_COLOR};
    if (types & SSG_T_KERNEL)
        return (struct ssg_shape){8, 1, 3, SSG_T_KERNEL};
    if (types & SSG_T_PATTERN)
        return (struct ssg_shape){4, 4, 2, SSG_T_PATTERN};
    if (types & SSG_T_LIGHTS)
        return (struct ssg_shape){LIGHTS, 2, 3, SSG_T_LIGHTS};
    if (types & SSG_T_SHADOWMAPS)
        return (struct ssg_shape){32, 32, LIGHTS, SSG_T_SHADOWMAPS};
    return (struct ssg_shape){32, 32, LIGHTS, SSG_T_LIGHTMAPS};
}

struct bound {
    struct ssg_shape in_shape[SSG_MAX_PORTS], out_shape[SSG_MAX_PORTS];
    const struct ssg_image *in[SSG_MAX_PORTS];
    struct ssg_image *out[SSG_MAX_PORTS];
};

static struct ssg_image *image_of(const struct ssg_shape *s)
{
    return ssg_image_create(s->width, s->height, s->channels);
}

/* Every input connected with its first type; outputs of one plausible shape each (the
   verification compares, it does not judge). */
static void bind_all(const struct ssg_node_desc *d, struct bound *b)
{
    memset(b, 0, sizeof *b);
    for (int i = 0; i < d->input_count; i++) {
        b->in_shape[i] = shape_of_type(d->inputs[i].types);
        b->in[i] = image_of(&b->in_shape[i]);
    }
    for (int i = 0; i < d->output_count; i++) {
        b->out_shape[i] = shape_of_type(d->outputs[i].types);
        b->out[i] = image_of(&b->out_shape[i]);
    }
}

static void release(const struct ssg_node_desc *d, struct bound *b)
{
    for (int i = 0; i < d->input_count; i++)
        ssg_image_destroy((struct ssg_image **)&b->in[i]);
    for (int i = 0; i < d->output_count; i++)
        ssg_image_destroy(&b->out[i]);
}

/* Runs the node the executor's way (no prepare: consts NULL, the params never read) and
   returns the error; the one diagnostic's text goes to msg. */
static enum ssg_err run(const struct ssg_node_desc *d, struct bound *b, char *msg, size_t len)
{
    struct ssg_diags diags = {0};
    struct ssg_frame frame = {.width = W, .height = H, .fov_y = 45, .near_z = 0.05f,
                              .far_z = 100, .seed = 1};
    struct ssg_shape extra[1] = {{0}};
    struct ssg_node_ctx ctx = {.desc = d, .instance = "n1", .frame = &frame, .out_dir = "out",
                               .diags = &diags, .in_shape = b->in_shape,
                               .out_shape = b->out_shape, .extra_shape = extra};
    struct ssg_io io = {.in = b->in, .out = b->out};
    struct ssg_node_timing t;
    enum ssg_err e = ssg_node_verify_io(&ctx, &io);
    if (e) /* the same refusal through the executor's entry */
        CHECK_EQ(ssg_node_run_prepared(d, &ctx, NULL, NULL, &io, SSG_BACKEND_CPU, &t), e);
    CHECK_EQ(diags.count, e ? 2 : 0);
    snprintf(msg, len, "%s", diags.count ? diags.items[0].message : "");
    return e;
}

static void expect_refused(const struct ssg_node_desc *d, struct bound *b, const char *side,
                           const char *port, enum ssg_err code)
{
    char msg[512], want[128];
    CHECK_EQ(run(d, b, msg, sizeof msg), code);
    snprintf(want, sizeof want, "node 'n1' (%s): %s '%s' is ", d->name, side, port);
    if (!strstr(msg, want) || !strstr(msg, "expected"))
        fprintf(stderr, "  %s: message '%s' lacks '%s' or 'expected'\n", d->name, msg, want);
    CHECK(strstr(msg, want) != NULL);
    CHECK(strstr(msg, "expected") != NULL);
}

/* Binds an image of shape s in *slot, expects the refusal, and puts the good one back. */
static void try_image(const struct ssg_node_desc *d, struct bound *b, struct ssg_image **slot,
                      struct ssg_shape s, const char *side, const char *port,
                      enum ssg_err code)
{
    struct ssg_image *good = *slot, *bad = image_of(&s);
    *slot = bad;
    expect_refused(d, b, side, port, code);
    *slot = good;
    ssg_image_destroy(&bad);
}

/* Port arrays are indexed by their enumerators: a skipped enumerator leaves a hole. The
   executor's per-node arrays hold SSG_MAX_PORTS ports a side. */
static void test_ports_named(const struct ssg_node_desc *d)
{
    CHECK(d->input_count <= SSG_MAX_PORTS && d->output_count <= SSG_MAX_PORTS);
    for (int i = 0; i < d->input_count; i++)
        CHECK(d->inputs[i].name != NULL && d->inputs[i].types != 0);
    for (int i = 0; i < d->output_count; i++)
        CHECK(d->outputs[i].name != NULL && d->outputs[i].types != 0);
}

static void test_doc_in_one_place(const struct ssg_node_desc *d)
{
    const char *readme = ssg_node_readme(d->name);
    int has_doc = d->doc != NULL && d->doc[0] != 0;
    if ((readme != NULL) == has_doc)
        fprintf(stderr, "node %s: %s\n", d->name,
                has_doc ? "has both nodes/<name>/README.md and a descriptor .doc"
                        : "has neither README.md nor a descriptor .doc");
    CHECK((readme != NULL) != has_doc);
    int len;
    ssg_node_doc(d, &len);
    CHECK(len > 40);
}

static void test_node(const struct ssg_node_desc *d)
{
    struct bound b;
    char msg[512];
    test_ports_named(d);
    test_doc_in_one_place(d);
    bind_all(d, &b);
    CHECK_EQ(run(d, &b, msg, sizeof msg), SSG_OK);
    for (int i = 0; i < d->input_count; i++) {
        struct ssg_image **slot = (struct ssg_image **)&b.in[i];
        const char *port = d->inputs[i].name;
        struct ssg_shape wide = b.in_shape[i], more = b.in_shape[i];
        wide.width += 1;
        more.channels = more.channels == 4 ? 3 : more.channels + 1;
        try_image(d, &b, slot, wide, "input", port, SSG_E_SIZE);
        try_image(d, &b, slot, more, "input", port, SSG_E_CHANNELS);
        if (d->inputs[i].optional) { /* checked as unconnected, bound anyway */
            struct ssg_shape checked = b.in_shape[i];
            b.in_shape[i] = (struct ssg_shape){0};
            expect_refused(d, &b, "input", port, SSG_E_CHANNELS);
            b.in_shape[i] = checked;
        }
    }
    for (int i = 0; i < d->output_count; i++) {
        struct ssg_shape tall = b.out_shape[i];
        tall.height += 1;
        try_image(d, &b, &b.out[i], tall, "output", d->outputs[i].name, SSG_E_SIZE);
    }
    release(d, &b);
}

int main(void)
{
    CHECK(ssg_node_count() >= 20);
    for (int n = 0; n < ssg_node_count(); n++) {
        const char *name = ssg_node_name(n);
        test_node(ssg_node_find(name, strlen(name)));
    }
    for (const struct ssg_node_readme *r = ssg_node_readmes; r->node; r++)
        CHECK(ssg_node_find(r->node, strlen(r->node)) != NULL);
    return check_report();
}
