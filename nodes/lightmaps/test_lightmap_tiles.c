/* test_lightmap_tiles.c - a directional light's map cut into tiles (lightmaps and
 * direct_light `tiles`, lightmap.h) is the map of side tiles x resolution, texel for
 * texel: tile (tx, ty)'s texel (x, y) has the ray of texel (tx R + x, ty R + y) of the
 * whole map. So, on the table scene under its own sun:
 * - the tiled faces cover the untiled face exactly (corners, halves, shared plane);
 * - lightmaps with resolution R and tiles T gives the depths of resolution T R and tiles 1,
 *   reassembled, on the CPU and on GL, fitted to the scene and to the view (a texel whose
 *   centre lies on a triangle's edge may go either way: a bound on those);
 * - direct_light reading the tiled maps with the same tiles gives what it gives on the
 *   whole map of T R (the lookup reads across the tiles' borders as within one map);
 * - lightmaps with normal and flux unbound (on demand: a direct_light's maps) draws the
 *   same depths;
 * - the two nodes' tiles apart is refused when the graph loads, with both counts named. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "graph/graph.h"
#include "light_maps.h"
#include "scratch.h"

enum { W = 80, H = 60, R = 32, T = 4 };
static const struct ssg_frame FRAME = {W, H, 40, 0.05f, 20, 1, 0, 0, 0};

static struct ssg_scene *table(void)
{
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load_lit("examples/table.scene", NULL, 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    return s;
}

/* The tiles' corners and halves against the whole face's. */
static void faces_cover_the_map(const struct ssg_scene *s)
{
    static struct ssg_lightmap_face whole[SSG_LIGHTMAP_FACES_MAX], tiled[SSG_LIGHTMAP_FACES_MAX];
    const struct ssg_lightmap_sources one = {1, 0, 1}, cut = {1, 0, T};
    CHECK_EQ(ssg_lightmap_faces(s, one, whole, SSG_LIGHTMAP_FACES_MAX), 1);
    CHECK_EQ(ssg_lightmap_face_count(s, cut), T * T);
    CHECK_EQ(ssg_lightmap_faces(s, cut, tiled, SSG_LIGHTMAP_FACES_MAX), T * T);
    const struct ssg_lightmap_face *w = &whole[0];
    for (int t = 0; t < T * T; t++) {
        const struct ssg_lightmap_face *f = &tiled[t];
        CHECK(f->ortho && f->light == w->light);
        CHECK(fabsf(f->half - w->half / T) <= 1e-6f * w->half);
        /* tile (tx, ty)'s first texel is texel (tx R, ty R) of the whole map of T R */
        float a[3], b[3];
        ssg_lightmap_texel_point(f, R, 0, 0, 0.0f, a);
        ssg_lightmap_texel_point(w, T * R, (t % T) * R, (t / T) * R, 0.0f, b);
        for (int k = 0; k < 3; k++)
            CHECK(fabsf(a[k] - b[k]) <= 1e-5f * w->half);
    }
}

/* Share of texels of the whole map (resolution T R) whose depth the tiled one (T x T faces
   of R) does not match within tol, the tiled one read through ssg_lightmap_tile_texel. */
static double tiles_apart(const struct ssg_image *whole, const struct ssg_image *tiled,
                          float tol, size_t *covered)
{
    size_t off = 0;
    *covered = 0;
    for (int y = 0; y < T * R; y++)
        for (int x = 0; x < T * R; x++) {
            int tx = x, ty = y, f = ssg_lightmap_tile_texel(T, R, &tx, &ty);
            float a = whole->data[(size_t)y * T * R + x];
            float b = tiled->data[((size_t)f * R + ty) * R + tx];
            *covered += a < SSG_SHADOW_EMPTY;
            off += !(fabsf(a - b) <= tol) && !(a >= SSG_SHADOW_EMPTY && b >= SSG_SHADOW_EMPTY);
        }
    return (double)off / ((double)T * R * T * R);
}

static void maps_match(const struct ssg_scene *s, const char *fit, enum ssg_backend backend)
{
    struct ssg_image *whole[3], *tiled[3];
    const struct ssg_lightmap_sources one = {1, 0, 1}, cut = {1, 0, T};
    CHECK_EQ(maps_fit(s, &FRAME, T * R, one, fit, backend, whole), SSG_OK);
    CHECK_EQ(maps_fit(s, &FRAME, R, cut, fit, backend, tiled), SSG_OK);
    CHECK_EQ(tiled[0]->channels, T * T);
    size_t covered = 0;
    double share = tiles_apart(whole[0], tiled[0],
                               1e-4f * ssg_scene_bounding_sphere(s).radius, &covered);
    fprintf(stderr, "tiles %s %s: %.4f%% of %d texels apart, %zu see a surface\n", fit,
            backend == SSG_BACKEND_GL ? "gl" : "cpu", 100 * share, T * R * T * R, covered);
    CHECK(covered > (size_t)(T * R * T * R) / 4); /* the map does show the table */
    CHECK(share <= 0.002);
    images_free(whole, 3);
    images_free(tiled, 3);
}

