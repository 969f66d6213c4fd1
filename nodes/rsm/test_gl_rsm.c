/* test_gl_rsm.c - CPU/GL parity of `rsm` (gl_parity.h's check) on maps made by hand
 * (rsm_maps.h): a directional light's disc with varied normals and flux, and a point
 * light's cube with scattered texels on every face; the exact VPL sum and stratified
 * draws, with and without albedo, with min_distance, several cell sizes, and maps with
 * more VPLs than one llvmpipe shader loop may walk; with visibility on among boxes (every
 * term tested, and the control variate over every 8th draw).
 *
 * Where differences come from: every pass does rsm_vpl.c's and rsm_cpu.c's operations in
 * their order without fused multiply-adds (`precise`), and the faces and offsets are the
 * CPU's floats; on llvmpipe the outputs are the same bits. A GPU whose division or square
 * root rounds otherwise moves a VPL's position or a CDF entry by an ulp, which can move a
 * stratified draw to the neighbouring VPL (a different, equally valid term) and needs
 * its own bound; the descriptor's is 0, as measured here on llvmpipe in every case. */
#include <string.h>

#include "gl_parity.h"
#include "rsm_maps.h"

static const char *const CAMERA = "camera(position=[0, 1, 4], target=[0, 1, 0])\n"
                                  "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n";

/* Receivers over the floor and in the room, facing every way but mostly down. */
static void receivers(struct gbuf *g)
{
    for (int i = 0; i < g->w * g->h; i++) {
        if (i % 7 == 3)
            continue; /* background */
        float t = (float)i;
        float x[3] = {1.6f * sinf(0.37f * t), 0.1f + 1.7f * (0.5f + 0.5f * cosf(0.23f * t)),
                      1.5f * sinf(0.61f * t + 1)};
        float n[3] = {sinf(1.3f * t), -0.6f + 0.5f * cosf(0.7f * t), cosf(2.1f * t)};
        gbuf_set(g, i, x, n);
    }
}

/* A disc of varied flux and normals on the directional light's face. */
static void disc(struct maps *m)
{
    const struct ssg_lightmap_face *f = &m->face[0];
    float s = 2.0f * f->half / (float)m->res;
    for (int y = 0; y < m->res; y++)
        for (int x = 0; x < m->res; x++) {
            float p[3];
            ssg_lightmap_texel_point(f, m->res, x, y, f->origin[1], p);
            if (p[0] * p[0] + p[2] * p[2] > 1.5f * 1.5f)
                continue;
            float w = 1.0f + 0.8f * sinf(3.0f * p[0]) * cosf(5.0f * p[2]);
            float n[3] = {0.9f * sinf(7.0f * p[2]), 1, 0.8f * cosf(4.0f * p[0])};
            float nl = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (int k = 0; k < 3; k++)
                n[k] /= nl;
            const float phi[3] = {w * s * s, 0.6f * w * s * s, 0.3f * w * s * s};
            maps_set(m, 0, x, y, f->origin[1] + 0.1f * sinf(9.0f * p[0]), n, phi, NULL);
        }
}

/* Texels scattered over the six faces of a point light's cube, depth 0.5 to 2. */
static void cube(struct maps *m)
{
    for (int f = 0; f < 6; f++)
        for (int y = 0; y < m->res; y++)
            for (int x = 0; x < m->res; x++) {
                unsigned h = (unsigned)(f * 7919 + y * 131 + x * 17) * 2654435761u;
                if ((h >> 28) > 9)
                    continue;
                float t = (float)(h >> 8) / 16777216.0f;
                float n[3] = {sinf(11 * t) - m->face[f].axis[0],
                              cosf(13 * t) - m->face[f].axis[1],
                              sinf(17 * t + 2) - m->face[f].axis[2]};
                float nl = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                for (int k = 0; k < 3; k++)
                    n[k] /= nl;
                const float phi[3] = {0.01f * t, 0.02f * (1 - t), 0.005f};
                maps_set(m, f, x, y, 0.5f + 1.5f * t, n, phi, NULL);
            }
}

static void run_case_at(const struct ssg_scene *s, const struct maps *m, const struct gbuf *g,
                        const char *label, int albedo, int frame, const char *const *sets,
                        int set_count, struct parity_tol tol)
{
    struct ssg_image *cpu = rsm_run_at(s, m, g, albedo, 7, frame, sets, set_count,
                                       SSG_BACKEND_CPU);
    struct ssg_image *gl = rsm_run_at(s, m, g, albedo, 7, frame, sets, set_count,
                                      SSG_BACKEND_GL);
    double peak = 0;
    for (size_t i = 0; i < 3 * (size_t)g->w * g->h; i++)
        peak = cpu->data[i] > peak ? cpu->data[i] : peak;
    CHECK(peak > 0); /* the case does reach its receivers */
    parity_check_output("rsm", label, "out", cpu, gl, tol);
    ssg_image_destroy(&cpu);
    ssg_image_destroy(&gl);
}

static void run_case(const struct ssg_scene *s, const struct maps *m, const struct gbuf *g,
                     const char *label, int albedo, const char *const *sets, int set_count,
                     struct parity_tol tol)
{
    run_case_at(s, m, g, label, albedo, 0, sets, set_count, tol);
}

/* A case's scene (CAMERA's floor plus `extra`), its maps and its receivers. */
struct setup {
    struct ssg_scene *s;
    struct maps m;
    struct gbuf g;
    int made; /* maps and receivers made */
};

/* The scene; 0 when it does not load (scene_from_text has said why). */
static int setup_scene(struct setup *u, const char *name, const char *extra)
{
    char text[1024];
    snprintf(text, sizeof text, "%s%s", CAMERA, extra);
    *u = (struct setup){.s = scene_from_text(name, text)};
    return u->s != NULL;
}

