/* imageio_load.c - the C side of imageio.h and text.h: hands EXR and PNG files to the
 * formats built into the library (formats.h: OpenEXRCore, libpng) by their first bytes, and
 * every other format, and text, to the OpenImageIO module (oiio_module.h), which it opens on
 * first use; the whole-file writers (stage, then commit) and the tone curves are here too.
 * Opening the module is timed and reported as a one-off load (graph/profile.h), so a run's
 * table shows it on a line of its own instead of in the node that met the first JPEG.
 *
 * The module is looked for in $SSGRAPH_MODULE_DIR alone when that is set, else next to
 * the program or library that holds this code and in its ssgraph/ folder (an installed
 * libssgraph.so: lib/ and lib/ssgraph/), next to the running program and where
 * `cmake --install` puts it relative to the program's bin/ (../lib/ssgraph), in the build
 * tree it was built in, and in the configured install directory (each place once). The
 * relative places make an installed tree movable. A
 * process opens it at most once (pthread_once), so concurrent first calls are safe; a
 * failure to open it is remembered and reported by every call. */
#define _GNU_SOURCE /* dladdr */
#include <dlfcn.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "graph/exec.h"
#include "graph/profile.h"
#include "io/formats.h"
#include "io/oiio_module.h"
#include "io/tonemap.h"

#ifndef SSG_MODULE_BUILD_DIR
#define SSG_MODULE_BUILD_DIR ""
#endif
#ifndef SSG_MODULE_INSTALL_DIR
#define SSG_MODULE_INSTALL_DIR ""
#endif
#ifndef SSG_MODULE_FROM_BINDIR /* the module directory relative to the installed bin/ */
#define SSG_MODULE_FROM_BINDIR "../lib/ssgraph"
#endif

static const struct ssg_oiio_host host = {
    .diag_file = ssg_diag_file,
    .image_create = ssg_image_create,
    .image_destroy = ssg_image_destroy,
    .image_size_ok = ssg_image_size_ok,
    .input_open = ssg_input_open,
};

static pthread_once_t module_once = PTHREAD_ONCE_INIT;
static const struct ssg_oiio_api *module_api;
static char module_why[1024];

/* dir = the directory part of path ("" when it has none); path may be dir itself. */
static void dir_of(const char *path, char *dir, size_t len)
{
    if (path != dir)
        snprintf(dir, len, "%s", path);
    char *slash = strrchr(dir, '/');
    if (slash)
        *slash = '\0';
    else
        dir[0] = '\0';
}

/* The directory of the program or shared library this code was linked into, as the
   dynamic linker names it: for the program, the name it was started by, which has no
   directory when a shell found it on PATH (exe_dir covers that case). */
static void own_dir(char *dir, size_t len)
{
    Dl_info info;
    dir[0] = '\0';
    if (dladdr((void *)own_dir, &info) && info.dli_fname)
        dir_of(info.dli_fname, dir, len);
}

/* The running program's directory, symbolic links resolved (/proc/self/exe). */
static void exe_dir(char *dir, size_t len)
{
    ssize_t n = readlink("/proc/self/exe", dir, len - 1);
    dir[n > 0 ? n : 0] = '\0';
    dir_of(dir, dir, len);
}

/* Adds "; " and a formatted reason to module_why (cut at its size: it is a message). */
static void add_why(const char *fmt, ...)
{
    size_t used = strlen(module_why);
    if (used)
        used += (size_t)snprintf(module_why + used, sizeof module_why - used, "; ");
    if (used >= sizeof module_why)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(module_why + used, sizeof module_why - used, fmt, ap);
    va_end(ap);
}

/* Opens dir/libssgraph_oiio.so and asks it for its api; 1 when that worked. The reason
   of a failure is appended to module_why. */
static int try_dir(const char *dir)
{
    if (!dir || !dir[0])
        return 0;
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, SSG_OIIO_MODULE_FILE);
    void *lib = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
        const char *e = dlerror();
        /* a missing file is the normal case of the search: name the directory only */
        int missing = e && strstr(e, "No such file");
        if (missing)
            add_why("%s", dir);
        else
            add_why("%s: %s", path, e ? e : "dlopen failed");
        return 0;
    }
    ssg_oiio_module_fn entry;
    void *sym = dlsym(lib, SSG_OIIO_MODULE_ENTRY);
    memcpy(&entry, &sym, sizeof sym); /* POSIX: object pointer to function pointer */
    module_api = entry ? entry(SSG_OIIO_MODULE_ABI, &host) : NULL;
    if (!module_api) {
        add_why("%s: not a module of this ssgraph (ABI %d)", path, SSG_OIIO_MODULE_ABI);
        dlclose(lib);
        return 0;
    }
    return 1; /* stays loaded until exit, like every library it pulls in */
}

