/* test_tune_search.c - the optimiser of `ssgraph tune` (cli/tune_search.h) on analytic
 * functions: a quadratic bowl in 2 and 3 dimensions is minimised to within 0.01 of its
 * centre inside the budget; a bowl centred outside the box ends on the box's face; an
 * integer axis (snapped) never has a point evaluated twice, nor a finely rounded one a near
 * copy; the same inputs give the
 * same sequence of points; an objective that fails (NaN) stops the search at once. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "tune_search.h"

enum { MAX_TRACE = 400 };

/* A bowl sum w_k (x_k - c_k)^2 with unequal weights (an elongated valley), recording every
   point it is asked for. */
struct bowl {
    double c[SSG_SEARCH_MAX_DIMS], w[SSG_SEARCH_MAX_DIMS];
    double trace[MAX_TRACE][SSG_SEARCH_MAX_DIMS];
    int calls, dims, fail_at; /* fail_at > 0: that call returns NaN */
};

static double bowl_f(void *user, const double *x)
{
    struct bowl *b = user;
    if (b->calls < MAX_TRACE)
        memcpy(b->trace[b->calls], x, (size_t)b->dims * sizeof *x);
    if (++b->calls == b->fail_at)
        return NAN;
    double v = 0;
    for (int k = 0; k < b->dims; k++)
        v += b->w[k] * (x[k] - b->c[k]) * (x[k] - b->c[k]);
    return v;
}

/* Axis 0 on an 11-level grid, as a parameter 0..10 rounded to integers. */
static void snap_grid(void *user, double *x)
{
    (void)user;
    x[0] = round(x[0] * 10) / 10;
}

/* Every axis to 4 decimals, as tune rounds a decimal parameter to 6 digits. */
static void snap_fine(void *user, double *x)
{
    struct bowl *b = user;
    for (int k = 0; k < b->dims; k++)
        x[k] = round(x[k] * 1e4) / 1e4;
}

/* Pairs of evaluated points at most `within` apart (L1); 0: identical points. */
static int close_pairs(const struct bowl *b, double within)
{
    int pairs = 0;
    for (int i = 0; i < b->calls; i++) {
        for (int j = 0; j < i; j++) {
            double dist = 0;
            for (int k = 0; k < b->dims; k++)
                dist += fabs(b->trace[i][k] - b->trace[j][k]);
            pairs += dist <= within;
        }
    }
    return pairs;
}

static struct ssg_search search_of(struct bowl *b, int budget)
{
    struct ssg_search s = {.dims = b->dims, .budget = budget, .f = bowl_f, .user = b};
    for (int k = 0; k < b->dims; k++)
        s.start[k] = 0.9; /* far from every centre below */
    return s;
}

static void test_bowl(int dims)
{
    struct bowl b = {.c = {0.31, 0.68, 0.52}, .w = {1, 4, 0.5}, .dims = dims};
    struct ssg_search s = search_of(&b, 150);
    CHECK_EQ(ssg_search_run(&s), 0);
    CHECK(s.evaluations <= 150 && s.evaluations == b.calls);
    for (int k = 0; k < dims; k++)
        CHECK_NEAR(s.best[k], b.c[k], 0.01);
    CHECK(s.best_value < 1e-4);
    CHECK(!s.stopped);
}

static void test_outside_the_box(void)
{
    struct bowl b = {.c = {1.4, 0.25}, .w = {1, 1}, .dims = 2};
    struct ssg_search s = search_of(&b, 100);
    ssg_search_run(&s);
    CHECK_NEAR(s.best[0], 1.0, 0);
    CHECK_NEAR(s.best[1], 0.25, 0.01);
    for (int i = 0; i < b.calls; i++)
        CHECK(b.trace[i][0] >= 0 && b.trace[i][0] <= 1);
}

static void test_snapped_points_once(void)
{
    struct bowl b = {.c = {0.43, 0.6}, .w = {1, 1}, .dims = 2};
    struct ssg_search s = search_of(&b, 200);
    s.snap = snap_grid;
    ssg_search_run(&s);
    CHECK_EQ(close_pairs(&b, 0), 0);
    CHECK_NEAR(s.best[0], 0.4, 1e-12); /* the grid point nearest the centre */
    CHECK_NEAR(s.best[1], 0.6, 0.01);
}

/* Rounding must not drift: a step and its reverse come back to the same point, so no two
   evaluated points are nearer than the smallest step (1/512) unless they are one point. */
static void test_no_near_copies(void)
{
    struct bowl b = {.c = {0.123, 0.77}, .w = {1, 3}, .dims = 2};
    struct ssg_search s = search_of(&b, 120);
    s.snap = snap_fine;
    ssg_search_run(&s);
    CHECK_EQ(close_pairs(&b, 1.0 / 1024), 0);
    CHECK_NEAR(s.best[0], 0.123, 0.01);
}

static void test_deterministic(void)
{
    static struct bowl a = {.c = {0.2, 0.7, 0.4}, .w = {2, 1, 3}, .dims = 3};
    static struct bowl b;
    b = a;
    struct ssg_search sa = search_of(&a, 60), sb = search_of(&b, 60);
    ssg_search_run(&sa);
    ssg_search_run(&sb);
    CHECK_EQ(a.calls, b.calls);
    CHECK(!memcmp(a.trace, b.trace, sizeof a.trace));
    CHECK(sa.best_value == sb.best_value);
}

static void test_failure_stops(void)
{
    struct bowl b = {.c = {0.5, 0.5}, .w = {1, 1}, .dims = 2, .fail_at = 4};
    struct ssg_search s = search_of(&b, 50);
    ssg_search_run(&s);
    CHECK_EQ(s.stopped, 1);
    CHECK_EQ(b.calls, 4);
    CHECK_EQ(s.evaluations, 4);
    CHECK(isfinite(s.best_value)); /* the three before it still count */
}

int main(void)
{
    test_bowl(2);
    test_bowl(3);
    test_outside_the_box();
    test_snapped_points_once();
    test_no_near_copies();
    test_deterministic();
    test_failure_stops();
    return check_report();
}
