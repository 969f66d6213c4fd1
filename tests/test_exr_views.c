/* test_exr_views.c - the library side of EXR metadata, depth and views (io/imageio.h,
 * ssgraph.h; docs/exr.md), on tiny images with known values:
 *  - a staged EXR with a struct ssg_exr_meta reads back through ssg_exr_meta_read (the
 *    numbers; strings are the shell test's, tests/test_exr_meta.sh); a file without it is
 *    foreign (found 0), ssg_exr_frame_read leaves the frame alone then;
 *  - the layer depth is read back as `depth` from its bare Z, and the main image beside it
 *    keeps its 3 channels;
 *  - ssg_exr_views_join names the second view's channels layer.VIEW.channel, which read
 *    back as `right`, `ao.right` and `depth.right`; views of different sizes are refused;
 *  - ssg_stereo_join makes NAME.exr and NAME_VIEW.png and removes the eye folders.
 * Scratch files go to $SSG_TMP. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "scratch.h"
#include "io/imageio.h"


static struct ssg_image *filled(int w, int h, int channels, float base)
{
    struct ssg_image *im = ssg_image_create(w, h, channels);
    for (int i = 0; i < w * h * channels; i++)
        im->data[i] = base + 0.25f * (float)i;
    return im;
}

/* Stages and commits an EXR of a colour main image, ao and depth, all offset by base. */
static void write_view(const char *path, float base, const struct ssg_exr_meta *meta, int w)
{
    struct ssg_image *rgb = filled(w, 3, 3, base), *ao = filled(w, 3, 1, base + 100),
                     *depth = filled(w, 3, 1, base + 200);
    struct ssg_exr_layer layers[] = {{NULL, rgb, SSG_LAYER_COLOR},
                                     {"ao", ao, SSG_LAYER_SCALAR},
                                     {"depth", depth, SSG_LAYER_SCALAR}};
    struct ssg_diags d = {0};
    struct ssg_tmp t;
    CHECK_EQ(ssg_exr_stage(path, layers, 3, SSG_EXR_ZIP, meta, &t, &d), SSG_OK);
    CHECK_EQ(ssg_tmp_commit(&t, 1, &d), SSG_OK);
    ssg_image_destroy(&rgb);
    ssg_image_destroy(&ao);
    ssg_image_destroy(&depth);
}

/* Reads layer of path and checks its channel count and first value. */
static void check_read(const char *path, const char *layer, int channels, float first)
{
    struct ssg_diags d = {0};
    struct ssg_image *im = NULL;
    CHECK_EQ(ssg_image_read(path, layer, &im, &d), SSG_OK);
    if (!im)
        return;
    CHECK_EQ(im->channels, channels);
    CHECK_NEAR(im->data[0], first, 0);
    ssg_image_destroy(&im);
}

static struct ssg_exr_meta meta_of(float x)
{
    static const char *const sets[] = {"ao.radius=0.3"};
    struct ssg_exr_meta m = {.has_camera = 1, .position = {x, 1, 3}, .target = {x, 1, 0},
                             .up = {0, 1, 0}, .fov_y = 33, .near_z = 0.5f, .far_z = 9,
                             .width = 4, .height = 3, .guard = 2, .seed = 1ull << 40,
                             .graph = "g.graph", .sets = sets, .set_count = 1};
    for (int i = 0; i < 16; i++)
        m.world_to_camera[i] = m.world_to_ndc[i] = (float)i + x;
    return m;
}