/* Maps of side res filled by fill, and a w x h G-buffer of receivers(), replacing any made
   before. */
static void setup_maps(struct setup *u, int res, void (*fill)(struct maps *), int w, int h)
{
    if (u->made) {
        gbuf_free(&u->g);
        maps_free(&u->m);
    }
    u->m = maps_make(u->s, res);
    fill(&u->m);
    u->g = gbuf_make(u->s, w, h);
    receivers(&u->g);
    u->made = 1;
}

static void setup_free(struct setup *u)
{
    if (u->made) {
        gbuf_free(&u->g);
        maps_free(&u->m);
    }
    ssg_scene_destroy(&u->s);
}

static void test_disc(void)
{
    struct setup u;
    if (!setup_scene(&u, "gl_rsm_sun", "directional_light(direction=[0.3, -1, 0.2])\n"))
        return;
    setup_maps(&u, 64, disc, 24, 16);
    const struct parity_tol tol = parity_tol_of("rsm");
    const char *exact[] = {"samples=0", "cell=1", "min_distance=0.3"};
    run_case(u.s, &u.m, &u.g, "disc exact", 1, exact, 3, tol);
    const char *drawn[] = {"samples=16", "cell=2"};
    run_case(u.s, &u.m, &u.g, "disc 16 draws", 0, drawn, 2, tol);
    const char *coarse[] = {"samples=5", "cell=8", "min_distance=0.2"};
    run_case(u.s, &u.m, &u.g, "disc 5 draws cell 8", 1, coarse, 3, tol);
    const char *turned[] = {"samples=16", "cell=2", "turn=true"}; /* frame 7's own tile */
    run_case_at(u.s, &u.m, &u.g, "disc 16 draws turned, frame 7", 0, 7, turned, 3, tol);
    setup_free(&u);
}

static void test_cube(void)
{
    struct setup u;
    if (!setup_scene(&u, "gl_rsm_point", "point_light(position=[0.2, 1.2, -0.1])\n"))
        return;
    setup_maps(&u, 20, cube, 24, 16);
    const struct parity_tol tol = parity_tol_of("rsm");
    const char *exact[] = {"samples=0", "cell=3"};
    run_case(u.s, &u.m, &u.g, "cube exact", 1, exact, 2, tol);
    const char *drawn[] = {"samples=24", "cell=3"};
    run_case(u.s, &u.m, &u.g, "cube 24 draws", 1, drawn, 2, tol);
    const char *fine[] = {"samples=64", "cell=1", "min_distance=0.5"};
    run_case(u.s, &u.m, &u.g, "cube 64 draws cell 1", 0, fine, 3, tol);
    /* More slots and VPLs than llvmpipe lets one shader loop walk (65535 iterations):
       the list and the exact sum run in several dispatches (rsm_gl.c) */
    setup_maps(&u, 192, cube, 12, 8);
    const char *big[] = {"samples=0", "cell=2"};
    run_case(u.s, &u.m, &u.g, "cube 192 exact cell 2", 1, big, 2, tol);
    const char *big_drawn[] = {"samples=32", "cell=2"};
    run_case(u.s, &u.m, &u.g, "cube 192 32 draws cell 2", 1, big_drawn, 2, tol);
    setup_free(&u);
}

/* Visibility on: the point light's cube among two boxes and a wall, whose distance field
   (scene/distance.h) the trace reads on both backends; every term tested (exact, and
   vis_draws=0) and the control variate. The boxes do shadow: the CPU's output moves. */
static void test_occluded(void)
{
    struct setup u;
    if (!setup_scene(&u, "gl_rsm_occluded",
                     "point_light(position=[0.2, 1.2, -0.1])\n"
                     "box(center=[0.5, 0.5, 0.3], size=[0.5, 1, 0.4], rotate=[0, 20, 0])\n"
                     "box(center=[-0.7, 1.2, -0.4], size=[0.4, 0.4, 0.4])\n"
                     "plane(center=[0, 1, -1.2], normal=[0, 0, 1], size=[3, 0, 2])\n"))
        return;
    setup_maps(&u, 20, cube, 24, 16);
    const struct parity_tol tol = parity_tol_of("rsm");
    const char *exact[] = {"samples=0", "cell=3", "visibility=true"};
    run_case(u.s, &u.m, &u.g, "occluded exact", 1, exact, 3, tol);
    const char *each[] = {"samples=24", "cell=3", "visibility=true", "vis_draws=0"};
    run_case(u.s, &u.m, &u.g, "occluded 24 draws each tested", 0, each, 4, tol);
    const char *tested[] = {"samples=64", "cell=1", "min_distance=0.3", "visibility=true",
                            "vis_draws=8", "vis_start=2.5"};
    run_case(u.s, &u.m, &u.g, "occluded 64 draws 8 tested", 1, tested, 6, tol);
    struct ssg_image *on = rsm_run(u.s, &u.m, &u.g, 0, 7, exact, 3, SSG_BACKEND_CPU);
    struct ssg_image *off = rsm_run(u.s, &u.m, &u.g, 0, 7, exact, 2, SSG_BACKEND_CPU);
    int moved = 0;
    for (size_t i = 0; i < 3 * (size_t)u.g.w * u.g.h; i++)
        moved += on->data[i] < off->data[i];
    CHECK(moved > u.g.w * u.g.h / 4); /* a quarter of the receivers lose light at least */
    ssg_image_destroy(&on);
    ssg_image_destroy(&off);
    setup_free(&u);
}

int main(void)
{
    test_disc();
    test_cube();
    test_occluded();
    return check_report();
}
