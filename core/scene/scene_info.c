/* scene_info.c - what `ssgraph check` tells about a loaded scene besides "ok": its bounds
 * and whether its size suits the AO radius (scene.h). Reads the scene only. */
#include <math.h>

#include "scene/scene.h"
#include "scene/scene_shapes.h"

void ssg_scene_bounds(const struct ssg_scene *s, float lo[3], float hi[3])
{
    for (int i = 0; i < 3; i++) {
        lo[i] = HUGE_VALF;
        hi[i] = -HUGE_VALF;
    }
    for (int i = 0; i < s->mesh_count; i++)
        ssg_mesh_bounds(&s->meshes[i], lo, hi);
}

/* Screen-space AO sees occluders within its radius: a model a thousand radii across has
   no occlusion to find, one a hundredth of a radius across is all occlusion. Only the
   mesh lines' models count: planes, boxes and spheres are written in the scene's own units,
   and a floor a hundred radii wide is an ordinary room. Between 1/20 and 200 radii a model
   may be in metres or centimetres alike, so only millimetres (or kilometres) get a hint. */
float ssg_scene_scale_hint(const struct ssg_scene *s, float radius, float *diagonal)
{
    float lo[3] = {HUGE_VALF, HUGE_VALF, HUGE_VALF}, hi[3] = {-HUGE_VALF, -HUGE_VALF, -HUGE_VALF};
    float d2 = 0.0f;
    for (int m = 0; m < s->model_count; m++)
        for (int i = 0; i < s->models[m].mesh_count; i++)
            ssg_mesh_bounds(&s->meshes[s->models[m].first_mesh + i], lo, hi);
    *diagonal = 0.0f;
    if (!(lo[0] <= hi[0]) || !(radius > 0.0f))
        return 0.0f;
    for (int i = 0; i < 3; i++)
        d2 += (hi[i] - lo[i]) * (hi[i] - lo[i]);
    *diagonal = sqrtf(d2);
    if (*diagonal >= radius / 20.0f && *diagonal <= radius * 200.0f)
        return 0.0f;
    if (!(*diagonal > 0.0f))
        return 0.0f; /* a single point or a flat line: no size to scale */
    return powf(10.0f, roundf(log10f(8.0f * radius / *diagonal)));
}
