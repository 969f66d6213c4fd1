/* fuzz_gltf.c - libFuzzer target for glTF loading: the input is a .glb (binary magic) or a
 * .gltf (JSON) file, read through tinygltf and flattened into meshes, materials, textures
 * and a camera (core/gltf.h). Buffers it names resolve next to the temporary file, so a
 * finding that needs one names a missing or special file (a URI of /dev/zero, say). */
#define _DEFAULT_SOURCE /* mkstemps */
#include "fuzz_input.h"
#include "gltf.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[4096], why[512];
    const char *suffix = fuzz_has_magic(data, size, "glTF", 4) ? ".glb" : ".gltf";
    if (!fuzz_write_temp(data, size, suffix, path))
        return 0;
    struct ssg_gltf *g = NULL;
    if (ssg_gltf_load(path, &g, why, sizeof why) == SSG_OK)
        ssg_gltf_destroy(&g);
    unlink(path);
    return 0;
}