static void test_meta_and_depth(void)
{
    const char *path = tmp_path("meta.exr");
    struct ssg_exr_meta m = meta_of(0.5f), back;
    write_view(path, 0, &m, 4);
    struct ssg_diags d = {0};
    int found = 0;
    CHECK_EQ(ssg_exr_meta_read(path, &back, &found, &d), SSG_OK);
    CHECK_EQ(found, 1);
    CHECK_EQ(back.has_camera, 1);
    CHECK_NEAR(back.fov_y, 33, 0);
    CHECK_NEAR(back.near_z, 0.5, 0);
    CHECK_NEAR(back.far_z, 9, 0);
    CHECK_NEAR(back.position[0], 0.5, 0);
    CHECK_NEAR(back.world_to_ndc[15], 15.5, 0);
    CHECK_EQ(back.width, 4);
    CHECK_EQ(back.guard, 2);
    CHECK(back.seed == 1ull << 40);
    struct ssg_frame f = SSG_FRAME_DEFAULTS;
    char spec[1100];
    snprintf(spec, sizeof spec, "%s:ao", path);
    CHECK_EQ(ssg_exr_frame_read(spec, &f), 1);
    CHECK_NEAR(f.fov_y, 33, 0);
    check_read(path, NULL, 3, 0);        /* R,G,B; Z is the depth */
    check_read(path, "depth", 1, 200);   /* the bare Z */
    check_read(path, "ao", 1, 100);
    /* a file without the metadata is foreign */
    const char *plain = tmp_path("plain.exr");
    write_view(plain, 0, NULL, 4);
    CHECK_EQ(ssg_exr_meta_read(plain, &back, &found, &d), SSG_OK);
    CHECK_EQ(found, 0);
    f = SSG_FRAME_DEFAULTS;
    CHECK_EQ(ssg_exr_frame_read(plain, &f), 0);
    CHECK_NEAR(f.fov_y, SSG_DEFAULT_FOV_Y, 0);
    CHECK_EQ(ssg_exr_frame_read(tmp_path("missing.exr"), &f), 0);
}

static void test_views(void)
{
    const char *left = tmp_path("left.exr"), *right = tmp_path("right.exr");
    struct ssg_exr_meta ml = meta_of(-1), mr = meta_of(1);
    write_view(left, 0, &ml, 4);
    write_view(right, 1000, &mr, 4);
    const char *views[] = {"left", "right"}, *files[] = {left, right};
    const char *both = tmp_path("both.exr");
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_exr_views_join(both, views, files, 2, &d), SSG_OK);
    check_read(both, NULL, 3, 0);
    check_read(both, "right", 3, 1000);
    check_read(both, "ao.right", 1, 1100);
    check_read(both, "depth", 1, 200);
    check_read(both, "depth.right", 1, 1200);
    struct ssg_exr_meta back;
    int found = 0;
    CHECK_EQ(ssg_exr_meta_read(both, &back, &found, &d), SSG_OK);
    CHECK_NEAR(back.position[0], -1, 0); /* the default view's camera */
    /* views of different sizes */
    const char *narrow = tmp_path("narrow.exr");
    write_view(narrow, 0, &mr, 2);
    files[1] = narrow;
    struct ssg_diags d2 = {0};
    CHECK_EQ(ssg_exr_views_join(tmp_path("bad.exr"), views, files, 2, &d2), SSG_E_SIZE);
    CHECK(strstr(d2.items[0].file, "narrow.exr") != NULL);
    CHECK(access(tmp_path("bad.exr"), F_OK) != 0);
}

static void test_stereo_join(void)
{
    const char *dirs[] = {tmp_path(".eye-l"), tmp_path(".eye-r")};
    const char *views[] = {"left", "right"};
    char exr[2][1100], png[2][1100];
    for (int k = 0; k < 2; k++) {
        mkdir(dirs[k], 0777);
        snprintf(exr[k], sizeof exr[k], "%s/x.exr", dirs[k]);
        snprintf(png[k], sizeof png[k], "%s/x.png", dirs[k]);
        write_view(exr[k], (float)k, NULL, 4);
        struct ssg_image *im = filled(4, 3, 3, 0);
        struct ssg_diags d = {0};
        CHECK_EQ(ssg_png_write(png[k], im, SSG_TONEMAP_CLAMP, 0, &d), SSG_OK);
        ssg_image_destroy(&im);
    }
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_stereo_join(tmp_path("joined"), dirs, views, 2, NULL, NULL, &d), SSG_OK);
    CHECK(access(tmp_path("joined/x.exr"), F_OK) == 0);
    CHECK(access(tmp_path("joined/x_left.png"), F_OK) == 0);
    CHECK(access(tmp_path("joined/x_right.png"), F_OK) == 0);
    CHECK(access(dirs[0], F_OK) != 0 && access(dirs[1], F_OK) != 0);
}

int main(void)
{
    setup_tmp("test_exr_views");
    test_meta_and_depth();
    test_views();
    test_stereo_join();
    return check_report();
}