static void search_module(void)
{
    const char *chosen = getenv("SSGRAPH_MODULE_DIR");
    if (chosen && chosen[0]) {
        try_dir(chosen);
        return;
    }
    char mine[4096], exe[4096], mine_installed[4200], exe_installed[4200];
    own_dir(mine, sizeof mine);
    exe_dir(exe, sizeof exe);
    mine_installed[0] = exe_installed[0] = '\0'; /* "" is skipped */
    if (mine[0])
        snprintf(mine_installed, sizeof mine_installed, "%s/ssgraph", mine);
    if (exe[0])
        snprintf(exe_installed, sizeof exe_installed, "%s/%s", exe, SSG_MODULE_FROM_BINDIR);
    /* installed places before the build tree: an installed program must not pick up the
       module of a build tree it was installed from (a later build may have changed it) */
    const char *dirs[] = {mine,          mine_installed,       exe,
                          exe_installed, SSG_MODULE_BUILD_DIR, SSG_MODULE_INSTALL_DIR};
    const size_t count = sizeof dirs / sizeof dirs[0];
    for (size_t i = 0; i < count; i++) {
        /* the program's two names for its directory usually agree: one try each place */
        size_t seen = 0;
        while (seen < i && strcmp(dirs[seen], dirs[i]) != 0)
            seen++;
        if (seen == i && try_dir(dirs[i]))
            return;
    }
}

/* Opens the module, timed: the 0.3-0.7 s of dynamic linking it costs are a one-off load
   of the process, not the work of whatever asked for the first image. */
static void open_module(void)
{
    double t0 = ssg_now_ms();
    search_module();
    ssg_load_note("OpenImageIO module", t0, ssg_now_ms());
}

/* The module's api, or NULL with a diagnostic on `file`. */
static const struct ssg_oiio_api *oiio(struct ssg_diags *diags, const char *file)
{
    pthread_once(&module_once, open_module);
    if (!module_api)
        ssg_diag_file(diags, SSG_E_BACKEND, file ? file : "",
                      "cannot load ssgraph's OpenImageIO module %s (searched: %s); set "
                      "SSGRAPH_MODULE_DIR to the directory that holds it",
                      SSG_OIIO_MODULE_FILE, module_why[0] ? module_why : "nowhere");
    return module_api;
}

enum ssg_image_format ssg_image_format_of(int fd)
{
    static const unsigned char exr[4] = {0x76, 0x2f, 0x31, 0x01},
                               png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    unsigned char head[8];
    ssize_t n = pread(fd, head, sizeof head, 0);
    if (n >= 4 && memcmp(head, exr, sizeof exr) == 0)
        return SSG_FORMAT_EXR;
    if (n >= 8 && memcmp(head, png, sizeof png) == 0)
        return SSG_FORMAT_PNG;
    return SSG_FORMAT_OTHER;
}

int ssg_image_plausible(const char *path, int w, int h, int nch, long long file_bytes,
                        struct ssg_diags *diags)
{
    const double max_ratio = 65536.0, slack_bytes = 64.0 * 1024 * 1024;
    double pixels = (double)w * (double)h * nch * sizeof(float);
    if (pixels <= (double)file_bytes * max_ratio + slack_bytes)
        return 1;
    ssg_diag_file(diags, SSG_E_IMAGE, path, "not a readable image: its header declares %d x "
                  "%d pixels, far more than a file of %lld bytes can hold (truncated or "
                  "forged)", w, h, file_bytes);
    return 0;
}

/* Opens path for reading (files.h: a regular file of a sane size) and names its format;
   SSG_OK with *fd open, else the error reported. */
static enum ssg_err open_image(const char *path, int *fd, enum ssg_image_format *format,
                               struct ssg_diags *diags)
{
    char why[320];
    enum ssg_err e = ssg_input_open(path, SSG_MAX_IMAGE_BYTES, fd, why, sizeof why);
    if (e) {
        ssg_diag_file(diags, e, path, "cannot read image: %s", why);
        return e;
    }
    *format = ssg_image_format_of(*fd);
    return SSG_OK;
}

/* A PNG holds the main image only: any other layer is missing. */
static enum ssg_err read_png(const char *path, int fd, const char *layer,
                             struct ssg_image **out, struct ssg_diags *diags)
{
    if (layer && layer[0]) {
        ssg_diag_file(diags, SSG_E_CHANNELS, path, "no layer '%s' (layers in the file: "
                      "(unnamed))", layer);
        return SSG_E_CHANNELS;
    }
    return ssg_png_read_fd(path, fd, 0, out, diags);
}

enum ssg_err ssg_image_read(const char *path, const char *layer, struct ssg_image **out,
                            struct ssg_diags *diags)
{
    if (out)
        *out = NULL;
    if (ssg_api_null(diags, "ssg_image_read", "path, out", 2, path, out))
        return SSG_E_USAGE;
    /* An empty path names no file: the module refuses it, after opening (which `ssgraph
       --version` relies on to name the OpenImageIO it would use). */
    int fd = -1, elsewhere = 0;
    enum ssg_image_format format = SSG_FORMAT_OTHER;
    enum ssg_err e = path[0] ? open_image(path, &fd, &format, diags) : SSG_OK;
    if (e)
        return e;
    if (format == SSG_FORMAT_EXR)
        e = ssg_exr_read_fd(path, fd, layer && layer[0] ? layer : NULL, out, &elsewhere,
                            diags);
    else if (format == SSG_FORMAT_PNG)
        e = read_png(path, fd, layer, out, diags);
    if (fd >= 0)
        close(fd);
    if (format != SSG_FORMAT_OTHER && !elsewhere)
        return e;
    const struct ssg_oiio_api *api = oiio(diags, path);
    return api ? api->image_read(path, layer, out, diags) : SSG_E_BACKEND;
}

