/* tune_search.h - the optimiser of `ssgraph tune` (tune_search.c): a deterministic,
 * derivative-free minimisation over the unit box [0,1]^dims, which the caller maps onto
 * its parameter ranges. It knows nothing of graphs: a test drives it with analytic
 * functions.
 *
 * Method: the start point, then a small Halton design over the box (a coarse look at the
 * whole range, so a start in a poor basin is not the only hope), then a compass search
 * (Kolda, Lewis and Torczon, "Optimization by Direct Search", SIAM Review 45(3), 2003,
 * section 3) from the best point so far: each axis is stepped by +-h in turn, the first
 * improvement is taken and its direction tried first next time, and h halves after a poll
 * that finds none. It needs no gradient, tolerates the small plateaus that integer
 * parameters make, never leaves the box (steps are clamped to it) and takes the same
 * steps for the same inputs. A point the caller's snap maps onto one already evaluated
 * is looked up, not evaluated again, and does not count against the budget.
 *
 * Ownership: the struct is the caller's; nothing is kept after ssg_search_run returns.
 * Thread safety: none needed; the objective is called on the caller's thread. */
#ifndef SSG_CLI_TUNE_SEARCH_H
#define SSG_CLI_TUNE_SEARCH_H

#define SSG_SEARCH_MAX_DIMS 8

/* The value at x (in the box, already snapped); NaN stops the search (a failure the
   objective has reported itself). */
typedef double (*ssg_search_fn)(void *user, const double *x);
/* Moves x (in the box) onto the point that is really evaluated, in place: an integer
   parameter's rounding. NULL = every point is its own. */
typedef void (*ssg_snap_fn)(void *user, double *x);

struct ssg_search {
    int dims;                           /* 1..SSG_SEARCH_MAX_DIMS */
    double start[SSG_SEARCH_MAX_DIMS];  /* the first point, clamped into the box */
    int budget;                         /* most evaluations of distinct points, >= 1 */
    double min_step;                    /* h below this: converged; 0 = 1/512 */
    ssg_search_fn f;
    ssg_snap_fn snap;                   /* NULL = none */
    void *user;                         /* passed to f and snap */
    /* Filled by ssg_search_run: */
    double best[SSG_SEARCH_MAX_DIMS];   /* the point of the lowest value */
    double best_value;                  /* +inf when nothing was evaluated */
    int evaluations;                    /* calls of f */
    int stopped;                        /* 1 = f returned NaN */
};

/* Runs the search until the budget is spent, the step converged or f stopped it.
   Returns 0, or -1 when out of memory (nothing evaluated). */
int ssg_search_run(struct ssg_search *s);

#endif
