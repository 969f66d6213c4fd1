/* shadowmap.c - the bounding sphere and map frames of shadowmap.h. */
#include <float.h>

#include "scene/scene.h"
#include "scene/scene_shapes.h"
#include "common/shadowmap.h"
#include "common/sampling.h"

struct ssg_bounding_sphere ssg_scene_bounding_sphere(const struct ssg_scene *scene)
{
    struct ssg_bounding_sphere s = {{0, 0, 0}, 1.0f};
    float lo[3] = {FLT_MAX, FLT_MAX, FLT_MAX}, hi[3] = {-FLT_MAX, -FLT_MAX, -FLT_MAX};
    int any = 0;
    for (int m = 0; scene && m < scene->mesh_count; m++) {
        if (scene->meshes[m].triangle_count < 1)
            continue;
        ssg_mesh_bounds(&scene->meshes[m], lo, hi); /* grows lo, hi */
        any = 1;
    }
    if (!any)
        return s;
    double r2 = 0.0;
    for (int k = 0; k < 3; k++) {
        s.centre[k] = 0.5f * (lo[k] + hi[k]);
        r2 += 0.25 * ((double)hi[k] - lo[k]) * ((double)hi[k] - lo[k]);
    }
    s.radius = (float)(sqrt(r2) * 1.001);
    if (!(s.radius > 0.0f))
        s.radius = 1.0f; /* a single point: any positive size frames it */
    return s;
}

struct ssg_shadow_frame ssg_shadow_frame_make(const struct ssg_bounding_sphere *sphere,
                                              const float l[3])
{
    struct ssg_shadow_frame f;
    ssg_sampling_basis(l[0], l[1], l[2], f.u, f.v); /* u x v = l */
    for (int k = 0; k < 3; k++) {
        f.l[k] = l[k];
        f.origin[k] = sphere->centre[k] + sphere->radius * l[k];
    }
    f.radius = sphere->radius;
    return f;
}
