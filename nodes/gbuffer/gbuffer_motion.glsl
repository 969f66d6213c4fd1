// gbuffer_motion.glsl - the G-buffer's motion to the previous frame on GL (README.md,
// `motion`): each pixel's surface point, from its depth and the pixel's ray, moved into
// the previous camera's view and projected, with gbuffer_cpu.c's motion() operation by
// operation (`precise`: no fused multiply-adds the CPU does not make).
uniform sampler2DArray first;  // the first layer's depth (0 = background)
layout(r32f) uniform writeonly image2DArray dst_motion;
#pragma ssg_consts
// proj (f, cx, cy), inv_f (1 / f rounded on the CPU), prev_f (the previous frame's focal
// length), m_rot (this view -> the previous view, row-major), m_move (this camera's
// position in the previous view), near_z: gbuffer.h's rows

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    float t = texelFetch(first, ivec3(p, 0), 0).r;
    // the ray with view z = -1 (gbuffer_cpu.c's make_rays)
    precise float vx = (float(p.x) + 0.5 - proj.y) * inv_f;
    precise float vy = -(float(p.y) + 0.5 - proj.z) * inv_f;
    precise float inv_t = t > 0.0 ? 1.0 / t : 0.0;
    precise float qx = m_rot[0] * vx + m_rot[1] * vy - m_rot[2] + m_move.x * inv_t;
    precise float qy = m_rot[3] * vx + m_rot[4] * vy - m_rot[5] + m_move.y * inv_t;
    precise float zq = 0.0 - (m_rot[6] * vx + m_rot[7] * vy - m_rot[8] + m_move.z * inv_t);
    precise float z = t > 0.0 ? t * zq : 0.0;
    bool seen = z >= near_z;
    precise float d = seen ? zq : 1.0;
    precise float df = prev_f - proj.x;
    precise float mx = prev_f * (qx / d - vx) + df * vx;
    precise float my = 0.0 - (prev_f * (qy / d - vy) + df * vy);
    SSG_STORE3(dst_motion, p, seen ? vec3(mx, my, z) : vec3(0.0, 0.0, z));
}
