/* fuzz_gltf.c - libFuzzer target for glTF loading: the input is a .glb (binary magic) or a
 * .gltf (JSON) file, read through tinygltf and flattened into meshes, materials, textures
 * and a camera (core/scene/gltf.h). Buffers it names resolve next to the temporary file, so a
 * finding that needs one names a missing or special file (a URI of /dev/zero, say). */
#define _DEFAULT_SOURCE /* mkstemps */
#include "fuzz_input.h"
#include "scene/gltf.h"

static void load_gltf(const char *path)
{
    char why[512];
    struct ssg_gltf *g = NULL;
    if (ssg_gltf_load(path, &g, why, sizeof why) == SSG_OK)
        ssg_gltf_destroy(&g);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_on_file(data, size, fuzz_has_magic(data, size, "glTF", 4) ? ".glb" : ".gltf",
                 load_gltf);
    return 0;
}
