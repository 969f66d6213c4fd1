/* write.c - the `write` sink node: the frame as a 32-bit float EXR with named layers, plus
 * an 8-bit sRGB PNG preview of the main image with exposure and a tone curve.
 *
 * `write(img.out, "ssao", ao=ao.out, depth=g.depth)` writes out/ssao.exr with channels
 * R,G,B (or Y for a scalar image), ao.Y, Z, and out/ssao.png. Extra inputs are named
 * layers: a scalar becomes <key>.Y, a vector <key>.X/Y/Z, a colour <key>.R/G/B; the scalar
 * `depth` is OpenEXR's depth channel, a bare Z. The EXR's header records the run
 * (write_meta.c; README, "EXR metadata").
 * The PNG's tone curve defaults to ACES (Narkowicz 2015 fit): it keeps highlights of the
 * shaded frame from clipping; `tonemap=clamp` shows data in [0, 1] (AO, albedo) unchanged.
 * Files appear complete or not at all (temporary name, then rename; core/io/imageio.h). */
#include <stdio.h>
#include <string.h>

#include "io/imageio.h"
#include "write.h"

static const struct ssg_port_desc inputs[] = {
    [SSG_WRITE_IN_IMAGE] = {.name = "image", .types = SSG_T_COLOR | SSG_T_SCALAR | SSG_T_VECTOR,
     .doc = "main image: EXR channels R,G,B (Y when scalar) and the PNG preview"},
};
_Static_assert(SSG_COUNT(inputs) == SSG_WRITE_INPUTS, "one entry a port enumerator");

static const char *const tonemaps[] = {"clamp", "reinhard", "aces", NULL};
static const char *const compressions[] = {"zip", "none", "rle", "piz", NULL};

static const struct ssg_param_desc param_table[] = {
    {.name = "name", SSG_FIELD_STRING(struct ssg_write_params, name), .required = 1,
     .help = "file stem: writes <out>/<name>.exr and <out>/<name>.png"},
    {.name = "exposure", SSG_FIELD_FLOAT(struct ssg_write_params, exposure), .def = 0,
     .min = -20, .max = 20, .unit = "stops",
     .help = "PNG only: values are scaled by 2^exposure before tone mapping"},
    {.name = "tonemap", SSG_FIELD_ENUM(struct ssg_write_params, tonemap),
     .def = SSG_TONEMAP_ACES, .choices = tonemaps,
     .help = "PNG only: clamp = min(x,1), reinhard = x/(1+x), aces = Narkowicz 2015 fit"},
    {.name = "png", SSG_FIELD_BOOL(struct ssg_write_params, png), .def = 1,
     .help = "write the 8-bit sRGB PNG preview"},
    {.name = "exr", SSG_FIELD_BOOL(struct ssg_write_params, exr), .def = 1,
     .help = "write the 32-bit float EXR with all layers"},
    {.name = "compression", SSG_FIELD_ENUM(struct ssg_write_params, compression),
     .def = SSG_EXR_ZIP, .choices = compressions,
     .help = "EXR compression, all lossless: zip (deflate level 1, chunks on every thread) "
             "is small; none ~1.7x faster to write and ~9x larger; rle and piz are slower"},
};

int ssg_write_name_ok(const char *name, char *why, size_t why_len)
{
    const char *problem = NULL;
    size_t len = strlen(name);
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
    for (const unsigned char *c = (const unsigned char *)name; !problem && *c; c++)
        if (*c < 0x20 || *c == 0x7f)
            problem = "it contains a control character";
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

static int output_files(const void *params, char (*files)[SSG_FILE_NAME_MAX], int max)
{
    const struct ssg_write_params *p = params;
    int n = 0;
    if (p->exr && n < max)
        snprintf(files[n++], SSG_FILE_NAME_MAX, "%.200s.exr", p->name);
    if (p->png && n < max)
        snprintf(files[n++], SSG_FILE_NAME_MAX, "%.200s.png", p->name);
    return n;
}

const struct ssg_node_desc ssg_node_write = {
    .name = "write",
    .summary = "write the image as a float EXR with named layers and an 8-bit PNG preview",
    .method = "OpenEXR, 32-bit float, ZIP (zlib level 1); PNG tone curves: Reinhard et al. "
              "2002 eq. 3, Narkowicz 2015 ACES fit; sRGB encoding IEC 61966-2-1",
    .doc = "Writes <out>/<name>.exr (channels R,G,B or Y of the main image, then one layer per "
           "extra key=port argument: scalar key.Y, vector key.X/Y/Z, colour key.R/G/B; a "
           "scalar depth is the bare channel Z, as Blender and Nuke read depth) and "
           "<out>/<name>.png (main image x 2^exposure, tone-mapped, sRGB-encoded 8-bit; gray "
           "for a scalar image). The tone curve defaults to aces, which keeps the highlights "
           "of a shaded frame from clipping; tonemap=clamp shows data in [0, 1] (AO, albedo) "
           "unchanged. Every layer must have the main image's size (a half-resolution result "
           "is an error when the graph is checked: upsample it first). The output directory "
           "is created if missing. Files are written under a "
           "temporary name and renamed, so a failed run leaves no partial file; the same "
           "pixels always give the same bytes. The EXR's header records the run: camera "
           "(worldToCamera, worldToNDC, ssgraph:camera_position/target/up, ssgraph:fov), "
           "frame, guard, seed, graph file, --set overrides and software (no timings: they "
           "would change the bytes).",
    SSG_NODE_INPUTS(inputs),
    .extra_inputs = 1,
    .extra_same_size = 1, /* one EXR part: every layer has the frame's size */
    SSG_NODE_PARAMS(param_table, struct ssg_write_params),
    .is_sink = 1,
    .check = write_check,
    .output_files = output_files,
    .run_cpu = ssg_write_run_cpu,
};
