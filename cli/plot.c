/* plot.c - PNG plots through gnuplot (plot.h). The numbers and every text (title, axis
 * names, series names, labels) go to <name>.dat, the drawing instructions to <name>.gp
 * (kept, so a user can restyle and rerun them: `gnuplot name.gp` writes name.png), both
 * written whole through temporaries (files.h). The script holds no text from outside: see
 * dat_text. gnuplot runs as a child process in the output folder (no shell: a folder name
 * is never parsed) and draws into a temporary made by ssg_tmp_create, renamed to
 * <name>.png once it succeeded; its messages are kept in <name>.log only when it fails. */
#define _DEFAULT_SOURCE /* open_memstream */
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "plot.h"
#include "ssgraph.h"

/* Runs `gnuplot -e "outfile='TMP'" NAME.gp` in dir, stderr into the log temporary. */
static int gnuplot_child(const char *dir, const char *name, const char *out, int log_fd)
{
    char script[300], set_out[4500];
    snprintf(script, sizeof script, "%s.gp", name);
    snprintf(set_out, sizeof set_out, "outfile='%s'", out);
    pid_t pid = fork();
    if (pid == 0) {
        if (chdir(dir) != 0 || dup2(log_fd, 2) < 0)
            _exit(126);
        execlp("gnuplot", "gnuplot", "-e", set_out, script, (char *)NULL);
        _exit(127);
    }
    int status = -1;
    if (pid < 0 || waitpid(pid, &status, 0) < 0)
        return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static int run_gnuplot(const char *dir, const char *name)
{
    char png[1200], log[1200];
    snprintf(png, sizeof png, "%s/%s.png", dir, name);
    snprintf(log, sizeof log, "%s/%s.log", dir, name);
    struct ssg_diags d = {0};
    struct ssg_tmp t[2];
    if (ssg_tmp_create(png, ".png", "plot", &t[0], &d) ||
        ssg_tmp_create(log, "", "gnuplot's messages", &t[1], &d)) {
        ssg_tmp_discard(t, t[0].slot >= 0 ? 1 : 0);
        ssg_diags_print(&d, stderr);
        return 1;
    }
    /* gnuplot opens the temporary by its name (relative to dir): it exists, made here. */
    const char *base = strrchr(t[0].path, '/');
    int status = gnuplot_child(dir, name, base ? base + 1 : t[0].path, t[1].fd);
    if (status == 0 && ssg_tmp_commit(&t[0], 1, &d) == SSG_OK) {
        ssg_tmp_discard(&t[1], 1); /* only a failure's log is worth keeping */
        return 0;
    }
    ssg_tmp_discard(&t[0], 1);
    ssg_tmp_commit(&t[1], 1, &d);
    ssg_diags_print(&d, stderr);
    fprintf(stderr, "ssgraph: error: %s: gnuplot failed (%s; see %s)\n", png,
            status == 127 ? "not installed: Debian package gnuplot-nox" : "exit status", log);
    return 1;
}

static void put_text(FILE *f, const void *user)
{
    fputs(user, f);
}

/* A memory stream for a file's text. */
struct text {
    FILE *f;
    char *buf;
    size_t len;
};

static int text_open(struct text *t)
{
    t->buf = NULL;
    t->f = open_memstream(&t->buf, &t->len);
    if (!t->f)
        fprintf(stderr, "ssgraph: error: out of memory for a plot\n");
    return t->f != NULL;
}

/* Closes the stream (which settles buf) and, when `save`, writes its text to
   <dir>/<name>.<ext> whole or not at all; frees it. 0 on success. */
static int text_close(struct text *t, int save, const char *dir, const char *name,
                      const char *ext)
{
    char path[1200];
    struct ssg_diags d = {0};
    int failed = fclose(t->f) != 0 || !t->buf;
    snprintf(path, sizeof path, "%s/%s.%s", dir, name, ext);
    if (save && !failed)
        failed = ssg_write_text_file(path, "plot data", put_text, t->buf, &d) != SSG_OK;
    ssg_diags_print(&d, stderr);
    free(t->buf);
    t->buf = NULL;
    return failed;
}

/* gnuplot runs what its script says: a double-quoted string has its `backticks` run by the
   shell, and a quote inside a name would end the string and start code (`system(...)`).
   So the script holds no text from outside (graph path, sweep keys and values, node and
   metric names, all of which a forged shard's bench.json can set): that text goes to the
   data file, which gnuplot only reads as data, and the script takes it from there
   (`stats ... strcol`, `columnheader`). The script's own words are this file's. */

/* Longest text kept (bytes): gnuplot cuts a data record past 1024 bytes, and a label this
   long is unreadable anyway. */
enum { TEXT_MAX = 400 };

/* One text as a double-quoted field of the data file. gnuplot has no escape for '"' there,
   so it becomes '\''; it reads "\\" as one backslash, so each is doubled; control
   characters (a newline would end the record) become spaces; a longer text is cut at a
   character's start and ends in "...". */
static void dat_text(FILE *f, const char *s)
{
    size_t len = strlen(s), cut = len > TEXT_MAX ? TEXT_MAX : len;
    while (cut < len && cut > 0 && ((unsigned char)s[cut] & 0xc0) == 0x80)
        cut--; /* not inside a UTF-8 sequence */
    fputc('"', f);
    for (size_t i = 0; i < cut; i++) {
        unsigned char ch = (unsigned char)s[i];
        if (ch == '"')
            fputc('\'', f);
        else if (ch == '\\')
            fputs("\\\\", f);
        else
            fputc(ch < 0x20 || ch == 0x7f ? ' ' : ch, f);
    }
    fputs(cut < len ? "...\"" : "\"", f);
}

/* Index 0 of the data file: the title and the axes' names, one a line (header() reads them). */
static void dat_texts(FILE *dat, const char *title, const char *xlabel, const char *ylabel)
{
    fputs("# the title, the x axis' and the y axis' names; then the data sets, one an index\n",
          dat);
    const char *texts[] = {title, xlabel, ylabel};
    for (int i = 0; i < 3; i++) {
        dat_text(dat, texts[i]);
        fputc('\n', dat);
    }
}

/* The name is put into the script as is: only letters, digits, '_' and '-' are taken. */
static int safe_name(const char *name)
{
    size_t len = strlen(name);
    if (len > 0 && len < 100 && strspn(name, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTU"
                                              "VWXYZ0123456789_-") == len)
        return 1;
    fprintf(stderr, "ssgraph: error: plot name '%s': expected letters, digits, _ and -\n", name);
    return 0;
}

static void header(FILE *gp, const char *name)
{
    static const char *const vars[] = {"plot_title", "plot_xlabel", "plot_ylabel"};
    fprintf(gp, "set terminal pngcairo size 900,600 enhanced font 'sans,11'\n"
                "if (!exists('outfile')) outfile = '%s.png'\nset output outfile\n"
                "# the texts are in the data file (index 0): this script holds none\n", name);
    for (int i = 0; i < 3; i++)
        fprintf(gp, "stats '%s.dat' index 0 every ::%d::%d using (%s = strcol(1), 0) nooutput\n",
                name, i, i, vars[i]);
    fputs("set title plot_title noenhanced\nset xlabel plot_xlabel noenhanced\n"
          "set ylabel plot_ylabel noenhanced\nset grid\nset key outside right top noenhanced\n",
          gp);
}

/* Opens the data file's and the script's texts; 0 (nothing open) on failure. */
static int open_both(struct text *td, struct text *tg, const char *dir, const char *name)
{
    if (!safe_name(name) || !text_open(td))
        return 0;
    if (!text_open(tg)) {
        text_close(td, 0, dir, name, "dat");
        return 0;
    }
    return 1;
}

/* Saves both, then draws: 0 when the PNG was written. */
static int close_both(struct text *td, struct text *tg, const char *dir, const char *name)
{
    int failed = text_close(td, 1, dir, name, "dat");
    failed |= text_close(tg, 1, dir, name, "gp");
    return failed ? 1 : run_gnuplot(dir, name);
}

int ssg_plot_ms(const char *dir, const char *name, const char *title, const char *xlabel,
                const char *ylabel, const struct ssg_plot_point *pts, int count)
{
    struct text td, tg;
    if (!open_both(&td, &tg, dir, name))
        return 1;
    FILE *dat = td.f, *gp = tg.f;
    double lo = INFINITY, hi = -INFINITY;
    int series = 0;
    dat_texts(dat, title, xlabel, ylabel);
    for (int i = 0; i < count; i++) {
        if (i == 0 || strcmp(pts[i].series, pts[i - 1].series) != 0) {
            fputs("\n\n", dat); /* a new index, its name first (columnheader) */
            dat_text(dat, pts[i].series);
            fputc('\n', dat);
            series++;
        }
        fprintf(dat, "%.9g %.9g %.9g %.9g\n", pts[i].x, pts[i].ms, pts[i].lo, pts[i].hi);
        lo = pts[i].x < lo ? pts[i].x : lo;
        hi = pts[i].x > hi ? pts[i].x : hi;
    }
    header(gp, name);
    /* the bars span each cell's fastest to slowest frame, the line joins the medians */
    fprintf(gp, "set offsets graph 0.03, graph 0.03, 0, 0\n%s"
                "plot for [i=1:%d] '%s.dat' index i using 1:2:3:4 with yerrorlines lw 2 pt 7 "
                "title columnheader(1)\n", lo > 0 && hi > 8 * lo ? "set logscale x 2\n" : "",
            series, name);
    return close_both(&td, &tg, dir, name);
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

/* Index 1: every point with an error and its label; index 2: the front, fastest first. */
static int dat_pareto(FILE *dat, const struct ssg_plot_point *pts, int count)
{
    struct ssg_plot_point *front = malloc(sizeof *front * (size_t)(count ? count : 1));
    if (!front) {
        fprintf(stderr, "ssgraph: error: out of memory for a plot\n");
        return 0;
    }
    int n = 0;
    fputs("\n\n\"points\"\n", dat);
    for (int i = 0; i < count; i++)
        if (!isnan(pts[i].err)) {
            fprintf(dat, "%.9g %.9g ", pts[i].ms, pts[i].err);
            dat_text(dat, pts[i].label);
            fputc('\n', dat);
            if (on_front(pts, count, i))
                front[n++] = pts[i];
        }
    qsort(front, (size_t)n, sizeof *front, by_ms);
    fputs("\n\n\"Pareto front\"\n", dat);
    for (int i = 0; i < n; i++)
        fprintf(dat, "%.9g %.9g\n", front[i].ms, front[i].err);
    free(front);
    return 1;
}

int ssg_plot_pareto(const char *dir, const char *name, const char *title, const char *xlabel,
                    const char *ylabel, const struct ssg_plot_point *pts, int count)
{
    struct text td, tg;
    if (!open_both(&td, &tg, dir, name))
        return 1;
    dat_texts(td.f, title, xlabel, ylabel);
    if (!dat_pareto(td.f, pts, count)) {
        text_close(&td, 0, dir, name, "dat");
        text_close(&tg, 0, dir, name, "gp");
        return 1;
    }
    header(tg.f, name);
    fprintf(tg.f, "set logscale x 2\n"
                  "plot '%s.dat' index 1 using 1:2 with points pt 7 ps 1.3 title 'cells', "
                  "'' index 1 using 1:2:3 with labels offset 0,1 font ',8' notitle noenhanced, "
                  "'' index 2 using 1:2 with lines lw 2 title 'Pareto front'\n", name);
    return close_both(&td, &tg, dir, name);
}
