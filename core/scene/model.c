/* model.c - ssg_model_load (model.h): picks the reader of a mesh file. glTF 2.0 stays on
 * tinygltf, which honours more of glTF 2.0 than Assimp's importer (texture coordinate
 * sets, the file's camera, bounds-checked accessors under fuzzing); a glTF that declares
 * version 1 goes to Assimp, which still reads 1.0; every other extension goes to Assimp
 * when the installed build knows it. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

enum ssg_err ssg_model_load(const char *path, struct ssg_gltf **out, char *why,
                            size_t why_len)
{
    char ext[16], reason[512];
    *out = NULL;
    enum ssg_err e = ssg_input_check(path, SSG_MAX_MODEL_BYTES, reason, sizeof reason);
    if (e) { /* a directory, a FIFO or /dev/zero is refused for what it is, first */
        snprintf(why, why_len, "%s: %s", path, reason);
        return e;
    }
    if (!ssg_model_supported(path, reason, sizeof reason)) {
        snprintf(why, why_len, "%s: %s", path, reason);
        return SSG_E_GLTF;
    }
    extension_of(path, ext, sizeof ext);
    if (is_gltf(ext) && gltf_major(path) != 1)
        return ssg_gltf_load(path, out, why, why_len);
    return ssg_assimp_load(path, out, why, why_len);
}
