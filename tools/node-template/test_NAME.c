/* test_@name@.c - the `@name@` node against its definition (README.md), out = gain * src:
 * on a tiny hand-made image whose answer is exact (a power-of-two gain rounds nothing), on
 * both backends, then the GL side against the CPU's on a larger image. It runs the node
 * through its descriptor (ssg_node_run_desc), so it also runs before the node is in the
 * registry: the build's template check compiles and runs this file as instantiated from
 * tools/node-template/ (tests/CMakeLists.txt, node_template). */
#include <math.h>
#include <stdio.h>

#include "@name@.h"
#include "check.h"
#include "gl_parity.h"
#include "graph/exec.h"

/* Runs the node on `src` with the given "param=value" sets ("backend=gl" among them
   for GL); returns output `out` (owned) or NULL. */
static struct ssg_image *run(const struct ssg_image *src, const char *const *sets, int n)
{
    struct ssg_binding b[] = {{"src", src}};
    struct ssg_diags diags = {0};
    struct ssg_outputs out;
    enum ssg_err e = ssg_node_run_desc(&ssg_node_@name@, b, 1, sets, n, NULL, &out, &diags);
    if (e)
        ssg_diags_print(&diags, stderr);
    CHECK_EQ(e, SSG_OK);
    return e ? NULL : out.images[0];
}

/* A 4 x 3 image of three channels, values k / 8 (exact in float), each gain's answer
   written out by the definition and compared bit for bit, on both backends. */
static void test_analytic(void)
{
    struct ssg_image *src = ssg_image_create(4, 3, 3);
    for (int i = 0; i < 4 * 3 * 3; i++)
        src->data[i] = (float)(i - 17) / 8.0f;
    static const struct {
        const char *set; /* NULL: the default, gain 1 */
        float gain;
    } cases[] = {{NULL, 1.0f}, {"gain=4", 4.0f}, {"gain=-0.5", -0.5f}, {"gain=0", 0.0f}};
    for (int gl = 0; gl < 2; gl++)
        for (int k = 0; k < (int)(sizeof cases / sizeof cases[0]); k++) {
            const char *sets[2];
            int n = 0;
            if (cases[k].set)
                sets[n++] = cases[k].set;
            if (gl)
                sets[n++] = "backend=gl";
            struct ssg_image *out = run(src, sets, n);
            if (!out)
                continue;
            CHECK_EQ(out->channels, 3);
            int wrong = 0;
            for (int i = 0; i < 4 * 3 * 3; i++)
                wrong += out->data[i] != cases[k].gain * src->data[i];
            CHECK_EQ(wrong, 0);
            ssg_image_destroy(&out);
        }
    ssg_image_destroy(&src);
}

/* GL against the CPU on an image whose size is no multiple of the 8 x 8 work groups and a
   gain that rounds: the same bits (one multiply rounds alike on both). A method with
   transcendental functions states its tolerance here instead. */
static void test_parity(void)
{
    struct ssg_image *src = ssg_image_create(37, 29, 1);
    for (int i = 0; i < 37 * 29; i++)
        src->data[i] = sinf(0.37f * (float)i) * 3.0f;
    const char *cpu_sets[] = {"gain=1.7"}, *gl_sets[] = {"gain=1.7", "backend=gl"};
    struct ssg_image *cpu = run(src, cpu_sets, 1), *gl = run(src, gl_sets, 2);
    if (cpu && gl)
        parity_check_output("@name@", "gain=1.7", "out", cpu, gl,
                            (struct parity_tol){.border = 0, .max_abs = 0, .mean_abs = 0});
    ssg_image_destroy(&cpu);
    ssg_image_destroy(&gl);
    ssg_image_destroy(&src);
}

int main(void)
{
    test_analytic();
    test_parity();
    return check_report();
}
