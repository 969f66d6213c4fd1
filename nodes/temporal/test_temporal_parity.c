/* test_temporal_parity.c - the `temporal` node's GL side against its CPU kernel, and the
 * CPU kernel against itself over thread counts, on a frame that exercises every branch:
 * fractional motion vectors reaching outside the image, depth and normal mismatches on
 * some taps, background pixels, a history far outside the neighbourhood on some pixels
 * (the clamp), 1 and 1 + 3 channels, 3 channels alone, and history_reset. */
#include <omp.h>

#include "gl_parity.h"
#include "temporal_test.h"

/* A frame of w x h: in (ch channels) and history in [0, 1) with a tenth of the history
   stale (+-4), in2 and history2 likewise, length 0 .. 40, motion up to +-3 px with the
   previous depth 0 .. 10% off, every 23rd pixel background, normals tilted by up to
   about 35 degrees between frames. */
static struct tframe random_frame(int w, int h, int ch, int in2, int normals)
{
    struct tframe f = tframe_make(w, h, ch, in2, normals);
    const size_t n = (size_t)w * (size_t)h;
    for (size_t i = 0; i < n; i++) {
        uint32_t k = (uint32_t)i;
        for (int c = 0; c < ch; c++) {
            ssg_image_plane(f.in, c)[i] = thash(1u, k, (uint32_t)c);
            float stale = thash(9u, k, (uint32_t)c) < 0.1f ? 8.0f * thash(8u, k, 0u) - 4.0f
                                                           : 0.0f;
            ssg_image_plane(f.hist, c)[i] = thash(2u, k, (uint32_t)c) + stale;
        }
        for (int c = 0; in2 && c < 3; c++) {
            ssg_image_plane(f.in2, c)[i] = thash(3u, k, (uint32_t)c);
            ssg_image_plane(f.hist2, c)[i] = thash(4u, k, (uint32_t)c);
        }
        f.len->data[i] = floorf(41.0f * thash(5u, k, 0u));
        float d = i % 23 == 0 ? 0.0f : 1.0f + 3.0f * thash(6u, k, 0u);
        f.depth->data[i] = d;
        f.pdepth->data[i] = i % 29 == 0 ? 0.0f : d * (1.0f + 0.1f * thash(6u, k, 1u));
        ssg_image_plane(f.motion, 0)[i] = 6.0f * thash(7u, k, 0u) - 3.0f;
        ssg_image_plane(f.motion, 1)[i] = 6.0f * thash(7u, k, 1u) - 3.0f;
        ssg_image_plane(f.motion, 2)[i] = d;
        for (int c = 0; normals && c < 2; c++) {
            ssg_image_plane(f.normal, c)[i] = 0.4f * thash(10u, k, (uint32_t)c) - 0.2f;
            ssg_image_plane(f.pnormal, c)[i] = 0.8f * thash(11u, k, (uint32_t)c) - 0.4f;
        }
    }
    return f;
}

static int same_bytes(const struct ssg_image *a, const struct ssg_image *b)
{
    size_t n = sizeof(float) * (size_t)a->width * (size_t)a->height * (size_t)a->channels;
    return a->channels == b->channels && memcmp(a->data, b->data, n) == 0;
}

/* 160 x 131 (more rows than one band, a row longer than one chunk): 1, 2 and 3 threads
   give the same bytes in every output. */
static void test_threads(void)
{
    struct tframe f = random_frame(160, 131, 1, 1, 1);
    struct tresult ref, r;
    omp_set_num_threads(1);
    if (trun(&f, NULL, 0, 0, 0, &ref))
        return;
    for (int t = 2; t <= 3; t++) {
        omp_set_num_threads(t);
        if (trun(&f, NULL, 0, 0, 0, &r))
            continue;
        CHECK(same_bytes(ref.out, r.out));
        CHECK(same_bytes(ref.out2, r.out2));
        CHECK(same_bytes(ref.length, r.length));
        tresult_free(&r);
    }
    int restarted = 0, kept = 0;
    for (int i = 0; i < 160 * 131; i++)
        restarted += ref.length->data[i] == 1.0f, kept += ref.length->data[i] > 1.0f;
    CHECK(restarted > 1000 && kept > 1000); /* the frame exercises both branches */
    omp_set_num_threads(2);
    tresult_free(&ref);
    tframe_free(&f);
}

/* One configuration on both backends: every output within the stated tolerances. */
static void parity(const char *label, int ch, int in2, int normals, int reset,
                   struct parity_tol tol)
{
    struct tframe f = random_frame(77, 61, ch, in2, normals);
    struct tresult cpu, gl;
    if (trun(&f, NULL, 0, reset, 0, &cpu) || trun(&f, NULL, 0, reset, 1, &gl)) {
        tframe_free(&f);
        return;
    }
    parity_check_output("temporal", label, "out", cpu.out, gl.out, tol);
    parity_check_output("temporal", label, "out2", cpu.out2, gl.out2, tol);
    parity_check_output("temporal", label, "length", cpu.length, gl.length, tol);
    tresult_free(&cpu);
    tresult_free(&gl);
    tframe_free(&f);
}

int main(void)
{
    test_threads();
    const struct parity_tol exact = parity_tol_of("temporal"); /* 0: bit-exact */
    parity("1+3 channels, normals", 1, 1, 1, 0, exact);
    parity("1 channel", 1, 0, 0, 0, exact);
    parity("3 channels, normals", 3, 0, 1, 0, exact);
    parity("history_reset", 1, 1, 1, 1, exact);
    return check_report();
}
