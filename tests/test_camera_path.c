/* test_camera_path.c - camera paths (core/scene/camera_path.h, docs/time.md):
 *   - the Catmull-Rom path passes through every key exactly, at the key's time, and
 *     through positions worked out by hand in its first, middle and last segment;
 *   - it is continuous: small steps in time make small steps in position, also across keys;
 *   - a cut jumps: the camera holds the key before until the cut's time, and the frame that
 *     crosses the cut says so; clamped before the first key and after the last;
 *   - the orbit matches its closed form at a few times;
 *   - scene files: keys in any order are sorted, a key's missing fov/up come from the
 *     camera line, the path sets the scene's camera at time 0;
 *   - errors at file:line:col with their code: two keys at one time, a lone key, an orbit
 *     beside keys, radius <= 0, period <= 0, a cut on the first key, a second orbit, a
 *     key looking along the camera line's up. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "scratch.h"
#include "scene/camera_path.h"

#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

static struct ssg_camera_key key(double t, float x, float y, float z, int cut)
{
    struct ssg_camera_key k = {.time = t, .position = {x, y, z}, .target = {0, y, -1},
                               .up = {0, 1, 0}, .fov_y = 40.0f + (float)t, .cut = cut};
    return k;
}

static struct ssg_camera_path keys_path(struct ssg_camera_key *keys, int n)
{
    return (struct ssg_camera_path){.fps = 10, .key_count = n, .keys = keys, .near_z = 0.1f,
                                    .far_z = 50};
}

static double dist(const float a[3], const float b[3])
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

static void test_through_keys_and_continuous(void)
{
    struct ssg_camera_key keys[] = {key(0, 0, 1, 3, 0), key(1, 1, 1.2f, 2.5f, 0),
                                    key(1.5, 1, 1.2f, 2.5f, 0), key(3, -2, 0.5f, 4, 0),
                                    key(4, -2.5f, 2, 4.5f, 0)};
    struct ssg_camera_path p = keys_path(keys, COUNT(keys));
    CHECK(ssg_camera_path_active(&p));
    for (int k = 0; k < COUNT(keys); k++) {
        struct ssg_camera c;
        ssg_camera_path_eval(&p, keys[k].time, &c);
        CHECK(memcmp(c.position, keys[k].position, sizeof c.position) == 0);
        CHECK(memcmp(c.target, keys[k].target, sizeof c.target) == 0);
        CHECK(c.fov_y == keys[k].fov_y);
        CHECK(c.near_z == 0.1f && c.far_z == 50.0f);
    }
    /* continuity: steps of 1e-4 s never move the eye more than a bound far below a key
       spacing, and the segment between two equal keys holds still */
    struct ssg_camera a, b;
    ssg_camera_path_eval(&p, -1.0, &a);
    double worst = 0;
    for (double t = -0.5; t < 4.5; t += 1e-4) {
        ssg_camera_path_eval(&p, t, &b);
        worst = fmax(worst, dist(a.position, b.position));
        a = b;
    }
    CHECK(worst < 5e-3);
    ssg_camera_path_eval(&p, 1.25, &b);
    CHECK(memcmp(b.position, keys[1].position, sizeof b.position) == 0);
    /* clamped ends */
    ssg_camera_path_eval(&p, -3.0, &b);
    CHECK(memcmp(b.position, keys[0].position, sizeof b.position) == 0);
    ssg_camera_path_eval(&p, 99.0, &b);
    CHECK(memcmp(b.position, keys[4].position, sizeof b.position) == 0);
    /* between keys the path really moves off the straight line (a curve, not a lerp) */
    ssg_camera_path_eval(&p, 2.25, &b);
    CHECK(dist(b.position, keys[2].position) > 0.1 && dist(b.position, keys[3].position) > 0.1);
    CHECK_NEAR(dist(b.up, (float[3]){0, 1, 0}), 0, 1e-6);
}

