/* write_meta.c - what the `write` node's EXR records of the run that made it (imageio.h,
 * struct ssg_exr_meta; the attribute names are listed in the README, "EXR metadata"): the
 * scene's camera and OpenEXR's two camera matrices, the frame, the seed, the graph file and
 * the --set overrides. Per-node timings are not recorded: they differ from run to run, and
 * the same inputs must give the same bytes (`--profile-json` has them). */
#include <math.h>
#include <string.h>

#include "io/imageio.h"
#include "scene/scene.h"
#include "write.h"

/* OpenEXR's camera space is left-handed, +z forward; ours looks down -z. Both matrices are
   row-vector (p' = p M), which is the layout of our column-major arrays. */
static void world_to_camera(const struct ssg_camera *cam, float m[16])
{
    ssg_camera_view_matrix(cam, m);
    for (int r = 0; r < 4; r++)
        m[4 * r + 2] = -m[4 * r + 2];
}

/* OpenEXR's NDC: (0, 0) the top left and (1, 1) the bottom right of the frame (the guard
   band, cropped at write, lies outside), after the divide by w = camera z; z runs from 0
   at the near plane to 1 at the far one. */
static void camera_to_ndc(const struct ssg_frame *f, float p[16])
{
    float ty = tanf(f->fov_y * 0.5f * 3.14159265358979f / 180.0f);
    float tx = ty * (float)f->width / (float)(f->height > 0 ? f->height : 1);
    float range = f->far_z - f->near_z;
    memset(p, 0, 16 * sizeof *p);
    p[0] = 0.5f / tx;       /* x: [0][0] */
    p[5] = -0.5f / ty;      /* y: [1][1], down */
    p[8] = 0.5f;            /* [2][0]: + 0.5 w */
    p[9] = 0.5f;            /* [2][1] */
    p[10] = range > 0 ? f->far_z / range : 1.0f;              /* [2][2] */
    p[11] = 1.0f;                                             /* [2][3]: w = z */
    p[14] = range > 0 ? -f->far_z * f->near_z / range : 0.0f; /* [3][2] */
}

static void multiply(const float a[16], const float b[16], float out[16])
{
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++) {
            float sum = 0.0f;
            for (int k = 0; k < 4; k++)
                sum += a[4 * r + k] * b[4 * k + c];
            out[4 * r + c] = sum;
        }
}

void ssg_write_meta(const struct ssg_node_ctx *ctx, struct ssg_exr_meta *m)
{
    const struct ssg_frame *f = ctx->frame;
    const struct ssg_scene *scene = ctx->scene;
    memset(m, 0, sizeof *m);
    m->fov_y = f->fov_y;
    m->near_z = f->near_z;
    m->far_z = f->far_z;
    m->width = f->width;
    m->height = f->height;
    m->guard = f->guard;
    m->seed = f->seed;
    m->graph = ctx->graph_path;
    m->sets = ctx->sets;
    m->set_count = ctx->set_count;
    if (!scene)
        return;
    m->scene = scene->path;
    m->lights = scene->lights_path;
    m->has_camera = 1;
    memcpy(m->position, scene->camera.position, sizeof m->position);
    memcpy(m->target, scene->camera.target, sizeof m->target);
    memcpy(m->up, scene->camera.up, sizeof m->up);
    float ndc[16];
    world_to_camera(&scene->camera, m->world_to_camera);
    camera_to_ndc(f, ndc);
    multiply(m->world_to_camera, ndc, m->world_to_ndc);
    for (int i = 0; i < 16; i++) { /* -0 + 0 = +0: no negative zeros in the header */
        m->world_to_camera[i] += 0.0f;
        m->world_to_ndc[i] += 0.0f;
    }
}
