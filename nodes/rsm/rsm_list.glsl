// rsm_list.glsl - `rsm` on GL, second pass (rsm_gl.c): one invocation walks the slots in slot
// order, as rsm_vpl.c's ssg_rsm_list, keeping the non-empty ones with the running sum of
// their weights (the CDF; one order of additions, the CPU's) and their count. A running sum
// is one thread's work. llvmpipe ends any shader loop after 65535 iterations, so each
// dispatch takes `rows` rows of slots (at most SSG_RSM_GL_ITERATIONS slots) and carries the
// count and the sum to the next in `state` (exact: r32f holds the float sum, and counts
// below 2^24).
uniform sampler2DArray cells;
layout(r32f) uniform writeonly image2DArray list;
layout(r32f) uniform image2DArray state; // (count, cdf)
#pragma ssg_consts
uniform int row0;  // this dispatch's first row; rows (a constant): how many it takes

void main()
{
    if (ssg_outside(ssg_pixel()) || ssg_pixel() != ivec2(0))
        return;
    ivec2 size = textureSize(cells, 0).xy;
    int n = row0 == 0 ? 0 : int(imageLoad(state, ivec3(0, 0, 0)).r);
    precise float cdf = row0 == 0 ? 0.0 : imageLoad(state, ivec3(0, 0, 1)).r;
    for (int gy = row0; gy < min(row0 + rows, size.y); gy++)
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
    imageStore(state, ivec3(0, 0, 0), vec4(float(n)));
    imageStore(state, ivec3(0, 0, 1), vec4(cdf));
}
