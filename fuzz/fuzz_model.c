/* fuzz_model.c - libFuzzer target for the model files Assimp reads (core/scene/model.h):
 * the input is an OBJ, PLY, DAE, 3DS or STL file, told apart by its first bytes as a
 * user's file would be by its name, pre-checked (model_check.c) and read through Assimp
 * in this process (ssg_model_load_here). The child process and its limits, which turn a
 * crash or a hang into an error in ssgraph itself, would hide exactly what fuzzing looks
 * for here: a crash, hang or blow-up the pre-checks let through. A .mtl or texture the
 * file names resolves next to the temporary file, and is missing. */
#define _DEFAULT_SOURCE /* mkstemps */
#include "fuzz_input.h"
#include "scene/model.h"

static void load_model(const char *path)
{
    char why[1024];
    struct ssg_model_up up;
    struct ssg_gltf *g = NULL;
    if (ssg_model_load_here(path, &g, &up, why, sizeof why) == SSG_OK)
        ssg_gltf_destroy(&g);
}

/* The extension by content: "ply", XML, a 3DS main chunk (0x4D4D, "MM"), "solid" or a
   binary STL header starting "STLB"; anything else is OBJ, whose reader takes any text. */
static const char *suffix_of(const uint8_t *data, size_t size)
{
    if (fuzz_has_magic(data, size, "ply", 3))
        return ".ply";
    if (fuzz_has_magic(data, size, "<", 1))
        return ".dae";
    if (fuzz_has_magic(data, size, "MM", 2))
        return ".3ds";
    if (fuzz_has_magic(data, size, "solid", 5) || fuzz_has_magic(data, size, "STLB", 4))
        return ".stl";
    return ".obj";
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_on_file(data, size, suffix_of(data, size), load_model);
    return 0;
}
