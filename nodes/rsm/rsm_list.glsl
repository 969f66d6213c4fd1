// rsm_list.glsl - `rsm` on GL, second pass (rsm_gl.c): one invocation walks the slots in slot
// order, as rsm_vpl.c's ssg_rsm_list, keeping the non-empty ones with the running sum of
// their weights (the CDF; one order of additions, the CPU's) and their count. A running sum
// is one thread's work; it reads each slot's 11 floats once.
uniform sampler2DArray cells;
layout(r32f) uniform writeonly image2DArray list, count;

void main()
{
    if (ssg_outside(ssg_pixel()) || ssg_pixel() != ivec2(0))
        return;
    ivec2 size = textureSize(cells, 0).xy;
    int n = 0;
    precise float cdf = 0.0;
    for (int gy = 0; gy < size.y; gy++)
        for (int gx = 0; gx < size.x; gx++) {
            float w = texelFetch(cells, ivec3(gx, gy, 10), 0).r;
            if (!(w > 0.0))
                continue;
            ivec2 at = ivec2(n % size.x, n / size.x);
            for (int k = 0; k < 11; k++)
                imageStore(list, ivec3(at, k), vec4(texelFetch(cells, ivec3(gx, gy, k), 0).r));
            cdf += w;
            imageStore(list, ivec3(at, 11), vec4(cdf));
            n++;
        }
    imageStore(count, ivec3(0, 0, 0), vec4(float(n)));
}
