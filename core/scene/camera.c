/* camera.c - the scene camera's view matrix (scene.h): world -> view for the frame
 * conventions of node.h (the camera looks down -z, x right, y up). */
#include <math.h>

#include "scene/scene.h"

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
