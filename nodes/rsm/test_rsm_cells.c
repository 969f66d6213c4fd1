/* test_rsm_cells.c - the `rsm` node's cells (rsm.h: C = ceil(R / cell) a face side) on maps
 * whose side R is not a multiple of `cell`, so the last cell of each row and column is
 * partial:
 * - a map whose only flux is one texel in the last partial column, row or both still lights
 *   a receiver above it, by the closed form Phi / (pi^2 max(h^2, A / pi)) worked out below;
 * - the VPLs' total flux (and their CDF's total) equals the maps' for several R and cell
 *   sizes on a point light's six faces: no texel is dropped or counted twice.
 * The cell count is prepare()'s, which both backends read: a slip there passes every
 * CPU/GL parity test, so these run on the CPU. */
#include <string.h>

#include "rsm_maps.h"

static const char *const CAMERA = "camera(position=[0, 1, 4], target=[0, 1, 0])\n"
                                  "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n";

static struct ssg_scene *scene_with(const char *name, const char *light)
{
    char text[512];
    snprintf(text, sizeof text, "%s%s\n", CAMERA, light);
    return scene_from_text(name, text);
}

/* One texel (x, y) of the sun's face holds flux phi, normal up; a receiver h above its
   point, facing down, gets E / pi = Phi / pi x cos cos / (d^2 max(d^2, A / pi)) / pi with
   both cosines 1 and d = h: Phi / (pi^2 max(h^2, A / pi)). A = s^2, s = 2 half / R (the
   texel faces the light). */
static void one_texel(const struct ssg_scene *s, int res, int cell, int x, int y)
{
    struct maps m = maps_make(s, res);
    const float up[3] = {0, 1, 0}, down[3] = {0, -1, 0}, phi[3] = {0.3f, 0.2f, 0.1f};
    const float h = 0.5f;
    float p[3];
    maps_set(&m, 0, x, y, m.face[0].origin[1], up, phi, p);
    struct gbuf g = gbuf_make(s, 1, 1);
    gbuf_set(&g, 0, (const float[3]){p[0], p[1] + h, p[2]}, down);
    char cs[32];
    snprintf(cs, sizeof cs, "cell=%d", cell);
    const char *sets[] = {"samples=0", cs};
    struct ssg_image *out = rsm_run(s, &m, &g, 0, 1, sets, 2, SSG_BACKEND_CPU);
    double side = 2.0 * m.face[0].half / res, r2 = side * side / M_PI;
    double d2 = (double)h * h > r2 ? (double)h * h : r2;
    for (int c = 0; c < 3; c++) {
        double want = phi[c] / (M_PI * M_PI * d2), got = px(out, c, 0);
        if (c == 0 && !(fabs(got - want) <= 1e-5 * want))
            fprintf(stderr, "R %d cell %d, flux at texel (%d, %d) alone: red %.7g, closed "
                    "form %.7g\n", res, cell, x, y, got, want);
        CHECK_NEAR(got, want, 1e-5 * want);
    }
    ssg_image_destroy(&out);
    gbuf_free(&g);
    maps_free(&m);
}

static void test_last_partial_cell(void)
{
    struct ssg_scene *s = scene_with("rsm_partial", "directional_light(direction=[0, -1, 0])");
    if (!s)
        return;
    /* R 18, cell 4: cells of texels 0-3, ..., 12-15 and 16-17 (C = 5, not 18 / 4 = 4);
       R 10, cell 3: 0-2, 3-5, 6-8 and 9 (C = 4, not 3). */
    const int cases[][2] = {{18, 4}, {10, 3}};
    for (int i = 0; i < 2; i++) {
        int res = cases[i][0], cell = cases[i][1], last = res - 1;
        one_texel(s, res, cell, last, last);
        one_texel(s, res, cell, last, 1);
        one_texel(s, res, cell, 2, last);
        one_texel(s, res, cell, 0, 0); /* a full cell, for contrast */
    }
    ssg_scene_destroy(&s);
}

