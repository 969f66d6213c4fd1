/* peak.c - reading bench/peak's cache and the profile's roofline (peak.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "peak.h"

int ssg_peak_path(char *out, size_t len)
{
    const char *env = getenv("SSGRAPH_PEAK"), *xdg = getenv("XDG_CACHE_HOME");
    const char *home = getenv("HOME");
    int n = -1;
    if (env && env[0])
        n = snprintf(out, len, "%s", env);
    else if (xdg && xdg[0])
        n = snprintf(out, len, "%s/ssgraph/peak.json", xdg);
    else if (home && home[0])
        n = snprintf(out, len, "%s/.cache/ssgraph/peak.json", home);
    return n > 0 && (size_t)n < len;
}

/* The number after "key": in text, or -1. */
static double number_of(const char *text, const char *key)
{
    char quoted[64];
    snprintf(quoted, sizeof quoted, "\"%s\":", key);
    const char *at = strstr(text, quoted);
    return at ? strtod(at + strlen(quoted), NULL) : -1.0;
}

int ssg_peak_load(struct ssg_peak *p)
{
    char path[4096], text[1024];
    memset(p, 0, sizeof *p);
    if (!ssg_peak_path(path, sizeof path))
        return 0;
    FILE *f = fopen(path, "r");
    if (!f)
        return 0;
    size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = '\0';
    double threads = number_of(text, "threads"), gflops = number_of(text, "gflops");
    double gbps = number_of(text, "gbps");
    if (!(threads >= 1 && threads < 1e6 && gflops > 0 && gbps > 0))
        return 0;
    *p = (struct ssg_peak){(int)threads, gflops, gbps};
    return 1;
}

void ssg_rates_of(const struct ssg_run_node *n, int threads, const struct ssg_peak *peak,
                  struct ssg_rates *r)
{
    double s = n->avg_ms * 1e-3;
    *r = (struct ssg_rates){.gflops = -1.0, .fraction = -1.0};
    if (!(s > 0))
        return;
    r->gbps = n->bytes / s * 1e-9;
    if (n->flops >= 0)
        r->gflops = n->flops / s * 1e-9;
    /* Only a CPU run with declared flops against a measured peak: GL runs elsewhere. */
    if (!peak || peak->gbps <= 0 || n->flops < 0 || strcmp(n->backend, "cpu") != 0)
        return;
    double flop_peak = peak->gflops * (threads < peak->threads ? threads : peak->threads) /
                       peak->threads;
    double t_mem = n->bytes / (peak->gbps * 1e9), t_fp = n->flops / (flop_peak * 1e9);
    r->bound = t_mem >= t_fp ? "memory" : "compute";
    r->fraction = (t_mem >= t_fp ? t_mem : t_fp) / s;
}
