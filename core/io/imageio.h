/* imageio.h - image files: EXR and PNG read and written by the library itself (formats.h:
 * OpenEXRCore, libpng), every other format read through the OpenImageIO module
 * (oiio_module.h, opened only when such a file is met), all behind this C header.
 *
 * Reading is ssg_image_read (ssgraph.h), which picks the reader by a file's first bytes,
 * never by its name. Writing covers what the `write` node needs: a multi-layer 32-bit float
 * EXR (ZIP, deflate level 1) and an 8-bit PNG preview whose tone mapping and sRGB encoding
 * happen here, in one place, so every caller previews images the same way.
 *
 * Both writers write a hidden temporary file next to the target (".stem.tmp-PID-N.ext",
 * same directory, so rename() is atomic) and rename it into place only once it is complete;
 * on any failure the temporary file is removed and the target is left untouched. Output is
 * byte-deterministic: the same pixels give the same bytes, whatever the thread count (no
 * time stamps, no host or software name in the headers but ssgraph's own `software`).
 *
 * Colour: EXR data is written and read as is (linear). PNG is written sRGB-encoded (with an
 * sRGB chunk); a PNG is decoded to linear on reading unless it says it is not sRGB (a gAMA
 * chunk without an sRGB chunk, read as stored, as OpenImageIO reads it), and other files
 * OpenImageIO reports as sRGB (JPEG, ...) are decoded too, so every image inside ssgraph is
 * linear. Alpha is read as stored (not premultiplied).
 *
 * Errors go to diags with the file name: SSG_E_IO (cannot open, create, write or rename),
 * SSG_E_IMAGE (unreadable or malformed file), SSG_E_SIZE (absurd size), SSG_E_CHANNELS
 * (no such layer, or a layer whose channel count does not fit its kind), SSG_E_VALUE and
 * SSG_E_DUPLICATE (bad or repeated layer names), SSG_E_NOMEM, SSG_E_BACKEND (a format only
 * OpenImageIO reads, and its module cannot be loaded). No C++ exception ever leaves these
 * functions.
 * Thread safety: no state but an atomic counter for temporary names and the module, opened
 * once; separate calls may run in separate threads. */
#ifndef SSG_IMAGEIO_H
#define SSG_IMAGEIO_H

#include "lang/files.h"
#include "ssgraph.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What a layer's channels mean; decides their names in the EXR. */
enum ssg_layer_kind {
    SSG_LAYER_SCALAR, /* 1 channel:  name.Y; the layer `depth` is OpenEXR's depth channel
                         Z (no prefix), which Blender and Nuke read as depth */
    SSG_LAYER_VECTOR, /* 3 channels: name.X, name.Y, name.Z */
    SSG_LAYER_COLOR,  /* 3 channels: name.R, name.G, name.B */
};

/* One layer of an EXR to write. */
struct ssg_exr_layer {
    const char *name;              /* layer name; NULL or "" = the main image, plain
                                      channels whatever the kind: Y (1 channel), R,G (2),
                                      R,G,B (3) or R,G,B,A (4) */
    const struct ssg_image *image; /* planar float; all layers share width and height */
    enum ssg_layer_kind kind;      /* how the channels are named; default SSG_LAYER_SCALAR */
};

/* Lossless EXR compressions, in the order of the write node's `compression` choices. The
 * chunks are compressed on OpenMP's threads and written in order (exr_core.h). Measured on
 * ssao.graph's 18-channel 1280x720 frame on the 2-core development machine, EXR alone with
 * its fsync, CPU ms of both threads (wall ms on a busy machine in brackets; io_micro):
 * zip ~400 (230-410; 15.7 MB), none ~95 (125-290; 66 MB), rle ~315 (165-190; 30 MB),
 * piz ~1050 (530-580; 14.9 MB). OpenImageIO wrote zip in ~700-950 CPU ms.
 * zip stays the default: for intermediates it is the fastest compression that keeps the
 * files small, and none only pays where disk space does not matter. */
enum ssg_exr_compression {
    SSG_EXR_ZIP,  /* deflate level 1 (libdeflate where built with it, else zlib), 16-line
                     chunks (the default) */
    SSG_EXR_NONE,
    SSG_EXR_RLE,
    SSG_EXR_PIZ,
};

/* What an EXR records of the run that made it, as header attributes (README, "EXR
 * metadata"): OpenEXR's standard names where it has them (worldToCamera, worldToNDC,
 * software), `ssgraph:` names otherwise. Nothing in it varies between two identical runs
 * (no time, host or timing), so the same inputs still give the same bytes. */
