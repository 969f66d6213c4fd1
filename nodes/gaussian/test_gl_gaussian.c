/* test_gl_gaussian.c - CPU/GL parity of `gaussian` (gl_parity.h): a 1-channel step edge
 * and a 3-channel noise image, small and wide windows. Both backends sum the same taps in
 * the same order with the same weights: identical on llvmpipe (measured 0), and so is
 * the descriptor's bound. */
#include "check.h"
#include "gl_parity.h"

static struct ssg_image *noise_image(int w, int h, int channels, unsigned seed)
{
    struct ssg_image *im = ssg_image_create(w, h, channels);
    for (size_t i = 0; i < (size_t)w * h * channels; i++) {
        seed = seed * 1664525u + 1013904223u;
        im->data[i] = (float)(seed >> 8) / 16777216.0f;
    }
    return im;
}

int main(void)
{
    const struct parity_tol exact = parity_tol_of("gaussian");
    struct ssg_image *step = ssg_image_create(61, 37, 1);
    for (int y = 0; y < 37; y++)
        for (int x = 30; x < 61; x++)
            step->data[y * 61 + x] = 1.0f;
    struct ssg_binding in = {"in", step};
    const char *small[] = {"sigma=1.5"};
    parity_node("step sigma 1.5", "gaussian", &in, 1, small, 1, NULL, exact);
    const char *wide[] = {"sigma=6", "size=41"};
    parity_node("step size 41", "gaussian", &in, 1, wide, 2, NULL, exact);
    struct ssg_image *rgb = noise_image(50, 29, 3, 7);
    struct ssg_binding in3 = {"in", rgb};
    parity_node("noise rgb", "gaussian", &in3, 1, small, 1, NULL, exact);
    ssg_image_destroy(&step);
    ssg_image_destroy(&rgb);
    return check_report();
}
