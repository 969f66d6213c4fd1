/* fuzz_scene.c - libFuzzer target for the scene format: the input is loaded as a scene
 * file with its assets (entities, materials, shapes tessellated, meshes and images it
 * names read, the ray-tracing scene built). See fuzz_input.h. */
#define _DEFAULT_SOURCE /* mkstemps */
#include "fuzz_input.h"
#include "ssgraph.h"

static void load_scene(const char *path)
{
    struct ssg_diags diags = {0};
    ssg_scene_check(path, &diags);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_on_file(data, size, ".scene", load_scene);
    return 0;
}
