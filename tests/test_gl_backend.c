/* test_gl_backend.c - the GL backend's own contract, apart from any node's maths:
 * a shader that does not compile is reported with node, file and line and fails the run
 * (SSG_SHADER_DIR points at tests/fixtures/shaders, whose gaussian.glsl is broken at
 * line 5), and an error in a file a shader includes is reported against that file; the
 * same node then compiles from the embedded copy; images handed to a GL
 * single-node run come back as plain CPU images (no texture left behind) holding the GL
 * result; a GL run is deterministic. */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "gl_parity.h"

static int has_diag(const struct ssg_diags *d, enum ssg_err code, const char *a, const char *b)
{
    for (int i = 0; i < d->count; i++)
        if (d->items[i].code == code && strstr(d->items[i].message, a) &&
            strstr(d->items[i].message, b))
            return 1;
    return 0;
}

static struct ssg_image *ramp(int w, int h)
{
    struct ssg_image *im = ssg_image_create(w, h, 1);
    for (int i = 0; i < w * h; i++)
        im->data[i] = (float)(i % w) / (float)w;
    return im;
}

static void shader_errors_are_located(struct ssg_image *in)
{
    setenv("SSG_SHADER_DIR", "tests/fixtures/shaders", 1);
    struct ssg_binding b = {"in", in};
    const char *sets[] = {"backend=gl"};
    struct ssg_outputs out = {0};
    struct ssg_diags d = {0};
    enum ssg_err e = ssg_node_run("gaussian", &b, 1, sets, 1, NULL, &out, &d);
    ssg_diags_print(&d, stderr);
    CHECK_EQ(e, SSG_E_SHADER);
    CHECK(has_diag(&d, SSG_E_SHADER, "gaussian.glsl:5:", "node 'gaussian'"));
    CHECK(has_diag(&d, SSG_E_SHADER, "undeclared_name", "gaussian.glsl"));
    CHECK_EQ(out.count, 0);
    unsetenv("SSG_SHADER_DIR");
}

/* A shader's #include is resolved by the program builder; a compiler message about the
   included text names the included file and its own line (core/gl/gl_program.c). */
static void include_errors_are_located(struct ssg_image *in)
{
    setenv("SSG_SHADER_DIR", "tests/fixtures/shaders", 1);
    struct ssg_binding b[2] = {{"in", in}, {"depth", in}};
    const char *sets[] = {"backend=gl"};
    struct ssg_outputs out = {0};
    struct ssg_diags d = {0};
    enum ssg_err e = ssg_node_run("bilateral", b, 2, sets, 1, NULL, &out, &d);
    ssg_diags_print(&d, stderr);
    CHECK_EQ(e, SSG_E_SHADER);
    CHECK(has_diag(&d, SSG_E_SHADER, "broken_include.glsl:3:", "undeclared_in_include"));
    CHECK_EQ(out.count, 0);
    unsetenv("SSG_SHADER_DIR");
}

static void outputs_come_back_to_the_cpu(struct ssg_image *in)
{
    struct ssg_binding b = {"in", in};
    const char *sets[] = {"backend=gl", "sigma=2"};
    struct ssg_outputs a = {0}, c = {0};
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_node_run("gaussian", &b, 1, sets, 2, NULL, &a, &d), SSG_OK);
    CHECK_EQ(ssg_node_run("gaussian", &b, 1, sets, 2, NULL, &c, &d), SSG_OK);
    CHECK(in->gpu == NULL);
    CHECK(a.count == 1 && a.images[0]->gpu == NULL);
    /* a ramp blurred stays a ramp in the interior: the pixels really came back */
    CHECK_NEAR(a.images[0]->data[20 * in->width + 30], in->data[20 * in->width + 30], 1e-5);
    CHECK(a.count == 1 && c.count == 1 &&
          memcmp(a.images[0]->data, c.images[0]->data,
                 (size_t)in->width * in->height * sizeof(float)) == 0);
    ssg_outputs_release(&a);
    ssg_outputs_release(&c);
}

static void cpu_only_nodes_refuse_gl(struct ssg_image *in)
{
    struct ssg_binding b[] = {{"a", in}, {"b", in}};
    const char *sets[] = {"backend=gl"};
    struct ssg_outputs out = {0};
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_node_run("compare", b, 2, sets, 1, NULL, &out, &d), SSG_E_BACKEND);
    const char *bad[] = {"backend=vulkan"};
    CHECK_EQ(ssg_node_run("gaussian", b, 1, bad, 1, NULL, &out, &d), SSG_E_VALUE);
}

int main(void)
{
    struct ssg_image *in = ramp(64, 40);
    shader_errors_are_located(in);
    include_errors_are_located(in);
    outputs_come_back_to_the_cpu(in);
    cpu_only_nodes_refuse_gl(in);
    ssg_image_destroy(&in);
    return check_report();
}
