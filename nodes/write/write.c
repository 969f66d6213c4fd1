/* write.c - the `write` sink node's descriptor and check: the frame as a float EXR with
 * named layers and an 8-bit PNG preview. Method and file layout: README.md. */
#include <stdio.h>
#include <string.h>

#include "io/imageio.h"
#include "write.h"

SSG_PORT_TABLE(inputs, SSG_WRITE_IN);

static const char *const ssg_write_tonemap_choices[] = {"clamp", "reinhard", "aces", NULL};
static const char *const ssg_write_compression_choices[] = {"zip", "none", "rle", "piz", NULL};
SSG_PARAMS_TABLE(param_table, ssg_write_params, SSG_WRITE_PARAMS);

int ssg_write_name_ok(const char *name, char *why, size_t why_len)
{
    const char *problem = NULL;
    size_t len = strlen(name);
    for (const unsigned char *c = (const unsigned char *)name; *c; c++)
        if (*c < 0x20 || *c == 0x7f) { /* not echoed: a newline would split the message */
            snprintf(why, why_len, "name is not a plain file name: it contains a control "
                     "character (0x%02x at byte %d)", *c, (int)(c - (const unsigned char *)name));
            return 0;
        }
    if (len == 0)
        problem = "it is empty";
    else if (len > 200)
        problem = "it is longer than 200 bytes";
    else if (strchr(name, '/') || strchr(name, '\\'))
        problem = "it contains a path separator";
    else if (strstr(name, ".."))
        problem = "it contains '..'";
    else if (name[0] == '.')
        problem = "it starts with '.' (hidden names are kept for temporary files)";
    if (problem)
        snprintf(why, why_len, "name '%s' is not a plain file name: %s", name, problem);
    return problem == NULL;
}

static enum ssg_err write_check(const void *params, const struct ssg_frame *frame,
                                const struct ssg_shape *in, struct ssg_shape *out, char *why,
                                size_t why_len)
{
    const struct ssg_write_params *p = params;
    if (!ssg_write_name_ok(p->name, why, why_len))
        return SSG_E_VALUE;
    if (!p->png && !p->exr) {
        snprintf(why, why_len, "png and exr are both off: nothing to write");
        return SSG_E_VALUE;
    }
    return SSG_OK;
}

void ssg_write_stem(const struct ssg_write_params *p, int frame_index, char *stem, size_t len)
{
    if (p->sequence)
        snprintf(stem, len, "%.200s_%04d", p->name, frame_index);
    else
        snprintf(stem, len, "%.200s", p->name);
}

static int output_files(const void *params, int frame_index, char (*files)[SSG_FILE_NAME_MAX],
                        int max)
{
    const struct ssg_write_params *p = params;
    char stem[224];
    int n = 0;
    ssg_write_stem(p, frame_index, stem, sizeof stem);
    if (p->exr && n < max)
        snprintf(files[n++], SSG_FILE_NAME_MAX, "%s.exr", stem);
    if (p->png && n < max)
        snprintf(files[n++], SSG_FILE_NAME_MAX, "%s.png", stem);
    return n;
}

/* A sequence writes in every frame; otherwise the last frame only (graph_run.c). */
static int every_frame(const void *params)
{
    return ((const struct ssg_write_params *)params)->sequence;
}

const struct ssg_node_desc ssg_node_write = {
    .name = "write",
    .summary = "write the image as a float EXR with named layers and an 8-bit PNG preview",
    .method = "OpenEXR, 32-bit float, ZIP (zlib level 1); PNG tone curves: Reinhard et al. "
              "2002 eq. 3, Narkowicz 2015 ACES fit; sRGB encoding IEC 61966-2-1",
    SSG_NODE_INPUTS(inputs),
    .extra_inputs = 1,
    .extra_same_size = 1, /* one EXR part: every layer has the frame's size */
    SSG_NODE_PARAMS(param_table, struct ssg_write_params),
    .is_sink = 1,
    .reads = SSG_READS_INPUTS | SSG_READS_LIGHTS | SSG_READS_CAMERA,
    .check = write_check,
    .output_files = output_files,
    .every_frame = every_frame,
    .run_cpu = ssg_write_run_cpu,
};