/* direct_light on the tiled maps (tiles=T) against the whole map: the same light. */
static void direct_light_matches(const struct ssg_scene *s, enum ssg_backend backend)
{
    struct ssg_image *g[SSG_GBUFFER_OUTPUTS], *whole[3], *tiled[3], *a[2], *b[2];
    const struct ssg_lightmap_sources one = {1, 0, 1}, cut = {1, 0, T};
    gbuffer_of(s, &FRAME, g);
    CHECK_EQ(maps_fit(s, &FRAME, T * R, one, "view", SSG_BACKEND_CPU, whole), SSG_OK);
    CHECK_EQ(maps_fit(s, &FRAME, R, cut, "view", SSG_BACKEND_CPU, tiled), SSG_OK);
    const char *plain[] = {"fit=view", "contact=8"};
    char tiles_set[16];
    snprintf(tiles_set, sizeof tiles_set, "tiles=%d", T);
    const char *tiles[] = {"fit=view", "contact=8", tiles_set};
    CHECK_EQ(direct_of(s, &FRAME, g, whole[0], plain, 2, backend, a), SSG_OK);
    CHECK_EQ(direct_of(s, &FRAME, g, tiled[0], tiles, 3, backend, b), SSG_OK);
    double worst = 0, sum = 0, shadowed = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        worst = fmax(worst, fabs((double)a[1]->data[i] - b[1]->data[i]));
        sum += fabs((double)a[1]->data[i] - b[1]->data[i]);
        shadowed += a[1]->data[i] < 0.5f;
    }
    fprintf(stderr, "direct_light %s, tiles against the whole map: visibility max |diff| "
            "%.3g, mean %.3g, %.0f pixels in shadow\n",
            backend == SSG_BACKEND_GL ? "gl" : "cpu", worst, sum / (W * H), shadowed);
    CHECK(shadowed > W * H / 50); /* the table does shadow the floor */
    CHECK(sum / (W * H) <= 1e-5);
    CHECK(worst <= 1e-3);
    images_free(g, SSG_GBUFFER_OUTPUTS);
    images_free(whole, 3);
    images_free(tiled, 3);
    images_free(a, 2);
    images_free(b, 2);
}

/* normal and flux unbound (on demand: what the executor does when only a direct_light
   reads the maps): the depth is the same bytes as with every output drawn. */
static void depth_alone(const struct ssg_scene *s, enum ssg_backend backend)
{
    struct ssg_image *all[3];
    const struct ssg_lightmap_sources cut = {1, 0, T};
    CHECK_EQ(maps_fit(s, &FRAME, R, cut, "view", backend, all), SSG_OK);
    char res_set[32], tiles_set[32];
    snprintf(res_set, sizeof res_set, "resolution=%d", R);
    snprintf(tiles_set, sizeof tiles_set, "tiles=%d", T);
    const char *sets[] = {res_set, "fit=view", tiles_set};
    void *params = node_params(&ssg_node_lightmaps, sets, 3);
    struct ssg_image *depth = ssg_image_create(R, R, T * T), *out[3] = {depth, NULL, NULL};
    CHECK_EQ(node_run_scene(&ssg_node_lightmaps, s, &FRAME, params, NULL, out, backend),
             SSG_OK);
    size_t n = (size_t)R * R * T * T;
    CHECK(memcmp(depth->data, all[0]->data, n * sizeof(float)) == 0);
    fprintf(stderr, "depth alone (%s): the same %zu depths\n",
            backend == SSG_BACKEND_GL ? "gl" : "cpu", n);
    free(params);
    ssg_image_destroy(&depth);
    images_free(all, 3);
}

/* A graph whose direct_light has other tiles than its maps' node: refused at load. */
static void tiles_apart_refused(void)
{
    const char *path = write_file("tiles_apart.graph",
                                  "scene \"" SSG_SOURCE_DIR "/examples/table.scene\"\n"
                                  "size 32 24\n"
                                  "g  = gbuffer()\n"
                                  "lm = lightmaps(resolution=32, fit=view, tiles=2)\n"
                                  "dl = direct_light(g.position, g.normal, g.albedo, "
                                  "lm.depth, fit=view)\n"
                                  "out = write(dl.out, \"dl\")\n");
    struct ssg_overrides ov = {.seed = -1};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    CHECK(ssg_graph_load(path, &ov, &g, &d) != SSG_OK);
    char text[4096] = "";
    FILE *m = fmemopen(text, sizeof text - 1, "w");
    if (m) {
        ssg_diags_print(&d, m);
        fclose(m);
    }
    fprintf(stderr, "%s", text);
    CHECK(strstr(text, "maps has 4 faces but the scene's lights need 1") != NULL);
    CHECK(strstr(text, "the same tiles") != NULL);
    ssg_graph_destroy(&g);
}

int main(void)
{
    setup_tmp("lightmap_tiles");
    struct ssg_scene *s = table();
    if (!s)
        return check_report();
    faces_cover_the_map(s);
    maps_match(s, "scene", SSG_BACKEND_CPU);
    maps_match(s, "view", SSG_BACKEND_CPU);
    maps_match(s, "view", SSG_BACKEND_GL);
    direct_light_matches(s, SSG_BACKEND_CPU);
    direct_light_matches(s, SSG_BACKEND_GL);
    depth_alone(s, SSG_BACKEND_CPU);
    depth_alone(s, SSG_BACKEND_GL);
    ssg_scene_destroy(&s);
    tiles_apart_refused();
    return check_report();
}
