// rsm.glsl - `rsm` on GL, last pass (rsm_gl.c): per pixel, rsm_cpu.c's gather: every VPL of
// the list, or the `samples` draws of the pixel's tile cell (rsm_picks.glsl), each term
// Phi cos cos / (d^2 max(d^2, r2)) x fade(d) in the CPU's order (`precise`), with
// visibility (vis) each term shadowed or the tested draws' occluded light subtracted.
uniform sampler2DArray position, normal, albedo, list, count, pick;
uniform bool albedo_bound;
layout(r32f) uniform writeonly image2DArray dst_out;
layout(r32f) uniform image2DArray acc;  // the sums between the dispatches of an exact run
// the scene's distance field (scene/distance.h, gl_scene.h), read when vis != 0
layout(std430, binding = 5) readonly buffer Distance { float distance_field[]; };
// per tile cell, which draw of each vis_stride is tested (rsm.h's vis_phase), when vis != 0
layout(std430, binding = 1) readonly buffer Phases { int vis_phase[]; };
#pragma ssg_params
#pragma ssg_consts
// rot[9], eye: view -> world, world = eye + rot^T view; inv_samples = 1 / samples
uniform int vpl0, vpls;       // exact: this dispatch's VPLs [vpl0, vpl0 + vpls)
uniform bool first, last;     // exact: the first and the last dispatch
const int TILE = 8;    // SSG_RSM_TILE

int list_w;

float vpl(int i, int k) { return texelFetch(list, ivec3(i % list_w, i / list_w, k), 0).r; }

// rsm.h's ssg_rsm_visible: the sphere trace from the receiver to VPL i in the distance field
bool visible(int i, vec3 x, vec3 nx)
{
    float a = p_vis_start;
    precise vec3 p, d;
    for (int k = 0; k < 3; k++) {
        p[k] = (x[k] - grid_lo[k]) * grid_inv + nx[k] * a;
        d[k] = ((vpl(i, k) - grid_lo[k]) * grid_inv + vpl(i, 3 + k) * a) - p[k];
    }
    precise float len = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    precise float end = len - a;
    if (!(end > a))
        return true;
    precise vec3 u = vec3(d.x / len, d.y / len, d.z / len);
    ivec3 n = ivec3(grid_nx, grid_ny, grid_nz);
    bool left = false; // once in an empty voxel: the occupied ones before are x's own
    for (precise float t = a; t < end;) {
        precise vec3 q = vec3(p.x + u.x * t, p.y + u.y * t, p.z + u.z * t);
        ivec3 v = ivec3(floor(q));
        precise float step = 1.0;
        if (all(greaterThanEqual(v, ivec3(0))) && all(lessThan(v, n))) {
            float dist = distance_field[(v.z * n.y + v.y) * n.x + v.x];
            if (dist == 0.0 && left)
                return false;
            left = left || dist != 0.0;
            step = dist - 1.0 > 1.0 ? dist - 1.0 : 1.0;
        } else {
            left = true;
        }
        t = t + step;
    }
    return true;
}

// rsm_cpu.c's vpl_weight: VPL i's term over its flux, 0 behind either surface
float vpl_weight(int i, vec3 x, vec3 nx, float scale)
{
    precise vec3 d = vec3(vpl(i, 0) - x.x, vpl(i, 1) - x.y, vpl(i, 2) - x.z);
    precise float d2 = d.x * d.x + d.y * d.y + d.z * d.z;
    precise float cs = -(vpl(i, 3) * d.x + vpl(i, 4) * d.y + vpl(i, 5) * d.z);
    precise float cr = nx.x * d.x + nx.y * d.y + nx.z * d.z;
    if (!(d2 > 0.0) || !(cs > 0.0) || !(cr > 0.0))
        return 0.0;
    float r2 = vpl(i, 9);
    precise float g = cs * cr / (d2 * (d2 > r2 ? d2 : r2));
    if (p_min_distance > 0.0) {
        precise float t = (sqrt(d2) - p_min_distance) / p_min_distance;
        t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
        g = g * (t * t * (3.0 - 2.0 * t));
    }
    precise float w = scale * g;
    return w;
}

