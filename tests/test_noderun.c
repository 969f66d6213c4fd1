/* test_noderun.c - the public single-node API (ssg_node_run) through ssgraph.h alone:
 * a node runs on in-memory images, and every input problem is reported by port name with
 * its own error code. */
#include <string.h>

#include "check.h"
#include "ssgraph.h"

static struct ssg_image *filled(int w, int h, int c, float v)
{
    struct ssg_image *im = ssg_image_create(w, h, c);
    for (size_t i = 0; i < (size_t)w * h * c; i++)
        im->data[i] = v;
    return im;
}

static int mentions(const struct ssg_diags *d, const char *text)
{
    return d->count > 0 && strstr(d->items[0].message, text) != NULL;
}

int main(void)
{
    struct ssg_image *depth = filled(16, 8, 1, 2.0f), *normal = filled(16, 8, 3, 0.0f);
    struct ssg_image *ao = filled(16, 8, 1, 0.5f), *rgb = filled(16, 8, 3, 0.25f);
    struct ssg_outputs out;
    struct ssg_diags d = {0};

    /* a working run: bilateral of a constant image is that constant, same size (out2, of
       the unconnected in2, comes back too) */
    struct ssg_binding ok[] = {{"in", ao}, {"depth", depth}};
    const char *sets[] = {"size=5"};
    CHECK_EQ(ssg_node_run("bilateral", ok, 2, sets, 1, NULL, &out, &d), SSG_OK);
    CHECK_EQ(out.count, 2);
    CHECK(out.count == 2 && strcmp(out.names[0], "out") == 0 &&
          strcmp(out.names[1], "out2") == 0);
    if (out.count == 2) {
        CHECK_EQ(out.images[0]->width, 16);
        CHECK_NEAR(out.images[0]->data[5 * 16 + 7], 0.5, 1e-6);
    }
    ssg_outputs_release(&out);
    CHECK_EQ(out.count, 0);

    /* a node without frame-sized outputs needs no frame */
    memset(&d, 0, sizeof d);
    CHECK_EQ(ssg_node_run("halton", NULL, 0, NULL, 0, NULL, &out, &d), SSG_OK);
    CHECK(out.count == 2 && out.images[0]->width == 16 && out.images[0]->height == 1);
    ssg_outputs_release(&out);

    memset(&d, 0, sizeof d);
    CHECK_EQ(ssg_node_run("bilaterl", ok, 2, NULL, 0, NULL, &out, &d), SSG_E_UNKNOWN_NODE);

    memset(&d, 0, sizeof d);
    struct ssg_binding unknown[] = {{"in", ao}, {"depth", depth}, {"dpeth", depth}};
    CHECK_EQ(ssg_node_run("bilateral", unknown, 3, NULL, 0, NULL, &out, &d),
             SSG_E_UNKNOWN_PORT);
    CHECK(mentions(&d, "'dpeth'"));

    memset(&d, 0, sizeof d);
    struct ssg_binding missing[] = {{"in", ao}};
    CHECK_EQ(ssg_node_run("bilateral", missing, 1, NULL, 0, NULL, &out, &d),
             SSG_E_MISSING_INPUT);
    CHECK(mentions(&d, "'depth'"));

    memset(&d, 0, sizeof d);
    struct ssg_binding channels[] = {{"in", ao}, {"depth", rgb}};
    CHECK_EQ(ssg_node_run("bilateral", channels, 2, NULL, 0, NULL, &out, &d),
             SSG_E_CHANNELS);
    CHECK(mentions(&d, "'depth'"));

    memset(&d, 0, sizeof d);
    const char *bad_set[] = {"size=4000"};
    CHECK_EQ(ssg_node_run("bilateral", ok, 2, bad_set, 1, NULL, &out, &d), SSG_E_RANGE);
    CHECK_EQ(out.count, 0);

    memset(&d, 0, sizeof d);
    CHECK_EQ(ssg_node_run("gbuffer", NULL, 0, NULL, 0, NULL, &out, &d), SSG_E_SCENE);

    ssg_image_destroy(&depth);
    ssg_image_destroy(&normal);
    ssg_image_destroy(&ao);
    ssg_image_destroy(&rgb);
    CHECK(depth == NULL);
    return check_report();
}