/* rsm's prepare() for maps of side res (rsm's defaults, samples 0 and `cell`) into c. */
static int consts_of(const struct ssg_scene *s, int faces, int res, int cell,
                     struct ssg_rsm_consts *c)
{
    char cs[32];
    snprintf(cs, sizeof cs, "cell=%d", cell);
    const char *sets[] = {"samples=0", cs};
    void *params = node_params(&ssg_node_rsm, sets, 2);
    struct ssg_shape in[SSG_RSM_INPUTS] = {
        [SSG_RSM_IN_POSITION] = {4, 4, 3, SSG_T_VECTOR},
        [SSG_RSM_IN_NORMAL] = {4, 4, 3, SSG_T_VECTOR},
        [SSG_RSM_IN_MAP_DEPTH] = {res, res, faces, SSG_T_LIGHTMAPS},
        [SSG_RSM_IN_MAP_NORMAL] = {res, res, 3 * faces, SSG_T_LIGHTMAPS},
        [SSG_RSM_IN_MAP_FLUX] = {res, res, 3 * faces, SSG_T_LIGHTMAPS}};
    enum ssg_err e = prepare_on(&ssg_node_rsm, s, in, params, c);
    free(params);
    CHECK_EQ(e, SSG_OK);
    return e == SSG_OK;
}

/* Every texel of the six faces non-empty, with flux and normals varying over the texels
   (so cells split into several bins); returns the maps' total flux per channel. */
static void fill_cube(struct maps *m, double total[3])
{
    total[0] = total[1] = total[2] = 0;
    for (int f = 0; f < m->faces; f++)
        for (int y = 0; y < m->res; y++)
            for (int x = 0; x < m->res; x++) {
                float n[3] = {sinf(1.3f * x + f), cosf(0.7f * y), sinf(0.9f * (x + y))};
                float ln = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) + 1e-3f;
                for (int k = 0; k < 3; k++)
                    n[k] /= ln;
                float w = 0.001f * (float)(1 + (7 * x + 3 * y + f) % 11);
                const float phi[3] = {w, 0.5f * w, 0.25f * w};
                maps_set(m, f, x, y, 1.0f + 0.01f * (float)x, n, phi, NULL);
                for (int k = 0; k < 3; k++)
                    total[k] += phi[k];
            }
}

static void test_total_flux(void)
{
    struct ssg_scene *s = scene_with("rsm_total", "point_light(position=[0, 1, 0])");
    if (!s)
        return;
    const int cases[][2] = {{10, 4}, {17, 4}, {18, 5}, {33, 8}, {20, 3}, {16, 4}};
    struct ssg_rsm_consts *c = calloc(1, sizeof *c);
    for (int i = 0; c && i < 6; i++) {
        int res = cases[i][0], cell = cases[i][1];
        struct maps m = maps_make(s, res);
        double total[3], vpl[3] = {0, 0, 0};
        fill_cube(&m, total);
        if (consts_of(s, m.faces, res, cell, c)) {
            CHECK_EQ(c->cells, (res + cell - 1) / cell);
            size_t n = (size_t)c->slots * SSG_RSM_SLOT;
            float *slots = calloc(n, sizeof(float)), *list = calloc(n, sizeof(float));
            CHECK(ssg_rsm_cells(c, m.depth->data, m.normal->data, m.flux->data, 0, c->grid_h,
                                slots));
            int count = ssg_rsm_list(c, slots, list, NULL);
            for (int v = 0; v < count; v++)
                for (int k = 0; k < 3; k++)
                    vpl[k] += list[(size_t)v * SSG_RSM_SLOT + 6 + k];
            double cdf = count > 0 ? list[(size_t)(count - 1) * SSG_RSM_SLOT + 11] : 0;
            fprintf(stderr, "R %d cell %d: %d VPLs, flux %.6f of the maps' %.6f\n", res, cell,
                    count, vpl[0], total[0]);
            for (int k = 0; k < 3; k++)
                CHECK_NEAR(vpl[k], total[k], 1e-5 * total[k]);
            CHECK_NEAR(cdf, total[0] + total[1] + total[2], 1e-5 * total[0]);
            free(slots);
            free(list);
        }
        maps_free(&m);
    }
    free(c);
    ssg_scene_destroy(&s);
}

int main(void)
{
    test_last_partial_cell();
    test_total_flux();
    return check_report();
}
