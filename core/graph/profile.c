/* profile.c - collecting the per-node profile and handing it out as the run's statistics
 * (profile.h). */
#include <float.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "graph/profile.h"

/* The process's one-off loads (profile.h): few, written once each, read by the reports. */
static pthread_mutex_t loads_lock = PTHREAD_MUTEX_INITIALIZER;
static struct ssg_load loads[SSG_LOADS_MAX];
static int load_count;

void ssg_load_note(const char *what, double t0_ms, double t1_ms)
{
    pthread_mutex_lock(&loads_lock);
    if (load_count < SSG_LOADS_MAX)
        loads[load_count++] = (struct ssg_load){what, t0_ms, t1_ms - t0_ms};
    pthread_mutex_unlock(&loads_lock);
}

int ssg_loads(struct ssg_load *out, int max)
{
    pthread_mutex_lock(&loads_lock);
    int n = load_count < max ? load_count : max;
    memcpy(out, loads, sizeof *out * (size_t)(n > 0 ? n : 0));
    pthread_mutex_unlock(&loads_lock);
    return n;
}

/* The time of the loads that began inside a node run which just ended (it took ran_ms up
   to now): the caller calls right after the run, so the run began ran_ms before now. */
static double loads_inside(double ran_ms)
{
    struct ssg_load l[SSG_LOADS_MAX];
    int n = ssg_loads(l, SSG_LOADS_MAX);
    double begun = ssg_now_ms() - ran_ms, ms = 0;
    for (int i = 0; i < n; i++)
        if (l[i].start_ms >= begun)
            ms += l[i].ms;
    return ms;
}

int ssg_profile_init(struct ssg_profile *p, int count)
{
    *p = (struct ssg_profile){0};
    p->rows = calloc((size_t)(count > 0 ? count : 1), sizeof *p->rows);
    p->rows_count = count;
    p->frame_min = DBL_MAX;
    for (int r = 0; p->rows && r < count; r++)
        p->rows[r].min = DBL_MAX;
    return p->rows != NULL;
}

void ssg_profile_free(struct ssg_profile *p)
{
    for (int r = 0; p->rows && r < p->rows_count; r++)
        free(p->rows[r].runs.v);
    free(p->rows);
    free(p->frame_ms.v);
    p->rows = NULL;
    p->frame_ms = (struct ssg_series){0};
}

static int series_add(struct ssg_series *s, double v)
{
    if (s->n == s->cap) {
        int cap = s->cap ? 2 * s->cap : 64;
        double *grown = realloc(s->v, sizeof *grown * (size_t)cap);
        if (!grown)
            return 0;
        s->v = grown, s->cap = cap;
    }
    s->v[s->n++] = v;
    return 1;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median (the mean of the middle two for an even count; 0 for none): the steady
   time, which the first frame's one-off costs (fresh pages for the image pool and the
   nodes' scratch) do not move as they move the average. */
static double series_median(const struct ssg_series *s)
{
    if (s->n < 1)
        return 0.0;
    double *sorted = malloc(sizeof *sorted * (size_t)s->n);
    if (!sorted)
        return 0.0;
    memcpy(sorted, s->v, sizeof *sorted * (size_t)s->n);
    qsort(sorted, (size_t)s->n, sizeof *sorted, by_value);
    int h = s->n / 2;
    double m = s->n % 2 ? sorted[h] : 0.5 * (sorted[h - 1] + sorted[h]);
    free(sorted);
    return m;
}

int ssg_profile_add(struct ssg_profile *p, int r, const struct ssg_node_timing *t)
{
    struct ssg_profile_row *row = &p->rows[r];
    row->load_ms = loads_inside(t->ms + t->transfer_ms);
    double ms = t->ms > row->load_ms ? t->ms - row->load_ms : 0.0;
    row->calls++;
    row->sum += ms;
    row->min = ms < row->min ? ms : row->min;
    row->max = ms > row->max ? ms : row->max;
    row->gpu_sum += t->gpu_ms;
    row->xfer_sum += t->transfer_ms;
    return series_add(&row->runs, ms);
}

int ssg_profile_frame(struct ssg_profile *p, double ms)
{
    p->frames++;
    p->frame_sum += ms;
    p->frame_min = ms < p->frame_min ? ms : p->frame_min;
    p->frame_max = ms > p->frame_max ? ms : p->frame_max;
    return series_add(&p->frame_ms, ms);
}

static double average(double sum, int n)
{
    return n ? sum / n : 0.0;
}

/* One node's entry: its last frame's timing t and its profile row. */
static int fill_node(struct ssg_run_node *n, const struct ssg_profile *p,
                     const struct ssg_profile_row *row, const struct ssg_node_timing *t)
{
    double avg = average(row->sum, row->calls), frame = average(p->frame_sum, p->frames);
    *n = (struct ssg_run_node){
        .name = strdup(row->name),
        .type = row->type,
        .backend = row->backend,
        .ms = t->ms > row->load_ms ? t->ms - row->load_ms : 0.0,
        .gpu_ms = t->gpu_ms,
        .transfer_ms = t->transfer_ms,
        .calls = row->calls,
        .avg_ms = avg,
        .min_ms = row->calls ? row->min : 0.0,
        .max_ms = row->max,
        .median_ms = series_median(&row->runs),
        .share = row->calls == p->frames && frame > 0 ? avg / frame : 0.0,
        .gpu_avg_ms = average(row->gpu_sum, row->calls),
        .transfer_avg_ms = average(row->xfer_sum, row->calls),
        .prepare_ms = row->prepare_ms,
        .bytes = row->bytes,
        .flops = row->flops,
    };
    return n->name != NULL;
}

int ssg_profile_stats(const struct ssg_profile *p, const struct ssg_node_timing *last,
                      struct ssg_run_stats *s)
{
    s->frames = p->frames;
    s->frame_avg_ms = average(p->frame_sum, p->frames);
    s->frame_min_ms = p->frames ? p->frame_min : 0.0;
    s->frame_max_ms = p->frame_max;
    s->frame_median_ms = series_median(&p->frame_ms);
    s->width = p->width, s->height = p->height, s->threads = p->threads;
    s->nodes = calloc((size_t)(p->rows_count > 0 ? p->rows_count : 1), sizeof *s->nodes);
    if (!s->nodes)
        return 0;
    for (int r = 0; r < p->rows_count; r++, s->node_count++)
        if (!fill_node(&s->nodes[r], p, &p->rows[r], &last[r]))
            return 0;
    return 1;
}

void ssg_run_stats_free(struct ssg_run_stats *stats)
{
    if (!stats)
        return;
    for (int i = 0; stats->nodes && i < stats->node_count; i++) {
        free(stats->nodes[i].name);
        free(stats->nodes[i].why);
    }
    free(stats->nodes);
    free(stats->metrics);
    free(stats->gl);
    *stats = (struct ssg_run_stats){0};
}
