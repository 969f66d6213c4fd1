// surface.glsl - the scene's materials and textures on GL, the twin of nodes/common/surface.c
// that gbuffer.glsl and lightmaps.glsl share (#include "surface.glsl" after scene.glsl,
// whose vdata fetch2 reads; the buffers are core/gl/gl_scene.h's bindings).
struct Material {
    float albedo[3];
    float specular[3];
    float shininess;
    int texels; // float offset in texel[], -1 = no texture
    int width;
    int height;
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

vec3 texel3(Material m, int x, int y)
{
    int o = m.texels + 3 * (y * m.width + x);
    return vec3(texel[o], texel[o + 1], texel[o + 2]);
}

// surface.c's sample_texture: bilinear between texel centres, wrapping around.
vec3 sample_texture(Material m, vec2 uv)
{
    float fx = uv.x * float(m.width) - 0.5, fy = uv.y * float(m.height) - 0.5;
    float x0f = floor(fx), y0f = floor(fy), ax = fx - x0f, ay = fy - y0f;
    int x0 = wrap(int(x0f), m.width), y0 = wrap(int(y0f), m.height);
    int x1 = x0 + 1 < m.width ? x0 + 1 : 0, y1 = y0 + 1 < m.height ? y0 + 1 : 0;
    vec3 a = texel3(m, x0, y0), b = texel3(m, x1, y0);
    vec3 c = texel3(m, x0, y1), d = texel3(m, x1, y1);
    return (1.0 - ay) * ((1.0 - ax) * a + ax * b) + ay * ((1.0 - ax) * c + ax * d);
}
