/* test_write.c - the `write` sink node called through its descriptor: file names are
 * checked, the output directory is created, the EXR holds the main image and every extra
 * input as a named layer (exact floats), the PNG is the tone-mapped main image, png/exr
 * switch files off, errors name the path, and the EXR is written after the PNG (docs/exr.md,
 * "The EXR and its PNG": an EXR never older than its PNG). Scratch files go to $SSG_TMP. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "scratch.h"
#include "io/imageio.h"
#include "write/write.h"

extern const struct ssg_node_desc ssg_node_write;


static int exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

static struct ssg_image *filled(int w, int h, int channels, float base)
{
    struct ssg_image *im = ssg_image_create(w, h, channels);
    for (int i = 0; i < w * h * channels; i++)
        im->data[i] = base + 0.03125f * (float)i;
    return im;
}

static void defaults(struct ssg_write_params *p, const char *name)
{
    memset(p, 0, sizeof *p);
    ssg_params_defaults(ssg_node_write.params, p);
    snprintf(p->name, sizeof p->name, "%s", name);
}

/* The node's view of one run: main image plus named extra inputs. */
struct run {
    struct ssg_diags diags;
    struct ssg_frame frame;
    struct ssg_node_ctx ctx;
    const struct ssg_image *in[1];
    const char *names[4];
    const struct ssg_image *extra[4];
    unsigned types[4];
    struct ssg_io io;
    char out_dir[1024]; /* a copy: tmp_path's buffers are reused */
};

static void run_init(struct run *r, const char *out_dir, const struct ssg_image *main_im)
{
    memset(r, 0, sizeof *r);
    snprintf(r->out_dir, sizeof r->out_dir, "%s", out_dir);
    r->frame = (struct ssg_frame){.width = main_im->width, .height = main_im->height,
                                  .fov_y = 45, .near_z = 0.05f, .far_z = 100, .seed = 1};
    r->ctx = (struct ssg_node_ctx){.desc = &ssg_node_write,
                                   .instance = "w",
                                   .frame = &r->frame,
                                   .out_dir = r->out_dir,
                                   .diags = &r->diags};
    r->in[0] = main_im;
    r->io = (struct ssg_io){.in = r->in, .extra_names = r->names, .extra_in = r->extra,
                            .extra_types = r->types};
}

static void add_extra(struct run *r, const char *name, const struct ssg_image *im,
                      unsigned type)
{
    r->names[r->io.extra_count] = name;
    r->extra[r->io.extra_count] = im;
    r->types[r->io.extra_count] = type;
    r->io.extra_count++;
}

static void check_layer(const char *path, const char *layer, const struct ssg_image *want)
{
    struct ssg_diags d = {0};
    struct ssg_image *got = NULL;
    CHECK_EQ(ssg_image_read(path, layer, &got, &d), SSG_OK);
    CHECK(got && got->width == want->width && got->height == want->height &&
          got->channels == want->channels);
    if (got && got->channels == want->channels && got->width == want->width &&
        got->height == want->height)
        CHECK(memcmp(got->data, want->data, sizeof(float) * (size_t)want->width *
                                                (size_t)want->height *
                                                (size_t)want->channels) == 0);
    ssg_image_destroy(&got);
}

static void test_descriptor(void)
{
    const struct ssg_node_desc *d = &ssg_node_write;
    CHECK(strcmp(d->name, "write") == 0);
    CHECK_EQ(d->is_sink, 1);
    CHECK_EQ(d->extra_inputs, 1);
    CHECK_EQ(d->output_count, 0);
    CHECK_EQ(d->input_count, 1);
    CHECK_EQ(d->inputs[0].types, SSG_T_COLOR | SSG_T_SCALAR | SSG_T_VECTOR);
    CHECK_EQ(d->consts_size, 0);
    CHECK_EQ(ssg_param_find(d->params, "name", 4), 0); /* first: `write(x, "ssao")` */
    CHECK(d->params.params[0].required);
    struct ssg_write_params p;
    defaults(&p, "");
    CHECK_NEAR(p.exposure, 0.0, 0.0);
    CHECK_EQ(p.tonemap, SSG_TONEMAP_ACES);
    CHECK_EQ(p.png, 1);
    CHECK_EQ(p.exr, 1);
    struct ssg_diags diags = {0};
    CHECK_EQ(ssg_param_set_text(d->params, &p, "tonemap=reinhard", "<test>", "write", &diags),
             SSG_OK);
    CHECK_EQ(p.tonemap, SSG_TONEMAP_REINHARD);
    CHECK_EQ(ssg_param_set_text(d->params, &p, "tonemap=clamp", "<test>", "write", &diags),
             SSG_OK);
    CHECK_EQ(p.tonemap, SSG_TONEMAP_CLAMP);
}

