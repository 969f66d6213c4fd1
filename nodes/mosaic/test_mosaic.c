/* test_mosaic.c - the `mosaic` contact sheet on constant images with known layouts: two
 * 32 x 32 images in a 64 x 32 frame, two columns, no gap, fill the halves exactly (a
 * scalar as grey, a colour as is, a vector as 0.5 + 0.5 v); a larger image is
 * area-averaged into its cell keeping its aspect ratio; labels darken a box in the cell's
 * corner and write white text in it and nowhere else; no image is an error. */
#include <unistd.h>

#include "check.h"
#include "scene_node.h"
#include "ssgraph.h"

static struct ssg_image *constant(int w, int h, int channels, const float *v)
{
    struct ssg_image *im = ssg_image_create(w, h, channels);
    for (int c = 0; c < channels; c++)
        for (int i = 0; i < w * h; i++)
            im->data[(size_t)c * w * h + i] = v[c];
    return im;
}

static float px(const struct ssg_image *im, int c, int x, int y)
{
    return im->data[((size_t)c * im->height + y) * im->width + x];
}

static struct ssg_image *sheet(const struct ssg_binding *b, int n, const char *const *sets,
                               int set_count, int w, int h, enum ssg_err want)
{
    struct ssg_frame f = {w, h, 45, 0.05f, 100, 1, 0, 0, 0};
    struct ssg_outputs out = {0};
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_node_run("mosaic", b, n, sets, set_count, &f, &out, &d), want);
    ssg_diags_print(&d, stderr);
    return want == SSG_OK ? out.images[0] : NULL;
}

static void test_halves(void)
{
    const float grey = 0.25f, red[3] = {1, 0, 0}, vec[3] = {0, 1, -1};
    struct ssg_image *a = constant(32, 32, 1, &grey), *b = constant(32, 32, 3, red);
    struct ssg_image *v = constant(32, 32, 3, vec);
    struct ssg_binding in[2] = {{"ao", a}, {"colour", b}};
    const char *sets[] = {"columns=2", "gap=0", "labels=false"};
    struct ssg_image *s = sheet(in, 2, sets, 3, 64, 32, SSG_OK);
    /* ssg_node_run types a 3-channel extra image as the first 3-channel type a port takes,
       a vector: shown as 0.5 + 0.5 v (colours keep theirs in graphs: test_graph_colour). */
    int wrong = 0;
    for (int y = 0; s && y < 32; y++)
        for (int x = 0; x < 64; x++)
            for (int c = 0; c < 3; c++)
                wrong += px(s, c, x, y) != (x < 32 ? grey : 0.5f + 0.5f * red[c]);
    CHECK_EQ(wrong, 0);
    ssg_image_destroy(&s);
    struct ssg_binding one[1] = {{"normal", v}};
    s = sheet(one, 1, sets, 3, 32, 32, SSG_OK);
    if (s)
        CHECK(px(s, 0, 5, 5) == 0.5f && px(s, 1, 5, 5) == 1.0f && px(s, 2, 5, 5) == 0.0f);
    ssg_image_destroy(&s);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
    ssg_image_destroy(&v);
}

/* A 64 x 64 checkerboard of 1 px squares into a 32 x 32 cell averages to 0.5; the aspect
   ratio keeps a 64 x 32 image 32 x 16, centred with black above and below. */
static void test_scaling(void)
{
    struct ssg_image *chk = ssg_image_create(64, 64, 1), *wide = ssg_image_create(64, 32, 1);
    for (int i = 0; i < 64 * 64; i++)
        chk->data[i] = (float)((i % 64 + i / 64) % 2);
    for (int i = 0; i < 64 * 32; i++)
        wide->data[i] = 1.0f;
    const char *sets[] = {"gap=0", "labels=false"};
    struct ssg_binding b1[1] = {{"checker", chk}}, b2[1] = {{"wide", wide}};
    struct ssg_image *s = sheet(b1, 1, sets, 2, 32, 32, SSG_OK);
    double mean = 0;
    for (int i = 0; s && i < 32 * 32; i++)
        mean += s->data[i] / (32.0 * 32.0);
    CHECK_NEAR(mean, 0.5, 1e-6);
    ssg_image_destroy(&s);
    s = sheet(b2, 1, sets, 2, 32, 32, SSG_OK);
    if (s) {
        CHECK(px(s, 0, 16, 2) == 0.0f && px(s, 0, 16, 29) == 0.0f); /* letterbox */
        CHECK(px(s, 0, 16, 16) == 1.0f);
    }
    ssg_image_destroy(&s);
    ssg_image_destroy(&chk);
    ssg_image_destroy(&wide);
}

static void test_labels(void)
{
    const float grey = 0.6f;
    struct ssg_image *a = constant(128, 128, 1, &grey);
    struct ssg_binding in[1] = {{"ssao", a}};
    const char *sets[] = {"gap=0", "font_size=16"};
    struct ssg_image *s = sheet(in, 1, sets, 2, 128, 128, SSG_OK);
    int dark = 0, white = 0, changed_far = 0;
    for (int y = 0; s && y < 128; y++)
        for (int x = 0; x < 128; x++) {
            float v = px(s, 0, x, y);
            int corner = x < 64 && y < 32;
            dark += corner && v < 0.25f;
            white += corner && v > 0.9f;
            changed_far += !corner && v != grey;
        }
    fprintf(stderr, "label: %d dark and %d white pixels in the corner, %d changed elsewhere\n",
            dark, white, changed_far);
    CHECK(dark > 50 && white > 20);
    CHECK_EQ(changed_far, 0);
    ssg_image_destroy(&s);
    ssg_image_destroy(&a);
}

/* In a graph a colour stays a colour: a one-cell sheet of the albedo at its own size is
   the albedo, bit for bit. */
static void test_graph_colour(void)
{
    char path[1100];
    snprintf(path, sizeof path, "%s", scene_node_path("sheet.graph")); /* a static buffer */
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f)
        return;
    char cwd[512];
    fprintf(f,
            "scene \"%s/examples/cornell.scene\"\ng = gbuffer()\n"
            "s = mosaic(gap=0, labels=false, albedo=g.albedo)\n"
            "out = write(s.out, \"m\", albedo=g.albedo)\n",
            getcwd(cwd, sizeof cwd) ? cwd : ".");
    fclose(f);
    const char *dir = scene_node_path("sheet_out");
    char out[1100];
    snprintf(out, sizeof out, "%s", dir);
    CHECK_EQ(graph_run(path, NULL, 48, 32, out), SSG_OK);
    struct ssg_image *m = exr_layer(out, "m.exr", NULL), *a = exr_layer(out, "m.exr", "albedo");
    int wrong = 0;
    for (int i = 0; m && a && i < 48 * 32 * 3; i++)
        wrong += m->data[i] != a->data[i];
    CHECK(m && a);
    CHECK_EQ(wrong, 0);
    ssg_image_destroy(&m);
    ssg_image_destroy(&a);
}

int main(void)
{
    test_graph_colour();
    test_halves();
    test_scaling();
    test_labels();
    fprintf(stderr, "expected error follows:\n");
    sheet(NULL, 0, NULL, 0, 32, 32, SSG_E_MISSING_INPUT);
    return check_report();
}
