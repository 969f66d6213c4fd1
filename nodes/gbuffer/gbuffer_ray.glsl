// gbuffer_ray.glsl - what the G-buffer's compute passes on GL share (#include'd by
// gbuffer.glsl, gbuffer_back.glsl and gbuffer_emission.glsl after scene.glsl and #pragma
// ssg_consts, whose proj, inv_f, rot and eye are the camera's): a pixel's ray and its
// intersection with the triangle the rasteriser found there, so that every pass's depths
// and barycentrics come from the same float operations.

// Pixel p's ray (gbuffer_cpu.c's make_rays): its view direction with z = -1 in ray (x, y),
// and the same in world space (rot^T view) as the result.
vec3 pixel_ray(ivec2 p, out vec2 ray)
{
    ray = vec2((float(p.x) + 0.5 - proj.y) * inv_f, -(float(p.y) + 0.5 - proj.z) * inv_f);
    return vec3(rot[0] * ray.x + rot[3] * ray.y - rot[6], rot[1] * ray.x + rot[4] * ray.y - rot[7],
                rot[2] * ray.x + rot[5] * ray.y - rot[8]);
}

// The vertex numbers of triangle `tri` of mesh me.
uvec3 triangle_vertices(Mesh me, int tri)
{
    int i3 = me.indices + 3 * tri;
    return uvec3(vindex[i3], vindex[i3 + 1], vindex[i3 + 2]);
}

// (t, u, v) of the ray eye + t w in the plane of the triangle (Moller and Trumbore 1997).
// No inside test: the rasteriser put the pixel centre on this triangle, and where it
// misses by a rounding error the plane and the barycentrics extend continuously.
vec3 intersect(vec3 w, vec3 p0, vec3 p1, vec3 p2)
{
    vec3 e1 = p1 - p0, e2 = p2 - p0, s = eye - p0;
    vec3 pv = cross(w, e2), qv = cross(s, e1);
    float inv_det = 1.0 / dot(e1, pv);
    return vec3(dot(e2, qv), dot(s, pv), dot(w, qv)) * inv_det;
}
