/* shaders.c - finds a GLSL file compiled into the binary (shaders.h). */
#include <string.h>

#include "shaders.h"

const char *ssg_shader_source(const char *name)
{
    for (const struct ssg_shader_file *f = ssg_shader_files; f->name; f++)
        if (!strcmp(f->name, name))
            return f->source;
    return NULL;
}