static void test_names(void)
{
    static const char *const bad[] = {"", "a/b", "/abs", "..", "../up", "x..y", ".hidden",
                                      "a\\b", "new\nline"};
    static const char *const good[] = {"ssao", "ssao-v2_1", "a.b", "CornellBox 2"};
    struct ssg_write_params p;
    char why[256];
    struct ssg_shape in = {4, 4, 3, SSG_T_COLOR};
    struct ssg_frame frame = {.width = 4, .height = 4};
    for (int i = 0; i < SSG_COUNT(bad); i++) {
        defaults(&p, bad[i]);
        why[0] = 0;
        CHECK_EQ(ssg_node_write.check(&p, &frame, &in, NULL, why, sizeof why), SSG_E_VALUE);
        CHECK(why[0] != 0);
    }
    for (int i = 0; i < SSG_COUNT(good); i++) {
        defaults(&p, good[i]);
        CHECK_EQ(ssg_node_write.check(&p, &frame, &in, NULL, why, sizeof why), SSG_OK);
    }
    defaults(&p, "ok");
    p.png = p.exr = 0;
    CHECK_EQ(ssg_node_write.check(&p, &frame, &in, NULL, why, sizeof why), SSG_E_VALUE);

    /* run_cpu refuses a bad name too and writes nothing. */
    struct ssg_image *im = filled(2, 2, 3, 0);
    struct run r;
    run_init(&r, tmp_path("badname"), im);
    defaults(&p, "../escape");
    CHECK_EQ(ssg_node_write.run_cpu(&r.ctx, &p, &r.io), SSG_E_VALUE);
    CHECK_EQ(r.diags.count, 1);
    CHECK(!exists(tmp_path("badname")));
    CHECK(!exists(tmp_path("escape.exr")));
    ssg_image_destroy(&im);
}

static void test_layers(void)
{
    struct ssg_image *color = filled(5, 4, 3, 0.5f), *ao = filled(5, 4, 1, -0.25f);
    struct ssg_image *normal = filled(5, 4, 3, -1.0f), *albedo = filled(5, 4, 3, 0.125f);
    const char *dir = tmp_path("nested/deeper/out");
    struct run r;
    run_init(&r, dir, color);
    add_extra(&r, "ao", ao, SSG_T_SCALAR);
    add_extra(&r, "normal", normal, SSG_T_VECTOR);
    add_extra(&r, "albedo", albedo, SSG_T_COLOR);
    struct ssg_write_params p;
    defaults(&p, "frame");
    CHECK_EQ(ssg_node_write.run_cpu(&r.ctx, &p, &r.io), SSG_OK);
    CHECK_EQ(r.diags.count, 0);
    const char *exr = tmp_path("nested/deeper/out/frame.exr");
    check_layer(exr, NULL, color);
    check_layer(exr, "ao", ao);
    check_layer(exr, "normal", normal);
    check_layer(exr, "albedo", albedo);
    /* The PNG: the main image, RGB, tone-mapped with ACES. */
    struct ssg_image *png = NULL;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_image_read(tmp_path("nested/deeper/out/frame.png"), NULL, &png, &d), SSG_OK);
    CHECK(png && png->width == 5 && png->height == 4 && png->channels == 3);
    ssg_image_destroy(&png);

    /* A scalar main image: EXR channel Y, gray PNG; clamp and exposure -1 put 1.0 at
       0.5 linear, 8-bit code 188, which reads back as 0.50289. */
    struct ssg_image *gray = ssg_image_create(3, 2, 1);
    for (int i = 0; i < 6; i++)
        gray->data[i] = 1.0f;
    run_init(&r, dir, gray);
    defaults(&p, "gray");
    p.tonemap = SSG_TONEMAP_CLAMP;
    p.exposure = -1.0f;
    CHECK_EQ(ssg_node_write.run_cpu(&r.ctx, &p, &r.io), SSG_OK);
    check_layer(tmp_path("nested/deeper/out/gray.exr"), NULL, gray);
    CHECK_EQ(ssg_image_read(tmp_path("nested/deeper/out/gray.png"), NULL, &png, &d), SSG_OK);
    CHECK(png && png->channels == 1);
    if (png)
        CHECK_NEAR(png->data[5], 0.50289, 1e-4);
    ssg_image_destroy(&png);

    /* png=0 and exr=0 each switch one file off (left-overs of an earlier run removed). */
    remove(tmp_path("nested/deeper/out/only_exr.png"));
    remove(tmp_path("nested/deeper/out/only_png.exr"));
    defaults(&p, "only_exr");
    p.png = 0;
    CHECK_EQ(ssg_node_write.run_cpu(&r.ctx, &p, &r.io), SSG_OK);
    CHECK(exists(tmp_path("nested/deeper/out/only_exr.exr")));
    CHECK(!exists(tmp_path("nested/deeper/out/only_exr.png")));
    defaults(&p, "only_png");
    p.exr = 0;
    CHECK_EQ(ssg_node_write.run_cpu(&r.ctx, &p, &r.io), SSG_OK);
    CHECK(!exists(tmp_path("nested/deeper/out/only_png.exr")));
    CHECK(exists(tmp_path("nested/deeper/out/only_png.png")));

    ssg_image_destroy(&color);
    ssg_image_destroy(&ao);
    ssg_image_destroy(&normal);
    ssg_image_destroy(&albedo);
    ssg_image_destroy(&gray);
}

