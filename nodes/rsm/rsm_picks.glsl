// rsm_picks.glsl - `rsm` on GL, third pass (rsm_gl.c): invocation (k, t) makes draw k of the
// pixels at cell t of the offset tile, rsm_vpl.c's ssg_rsm_pick: the smallest i with
// CDF > (k + offset[t]) / S x total (ssg_rsm_search), the same for every such pixel.
uniform sampler2DArray list, count;
layout(std430, binding = 1) readonly buffer Offsets { float offset[]; };
layout(r32f) uniform writeonly image2DArray pick;
#pragma ssg_consts
// inv_samples (a constant): 1 / samples

float cdf(int i, int w) { return texelFetch(list, ivec3(i % w, i / w, 11), 0).r; }

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    int n = int(texelFetch(count, ivec3(0, 0, 0), 0).r), w = textureSize(list, 0).x;
    int lo = 0, hi = n - 1;
    if (n > 0) {
        precise float u = (float(p.x) + offset[p.y]) * inv_samples * cdf(n - 1, w);
        while (lo < hi) {
            int mid = (lo + hi) >> 1;
            if (cdf(mid, w) > u)
                hi = mid;
            else
                lo = mid + 1;
        }
    }
    imageStore(pick, ivec3(p, 0), vec4(float(lo)));
}
