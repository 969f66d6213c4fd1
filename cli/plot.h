/* plot.h - the bench's pictures (plot.c): PNG plots drawn by gnuplot from the bench's own
 * numbers. ssgraph writes a data file and a gnuplot script next to them and runs gnuplot
 * (Debian: gnuplot-nox); the PNG appears whole or not at all. Every text given here (which
 * may come from a file name or a forged bench.json) goes to the data file only, never into
 * the script: gnuplot cannot run it. */
#ifndef SSG_CLI_PLOT_H
#define SSG_CLI_PLOT_H

#include <stdio.h>

/* One point of a plot: x (a swept value), its time (ms: the median, lo and hi the fastest
 * and slowest run) and err (an error metric, NAN = none), the series it belongs to and a
 * label (cut with "..." when longer). */
struct ssg_plot_point {
    double x, ms, lo, hi, err;
    const char *series;
    char label[160];
};

/* Writes <dir>/<name>.png: ms against x, one line per series through the medians with bars
 * from lo to hi (log x when the values span more than a factor of 8), titled `title`, x
 * axis `xlabel`. name: letters, digits, _ and - only. Returns 0 on success, else prints why
 * to stderr. */
int ssg_plot_ms(const char *dir, const char *name, const char *title, const char *xlabel,
                const char *ylabel, const struct ssg_plot_point *pts, int count);

/* Writes <dir>/<name>.png: error against ms for every point with an error, labelled, and
 * the Pareto front (the points no other point beats in both) joined by a line. */
int ssg_plot_pareto(const char *dir, const char *name, const char *title, const char *xlabel,
                    const char *ylabel, const struct ssg_plot_point *pts, int count);

#endif
