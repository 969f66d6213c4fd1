/* scene_info.h - `ssgraph check FILE.scene` (scene_info.c): loads the scene with its meshes
 * and prints what a newcomer needs to see before the first render: the bounds, the
 * triangles of each mesh line, the camera, the lights, and a scale hint when the scene's
 * size does not suit the AO radius of the default graph. Single-threaded, as the CLI. */
#ifndef SSG_CLI_SCENE_INFO_H
#define SSG_CLI_SCENE_INFO_H

#include <stdio.h>

#include "ssgraph.h"

/* The AO radius of the default graph (graphs/ssdo.graph's ssdo radius), scene units: the
   scale the hint compares the scene's bounding-box diagonal with. */
#define SSG_CLI_DEFAULT_AO_RADIUS 0.5f

/* Loads and validates the scene at path (problems go to diags) and, when it loads, prints
 * "PATH: ok" and its summary to out. */
enum ssg_err ssg_cli_check_scene(const char *path, FILE *out, struct ssg_diags *diags);

#endif
