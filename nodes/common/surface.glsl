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
};
layout(std430, binding = 2) readonly buffer Texels { float texel[]; };
layout(std430, binding = 4) readonly buffer Materials { Material scene_material[]; };

vec2 fetch2(int base, uint vertex)
{
    int o = base + 2 * int(vertex);
    return vec2(vdata[o], vdata[o + 1]);
}

// The floor modulo that C's fmodf plus "add n when negative" gives for integers.
int wrap(int i, int n)
{
    int r = abs(i) % n;
    return i < 0 && r != 0 ? n - r : r;
}

// coverage.c's ssg_texture_bilinear: the four texels around uv (texel numbers y w + x, in
// the order a b / c d) and the weights (ax, ay) between their centres, wrapping around.
void bilinear_taps(Material m, vec2 uv, out ivec4 at, out vec2 w)
{
    float fx = uv.x * float(m.width) - 0.5, fy = uv.y * float(m.height) - 0.5;
    float x0f = floor(fx), y0f = floor(fy);
    w = vec2(fx - x0f, fy - y0f);
    int x0 = wrap(int(x0f), m.width), y0 = wrap(int(y0f), m.height);
    int x1 = x0 + 1 < m.width ? x0 + 1 : 0, y1 = y0 + 1 < m.height ? y0 + 1 : 0;
    at = ivec4(y0 * m.width + x0, y0 * m.width + x1, y1 * m.width + x0, y1 * m.width + x1);
}

vec3 texel3(Material m, int i)
{
    int o = m.texels + 3 * i;
    return vec3(texel[o], texel[o + 1], texel[o + 2]);
}

vec3 sample_texture(Material m, vec2 uv)
{
    ivec4 at;
    vec2 w;
    bilinear_taps(m, uv, at, w);
    vec3 a = texel3(m, at.x), b = texel3(m, at.y), c = texel3(m, at.z), d = texel3(m, at.w);
    return (1.0 - w.y) * ((1.0 - w.x) * a + w.x * b) + w.y * ((1.0 - w.x) * c + w.x * d);
}

float sample_alpha(Material m, vec2 uv)
{
    ivec4 at;
    vec2 w;
    bilinear_taps(m, uv, at, w);
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