// the term into the sum; `each`: shadowed by its own visibility
void add_vpl(int i, vec3 x, vec3 nx, float scale, bool each, inout vec3 sum)
{
    precise float k = vpl_weight(i, x, nx, scale);
    if (each && k > 0.0 && !visible(i, x, nx))
        k = 0.0;
    precise vec3 add = vec3(k * vpl(i, 6), k * vpl(i, 7), k * vpl(i, 8));
    sum = vec3(sum.x + add.x, sum.y + add.y, sum.z + add.z);
}

// rsm_cpu.c's shadow_subtract: the sum less the occluded light of the tested draws, each
// scaled by vis_stride, clamped at 0
vec3 shadow_subtract(int t0, vec3 x, vec3 nx, float step, vec3 sum0)
{
    precise vec3 sum = sum0;
    precise float stride = float(vis_stride);
    int phase = vis_phase[t0];
    for (int t = 0; t < vis_tested; t++) {
        int i = int(texelFetch(pick, ivec3(t * vis_stride + phase, t0, 0), 0).r);
        precise float scale = step / vpl(i, 10);
        precise float w = vpl_weight(i, x, nx, scale);
        if (!(w > 0.0) || visible(i, x, nx))
            continue;
        for (int ch = 0; ch < 3; ch++) {
            precise float light = w * vpl(i, 6 + ch);
            sum[ch] = sum[ch] - stride * light;
        }
    }
    return vec3(sum.x > 0.0 ? sum.x : 0.0, sum.y > 0.0 ? sum.y : 0.0, sum.z > 0.0 ? sum.z : 0.0);
}

vec3 gather(ivec2 p, vec3 x, vec3 nx, int n, vec3 sum0)
{
    precise vec3 sum = sum0;
    bool exact = p_samples == 0 || p_samples >= n;
    bool each = vis != 0 && (exact || vis_stride == 1);
    if (exact) {
        for (int i = vpl0; i < min(vpl0 + vpls, n); i++)
            add_vpl(i, x, nx, 1.0, each, sum);
        return sum;
    }
    float total = vpl(n - 1, 11);
    int t = (p.y % TILE) * TILE + p.x % TILE;
    precise float step = inv_samples * total;
    for (int k = 0; k < p_samples; k++) {
        int i = int(texelFetch(pick, ivec3(k, t, 0), 0).r);
        precise float scale = step / vpl(i, 10);
        add_vpl(i, x, nx, scale, each, sum);
    }
    if (vis != 0 && vis_stride > 1)
        sum = shadow_subtract(t, x, nx, step, sum);
    return sum;
}

void main()
{
    ivec2 p = ssg_pixel();
    if (ssg_outside(p))
        return;
    list_w = textureSize(list, 0).x;
    vec3 P = ssg_load3(position, p), N = ssg_load3(normal, p);
    bool bg = N.x == 0.0 && N.y == 0.0 && N.z == 0.0;
    int n = int(texelFetch(count, ivec3(0, 0, 0), 0).r);
    bool exact = p_samples == 0 || p_samples >= n;
    if (!exact && !first)
        return; // a sampled run is done in its first dispatch
    precise vec3 sum = vec3(0.0);
    if (exact && !first)
        sum = vec3(imageLoad(acc, ivec3(p, 0)).r, imageLoad(acc, ivec3(p, 1)).r,
                   imageLoad(acc, ivec3(p, 2)).r);
    if (!bg && n > 0) {
        precise vec3 x, nx;
        for (int i = 0; i < 3; i++) {
            x[i] = eye[i] + rot[i] * P.x + rot[3 + i] * P.y + rot[6 + i] * P.z;
            nx[i] = rot[i] * N.x + rot[3 + i] * N.y + rot[6 + i] * N.z;
        }
        sum = gather(p, x, nx, n, sum);
    }
    if (exact && !last) {
        for (int c = 0; c < 3; c++)
            imageStore(acc, ivec3(p, c), vec4(sum[c]));
        return;
    }
    vec3 a = albedo_bound ? ssg_load3(albedo, p) : vec3(1.0);
    precise vec3 e = vec3(sum.x * 0.101321184, sum.y * 0.101321184, sum.z * 0.101321184);
    precise vec3 o = vec3(a.x * e.x, a.y * e.y, a.z * e.z);
    SSG_STORE3(dst_out, p, bg ? vec3(0.0) : o);
}
