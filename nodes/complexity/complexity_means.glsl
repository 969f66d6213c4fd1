// complexity_means.glsl - first pass of the `complexity` node's GL side (mapping in
// README.md, C side complexity_gl.c): one invocation per cell of side `side` px, the
// means of its surface pixels' normal, depth and view-space point. Sums run in double and
// in pixel order with the CPU kernel's expressions (complexity_cpu.c, cell_means), so the
// means, rounded to float, are the CPU's: this is what keeps a plane's mean point on the
// plane, to far below depth_threshold, at any cell size.
uniform sampler2DArray depth, normal;
layout(r32f) uniform writeonly image2DArray nd; // mean normal x, y, z and mean depth
layout(r32f) uniform writeonly image2DArray pt; // mean view-space point
uniform int side;                               // cell side, px
// proj (a constant of the table): (f, cx, cy) of the inputs' size
#pragma ssg_consts

#include "complexity_surface.glsl" // is_surface, the CPU's test

void main()
{
    ivec2 g = ssg_pixel();
    if (ssg_outside(g))
        return;
    ivec2 end = min((g + 1) * side, textureSize(depth, 0).xy);
    precise dvec3 sn = dvec3(0.0), sp = dvec3(0.0);
    precise double sd = 0.0;
    int m = 0;
    for (int y = g.y * side; y < end.y; y++)
        for (int x = g.x * side; x < end.x; x++) {
            float d = texelFetch(depth, ivec3(x, y, 0), 0).r;
            vec3 n = ssg_load3(normal, ivec2(x, y));
            if (!is_surface(d, n))
                continue;
            double dd = double(d);
            precise double px = dd * ((double(x) + 0.5lf - double(proj.y)) / double(proj.x));
            precise double py = dd * (-(double(y) + 0.5lf - double(proj.z)) / double(proj.x));
            sp += dvec3(px, py, -dd);
            sd += dd;
            sn += dvec3(n);
            m++;
        }
    vec3 mn = m > 0 ? vec3(sn / double(m)) : vec3(0.0);
    vec3 mp = m > 0 ? vec3(sp / double(m)) : vec3(0.0);
    float md = m > 0 ? float(sd / double(m)) : 0.0;
    SSG_STORE3(pt, g, mp);
    SSG_STORE3(nd, g, mn);
    imageStore(nd, ivec3(g, 3), vec4(md));
}