static void test_errors(void)
{
    struct ssg_image *im = filled(4, 4, 3, 0), *other = filled(4, 3, 1, 0);
    struct ssg_write_params p;
    defaults(&p, "x");
    /* out_dir is a regular file: SSG_E_IO naming it. */
    char file[1024];
    snprintf(file, sizeof file, "%s", tmp_path("not_a_dir"));
    FILE *f = fopen(file, "w");
    if (f)
        fclose(f);
    struct run r;
    run_init(&r, file, im);
    CHECK_EQ(ssg_node_write.run_cpu(&r.ctx, &p, &r.io), SSG_E_IO);
    CHECK(r.diags.count >= 1 && strstr(r.diags.items[0].file, "not_a_dir"));
    /* ... or below a regular file. */
    run_init(&r, tmp_path("not_a_dir/sub"), im);
    CHECK_EQ(ssg_node_write.run_cpu(&r.ctx, &p, &r.io), SSG_E_IO);
    CHECK(r.diags.count >= 1 && strstr(r.diags.items[0].file, "not_a_dir"));
    /* The target is a directory: the EXR cannot be renamed into place, the error names
       the path and nothing else is left. */
    char dir[1024];
    snprintf(dir, sizeof dir, "%s", tmp_path("blocked"));
    mkdir(dir, 0777);
    mkdir(tmp_path("blocked/x.exr"), 0777);
    run_init(&r, dir, im);
    CHECK_EQ(ssg_node_write.run_cpu(&r.ctx, &p, &r.io), SSG_E_IO);
    CHECK(r.diags.count >= 1 && strstr(r.diags.items[0].file, "blocked/x.exr"));
    CHECK(!exists(tmp_path("blocked/x.png")));
    /* A layer of another size, and a layer that is not an image. */
    run_init(&r, tmp_path("layers"), im);
    add_extra(&r, "ao", other, SSG_T_SCALAR);
    CHECK_EQ(ssg_node_write.run_cpu(&r.ctx, &p, &r.io), SSG_E_SIZE);
    CHECK(!exists(tmp_path("layers/x.exr")));
    run_init(&r, tmp_path("layers"), im);
    add_extra(&r, "k", im, SSG_T_KERNEL);
    CHECK_EQ(ssg_node_write.run_cpu(&r.ctx, &p, &r.io), SSG_E_TYPE);
    CHECK(!exists(tmp_path("layers/x.exr")));
    ssg_image_destroy(&im);
    ssg_image_destroy(&other);
}

/* 1 when a's modification time is at or after b's. */
static int not_older(const char *a, const char *b)
{
    struct stat sa, sb;
    if (stat(a, &sa) != 0 || stat(b, &sb) != 0)
        return 0;
    return sa.st_mtim.tv_sec > sb.st_mtim.tv_sec ||
           (sa.st_mtim.tv_sec == sb.st_mtim.tv_sec && sa.st_mtim.tv_nsec >= sb.st_mtim.tv_nsec);
}

/* The PNG is staged and renamed before the EXR, so a kill between the two renames leaves
   the new PNG beside the previous EXR, which is then older than it: a complete pair is one
   whose EXR is not older than its PNG. A frame whose PNG takes several clock ticks to write
   would show the wrong order (PNG last) as an older EXR. */
static void test_pair_order(void)
{
    struct ssg_image *im = filled(1024, 512, 3, 0.25f);
    struct run r;
    run_init(&r, tmp_path("order"), im);
    struct ssg_write_params p;
    defaults(&p, "pair");
    for (int i = 0; i < 3; i++) {
        CHECK_EQ(ssg_node_write.run_cpu(&r.ctx, &p, &r.io), SSG_OK);
        CHECK(not_older(tmp_path("order/pair.exr"), tmp_path("order/pair.png")));
    }
    ssg_image_destroy(&im);
}

int main(void)
{
    setup_tmp("test_write");
    test_descriptor();
    test_names();
    test_layers();
    test_errors();
    test_pair_order();
    return check_report();
}