enum ssg_err ssg_image_read_data(const char *path, struct ssg_image **out,
                                 struct ssg_diags *diags)
{
    if (out)
        *out = NULL;
    if (ssg_api_null(diags, "ssg_image_read_data", "path, out", 2, path, out))
        return SSG_E_USAGE;
    int fd = -1, elsewhere = 0;
    enum ssg_image_format format = SSG_FORMAT_OTHER;
    enum ssg_err e = open_image(path, &fd, &format, diags);
    if (e)
        return e;
    if (format == SSG_FORMAT_EXR)
        e = ssg_exr_read_fd(path, fd, NULL, out, &elsewhere, diags);
    else if (format == SSG_FORMAT_PNG)
        e = ssg_png_read_fd(path, fd, 1, out, diags);
    close(fd);
    if (format == SSG_FORMAT_OTHER || elsewhere) {
        ssg_diag_file(diags, SSG_E_IMAGE, path, "a data texture (a normal map) must be a PNG "
                      "or an EXR whose values ssgraph reads as stored (this file is neither, "
                      "or an EXR compression only OpenImageIO decodes)");
        ssg_image_destroy(out);
        return SSG_E_IMAGE;
    }
    return e;
}

enum ssg_err ssg_exr_meta_read(const char *path, struct ssg_exr_meta *meta, int *found,
                               struct ssg_diags *diags)
{
    int fd = -1;
    enum ssg_image_format format;
    *found = 0;
    enum ssg_err e = open_image(path, &fd, &format, diags);
    if (e)
        return e;
    if (format == SSG_FORMAT_EXR) /* any other file is foreign: no metadata */
        e = ssg_exr_meta_read_fd(path, fd, meta, found, diags);
    close(fd);
    return e;
}

int ssg_exr_frame_read(const char *spec, struct ssg_frame *frame)
{
    char path[4096];
    snprintf(path, sizeof path, "%s", spec);
    char *colon = strrchr(path, ':');
    if (colon && !strchr(colon, '/'))
        *colon = '\0';
    struct ssg_diags quiet = {0};
    struct ssg_exr_meta m;
    int found = 0;
    if (ssg_exr_meta_read(path, &m, &found, &quiet) || !found)
        return 0;
    frame->fov_y = m.fov_y;
    frame->near_z = m.near_z;
    frame->far_z = m.far_z;
    return 1;
}

enum ssg_err ssg_exr_views_join(const char *path, const char *const *views,
                                const char *const *files, int count, struct ssg_diags *diags)
{
    struct ssg_tmp t;
    enum ssg_err e = ssg_exr_views_stage(path, views, files, count, &t, diags);
    return e ? e : ssg_tmp_commit(&t, 1, diags);
}

enum ssg_err ssg_text_draw(struct ssg_image *im, int x, int y, int size, const char *text,
                           struct ssg_diags *diags)
{
    const struct ssg_oiio_api *api = oiio(diags, "<labels>");
    return api ? api->text_draw(im, x, y, size, text, diags) : SSG_E_BACKEND;
}

enum ssg_err ssg_exr_write(const char *path, const struct ssg_exr_layer *layers, int count,
                           struct ssg_diags *diags)
{
    return ssg_exr_write_compressed(path, layers, count, SSG_EXR_ZIP, diags);
}

enum ssg_err ssg_exr_write_compressed(const char *path, const struct ssg_exr_layer *layers,
                                      int count, enum ssg_exr_compression compression,
                                      struct ssg_diags *diags)
{
    struct ssg_tmp t;
    enum ssg_err e = ssg_exr_stage(path, layers, count, compression, NULL, &t, diags);
    return e ? e : ssg_tmp_commit(&t, 1, diags);
}

enum ssg_err ssg_png_write(const char *path, const struct ssg_image *image,
                           enum ssg_tonemap tonemap, float exposure, struct ssg_diags *diags)
{
    struct ssg_tmp t;
    enum ssg_err e = ssg_png_stage(path, image, tonemap, exposure, &t, diags);
    return e ? e : ssg_tmp_commit(&t, 1, diags);
}

float ssg_tonemap_apply(enum ssg_tonemap tonemap, float exposure, float x)
{
    return ssg_tonemap_scaled(tonemap, x * exp2f(exposure));
}

unsigned char ssg_tonemap_to_srgb8(enum ssg_tonemap tonemap, float exposure, float x)
{
    return ssg_srgb8_scaled(tonemap, exp2f(exposure), x);
}
