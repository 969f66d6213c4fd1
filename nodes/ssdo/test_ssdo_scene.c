/* test_ssdo_scene.c - SSDO through whole graphs on real scenes, where its two promises are
 * visible (Szentandrasi sections 3.2 and 5, figure 8):
 * - colour bleeding: graphs/ssdo.graph on the Cornell box sends red light onto the floor
 *   beside the red wall and green light onto the floor beside the green wall;
 * - shadows move with the light: a box on a floor lit by one point light from the left,
 *   then from the right; the floor beside the box on the side away from the light is the
 *   one SSDO darkens (SSAO could not tell the two apart);
 * - one step and two steps agree: ssdo.graph's and ssdo_2step.graph's final images on the
 *   Cornell box differ by less than a stated tolerance.
 * Graphs run through the public API at small sizes; results are read back from the EXR
 * layers the graphs write. */
#include <string.h>
#include <sys/stat.h>

#include "check.h"
#include "graph/node.h"
#include "scene/scene.h"
#include "scene_node.h"

enum { W = 160, H = 96 };

static char tmp[512];

static enum ssg_err run_graph(const char *graph, const char *scene, const char *out_dir)
{
    return graph_run(graph, scene, W, H, out_dir);
}

static struct ssg_image *layer(const char *dir, const char *file, const char *name)
{
    return exr_layer(dir, file, name);
}

static float px(const struct ssg_image *im, int c, int x, int y)
{
    return ssg_image_plane(im, c)[(size_t)y * (size_t)im->width + (size_t)x];
}

/* Floor pixels (view normal pointing up: the Cornell camera looks straight ahead) within
   0.35 of the red wall (x = -1) and of the green wall (x = 1); view x comes from the
   depth and the pixel (node.h's projection, the scene's 40 degree field of view). */
static void test_colour_bleeding(void)
{
    char dir[600];
    snprintf(dir, sizeof dir, "%s/bleed", tmp);
    CHECK_EQ(run_graph("graphs/ssdo.graph", NULL, dir), SSG_OK);
    struct ssg_image *bounce = layer(dir, "ssdo.exr", "bounce");
    struct ssg_image *normal = layer(dir, "ssdo.exr", "normal");
    struct ssg_image *depth = layer(dir, "ssdo.exr", "depth");
    if (!bounce || !normal || !depth)
        return;
    const double f = 0.5 * H / tan(20.0 * M_PI / 180.0);
    double sum[2][3] = {{0}}; /* [red side, green side][channel] */
    int count[2] = {0, 0};
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double vx = (x + 0.5 - 0.5 * W) / f * px(depth, 0, x, y);
            int side = vx < -0.65 ? 0 : vx > 0.65 ? 1 : -1;
            if (side < 0 || px(normal, 1, x, y) < 0.9f || px(depth, 0, x, y) <= 0)
                continue;
            for (int c = 0; c < 3; c++)
                sum[side][c] += px(bounce, c, x, y);
            count[side]++;
        }
    CHECK(count[0] > 50 && count[1] > 50);
    /* Red wall albedo (0.63, 0.065, 0.05), green (0.14, 0.45, 0.091): the bounce beside
       each wall takes its hue, far from the grey of the white floor (ratios ~1). */
    CHECK(sum[0][0] > 2.0 * sum[0][1]);
    CHECK(sum[1][1] > 2.0 * sum[1][0]);
    CHECK(sum[0][0] / (count[0] ? count[0] : 1) > 1e-3); /* visible, not round-off */
    ssg_image_destroy(&bounce);
    ssg_image_destroy(&normal);
    ssg_image_destroy(&depth);
}

static const char *box_scene =
    "camera(position=[0, 2.5, 3], target=[0, 0, 0], up=[0, 1, 0], fov=40, near=0.05, far=20)\n"
    "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[6, 0, 6])\n"
    "box(center=[0, 0.3, 0], size=[0.6, 0.6, 0.6])\n"
    "point_light(position=[%g, 0.8, 0], intensity=4)\n";

static const char *box_graph =
    "size 160 96\n"
    "g  = gbuffer()\n"
    "k  = halton(count=32, bases=[2, 3], mapping=uniform, falloff=1)\n"
    "do = ssdo(g.position, g.normal, kernel=k.samples, rotation=k.rotation, depth=g.depth,\n"
    "          radius=0.5, bias=0.01, mode=modulation, channels=1)\n"
    "out = write(do.out, \"box\", position=g.position, normal=g.normal)\n";

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

/* Mean modulation of the floor strips left (x in [-0.55, -0.32]) and right of the box
   (|z| < 0.25), found from the view-space positions and the scene's camera. */
