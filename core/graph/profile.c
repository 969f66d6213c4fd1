/* profile.c - collecting, printing and writing the per-node profile (profile.h). */
#include <float.h>
#include <stdlib.h>

#include "lang/diag.h"
#include "graph/profile.h"

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
    free(p->rows);
    p->rows = NULL;
}

void ssg_profile_add(struct ssg_profile *p, int r, const struct ssg_node_timing *t)
{
    struct ssg_profile_row *row = &p->rows[r];
    row->calls++;
    row->sum += t->ms;
    row->min = t->ms < row->min ? t->ms : row->min;
    row->max = t->ms > row->max ? t->ms : row->max;
    row->gpu_sum += t->gpu_ms;
    row->xfer_sum += t->transfer_ms;
}

void ssg_profile_frame(struct ssg_profile *p, double ms)
{
    p->frames++;
    p->frame_sum += ms;
    p->frame_min = ms < p->frame_min ? ms : p->frame_min;
    p->frame_max = ms > p->frame_max ? ms : p->frame_max;
}

static double average(double sum, int n)
{
    return n ? sum / n : 0.0;
}

/* A profiler's tree: the frame at the root, the passes under it, then the sinks that ran
   once after the last frame. */
void ssg_profile_print(const struct ssg_profile *p, FILE *f)
{
    double frame = average(p->frame_sum, p->frames);
    fprintf(f, "%-18s %-12s %-4s %6s %10s %10s %10s %7s %10s %10s\n", "node", "type", "on",
            "calls", "avg ms", "min ms", "max ms", "share", "gpu ms", "prepare ms");
    fprintf(f, "%-18s %-12s %-4s %6d %10.2f %10.2f %10.2f %6.1f%%   (%dx%d, %d threads, "
            "%.1f fps)\n", "frame", "", "", p->frames, frame, p->frames ? p->frame_min : 0.0,
            p->frame_max, 100.0, p->width, p->height, p->threads,
            frame > 0 ? 1000.0 / frame : 0.0);
    for (int pass = 0; pass < 2; pass++)
        for (int r = 0; r < p->rows_count; r++) {
            const struct ssg_profile_row *row = &p->rows[r];
            int in_frame = row->calls == p->frames;
            if (in_frame != !pass)
                continue;
            double avg = average(row->sum, row->calls);
            char gpu[32] = "-", share[16] = "     -", name[64];
            if (row->backend[0] == 'g')
                snprintf(gpu, sizeof gpu, "%.2f", average(row->gpu_sum, row->calls));
            if (in_frame && frame > 0)
                snprintf(share, sizeof share, "%5.1f%%", 100.0 * avg / frame);
            snprintf(name, sizeof name, "%s%s", in_frame ? "  " : "", row->name);
            fprintf(f, "%-18s %-12s %-4s %6d %10.2f %10.2f %10.2f %7s %10s %10.2f\n", name,
                    row->type, row->backend, row->calls, avg, row->calls ? row->min : 0.0,
                    row->max, share, gpu, row->prepare_ms);
        }
}

static void write_json(FILE *f, const void *user)
{
    const struct ssg_profile *p = user;
    double frame = average(p->frame_sum, p->frames);
    fprintf(f, "{\n  \"frames\": %d, \"width\": %d, \"height\": %d, \"threads\": %d,\n",
            p->frames, p->width, p->height, p->threads);
    fprintf(f, "  \"frame\": {\"avg_ms\": %.6g, \"min_ms\": %.6g, \"max_ms\": %.6g},\n", frame,
            p->frames ? p->frame_min : 0.0, p->frame_max);
    fputs("  \"nodes\": [", f);
    for (int r = 0; r < p->rows_count; r++) {
        const struct ssg_profile_row *row = &p->rows[r];
        double avg = average(row->sum, row->calls);
        char share[32] = "null"; /* sinks run once, outside the frame */
        if (row->calls == p->frames && frame > 0)
            snprintf(share, sizeof share, "%.6g", avg / frame);
        fprintf(f, "%s\n    {\"name\": \"%s\", \"type\": \"%s\", \"backend\": \"%s\", "
                "\"calls\": %d, \"avg_ms\": %.6g, \"min_ms\": %.6g, \"max_ms\": %.6g, "
                "\"share\": %s, \"gpu_avg_ms\": %.6g, \"transfer_avg_ms\": %.6g, "
                "\"prepare_ms\": %.6g}", r ? "," : "", row->name, row->type, row->backend,
                row->calls, avg, row->calls ? row->min : 0.0, row->max, share,
                average(row->gpu_sum, row->calls),
                average(row->xfer_sum, row->calls), row->prepare_ms);
    }
    fputs("\n  ]\n}\n", f);
}

enum ssg_err ssg_profile_write_json(const struct ssg_profile *p, const char *path,
                                    struct ssg_diags *diags)
{
    return ssg_write_text_file(path, "profile", write_json, p, diags);
}