/* Positions worked out by hand, one in each segment of a 4-key path, so a segment that
 * takes a wrong neighbour fails (not only "not a straight line"). Keys at t = 0, 1, 2, 3
 * with x = 0, 1, 5, 14 (y and z fixed): the centripetal knot intervals sqrt|dx| are 1, 2,
 * 3. The end condition (camera_path.c): the first segment's missing p0 and the last
 * segment's missing p3 are the end key itself, a zero knot interval whose first-level lerp
 * is that key. Barry-Goldman with t0 = 0, t at u = 0.5, all in x:
 *   first  [0,1]: p = 0, 0, 1, 5; t1 = 0, t2 = 1, t3 = 3, t = 0.5
 *          A1 = 0; A2 = (0.5*0 + 0.5*1)/1 = 0.5; A3 = (2.5*1 - 0.5*5)/2 = 0
 *          B1 = (0.5*0 + 0.5*0.5)/1 = 0.25; B2 = (2.5*0.5 + 0.5*0)/3 = 5/12
 *          C  = (0.5*0.25 + 0.5*5/12)/1 = 1/8 + 5/24 = 1/3
 *   middle [1,2]: p = 0, 1, 5, 14; t1 = 1, t2 = 3, t3 = 6, t = 2
 *          A1 = (-1*0 + 2*1)/1 = 2; A2 = (1*1 + 1*5)/2 = 3; A3 = (4*5 - 1*14)/3 = 2
 *          B1 = (1*2 + 2*3)/3 = 8/3; B2 = (4*3 + 1*2)/5 = 14/5
 *          C  = (1*8/3 + 1*14/5)/2 = 41/15
 *   last   [2,3] (the segment before the last key): p = 1, 5, 14, 14; t1 = 2, t2 = 5,
 *          t3 = 5, t = 3.5
 *          A1 = (-1.5*1 + 3.5*5)/2 = 8; A2 = (1.5*5 + 1.5*14)/3 = 9.5; A3 = 14
 *          B1 = (1.5*8 + 3.5*9.5)/5 = 9.05; B2 = (1.5*9.5 + 1.5*14)/3 = 11.75
 *          C  = (1.5*9.05 + 1.5*11.75)/3 = 10.4
 * The middle segment is the one before the last key's segment: a k3 that takes k + 1 for
 * the last key (`k + 2 < b`) gives 91/30 there. (Taking p2 for the first segment's p0, or
 * p1 for the last segment's p3, is no slip: with centripetal knots it gives the same curve
 * as the duplicated end key, since the knots only shift.) */
static void test_hand_worked(void)
{
    struct ssg_camera_key keys[] = {key(0, 0, 1, 3, 0), key(1, 1, 1, 3, 0), key(2, 5, 1, 3, 0),
                                    key(3, 14, 1, 3, 0)};
    struct ssg_camera_path p = keys_path(keys, COUNT(keys));
    const double at[][2] = {{0.5, 1.0 / 3.0}, {1.5, 41.0 / 15.0}, {2.5, 10.4}};
    for (int i = 0; i < COUNT(at); i++) {
        struct ssg_camera c;
        ssg_camera_path_eval(&p, at[i][0], &c);
        CHECK_NEAR(c.position[0], at[i][1], 1e-5);
        CHECK_NEAR(c.position[1], 1, 1e-6);
        CHECK_NEAR(c.position[2], 3, 1e-6);
    }
}

static void test_cut(void)
{
    struct ssg_camera_key keys[] = {key(0, 0, 1, 3, 0), key(1, 1, 1, 3, 0), key(2, 5, 1, 3, 1),
                                    key(3, 6, 1, 3, 0)};
    struct ssg_camera_path p = keys_path(keys, COUNT(keys));
    struct ssg_camera c;
    ssg_camera_path_eval(&p, 1.99, &c); /* held at the key before the cut */
    CHECK(memcmp(c.position, keys[1].position, sizeof c.position) == 0);
    ssg_camera_path_eval(&p, 2.0, &c);
    CHECK(memcmp(c.position, keys[2].position, sizeof c.position) == 0);
    ssg_camera_path_eval(&p, 2.5, &c); /* the piece after the cut alone: between 5 and 6 */
    CHECK(c.position[0] > 5.0f && c.position[0] < 6.0f);
    CHECK_EQ(ssg_camera_path_piece(&p, 1.5), 0);
    CHECK_EQ(ssg_camera_path_piece(&p, 2.0), 1);
    int cuts = 0, cut_frame = -1;
    for (int f = 0; f < 40; f++) { /* 10 fps: frame 20 is at the cut's time */
        int cut;
        ssg_camera_path_frame(&p, f, &c, &cut);
        cuts += cut;
        if (cut)
            cut_frame = f;
    }
    CHECK_EQ(cuts, 1);
    CHECK_EQ(cut_frame, 20);
}

static void test_orbit(void)
{
    struct ssg_camera_path p = {.fps = 30, .has_orbit = 1, .near_z = 0.1f, .far_z = 9,
                                .orbit = {.target = {1, 2, 3}, .up = {0, 1, 0}, .radius = 2,
                                          .height = 0.5f, .period = 4, .start = 30,
                                          .fov_y = 50}};
    const double times[] = {0, 0.5, 1, 2.75, 7.9};
    for (int i = 0; i < COUNT(times); i++) {
        struct ssg_camera c;
        ssg_camera_path_eval(&p, times[i], &c);
        double a = (30.0 + 360.0 * times[i] / 4.0) * 3.14159265358979323846 / 180.0;
        /* start 0 is the +z side, 90 the +x side: x = sin, z = cos */
        CHECK_NEAR(c.position[0], 1 + 2 * sin(a), 1e-5);
        CHECK_NEAR(c.position[1], 2.5, 1e-6);
        CHECK_NEAR(c.position[2], 3 + 2 * cos(a), 1e-5);
        CHECK(c.target[0] == 1 && c.target[1] == 2 && c.target[2] == 3);
        CHECK(c.fov_y == 50 && c.near_z == 0.1f && c.far_z == 9);
    }
}

