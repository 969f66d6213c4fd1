// surface.glsl - the scene's materials and textures on GL, the twin of nodes/common/surface.c
// and core/scene/coverage.c that gbuffer.glsl, lightmaps.glsl and every raster program
// share (#include "surface.glsl" after scene.glsl, whose vdata fetch2 reads and whose
// scene_mesh mesh_covers reads; the buffers are core/gl/gl_scene.h's bindings).
struct Material {
    float albedo[3];
    float specular[3];
    float shininess;
    int texels; // float offset in texel[], -1 = no texture
    int width;
    int height;
    float opacity;      // alpha factor (coverage.h)
    float alpha_cutoff; // a masked surface exists where opacity x alpha >= this
    int alpha_texels;   // float offset of the texture's alpha plane, -1 = none
    int masked;         // 1: alpha_mode mask or blend
    int normal_texels;  // float offset of the tangent-space normal map, -1 = none
    int normal_width;
    int normal_height;
    float normal_scale; // multiplies the map's x and y
    float emission[3];  // emitted radiance, linear RGB
    int emission_texels; // float offset of the emission texture (RGB), -1 = none
    int emission_width;
    int emission_height;
};
layout(std430, binding = 2) readonly buffer Texels { float texel[]; };
layout(std430, binding = 4) readonly buffer Materials { Material scene_material[]; };

vec2 fetch2(int base, uint vertex)
{
    int o = base + 2 * int(vertex);
    return vec2(vdata[o], vdata[o + 1]);
}

vec4 fetch4(int base, uint vertex)
{
    int o = base + 4 * int(vertex);
    return vec4(vdata[o], vdata[o + 1], vdata[o + 2], vdata[o + 3]);
}

// The floor modulo that C's fmodf plus "add n when negative" gives for integers.
int wrap(int i, int n)
{
    int r = abs(i) % n;
    return i < 0 && r != 0 ? n - r : r;
}

// coverage.c's ssg_texture_bilinear: the four texels around uv (texel numbers y w + x, in
// the order a b / c d) and the weights (ax, ay) between their centres, wrapping around.
void bilinear_taps(int width, int height, vec2 uv, out ivec4 at, out vec2 w)
{
    float fx = uv.x * float(width) - 0.5, fy = uv.y * float(height) - 0.5;
    float x0f = floor(fx), y0f = floor(fy);
    w = vec2(fx - x0f, fy - y0f);
    int x0 = wrap(int(x0f), width), y0 = wrap(int(y0f), height);
    int x1 = x0 + 1 < width ? x0 + 1 : 0, y1 = y0 + 1 < height ? y0 + 1 : 0;
    at = ivec4(y0 * width + x0, y0 * width + x1, y1 * width + x0, y1 * width + x1);
}

vec3 texel3(int base, int i)
{
    int o = base + 3 * i;
    return vec3(texel[o], texel[o + 1], texel[o + 2]);
}

// The RGB texture at float offset base, width x height texels, at uv.
vec3 sample_rgb(int base, int width, int height, vec2 uv)
{
    ivec4 at;
    vec2 w;
    bilinear_taps(width, height, uv, at, w);
    vec3 a = texel3(base, at.x), b = texel3(base, at.y), c = texel3(base, at.z);
    vec3 d = texel3(base, at.w);
    return (1.0 - w.y) * ((1.0 - w.x) * a + w.x * b) + w.y * ((1.0 - w.x) * c + w.x * d);
}

vec3 sample_texture(Material m, vec2 uv)
{
    return sample_rgb(m.texels, m.width, m.height, uv);
}

float sample_alpha(Material m, vec2 uv)
{
    ivec4 at;
    vec2 w;
    bilinear_taps(m.width, m.height, uv, at, w);
    int o = m.alpha_texels;
    float a = texel[o + at.x], b = texel[o + at.y], c = texel[o + at.z], d = texel[o + at.w];
    return (1.0 - w.y) * ((1.0 - w.x) * a + w.x * b) + w.y * ((1.0 - w.x) * c + w.x * d);
}

// coverage.c's ssg_mesh_covers at texture coordinates uv: a surface there (always for an
// opaque material).
bool mesh_covers(int mesh, vec2 uv)
{
    Mesh me = scene_mesh[mesh];
    Material m = scene_material[me.material];
    if (m.masked == 0)
        return true;
    float alpha = me.uvs >= 0 && m.alpha_texels >= 0 ? sample_alpha(m, uv) : 1.0;
    return m.opacity * alpha >= m.alpha_cutoff;
}

// surface.c's normal_map: the material's tangent-space normal map bends the interpolated
// normal n (not normalised) at barycentrics (u, v) of triangle tri, step by step as there.
vec3 shading_normal(Mesh me, Material m, uvec3 tri, float u, float v, vec3 n)
{
    if (m.normal_texels < 0 || me.uvs < 0 || me.tangents < 0)
        return n;
    float w0 = 1.0 - u - v;
    vec2 uv = w0 * fetch2(me.uvs, tri.x) + u * fetch2(me.uvs, tri.y) + v * fetch2(me.uvs, tri.z);
    vec4 t = w0 * fetch4(me.tangents, tri.x) + u * fetch4(me.tangents, tri.y) +
             v * fetch4(me.tangents, tri.z);
    float len = sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    if (!(len > 0.0))
        return n;
    vec3 un = n / len;
    vec3 tt = t.xyz - un * (t.x * un.x + t.y * un.y + t.z * un.z);
    float tl = sqrt(tt.x * tt.x + tt.y * tt.y + tt.z * tt.z);
    if (!(tl > 0.0))
        return n;
    tt /= tl;
    vec3 b = cross(un, tt) * (t.w < 0.0 ? -1.0 : 1.0);
    vec3 rgb = sample_rgb(m.normal_texels, m.normal_width, m.normal_height, uv);
    float x = (2.0 * rgb.x - 1.0) * m.normal_scale, y = (2.0 * rgb.y - 1.0) * m.normal_scale;
    return x * tt + y * b + (2.0 * rgb.z - 1.0) * un;
}

// surface.c's ssg_hit_albedo's last step: glTF COLOR_0 multiplies the albedo a.
vec3 vertex_colour(Mesh me, uvec3 tri, float u, float v, vec3 a)
{
    if (me.colors < 0)
        return a;
    float w0 = 1.0 - u - v;
    return a * (w0 * fetch3(me.colors, tri.x) + u * fetch3(me.colors, tri.y) +
                v * fetch3(me.colors, tri.z));
}
