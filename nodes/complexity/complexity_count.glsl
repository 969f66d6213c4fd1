// complexity_count.glsl - last pass of the `complexity` node's GL side (mapping in
// README.md, C side complexity_gl.c): per pixel w = the max of its cell's weight over
// the grids (grid r has cells of side p_scale << r, as prepare() lays them out, nearest,
// no filtering), then the count p_levels[min(L - 1, floor(w L))], L = p_levels_count;
// background pixels get the lowest level (w = 0).
uniform sampler2DArray depth, normal;
uniform sampler2DArray t0, t1, t2, t3; // weights of grids 0..3 (unused ones unbound)
layout(r32f) uniform writeonly image2DArray dst_count;
#pragma ssg_params

#include "complexity_surface.glsl" // is_surface, the CPU's test

// The larger of w and grid r's weight at pixel p; a NaN weight leaves w (as on the CPU).
float max_cell(float w, sampler2DArray t, ivec2 p, int r)
{
    float v = texelFetch(t, ivec3(p / (p_scale << r), 0), 0).r;
    return v > w ? v : w;
}

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    float w = 0.0;
    if (is_surface(ssg_load1(depth, p), ssg_load3(normal, p))) {
        w = max_cell(w, t0, p, 0);
        if (p_resolutions > 1)
            w = max_cell(w, t1, p, 1);
        if (p_resolutions > 2)
            w = max_cell(w, t2, p, 2);
        if (p_resolutions > 3)
            w = max_cell(w, t3, p, 3);
    }
    int level = min(int(w * float(p_levels_count)), p_levels_count - 1);
    SSG_STORE1(dst_count, p, float(p_levels[level]));
}
