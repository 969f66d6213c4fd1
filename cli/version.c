/* version.c - `ssgraph --version` (version.h): the version and what this build and this
 * machine provide, found at run time: the backends, the GL platform the GL backend opens
 * (EGL on a GPU, else OSMesa), and the Embree and OpenImageIO libraries the process loaded.
 * OpenImageIO comes with the module libssgraph_oiio.so, which is opened with dlopen on the
 * first image read (core/io/oiio_module.h): --version opens it on purpose, every other
 * command that does not read or write an image still starts without it. */
#define _GNU_SOURCE /* dl_iterate_phdr */
#include <limits.h>
#include <link.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ssgraph.h"
#include "version.h"

struct library {
    const char *stem;  /* "libembree3.so": the file name starts so */
    char path[PATH_MAX]; /* where it was loaded from, its links resolved; "" = not loaded */
};

static int find_library(struct dl_phdr_info *info, size_t size, void *user)
{
    (void)size;
    struct library *lib = user;
    const char *base = strrchr(info->dlpi_name, '/');
    base = base ? base + 1 : info->dlpi_name;
    if (strncmp(base, lib->stem, strlen(lib->stem)))
        return 0;
    if (!realpath(info->dlpi_name, lib->path))
        snprintf(lib->path, sizeof lib->path, "%s", info->dlpi_name);
    return 1;
}

/* "name: 3.13.5 (path)": the version is the loaded file's (libembree3.so.3.13.5 once its
   links are resolved), as Debian's packages name their libraries. */
static void print_library(const char *name, const char *stem)
{
    struct library lib = {.stem = stem};
    dl_iterate_phdr(find_library, &lib);
    if (!lib.path[0]) {
        printf("%s: not loaded\n", name);
        return;
    }
    const char *so = strstr(strrchr(lib.path, '/') ? strrchr(lib.path, '/') : lib.path, ".so.");
    printf("%s: %s (%s)\n", name, so ? so + 4 : "version unknown", lib.path);
}

/* The GL platform as a run would open it (SSG_GL_PLATFORM: auto, egl, osmesa). */
static void print_gl(void)
{
    struct ssg_diags d = {0};
    const char *want = getenv("SSG_GL_PLATFORM");
    printf("gl platforms: EGL on a GPU device, else OSMesa (SSG_GL_PLATFORM=%s)\n",
           want && *want ? want : "auto");
    char gl[256];
    if (ssg_gl_info(gl, sizeof gl, &d) == SSG_OK) {
        printf("gl: %s\n", gl);
    } else {
        printf("gl: unavailable: %s\n", d.count ? d.items[0].message : "unknown cause");
    }
}

static void print_oiio(void)
{
    struct ssg_diags d = {0};
    struct ssg_image *none = NULL;
    /* The empty path is no image: the read fails, after the module was opened. */
    ssg_image_read("", NULL, &none, &d);
    ssg_image_destroy(&none);
    struct library module = {.stem = "libssgraph_oiio.so"};
    dl_iterate_phdr(find_library, &module);
    if (!module.path[0]) {
        printf("openimageio: unavailable: %s\n", d.count ? d.items[0].message : "no module");
        return;
    }
    print_library("openimageio", "libOpenImageIO.so");
    printf("openimageio module: %s\n", module.path);
}

int ssg_cli_version(void)
{
    printf("ssgraph %s\n", SSG_VERSION);
    printf("backends: cpu, gl (OpenGL 4.5 core)\n");
    print_gl();
    print_library("embree", "libembree3.so");
    print_oiio();
    return 0;
}
