/* camera.c - the scene camera's view matrix (scene.h): world -> view for the frame
 * conventions of node.h (the camera looks down -z, x right, y up). */
#include <math.h>

#include "lang/params.h"
#include "scene/scene.h"

int ssg_camera_frame_box(const float lo[3], const float hi[3], const float dir[3],
                         struct ssg_camera *camera)
{
    if (!(lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2]))
        return 0;
    float c[3], r = 0.0f;
    for (int i = 0; i < 3; i++) {
        c[i] = 0.5f * (lo[i] + hi[i]);
        r += 0.25f * (hi[i] - lo[i]) * (hi[i] - lo[i]);
    }
    r = fmaxf(sqrtf(r), 1e-3f);
    float dist = 1.1f * r / sinf(0.5f * SSG_DEFAULT_FOV_Y * 3.14159265f / 180.0f);
    for (int i = 0; i < 3; i++) {
        camera->position[i] = c[i] + dist * dir[i];
        camera->target[i] = c[i];
        camera->up[i] = i == 1 ? 1.0f : 0.0f;
    }
    camera->fov_y = SSG_DEFAULT_FOV_Y;
    camera->near_z = fmaxf(0.01f * dist, dist - 1.5f * r);
    camera->far_z = dist + 2.0f * r;
    return 1;
}

void ssg_camera_view_matrix(const struct ssg_camera *camera, float m[16])
{
    const float *eye = camera->position;
    float f[3], s[3], u[3];
    for (int i = 0; i < 3; i++)
        f[i] = camera->target[i] - eye[i];
    float fl = sqrtf(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (int i = 0; i < 3; i++)
        f[i] = fl > 0.0f ? f[i] / fl : (i == 2 ? -1.0f : 0.0f);
    const float *up = camera->up;
    const float alt[3] = {fabsf(f[1]) < 0.9f ? 0.0f : 1.0f, fabsf(f[1]) < 0.9f ? 1.0f : 0.0f,
                          0};
    for (int attempt = 0; attempt < 2; attempt++, up = alt) {
        s[0] = f[1] * up[2] - f[2] * up[1];
        s[1] = f[2] * up[0] - f[0] * up[2];
        s[2] = f[0] * up[1] - f[1] * up[0];
        float sl = sqrtf(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
        if (sl > 1e-8f) { /* else up is parallel to the view: retry with another axis */
            s[0] /= sl, s[1] /= sl, s[2] /= sl;
            break;
        }
    }
    u[0] = s[1] * f[2] - s[2] * f[1];
    u[1] = s[2] * f[0] - s[0] * f[2];
    u[2] = s[0] * f[1] - s[1] * f[0];
    /* rows: x = s, y = u, z = -f (the camera looks down -z) */
    for (int i = 0; i < 3; i++) {
        m[4 * i] = s[i];
        m[4 * i + 1] = u[i];
        m[4 * i + 2] = -f[i];
        m[4 * i + 3] = 0.0f;
    }
    m[12] = -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]);
    m[13] = -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
    m[14] = f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2];
    m[15] = 1.0f;
}

static int within(const float v[3])
{
    for (int i = 0; i < 3; i++)
        if (!(fabsf(v[i]) <= SSG_PARAM_ABS_MAX)) /* NaN fails too */
            return 0;
    return 1;
}

static const char *fault(enum ssg_camera_part *part, enum ssg_camera_part which,
                         const char *why)
{
    *part = which;
    return why;
}

const char *ssg_camera_fault(const struct ssg_camera *c, enum ssg_camera_part *part)
{
    float f[3]; /* the direction as ssg_camera_view_matrix makes it */
    double ff = 0, uu = 0, x[3], xx = 0;
    *part = SSG_CAMERA_FINE;
    if (!within(c->position) || !within(c->target))
        return fault(part, SSG_CAMERA_POSITION, "a coordinate of position or target is not "
                     "finite or lies past +-1e9 (the scene format's limit, which keeps the "
                     "view direction and its square finite floats)");
    if (!within(c->up))
        return fault(part, SSG_CAMERA_UP, "a coordinate of up is not finite or lies past "
                     "+-1e9");
    for (int i = 0; i < 3; i++) {
        f[i] = c->target[i] - c->position[i];
        ff += (double)f[i] * f[i];
        uu += (double)c->up[i] * c->up[i];
    }
    if (ff == 0)
        return fault(part, SSG_CAMERA_TARGET, "the target is the position (in float): no "
                     "direction to look in");
    x[0] = (double)f[1] * c->up[2] - (double)f[2] * c->up[1];
    x[1] = (double)f[2] * c->up[0] - (double)f[0] * c->up[2];
    x[2] = (double)f[0] * c->up[1] - (double)f[1] * c->up[0];
    for (int i = 0; i < 3; i++)
        xx += x[i] * x[i];
    if (!(xx > 1e-12 * ff * uu) || uu == 0)
        return fault(part, SSG_CAMERA_UP, "up is zero or parallel to the view direction");
    if (!(c->fov_y >= SSG_CAMERA_FOV_MIN && c->fov_y <= 180 - SSG_CAMERA_FOV_MIN))
        return fault(part, SSG_CAMERA_FOV, "fov_y must lie in [0.001, 179.999] degrees");
    if (!(c->near_z > 0 && c->far_z > c->near_z && isfinite(c->far_z)))
        return fault(part, SSG_CAMERA_PLANES, "near and far must be finite with "
                     "0 < near < far");
    return NULL;
}

const char *ssg_camera_part_arg(enum ssg_camera_part part)
{
    static const char *const args[] = {"position", "position", "target", "up", "fov", "far"};
    return args[part];
}
