/* fuzz_image.c - libFuzzer target for image and light-probe loading: the input, named by
 * its magic bytes (.exr, .png, .hdr, else .img), is read as an image by OpenImageIO
 * (ssg_image_read: every layout, tiled or scanline, every channel count) and then as a
 * scene's environment probe (the probe checks and tables of core/scene/env.h); its layers
 * are listed (ssg_image_layers) and read by their names. See
 * fuzz_input.h. */
#define _DEFAULT_SOURCE /* mkstemps */
#include "fuzz_input.h"
#include "ssgraph.h"

static const char *suffix_of(const uint8_t *data, size_t size)
{
    if (fuzz_has_magic(data, size, "\x76\x2f\x31\x01", 4))
        return ".exr";
    if (fuzz_has_magic(data, size, "\x89PNG", 4))
        return ".png";
    if (fuzz_has_magic(data, size, "#?", 2))
        return ".hdr";
    return ".img";
}

/* The image as the environment of a one-plane scene: what `environment(image=...)` does. */
static void load_as_probe(const char *image)
{
    char scene[4096], text[4200];
    if (!fuzz_write_temp((const uint8_t *)"", 0, ".scene", scene))
        return;
    int n = snprintf(text, sizeof text, "plane()\nenvironment(image=\"%s\")\n", image);
    FILE *f = fopen(scene, "w");
    if (f && n > 0 && fwrite(text, 1, (size_t)n, f) == (size_t)n && fclose(f) == 0) {
        struct ssg_diags diags = {0};
        ssg_scene_check(scene, &diags);
    } else if (f) {
        fclose(f);
    }
    unlink(scene);
}

/* Its layers as `ssgraph layers` lists them, the first few read by the names listed. */
static void load_layers(const char *path)
{
    static struct ssg_layer_info layers[SSG_LAYERS_MAX];
    struct ssg_diags diags = {0};
    int count = 0;
    if (ssg_image_layers(path, layers, SSG_LAYERS_MAX, &count, &diags) != SSG_OK)
        return;
    for (int i = 0; i < count && i < 4; i++) {
        struct ssg_image *im = NULL;
        struct ssg_diags d = {0};
        ssg_image_read(path, layers[i].name[0] ? layers[i].name : NULL, &im, &d);
        ssg_image_destroy(&im);
    }
}

static void load_image(const char *path)
{
    struct ssg_diags diags = {0};
    struct ssg_image *im = NULL;
    load_layers(path);
    if (ssg_image_read(path, NULL, &im, &diags) == SSG_OK) {
        ssg_image_destroy(&im);
        load_as_probe(path);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_on_file(data, size, suffix_of(data, size), load_image);
    return 0;
}
