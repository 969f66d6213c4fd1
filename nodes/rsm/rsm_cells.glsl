// rsm_cells.glsl - `rsm` on GL, first pass (rsm_gl.c): one invocation a map cell (cx, f C +
// cy) writes its SSG_RSM_BINS slots, the floats of rsm_vpl.c's ssg_rsm_cells in the same
// order (`precise`: no fused multiply-adds the CPU does not make).
uniform sampler2DArray map_depth, map_normal, map_flux;
layout(r32f) uniform writeonly image2DArray cells;
layout(std430, binding = 0) readonly buffer Faces { float face[]; };
#pragma ssg_params
#pragma ssg_consts
// res: the maps' side; ncells: cells per face side; p_cell: texels per cell side
const float MIN_COSINE = 0.1;   // SSG_RSM_MIN_COSINE
const float EMPTY = 1.0e30;     // SSG_SHADOW_EMPTY
const int BINS = 6;

precise float pw[3 * BINS], nw[3 * BINS], flux[3 * BINS], area[BINS], wsum[BINS];

float fv(int f, int k) { return face[16 * f + k]; }

// ssg_lightmap_texel_point (nodes/common/lightmap.h)
vec3 texel_point(int f, int x, int y, float z)
{
    precise float a = 2.0 * (float(x) + 0.5) / float(res) - 1.0;
    precise float b = 2.0 * (float(y) + 0.5) / float(res) - 1.0;
    precise vec3 p;
    for (int k = 0; k < 3; k++) {
        if (fv(f, 13) != 0.0)
            p[k] = fv(f, k) + fv(f, 12) * (a * fv(f, 3 + k) + b * fv(f, 6 + k)) +
                   z * fv(f, 9 + k);
        else
            p[k] = fv(f, k) + z * (fv(f, 9 + k) + fv(f, 12) * a * fv(f, 3 + k) +
                                   fv(f, 12) * b * fv(f, 6 + k));
    }
    return p;
}

// ssg_lightmap_cube_face: the dominant axis, ties to the lower index
int dominant(vec3 d)
{
    float ax = abs(d.x), ay = abs(d.y), az = abs(d.z);
    if (ax >= ay && ax >= az)
        return d.x >= 0.0 ? 0 : 1;
    if (ay >= az)
        return d.y >= 0.0 ? 2 : 3;
    return d.z >= 0.0 ? 4 : 5;
}

float texel_area(int f, int x, int y, vec3 p, vec3 n)
{
    if (fv(f, 13) != 0.0) {
        precise float c = abs(n.x * fv(f, 9) + n.y * fv(f, 10) + n.z * fv(f, 11));
        precise float r = fv(f, 14) / (c > MIN_COSINE ? c : MIN_COSINE);
        return r;
    }
    precise vec3 d = vec3(p.x - fv(f, 0), p.y - fv(f, 1), p.z - fv(f, 2));
    precise float r2 = d.x * d.x + d.y * d.y + d.z * d.z;
    precise float c = abs(n.x * d.x + n.y * d.y + n.z * d.z) / sqrt(r2);
    // ssg_lightmap_texel_solid_angle
    precise float a = 2.0 * (float(x) + 0.5) / float(res) - 1.0;
    precise float b = 2.0 * (float(y) + 0.5) / float(res) - 1.0;
    precise float h = fv(f, 12), q = 1.0 + h * h * (a * a + b * b);
    precise float s = 2.0 * h / float(res);
    precise float omega = s * s / (q * sqrt(q));
    precise float r = omega * r2 / (c > MIN_COSINE ? c : MIN_COSINE);
    return r;
}

void add_texel(int f, int x, int y)
{
    float z = texelFetch(map_depth, ivec3(x, y, f), 0).r;
    vec3 phi, n;
    for (int k = 0; k < 3; k++) {
        phi[k] = texelFetch(map_flux, ivec3(x, y, 3 * f + k), 0).r;
        n[k] = texelFetch(map_normal, ivec3(x, y, 3 * f + k), 0).r;
    }
    precise float w = phi.x + phi.y + phi.z;
    if (!(w > 0.0) || !(z < 0.5 * EMPTY))
        return;
    vec3 p = texel_point(f, x, y, z);
    int b = dominant(n);
    for (int k = 0; k < 3; k++) {
        pw[3 * b + k] += w * p[k];
        nw[3 * b + k] += w * n[k];
        flux[3 * b + k] += phi[k];
    }
    area[b] += texel_area(f, x, y, p, n);
    wsum[b] += w;
}

void store_slot(ivec2 at, int b)
{
    precise float v[11];
    for (int k = 0; k < 11; k++)
        v[k] = 0.0;
    if (wsum[b] > 0.0) {
        precise float len = sqrt(nw[3 * b] * nw[3 * b] + nw[3 * b + 1] * nw[3 * b + 1] +
                                 nw[3 * b + 2] * nw[3 * b + 2]);
        for (int k = 0; k < 3; k++) {
            v[k] = pw[3 * b + k] / wsum[b];
            v[3 + k] = nw[3 * b + k] / len;
            v[6 + k] = flux[3 * b + k];
        }
        v[9] = area[b] * 0.318309886;
        v[10] = v[6] + v[7] + v[8];
    }
    for (int k = 0; k < 11; k++)
        imageStore(cells, ivec3(at.x * BINS + b, at.y, k), vec4(v[k]));
}

void main()
{
    ivec2 g = ssg_pixel();
    if (ssg_outside(g))
        return;
    int f = g.y / ncells, cy = g.y % ncells, cx = g.x;
    for (int b = 0; b < BINS; b++) {
        area[b] = 0.0;
        wsum[b] = 0.0;
        for (int k = 0; k < 3; k++)
            pw[3 * b + k] = nw[3 * b + k] = flux[3 * b + k] = 0.0;
    }
    for (int y = cy * p_cell; y < (cy + 1) * p_cell && y < res; y++)
        for (int x = cx * p_cell; x < (cx + 1) * p_cell && x < res; x++)
            add_texel(f, x, y);
    for (int b = 0; b < BINS; b++)
        store_slot(g, b);
}