static void box_sides(const char *dir, float light_x, double mean[2])
{
    char scene[700], text[600], graph[700];
    snprintf(scene, sizeof scene, "%s/box.scene", dir);
    snprintf(graph, sizeof graph, "%s/box.graph", dir);
    snprintf(text, sizeof text, box_scene, light_x);
    mkdir(dir, 0755);
    write_text(scene, text);
    write_text(graph, box_graph);
    CHECK_EQ(run_graph(graph, scene, dir), SSG_OK);
    struct ssg_image *m = layer(dir, "box.exr", NULL);
    struct ssg_image *pos = layer(dir, "box.exr", "position");
    struct ssg_image *nrm = layer(dir, "box.exr", "normal");
    mean[0] = mean[1] = 0;
    if (!m || !pos || !nrm)
        return;
    struct ssg_camera cam = {{0, 2.5f, 3}, {0, 0, 0}, {0, 1, 0}, 40, 0.05f, 20};
    float v[16];
    ssg_camera_view_matrix(&cam, v);
    int count[2] = {0, 0};
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float p[3] = {px(pos, 0, x, y), px(pos, 1, x, y), px(pos, 2, x, y)}, w[3];
            if (p[2] >= 0)
                continue; /* background */
            for (int i = 0; i < 3; i++) /* world = R^T (view - t) */
                w[i] = v[4 * i] * (p[0] - v[12]) + v[4 * i + 1] * (p[1] - v[13]) +
                       v[4 * i + 2] * (p[2] - v[14]);
            int floor = fabsf(w[1]) < 1e-3f && fabsf(w[2]) < 0.25f;
            int side = w[0] > -0.55f && w[0] < -0.32f ? 0
                       : w[0] > 0.32f && w[0] < 0.55f ? 1
                                                      : -1;
            if (!floor || side < 0)
                continue;
            mean[side] += px(m, 0, x, y);
            count[side]++;
        }
    CHECK(count[0] > 10 && count[1] > 10);
    for (int s = 0; s < 2; s++)
        mean[s] /= count[s] ? count[s] : 1;
    ssg_image_destroy(&m);
    ssg_image_destroy(&pos);
    ssg_image_destroy(&nrm);
}

static void test_shadow_follows_light(void)
{
    char dir[600];
    double left_lit[2], right_lit[2];
    snprintf(dir, sizeof dir, "%s/light_left", tmp);
    box_sides(dir, -2.0f, left_lit);
    snprintf(dir, sizeof dir, "%s/light_right", tmp);
    box_sides(dir, 2.0f, right_lit);
    /* Light on the left: the floor right of the box lies in its shadow, and vice versa. */
    CHECK(left_lit[1] < left_lit[0] - 0.1);
    CHECK(right_lit[0] < right_lit[1] - 0.1);
    CHECK(right_lit[0] < left_lit[0] - 0.1);
    CHECK(left_lit[1] < right_lit[1] - 0.1);
}

/* One step and two steps from the same samples, before the filters (the two-step graph
   filters radiance, which blurs the light's own gradients; the one-step graph filters
   only the modulation): the direct parts, M x direct and the radiance pass, are the same
   light (one light, so the modulation is its visibility) within float rounding; the
   totals differ by what the bounce's senders emit (undarkened in one step, occluded in two)
   and the bounce's darkening, held to 5 % of the mean brightness. The one-step graph runs
   with the two-step graph's bounce strength and without its modulation power, so both
   compute the same estimator. */
static void test_one_and_two_steps(void)
{
    char one[600], two[600];
    snprintf(one, sizeof one, "%s/one", tmp);
    snprintf(two, sizeof two, "%s/two", tmp);
    const char *same[] = {"do.power=1", "do.strength=4"};
    CHECK_EQ(graph_run_sets("graphs/ssdo.graph", NULL, W, H, one, same, 2), SSG_OK);
    CHECK_EQ(run_graph("graphs/ssdo_2step.graph", NULL, two), SSG_OK);
    struct ssg_image *m = layer(one, "ssdo.exr", "modulation_raw");
    struct ssg_image *direct = layer(one, "ssdo.exr", "direct");
    struct ssg_image *b1 = layer(one, "ssdo.exr", "bounce_raw");
    struct ssg_image *d2 = layer(two, "ssdo_2step.exr", "direct_raw");
    struct ssg_image *b2 = layer(two, "ssdo_2step.exr", "bounce_raw");
    if (!m || !direct || !b1 || !d2 || !b2)
        return;
    double direct_diff = 0, diff = 0, level = 0;
    for (int c = 0; c < 3; c++)
        for (size_t i = 0; i < (size_t)W * H; i++) {
            double mi = m->data[i], d1 = mi * ssg_image_plane(direct, c)[i];
            double t1 = d1 + mi * ssg_image_plane(b1, c)[i];
            double t2 = ssg_image_plane(d2, c)[i] + ssg_image_plane(b2, c)[i];
            direct_diff = fmax(direct_diff, fabs(d1 - ssg_image_plane(d2, c)[i]) /
                                                (1e-3 + fabs(d1)));
            diff += fabs(t1 - t2);
            level += fabs(t2);
        }
    size_t n = (size_t)W * H * 3;
    printf("one step vs two steps: direct rel. diff %.2e, mean |total difference| %.4f, "
           "mean level %.4f\n", direct_diff, diff / n, level / n);
    CHECK(direct_diff < 1e-4);
    CHECK(level > 0);
    CHECK(diff < 0.05 * level);
    struct ssg_image *all[] = {m, direct, b1, d2, b2};
    for (int i = 0; i < 5; i++)
        ssg_image_destroy(&all[i]);
}

int main(void)
{
    const char *dir = getenv("SSG_TMP");
    snprintf(tmp, sizeof tmp, "%s", dir && dir[0] ? dir : CHECK_TMP_ROOT "/test_ssdo_scene");
    mkdir(tmp, 0755);
    test_colour_bleeding();
    test_shadow_follows_light();
    test_one_and_two_steps();
    return check_report();
}
