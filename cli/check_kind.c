/* check_kind.c - what `ssgraph check FILE` takes a file for (check_kind.h). */
#define _DEFAULT_SOURCE
#include "check_kind.h"

#include <fcntl.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "ssgraph.h"

int ssg_cli_is_model(const char *path)
{
    size_t len = strlen(path);
    char why[512];
    if ((len > 6 && !strcmp(path + len - 6, ".scene")) ||
        (len > 6 && !strcmp(path + len - 6, ".graph")))
        return 0;
    return ssg_model_supported(path, why, sizeof why);
}

/* Known by their first bytes (a model is known by its extension first, so a binary .glb
   or .stl never gets here). */
const char *ssg_cli_not_checkable(const char *path)
{
    static const struct {
        const char *magic;
        size_t len;
        const char *kind;
    } images[] = {{"\x89PNG\r\n\x1a\n", 8, "a PNG image"}, {"v/1\x01", 4, "an OpenEXR image"},
                  {"\xff\xd8\xff", 3, "a JPEG image"}, {"#?RADIANCE", 10, "a Radiance HDR image"},
                  {"#?RGBE", 6, "a Radiance HDR image"}, {"II*\0", 4, "a TIFF image"},
                  {"MM\0*", 4, "a TIFF image"}, {"GIF8", 4, "a GIF image"}};
    char head[4096];
    struct stat st;
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0)
        return NULL;
    ssize_t n = !fstat(fd, &st) && S_ISREG(st.st_mode) ? pread(fd, head, sizeof head, 0) : -1;
    close(fd);
    for (size_t i = 0; i < sizeof images / sizeof images[0]; i++)
        if (n >= (ssize_t)images[i].len && !memcmp(head, images[i].magic, images[i].len))
            return images[i].kind;
    return n > 0 && memchr(head, 0, (size_t)n) ? "a binary file (it holds NUL bytes)" : NULL;
}
