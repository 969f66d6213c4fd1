/* camera_path.h - the camera of a scene's path at a time or a frame (docs/time.md).
 *
 * camera_key paths: centripetal Catmull-Rom (alpha 0.5, Yuksel et al. 2011) through the
 * keys' positions and, separately, their targets, the end keys duplicated; up (then
 * re-normalised) and fov linear between keys; before the first key and after the last the
 * camera stays at that key. A key with cut = 1 splits the path: the pieces are evaluated
 * apart (each with its own duplicated ends), so the camera holds the key before the cut
 * until the cut's time and jumps there. An orbit circles its target in closed form.
 * Pure functions of the path: thread-safe. */
#ifndef SSG_CAMERA_PATH_H
#define SSG_CAMERA_PATH_H

#include "scene/scene.h"

/* 1 when the path moves the camera (keys or an orbit), 0 for a static camera. */
int ssg_camera_path_active(const struct ssg_camera_path *path);
/* The camera at time t (seconds); an inactive path leaves *out as it is. */
void ssg_camera_path_eval(const struct ssg_camera_path *path, double t, struct ssg_camera *out);
/* The piece of the path time t falls in: how many cut keys lie at or before t. */
int ssg_camera_path_piece(const struct ssg_camera_path *path, double t);
/* The camera of frame `frame` (time frame / fps), and *cut = 1 when a cut lies between the
 * frame before and this one (never in frame 0). */
void ssg_camera_path_frame(const struct ssg_camera_path *path, int frame,
                           struct ssg_camera *out, int *cut);
/* Moves the camera and its target `offset` along the camera's right axis (parallel
 * stereo eyes, ssg_overrides.eye_offset). */
void ssg_camera_shift(struct ssg_camera *camera, float offset);
/* 1 when two cameras differ in anything a node may read. */
int ssg_camera_differs(const struct ssg_camera *a, const struct ssg_camera *b);

#endif