struct ssg_exr_meta {
    int has_camera;            /* 1 = position, target, up and both matrices are set (the
                                  scene's camera); 0 = none written (no scene) */
    float position[3];         /* camera, world, scene units: ssgraph:camera_position */
    float target[3];           /* world point looked at: ssgraph:camera_target */
    float up[3];               /* world up hint: ssgraph:camera_up */
    float world_to_camera[16]; /* OpenEXR worldToCamera: row vectors (p' = p M), camera
                                  space left-handed, +z forward, x right, y up */
    float world_to_ndc[16];    /* OpenEXR worldToNDC: (0,0) top left, (1,1) bottom right of
                                  the frame after the divide by w; z 0 at near, 1 at far */
    float fov_y;               /* vertical field of view of the frame, degrees: ssgraph:fov */
    float near_z, far_z;       /* scene units: ssgraph:near, ssgraph:far */
    int width, height;         /* the frame, pixels (guard cropped): ssgraph:frame_size */
    int guard;                 /* guard band rendered and cropped, pixels: ssgraph:guard */
    uint64_t seed;             /* ssgraph:seed, a decimal string (64 bits) */
    const char *graph;         /* graph file as given: ssgraph:graph; NULL = not written */
    const char *scene;         /* scene file: ssgraph:scene; NULL or "" = none */
    const char *lights;        /* lights file replacing the scene's: ssgraph:lights */
    const char *const *sets;   /* --set overrides as given: ssgraph:overrides (strings) */
    int set_count;             /* entries of sets; 0 = the attribute is not written */
};

/* Writes all layers into one scanline EXR with 32-bit float channels and ZIP compression.
 * Layer names must be unique, non-empty except for at most one main image, and must not
 * contain '.'. */
enum ssg_err ssg_exr_write(const char *path, const struct ssg_exr_layer *layers, int count,
                           struct ssg_diags *diags);
/* The same with a chosen compression. */
enum ssg_err ssg_exr_write_compressed(const char *path, const struct ssg_exr_layer *layers,
                                      int count, enum ssg_exr_compression compression,
                                      struct ssg_diags *diags);

/* Staged writes (files.h): the file is written whole under its temporary name, synced,
 * and left for ssg_tmp_commit (or ssg_tmp_discard) with the other outputs of the same
 * node, so that no output is renamed into place before all of them are complete. On an
 * error the temporary is already gone. */
enum ssg_err ssg_exr_stage(const char *path, const struct ssg_exr_layer *layers, int count,
                           enum ssg_exr_compression compression,
                           const struct ssg_exr_meta *meta, struct ssg_tmp *t,
                           struct ssg_diags *diags);
/* meta NULL = no metadata attributes. */

/* Reads the metadata an ssgraph EXR carries back (the numbers: camera, fov, near, far,
 * frame, guard, seed; the string fields come back NULL). *found = 1 when the file has
 * ssgraph:fov; 0 for a foreign file (or one that is not an EXR), meta then untouched.
 * Errors: the file cannot be read (SSG_E_IO, SSG_E_IMAGE). */
enum ssg_err ssg_exr_meta_read(const char *path, struct ssg_exr_meta *meta, int *found,
                               struct ssg_diags *diags);

/* ssg_exr_frame_read: in ssgraph.h (public). */

/* Joins single-view EXRs of one size (each an ssgraph EXR, e.g. a stereo run's eyes) into
 * one multi-view EXR (OpenEXR's multi-view convention): a multiView attribute listing
 * views, views[0] the default view whose channels keep their names, each other view's
 * channels named layer.VIEW.channel (R -> right.R, depth's Z -> right.Z, ao.Y ->
 * ao.right.Y). The header is the default view's; each attribute of another view that
 * differs from it (its camera) is added as ssgraph:VIEW:NAME (ssgraph:right:worldToCamera,
 * ssgraph:right:camera_position). Written through a temporary file renamed into place,
 * compressed as the default view's file. */
enum ssg_err ssg_exr_views_join(const char *path, const char *const *views,
                                const char *const *files, int count,
                                struct ssg_diags *diags);

/* Tone mapping of the PNG preview, applied to exposure-scaled linear values. The order
 * matches the `tonemap` choices of the write node. */
enum ssg_tonemap {
    SSG_TONEMAP_CLAMP,    /* min(x, 1): values in [0, 1] shown unchanged */
    SSG_TONEMAP_REINHARD, /* x / (1 + x) (Reinhard et al. 2002, eq. 3) */
    SSG_TONEMAP_ACES,     /* Narkowicz 2015 fit of the ACES filmic curve, clamped to 1 */
};

/* The display value in [0, 1] (linear, before sRGB encoding) of a linear value x scaled
 * by 2^exposure. Negative values and NaN give 0, +inf gives the curve's limit. */
float ssg_tonemap_apply(enum ssg_tonemap tonemap, float exposure, float x);

/* The 8-bit code of a linear value: tone mapped as above, sRGB-encoded (IEC 61966-2-1)
 * and rounded to nearest. */
unsigned char ssg_tonemap_to_srgb8(enum ssg_tonemap tonemap, float exposure, float x);

/* Writes an 8-bit PNG preview of a 1-channel (gray) or 3-channel (RGB) image, every value
 * mapped by ssg_tonemap_to_srgb8. */
enum ssg_err ssg_png_write(const char *path, const struct ssg_image *image,
                           enum ssg_tonemap tonemap, float exposure, struct ssg_diags *diags);
/* The same, staged (see ssg_exr_stage). */
enum ssg_err ssg_png_stage(const char *path, const struct ssg_image *image,
                           enum ssg_tonemap tonemap, float exposure, struct ssg_tmp *t,
                           struct ssg_diags *diags);

#ifdef __cplusplus
}
#endif
#endif
