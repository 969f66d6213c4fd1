/* model.c - ssg_model_load (model.h): picks the reader of a mesh file. glTF 2.0 stays on
 * tinygltf, which honours more of glTF 2.0 than Assimp's importer (texture coordinate
 * sets, the file's camera, bounds-checked accessors under fuzzing); a glTF that declares
 * version 1 goes to Assimp, which still reads 1.0; every other extension goes to Assimp
 * when the installed build knows it. Every file is pre-checked first (model_check.c), and
 * Assimp runs in a child process under limits (model_sandbox.c). */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "lang/files.h"
#include "scene/model.h"

/* The extension of path's last component, with its dot, lower-cased into ext; "" when
   there is none (or it does not fit). */
static void extension_of(const char *path, char *ext, size_t len)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash + 1 : path, '.');
    ext[0] = 0;
    if (!dot || dot[1] == 0 || strlen(dot) >= len)
        return;
    size_t i = 0;
    for (; dot[i]; i++)
        ext[i] = (char)tolower((unsigned char)dot[i]);
    ext[i] = 0;
}

static int is_gltf(const char *ext)
{
    return !strcmp(ext, ".gltf") || !strcmp(ext, ".glb");
}

int ssg_model_supported(const char *path, char *why, size_t why_len)
{
    char ext[16];
    extension_of(path, ext, sizeof ext);
    if (ext[0] && (is_gltf(ext) || ssg_assimp_supports(ext)))
        return 1;
    if (ext[0])
        snprintf(why, why_len, "unsupported model format '%s' (expected %s)", ext,
                 SSG_MODEL_FORMATS);
    else
        snprintf(why, why_len, "no file extension to tell the model format by (expected %s)",
                 SSG_MODEL_FORMATS);
    return 0;
}

/* The major version a glTF file declares (0: none or unreadable; tinygltf then says). */
static int gltf_major(const char *path)
{
    char *data = NULL, why[256];
    size_t len = 0;
    int major = 0, draco = 0;
    if (ssg_input_read(path, SSG_MAX_MODEL_BYTES, &data, &len, why, sizeof why) == SSG_OK)
        ssg_gltf_sniff(data, len, &major, &draco);
    free(data);
    return major;
}

enum ssg_err ssg_model_precheck(const char *path, char *why, size_t why_len)
{
    char ext[16], reason[512];
    int fd;
    struct stat st;
    enum ssg_err e = ssg_input_open(path, SSG_MAX_MODEL_BYTES, &fd, reason, sizeof reason);
    if (e) {
        snprintf(why, why_len, "%s: %s", path, reason);
        return e;
    }
    extension_of(path, ext, sizeof ext);
    if (fstat(fd, &st) || st.st_size == 0) { /* nothing to map: Assimp says what is wrong */
        close(fd);
        return SSG_OK;
    }
    /* Mapped, not read: a 1 GB model costs no second gigabyte to check */
    void *data = mmap(NULL, (size_t)st.st_size, PROT_READ, MAP_PRIVATE, fd, 0);
    close(fd);
    if (data == MAP_FAILED) {
        snprintf(why, why_len, "%s: cannot map it to check it: %s", path, strerror(errno));
        return SSG_E_IO;
    }
    e = ssg_model_precheck_bytes(path, ext, data, (size_t)st.st_size, why, why_len);
    munmap(data, (size_t)st.st_size);
    return e;
}

/* What ssg_model_load_up and ssg_model_load_here share: the checks, and the glTF 2.0 path;
   *done 0 when the file is for Assimp. */
static enum ssg_err prepare(const char *path, struct ssg_gltf **out, struct ssg_model_up *up,
                            char *why, size_t why_len, int *done)
{
    char ext[16], reason[512];
    *done = 1;
    if (out)
        *out = NULL;
    *up = (struct ssg_model_up){.axis = -1, .sign = 1};
    enum ssg_err e = ssg_input_check(path, SSG_MAX_MODEL_BYTES, reason, sizeof reason);
    if (e) { /* a directory, a FIFO or /dev/zero is refused for what it is, first */
        snprintf(why, why_len, "%s: %s", path, reason);
        return e;
    }
    if (!ssg_model_supported(path, reason, sizeof reason)) {
        snprintf(why, why_len, "%s: %s", path, reason);
        return SSG_E_GLTF;
    }
    if ((e = ssg_model_precheck(path, why, why_len)))
        return e;
    extension_of(path, ext, sizeof ext);
    if (is_gltf(ext) && gltf_major(path) != 1) {
        *up = (struct ssg_model_up){.axis = 1, .sign = 1,
                                    .basis = "the glTF 2.0 specification (+Y up)"};
        return out ? ssg_gltf_load(path, out, why, why_len) : SSG_OK;
    }
    *done = 0;
    return SSG_OK;
}

enum ssg_err ssg_model_load_up(const char *path, struct ssg_gltf **out,
                               struct ssg_model_up *up, char *why, size_t why_len)
{
    int done;
    enum ssg_err e = prepare(path, out, up, why, why_len, &done);
    if (done)
        return e;
    struct stat st;
    struct ssg_model_limits limits;
    ssg_model_limits_default(stat(path, &st) ? 0 : (long long)st.st_size, &limits);
    return ssg_model_sandbox(path, ssg_assimp_load, &limits, out, up, why, why_len);
}

enum ssg_err ssg_model_load_here(const char *path, struct ssg_gltf **out,
                                 struct ssg_model_up *up, char *why, size_t why_len)
{
    int done;
    enum ssg_err e = prepare(path, out, up, why, why_len, &done);
    return done ? e : ssg_assimp_load(path, out, up, why, why_len);
}

enum ssg_err ssg_model_load(const char *path, struct ssg_gltf **out, char *why,
                            size_t why_len)
{
    struct ssg_model_up up;
    return ssg_model_load_up(path, out, &up, why, why_len);
}
