// complexity_surface.glsl - the surface test of the `complexity` node's GL passes
// (complexity_means.glsl and complexity_count.glsl include it), complexity_cpu.c's
// is_surface: depth > 0 and finite, non-zero normal (node.h).
bool is_surface(float d, vec3 n)
{
    precise float nn = n.x * n.x + n.y * n.y + n.z * n.z;
    return d > 0.0 && d <= 3.0e38 && nn > 1e-12;
}
