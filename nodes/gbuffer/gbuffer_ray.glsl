// gbuffer_ray.glsl - what the G-buffer's compute passes on GL share (#include'd by
// gbuffer.glsl and gbuffer_back.glsl after scene.glsl and #pragma ssg_consts, whose `eye`
// is the camera's world position): the intersection of a pixel's ray with the triangle the
// rasteriser found there, so that both layers' depths come from the same float operations.

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
