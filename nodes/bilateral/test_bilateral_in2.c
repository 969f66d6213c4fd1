/* test_bilateral_in2.c - the `bilateral` node's second image: in2 is filtered with in's
 * weights into out2, bit for bit what a second node on in2 gives, for 1 + 3 and 3 + 1
 * channels, full and separable; out is unchanged by the ride-along; unconnected, out2 is
 * all 0; an in2 of another size is refused. */
#include <string.h>

#include "bilateral_inputs.h"
#include "graph/node.h"

/* in2 is filtered with in's weights: out2 is bit for bit a second node's output on in2
   (same depth and normals), for 1 + 3 and 3 + 1 channels, full and separable; out is
   unchanged by the ride-along; unconnected, out2 is all 0. */
static void test_second_image(void)
{
    enum { W = 70, H = 41 };
    struct images a = make(W, H, 1), c = make(W, H, 3);
    for (size_t o = 0; o < (size_t)W * H; o++) {
        a.in->data[o] = (float)uniform01();
        for (int ch = 0; ch < 3; ch++)
            c.in->data[(size_t)ch * W * H + o] = (float)uniform01();
        a.depth->data[o] = c.depth->data[o] = o % 13 == 0 ? 0.0f : (float)(1 + uniform01());
        set_normal(a.normal, o, uniform01() - 0.5, uniform01() - 0.5, 1.0);
        for (int ch = 0; ch < 3; ch++)
            c.normal->data[(size_t)ch * W * H + o] = a.normal->data[(size_t)ch * W * H + o];
    }
    const char *full[] = {"size=9"}, *sep[] = {"size=9", "separable=true"};
    for (int form = 0; form < 2; form++) {
        const char *const *sets = form ? sep : full;
        for (int order = 0; order < 2; order++) {
            const struct images *first = order ? &c : &a, *second = order ? &a : &c;
            struct ssg_binding b[4] = {{"in", first->in}, {"depth", a.depth},
                                       {"normal", a.normal}, {"in2", second->in}};
            struct ssg_diags d = {0};
            struct ssg_outputs out;
            CHECK_EQ(ssg_node_run("bilateral", b, 4, sets, form + 1, NULL, &out, &d), SSG_OK);
            struct ssg_image *alone1 = filter(first, 1, sets, form + 1);
            struct ssg_image *alone2 = filter(second, 1, sets, form + 1);
            if (alone1 && alone2 && out.images[0] && out.images[1]) {
                size_t n1 = sizeof(float) * W * H * (size_t)first->in->channels;
                size_t n2 = sizeof(float) * W * H * (size_t)second->in->channels;
                CHECK(memcmp(out.images[0]->data, alone1->data, n1) == 0);
                CHECK(memcmp(out.images[1]->data, alone2->data, n2) == 0);
                CHECK(memcmp(alone2->data, second->in->data, n2) != 0); /* it did filter */
            }
            ssg_image_destroy(&out.images[0]);
            ssg_image_destroy(&out.images[1]);
            ssg_image_destroy(&alone1);
            ssg_image_destroy(&alone2);
        }
    }
    struct ssg_binding b[3] = {{"in", c.in}, {"depth", a.depth}, {"normal", a.normal}};
    struct ssg_diags d = {0};
    struct ssg_outputs out;
    CHECK_EQ(ssg_node_run("bilateral", b, 3, full, 1, NULL, &out, &d), SSG_OK);
    int nonzero = 0;
    for (size_t i = 0; out.images[1] && i < (size_t)W * H * 3; i++)
        nonzero += out.images[1]->data[i] != 0.0f;
    CHECK(out.images[1] && out.images[1]->channels == 3 && nonzero == 0);
    ssg_image_destroy(&out.images[0]);
    ssg_image_destroy(&out.images[1]);
    struct ssg_image *small = ssg_image_create(W - 1, H, 1);
    struct ssg_binding bad[3] = {{"in", a.in}, {"depth", a.depth}, {"in2", small}};
    CHECK_EQ(ssg_node_run("bilateral", bad, 3, full, 1, NULL, &out, &d), SSG_E_SIZE);
    ssg_image_destroy(&small);
    release(&a);
    release(&c);
}

int main(void)
{
    test_second_image();
    return check_report();
}
