/* shaders.c - finds a GLSL file by name (shaders.h): the copy compiled into the binary, or,
 * when the environment variable SSG_SHADER_DIR names a directory holding a file of that
 * name, that file (so a shader can be edited and rerun without rebuilding ssgraph). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl/shaders.h"

enum { OVERRIDES_MAX = 64, OVERRIDE_MAX_BYTES = 1 << 20 };

/* Files read from SSG_SHADER_DIR, kept for the process (programs are cached too). */
static struct ssg_shader_file overrides[OVERRIDES_MAX];
static int override_count;

static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *text = malloc(OVERRIDE_MAX_BYTES + 1);
    size_t n = text ? fread(text, 1, OVERRIDE_MAX_BYTES, f) : 0;
    fclose(f);
    if (text)
        text[n] = 0;
    return text;
}

static const char *from_directory(const char *name)
{
    const char *dir = getenv("SSG_SHADER_DIR");
    if (!dir || !*dir)
        return NULL;
    for (int i = 0; i < override_count; i++)
        if (!strcmp(overrides[i].name, name))
            return overrides[i].source;
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    char *text = override_count < OVERRIDES_MAX ? read_text(path) : NULL;
    if (!text)
        return NULL;
    overrides[override_count].name = strdup(name);
    overrides[override_count++].source = text;
    return text;
}

const char *ssg_shader_source(const char *name)
{
    const char *text = from_directory(name);
    if (text)
        return text;
    for (const struct ssg_shader_file *f = ssg_shader_files; f->name; f++)
        if (!strcmp(f->name, name))
            return f->source;
    return NULL;
}