static void test_scene_path(void)
{
    const char *path = write_file("keys.scene",
                                  "camera(position=[0,1,4], fov=33, near=0.2, far=30)\n"
                                  "frame_rate(fps=24)\n"
                                  "camera_key(time=2, position=[1,1,4], target=[0,1,0])\n"
                                  "camera_key(time=0, position=[-1,1,4], target=[0,1,0], "
                                  "fov=50)\n"
                                  "plane()\n");
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load(path, 0, &s, &d), SSG_OK);
    if (!s)
        return;
    CHECK_EQ(s->camera_path.key_count, 2);
    CHECK(s->camera_path.keys[0].time == 0 && s->camera_path.keys[1].time == 2);
    CHECK(s->camera_path.keys[0].fov_y == 50 && s->camera_path.keys[1].fov_y == 33);
    CHECK(s->camera_path.fps == 24 && s->camera_path.near_z == 0.2f);
    CHECK(s->camera.position[0] == -1 && s->camera.fov_y == 50 && s->has_camera);
    ssg_scene_destroy(&s);
}

struct bad {
    const char *text;     /* the scene */
    enum ssg_err code;
    int line;
    const char *marker;   /* the column: where this text starts on that line */
};

static const struct bad bads[] = {
    {"camera_key(time=1, position=[0,0,3], target=[0,0,0])\n"
     "camera_key(time=1, position=[1,0,3], target=[0,0,0])\n",
     SSG_E_DUPLICATE, 2, "1, position"},
    {"camera_key(time=1, position=[0,0,3], target=[0,0,0])\n", SSG_E_VALUE, 1, "camera_key"},
    {"camera_key(time=0, position=[0,0,3], target=[0,0,0])\n"
     "camera_key(time=1, position=[1,0,3], target=[0,0,0])\n"
     "orbit(radius=2)\n", SSG_E_DUPLICATE, 3, "orbit"},
    {"orbit(radius=0)\n", SSG_E_RANGE, 1, "0)"},
    {"orbit(radius=-1, period=3)\n", SSG_E_RANGE, 1, "-1"},
    {"orbit(period=0)\n", SSG_E_RANGE, 1, "0)"},
    {"orbit(up=[0,0,0])\n", SSG_E_VALUE, 1, "[0,0,0]"},
    {"orbit()\norbit()\n", SSG_E_DUPLICATE, 2, "orbit"},
    {"camera_key(time=0, position=[0,0,3], target=[0,0,0], cut=true)\n"
     "camera_key(time=1, position=[1,0,3], target=[0,0,0])\n", SSG_E_VALUE, 1, "true"},
    {"camera_key(time=0, position=[0,0,3], target=[0,0,3])\n"
     "camera_key(time=1, position=[1,0,3], target=[0,0,0])\n", SSG_E_VALUE, 1, "[0,0,3])"},
    {"frame_rate(fps=0)\n", SSG_E_RANGE, 1, "0)"},
    {"camera(position=[0,3,0], up=[0,0,1])\n"
     "camera_key(time=0, position=[0,0,3], target=[0,0,0])\n"
     "camera_key(time=1, position=[1,0,3], target=[0,0,0])\n", SSG_E_VALUE, 2, "camera_key"},
    {"camera_key(position=[0,0,3], target=[0,0,0])\n", SSG_E_MISSING_INPUT, 1, "camera_key"},
};

/* Column of `marker` on line `line` of text (1-based). */
static int column_of(const char *text, int line, const char *marker)
{
    for (int l = 1; l < line; l++)
        text = strchr(text, '\n') + 1;
    return (int)(strstr(text, marker) - text) + 1;
}

static void test_errors(void)
{
    for (int i = 0; i < COUNT(bads); i++) {
        const char *path = write_file("bad.scene", bads[i].text);
        struct ssg_diags d = {0};
        struct ssg_scene *s = NULL;
        CHECK_EQ(ssg_scene_load(path, 0, &s, &d), bads[i].code);
        CHECK(s == NULL);
        int col = column_of(bads[i].text, bads[i].line, bads[i].marker), found = 0;
        for (int k = 0; k < d.count; k++)
            found |= d.items[k].code == bads[i].code && d.items[k].line == bads[i].line &&
                     d.items[k].column == col;
        if (!found) {
            fprintf(stderr, "case %d: expected %s at %d:%d, got:\n", i,
                    ssg_err_name(bads[i].code), bads[i].line, col);
            ssg_diags_print(&d, stderr);
        }
        CHECK(found);
    }
}

int main(void)
{
    setup_tmp("camera_path");
    test_through_keys_and_continuous();
    test_hand_worked();
    test_cut();
    test_orbit();
    test_scene_path();
    test_errors();
    return check_report();
}
