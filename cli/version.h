/* version.h - `ssgraph --version` (version.c): the version, then one line per build
 * feature as this machine provides it: the backends, the GL platform and renderer, the
 * Embree and OpenImageIO versions. It opens GL and the OpenImageIO module, so it takes
 * a moment; nothing else calls it. */
#ifndef SSG_CLI_VERSION_H
#define SSG_CLI_VERSION_H

/* Prints it all to stdout; returns the exit status (0). */
int ssg_cli_version(void);

#endif
