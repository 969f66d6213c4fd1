/* scene_info.h - `ssgraph check FILE.scene` and `ssgraph check MODEL` (scene_info.c). A
 * scene is loaded with its meshes and printed as a newcomer needs to see it before the
 * first render: the bounds, the triangles of each mesh line with each mesh's box after the
 * line's transform and an up-axis hint, the camera, the lights, and a scale hint when the
 * scene's size does not suit the AO radius of the default graph. A model file alone gets
 * its meshes, bounds, up axis, scale hint and a scene to paste around it. Single-threaded,
 * as the CLI. */
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

/* 1 when `check` should take path for a model file: an extension the model reader knows
   (core/scene/model.h), and not .scene or .graph. */
int ssg_cli_is_model(const char *path);

/* Loads the model at path (a problem goes to diags, at its line and column where the file
 * has them) and prints "PATH: ok", its meshes with their boxes, its bounds, its up axis
 * and on what that rests, a scale hint, and a scene file to paste around it. */
enum ssg_err ssg_cli_check_model(const char *path, FILE *out, struct ssg_diags *diags);

#endif
