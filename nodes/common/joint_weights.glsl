// joint_weights.glsl - the weight of one tap of the joint (cross) bilateral filters on GL,
// the twin of the CPU's add_tap (nodes/bilateral/bilateral_math.h, constants from
// nodes/common/joint_weights.h): bilateral.glsl and upsample.glsl include it. The
// including shader declares the normal term's normal_power, normal_min and squarings
// (#pragma ssg_consts) and defines NORMALS (0 or 1).
//
// Weight of the tap at q of depth image dtex and normal image ntex, with spatial log-weight
// es, for a centre of depth dc, kd = depth_scale / dc and unit normal nc: relative depth
// term, normal term by squarings (power 2^m) or p ln(c), one exp; `precise` keeps the
// CPU's roundings.
float joint_weight(sampler2DArray dtex, sampler2DArray ntex, ivec2 q, float es, float dc,
                   float kd, vec3 nc)
{
    float dq = ssg_load1(dtex, q);
    precise float delta = (dq - dc) * kd;
    precise float e = es - 0.5 * delta * delta;
    precise float wn = 1.0, c0 = 1.0;
#if NORMALS
    vec3 nq = ssg_load3(ntex, q);
    c0 = nc.x * nq.x + nc.y * nq.y + nc.z * nq.z;
    wn = ssg_normal_factor(c0 >= normal_min ? c0 : 1.0, float(normal_power), squarings, e);
#endif
    precise float w = ssg_exp_neg(e) * wn;
    w = w >= 1e-30 ? w : 0.0;
    w = dq > 0.0 ? w : 0.0; // background lends nothing
#if NORMALS
    w = c0 >= normal_min ? w : 0.0;
#endif
    return w;
}
