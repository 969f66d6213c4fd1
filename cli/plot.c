/* plot.c - PNG plots through gnuplot (plot.h). The numbers go to <name>.dat, the drawing
 * instructions to <name>.gp (kept, so a user can restyle and rerun them), and gnuplot
 * writes <name>.png.tmp, renamed to <name>.png once it succeeded. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "plot.h"

static int run_gnuplot(const char *dir, const char *name)
{
    char cmd[2400], tmp[1200], png[1200];
    snprintf(cmd, sizeof cmd, "cd '%s' && gnuplot '%s.gp' 2> '%s.log'", dir, name, name);
    int rc = system(cmd);
    snprintf(tmp, sizeof tmp, "%s/%s.png.tmp", dir, name);
    snprintf(png, sizeof png, "%s/%s.png", dir, name);
    if (rc != 0 || rename(tmp, png) != 0) {
        remove(tmp);
        int status = rc != -1 && WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
        fprintf(stderr, "ssgraph: error: %s: gnuplot failed (%s; see %s/%s.log)\n", png,
                status == 127 ? "not installed: Debian package gnuplot-nox" : "exit status",
                dir, name);
        return 1;
    }
    char log[1200];
    snprintf(log, sizeof log, "%s/%s.log", dir, name);
    remove(log); /* only a failure's log is worth keeping */
    return 0;
}

static FILE *open_in(const char *dir, const char *name, const char *ext)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/%s.%s", dir, name, ext);
    FILE *f = fopen(path, "w");
    if (!f)
        fprintf(stderr, "ssgraph: error: cannot write %s\n", path);
    return f;
}

static void header(FILE *gp, const char *name, const char *title)
{
    fprintf(gp, "set terminal pngcairo size 900,600 enhanced font 'sans,11'\n"
                "set output '%s.png.tmp'\nset title \"%s\" noenhanced\nset grid\n"
                "set key outside right top noenhanced\n", name, title);
}

int ssg_plot_ms(const char *dir, const char *name, const char *title, const char *xlabel,
                const char *ylabel, const struct ssg_plot_point *pts, int count)
{
    FILE *dat = open_in(dir, name, "dat"), *gp = open_in(dir, name, "gp");
    if (!dat || !gp) {
        if (dat) fclose(dat);
        if (gp) fclose(gp);
        return 1;
    }
    double lo = INFINITY, hi = -INFINITY;
    int series = 0;
    for (int i = 0; i < count; i++) {
        if (i == 0 || strcmp(pts[i].series, pts[i - 1].series) != 0)
            fprintf(dat, "%s\"%s\"\n", series++ ? "\n\n" : "", pts[i].series);
        fprintf(dat, "%.9g %.9g\n", pts[i].x, pts[i].ms);
        lo = pts[i].x < lo ? pts[i].x : lo;
        hi = pts[i].x > hi ? pts[i].x : hi;
    }
    header(gp, name, title);
    fprintf(gp, "set xlabel \"%s\" noenhanced\nset ylabel \"%s\" noenhanced\n%s"
                "plot for [i=0:%d] '%s.dat' index i using 1:2 with linespoints lw 2 pt 7 "
                "title columnheader(1)\n", xlabel, ylabel,
            lo > 0 && hi > 8 * lo ? "set logscale x 2\n" : "", series - 1, name);
    fclose(dat);
    fclose(gp);
    return run_gnuplot(dir, name);
}

/* 1 when no other point is at least as fast and as accurate, and better in one. */
static int on_front(const struct ssg_plot_point *pts, int count, int i)
{
    for (int j = 0; j < count; j++)
        if (j != i && !isnan(pts[j].err) && pts[j].ms <= pts[i].ms &&
            pts[j].err <= pts[i].err && (pts[j].ms < pts[i].ms || pts[j].err < pts[i].err))
            return 0;
    return 1;
}

static int by_ms(const void *a, const void *b)
{
    const struct ssg_plot_point *p = a, *q = b;
    return (p->ms > q->ms) - (p->ms < q->ms);
}

int ssg_plot_pareto(const char *dir, const char *name, const char *title,
                    const char *errlabel, const struct ssg_plot_point *pts, int count)
{
    struct ssg_plot_point *front = malloc(sizeof *front * (size_t)(count ? count : 1));
    FILE *dat = open_in(dir, name, "dat"), *gp = front ? open_in(dir, name, "gp") : NULL;
    if (!dat || !gp) {
        if (dat) fclose(dat);
        if (gp) fclose(gp);
        free(front);
        return 1;
    }
    int n = 0;
    fputs("\"points\"\n", dat);
    for (int i = 0; i < count; i++)
        if (!isnan(pts[i].err)) {
            fprintf(dat, "%.9g %.9g \"%s\"\n", pts[i].ms, pts[i].err, pts[i].label);
            if (on_front(pts, count, i))
                front[n++] = pts[i];
        }
    qsort(front, (size_t)n, sizeof *front, by_ms);
    fputs("\n\n\"Pareto front\"\n", dat);
    for (int i = 0; i < n; i++)
        fprintf(dat, "%.9g %.9g\n", front[i].ms, front[i].err);
    header(gp, name, title);
    fprintf(gp, "set xlabel 'ms' \nset ylabel \"%s\" noenhanced\nset logscale x 2\n"
                "plot '%s.dat' index 0 using 1:2 with points pt 7 ps 1.3 title 'cells', "
                "'' index 0 using 1:2:3 with labels offset 0,1 font ',8' notitle noenhanced, "
                "'' index 1 using 1:2 with lines lw 2 title 'Pareto front'\n", errlabel, name);
    fclose(dat);
    fclose(gp);
    free(front);
    return run_gnuplot(dir, name);
}
