/* stereo.h - the files of a stereo run (`ssgraph run --stereo`) put together: each eye's
 * graph run writes into a folder of its own, then ssg_stereo_join makes one multi-view EXR
 * of each EXR the eyes share (imageio.h, ssg_exr_views_join: the first view the default
 * one, the others' channels named layer.VIEW.channel) and moves every other file, the PNG
 * previews among them, next to it as STEM_VIEW.EXT (ssao_left.png, ssao_right.png).
 * The eye folders are removed at the end either way (ssg_stereo_discard), and a killed run's
 * by the next stereo run into the same folder (ssg_stereo_sweep).
 * Thread safety: none needed; touches only the folders it is given. */
#ifndef SSG_STEREO_H
#define SSG_STEREO_H

#include "ssgraph.h"

/* dirs[k] holds view views[k]'s files (count views, the first the default); the results go
   to out_dir, which is created if missing, each announced to log ("wrote out/ssao.exr";
   NULL = not). Every problem goes to diags. */
enum ssg_err ssg_stereo_join(const char *out_dir, const char *const *dirs,
                             const char *const *views, int count, ssg_log_fn log,
                             void *user, struct ssg_diags *diags);

/* Removes the plain files in each of the count folders, then the folders (a failed run's
   leftovers); a missing folder is no error. */
void ssg_stereo_discard(const char *const *dirs, int count);

/* Removes the eye folders (".stereo-VIEW-PID") in out_dir that a killed stereo run left:
   those whose process is gone. Called by each stereo run before it starts. */
void ssg_stereo_sweep(const char *out_dir);

#endif
