/* graph_time.c - a graph in time (docs/time.md): which camera each frame of a run sees,
 * which frame it follows on from, and the public calls that ask for a frame's camera
 * (ssg_graph_camera_at) and choose the next frame of a live graph (ssg_graph_set_frame).
 *
 * Frame f is at time f / fps (the scene's frame_rate, 30 without one). A scene with a
 * camera path gives frame f the path's camera (camera_path.h), moved by the graph's
 * eye_offset; a scene without one keeps its camera in every frame. A frame follows on from
 * the one before (prev_camera = that frame's camera, history kept) unless it is the first
 * frame of a run (a live graph's run follows on from its last frame when it runs the next
 * one), a cut of the path lies between them, or ssg_graph_set_view set a new camera. */
#include <string.h>

#include "scene/radical_inverse.h" /* the Halton points the halton node also draws */
#include "graph/graph.h"
#include "scene/camera_path.h"

static double frames_per_second(const struct ssg_graph *g)
{
    return g->scene && g->scene->camera_path.fps > 0 ? g->scene->camera_path.fps : 30.0;
}

/* Frame `frame`'s camera from the path (the scene's current camera without one) and
   whether a cut lies just before it. */
static void frame_camera(const struct ssg_graph *g, int frame, struct ssg_camera *out,
                         int *cut)
{
    const struct ssg_camera_path *path = &g->scene->camera_path;
    *out = g->scene->camera;
    *cut = 0;
    if (!ssg_camera_path_active(path))
        return;
    ssg_camera_path_frame(path, frame, out, cut);
    if (g->eye_offset != 0.0f)
        ssg_camera_shift(out, g->eye_offset);
}

/* Makes `camera` the one every node sees (ctx->scene->camera, ctx->frame's fov and
   planes), as ssg_graph_set_view does. */
static void use_camera(struct ssg_graph *g, const struct ssg_camera *camera)
{
    g->scene->camera = *camera;
    g->frame.fov_y = camera->fov_y;
    g->frame.near_z = camera->near_z;
    g->frame.far_z = camera->far_z;
    struct ssg_diags quiet = {0};
    ssg_graph_reinfer(g, &quiet); /* shapes do not depend on the camera; checks may read it */
}

/* Frame `frame`'s sub-pixel jitter under a `jitter N` line (ssg_frame.jitter_x, _y):
   the Halton points (2, 3) of index 1 .. N in turn, less 0.5, so that the offsets cover
   the pixel evenly with their mean near its centre (Karis, High Quality Temporal
   Supersampling, SIGGRAPH 2014); index 0, the corner, is left out. */
static void jitter_of(const struct ssg_graph *g, int frame, float *jx, float *jy)
{
    *jx = *jy = 0.0f;
    if (g->jitter > 0) {
        uint64_t i = (uint64_t)(frame % g->jitter) + 1;
        *jx = (float)(ssg_halton_radical_inverse(i, 2) - 0.5);
        *jy = (float)(ssg_halton_radical_inverse(i, 3) - 0.5);
    }
}

/* Makes frame `frame`'s jitter the one every node sees (ssg_frame); 1 if it moved. */
static int frame_jitter(struct ssg_graph *g, int frame)
{
    float jx, jy;
    jitter_of(g, frame, &jx, &jy);
    int moved = jx != g->frame.jitter_x || jy != g->frame.jitter_y;
    g->frame.jitter_x = jx;
    g->frame.jitter_y = jy;
    return moved;
}

int ssg_time_begin(struct ssg_graph *g, int frame, int first, int frames, int live,
                   struct ssg_time_step *step)
{
    step->time_s = (float)(frame / frames_per_second(g)); /* as the path's (camera_path.c) */
    step->reset = 1;
    int jittered = frame_jitter(g, frame); /* the camera's readers see it, as a move */
    if (!g->scene)
        return jittered;
    struct ssg_camera camera = g->scene->camera;
    int cut = 0, moved = jittered;
    if (!(g->time.view_set && frames == 1))
        frame_camera(g, frame, &camera, &cut);
    if (ssg_camera_differs(&camera, &g->scene->camera)) {
        use_camera(g, &camera);
        moved = 1;
    }
    /* frame - 1, not last + 1: last may be INT_MAX (ssg_graph_set_frame), frame is >= 0 */
    int follows = first ? live && g->time.has_last && frame - 1 == g->time.last : 1;
    step->reset = !follows || cut;
    step->prev = step->reset ? camera : g->time.last_camera;
    /* prepare() reads the previous camera too (gbuffer's motion): in the frame after the
       camera stops, the camera is the same but the previous one is not. */
    if (g->time.has_prepared_prev && ssg_camera_differs(&step->prev, &g->time.prepared_prev))
        moved = 1; /* (before any prepare there is nothing to redo) */
    g->time.prepared_prev = step->prev;
    g->time.has_prepared_prev = 1;
    return moved;
}

void ssg_time_end(struct ssg_graph *g, int frame)
{
    g->time.last = frame;
    g->time.has_last = 1;
    g->time.kept_frame = frame;
    if (g->scene)
        g->time.last_camera = g->scene->camera;
}

enum ssg_err ssg_graph_camera_at(const struct ssg_graph *g, int frame, struct ssg_view *out,
                                 struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_graph_camera_at", "graph, out", 2, g, out))
        return SSG_E_USAGE;
    if (!g->scene || frame < 0) {
        ssg_diag_file(diags, g->scene ? SSG_E_VALUE : SSG_E_SCENE, g->path, "no camera for "
                      "frame %d: %s", frame, g->scene ? "frames count from 0" :
                      "the graph has no scene");
        return g->scene ? SSG_E_VALUE : SSG_E_SCENE;
    }
    struct ssg_camera c;
    int cut;
    frame_camera(g, frame, &c, &cut);
    memcpy(out->position, c.position, sizeof out->position);
    memcpy(out->target, c.target, sizeof out->target);
    memcpy(out->up, c.up, sizeof out->up);
    out->fov_y = c.fov_y;
    return SSG_OK;
}

enum ssg_err ssg_graph_jitter_at(const struct ssg_graph *g, int frame, float jitter[2],
                                 struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_graph_jitter_at", "graph, jitter", 2, g, jitter))
        return SSG_E_USAGE;
    if (frame < 0) {
        ssg_diag_file(diags, SSG_E_VALUE, g->path, "no jitter for frame %d: frames count "
                      "from 0", frame);
        return SSG_E_VALUE;
    }
    jitter_of(g, frame, &jitter[0], &jitter[1]);
    return SSG_OK;
}

enum ssg_err ssg_graph_set_frame(struct ssg_graph *g, int frame, struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_graph_set_frame", "graph", 1, g))
        return SSG_E_USAGE;
    if (frame < 0) {
        ssg_diag_file(diags, SSG_E_VALUE, g->path, "frame %d: frames count from 0", frame);
        return SSG_E_VALUE;
    }
    g->time.next = frame;
    g->time.view_set = 0;
    return SSG_OK;
}
