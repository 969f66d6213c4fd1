// rsm_strata.glsl - `rsm` on GL, third pass (rsm_gl.c): invocation k (0..samples) finds the
// first VPL of stratum k, as rsm_vpl.c's ssg_rsm_list: the smallest i with CDF > k / S x
// total (ssg_rsm_search), so that a pixel searches only its stratum's VPLs.
uniform sampler2DArray list, count;
layout(r32f) uniform writeonly image2DArray first;
uniform float inv_samples;

float cdf(int i, int w) { return texelFetch(list, ivec3(i % w, i / w, 11), 0).r; }

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    int n = int(texelFetch(count, ivec3(0, 0, 0), 0).r), w = textureSize(list, 0).x;
    int lo = 0, hi = n - 1;
    if (n > 0) {
        precise float u = float(p.x) * inv_samples * cdf(n - 1, w);
        while (lo < hi) {
            int mid = (lo + hi) >> 1;
            if (cdf(mid, w) > u)
                hi = mid;
            else
                lo = mid + 1;
        }
    }
    imageStore(first, ivec3(p.x, 0, 0), vec4(float(lo)));
}
