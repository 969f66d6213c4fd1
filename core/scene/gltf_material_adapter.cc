/* gltf_material_adapter.cc - gltf_adapter.h's Materials: a glTF file's materials and the
 * textures they read, as ssgraph honours them (docs/scenes.md, "Model file features"): the
 * base colour and its sRGB texture (with the alpha channel a masked material cuts by),
 * alphaMode and alphaCutoff, the normal map (read as data, not sRGB), emission with
 * KHR_materials_emissive_strength; and, into `ignored`, what a material uses that no path
 * reads. Problems are thrown as Failure and caught in ssg_gltf_load. */
#include "scene/gltf_adapter.h"

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace gltf_adapter {

using model_adapter::printable;
using model_adapter::srgb_to_linear;
using model_adapter::Tex;

namespace {

/* A number of a KHR_texture_transform field, or `def` without it. */
double number_of(const tinygltf::Value &v, const char *key, int index, double def)
{
    if (!v.Has(key))
        return def;
    const tinygltf::Value &f = v.Get(key);
    const tinygltf::Value &x = index >= 0 ? f.Get(index) : f;
    return x.IsNumber() ? x.GetNumberAsDouble() : def;
}

/* The KHR_texture_transform of one texture reference (identity without); its texCoord,
   when it gives one, replaces the reference's in *texcoord. */
UvTransform texture_transform(const tinygltf::ExtensionMap &ext, int *texcoord)
{
    auto it = ext.find("KHR_texture_transform");
    if (it == ext.end())
        return UV_IDENTITY;
    const tinygltf::Value &v = it->second;
    double ox = number_of(v, "offset", 0, 0), oy = number_of(v, "offset", 1, 0);
    double sx = number_of(v, "scale", 0, 1), sy = number_of(v, "scale", 1, 1);
    double r = number_of(v, "rotation", -1, 0), c = std::cos(r), s = std::sin(r);
    if (v.Has("texCoord") && v.Get("texCoord").IsInt())
        *texcoord = v.Get("texCoord").GetNumberAsInt();
    /* T R S with R = [cos r, sin r; -sin r, cos r] (the extension's matrix) */
    return {c * sx, s * sy, ox, -s * sx, c * sy, oy};
}

/* The uv set a texture reference reads: its texCoord, or its transform's. */
template <class Ref> int uv_set(const Ref &ref)
{
    int set = ref.texCoord;
    texture_transform(ref.extensions, &set);
    return set;
}


} // namespace

/* The parts of a material no path reads yet (docs/scenes.md's feature table). */
void Materials::note_ignored(const tinygltf::Material &src, const std::string &who)
{
    int colour_set = src.pbrMetallicRoughness.baseColorTexture.index >= 0
                         ? uv_set(src.pbrMetallicRoughness.baseColorTexture)
                         : uv_set(src.normalTexture);
    if (src.normalTexture.index >= 0 && uv_set(src.normalTexture) != colour_set)
        ignored.add("normal maps on another texture coordinate set than the base colour's",
                    who);
    int mesh_set = src.normalTexture.index >= 0 ? uv_set(src.normalTexture) : colour_set;
    if (src.emissiveTexture.index >= 0 && uv_set(src.emissiveTexture) != mesh_set)
        ignored.add("emission textures on another texture coordinate set than the base "
                    "colour's", who);
}

/* The transform of the textures the material reads (base colour, normal map, emission
   texture, as its uv set: their texCoord as KHR_texture_transform may replace it): the
   mesh's uvs carry one, so textures that disagree keep the first's, listed as ignored. */
UvTransform Materials::read_uv_transform(const tinygltf::Material &src, const std::string &who)
{
    const tinygltf::TextureInfo &base = src.pbrMetallicRoughness.baseColorTexture;
    const tinygltf::ExtensionMap *refs[3] = {base.index >= 0 ? &base.extensions : nullptr,
                                             src.normalTexture.index >= 0
                                                 ? &src.normalTexture.extensions : nullptr,
                                             src.emissiveTexture.index >= 0
                                                 ? &src.emissiveTexture.extensions : nullptr};
    bool have = false;
    UvTransform first = UV_IDENTITY;
    for (const tinygltf::ExtensionMap *ext : refs) {
        if (!ext)
            continue;
        int unused = 0;
        UvTransform t = texture_transform(*ext, &unused);
        if (have && t != first)
            ignored.add("texture transforms (KHR_texture_transform) that differ between a "
                        "material's textures (the base colour's is used)", who);
        if (!have)
            first = t, have = true;
    }
    return first;
}

/* emissiveFactor (default black) x KHR_materials_emissive_strength's emissiveStrength
   (default 1), and emissiveTexture (sRGB) on the material's texture coordinates. */
void Materials::read_emission(const tinygltf::Material &src, ssg_gltf_material &mat)
{
    const std::vector<double> &e = src.emissiveFactor;
    double strength = 1.0;
    auto ext = src.extensions.find("KHR_materials_emissive_strength");
    if (ext != src.extensions.end() && ext->second.Has("emissiveStrength"))
        strength = ext->second.Get("emissiveStrength").GetNumberAsDouble();
    if (!(strength >= 0.0) || !std::isfinite(strength))
        fail("material '" + printable(src.name) + "': emissiveStrength " + shown(strength) +
             " is not a finite number >= 0");
    for (int k = 0; k < 3; k++) {
        double v = e.size() == 3 ? e[(size_t)k] * strength : 0.0;
        if (!(v >= 0.0) || !std::isfinite(v))
            fail("material '" + printable(src.name) + "': emissiveFactor x emissiveStrength "
                 "is not finite and >= 0");
        mat.emission[k] = (float)v;
    }
    mat.emission_texture = -1;
    const tinygltf::TextureInfo &et = src.emissiveTexture;
    bool has_set = mat.texture >= 0 || mat.normal_texture >= 0;
    if (et.index >= 0 && (!has_set || uv_set(et) == mat.texcoord)) {
        mat.emission_texture = texture(et.index, false);
        mat.texcoord = uv_set(et);
    }
}

void Materials::convert()
{
    texture_slot.assign(m.textures.size(), -1);
    data_slot.assign(m.textures.size(), -1);
    for (size_t k = 0; k < m.materials.size(); k++) {
        const tinygltf::Material &src = m.materials[k];
        std::string who = src.name.empty() ? "material " + std::to_string(k)
                                           : "'" + printable(src.name) + "'";
        note_ignored(src, who);
        ssg_gltf_material mat{};
        std::snprintf(mat.name, sizeof mat.name, "%s", src.name.c_str());
        const std::vector<double> &f = src.pbrMetallicRoughness.baseColorFactor;
        for (int i = 0; i < 4; i++) mat.base_color[i] = f.size() == 4 ? (float)f[(size_t)i] : 1.0f;
        /* glTF 2.0, 3.9.4: alpha is ignored unless MASK (cutoff, default 0.5) or BLEND */
        mat.alpha_mode = src.alphaMode == "MASK"    ? SSG_ALPHA_MASK
                         : src.alphaMode == "BLEND" ? SSG_ALPHA_BLEND
                                                    : SSG_ALPHA_OPAQUE;
        mat.alpha_cutoff = mat.alpha_mode == SSG_ALPHA_MASK ? (float)src.alphaCutoff : 0.5f;
        if (!(mat.alpha_cutoff >= 0.0f && mat.alpha_cutoff <= 1.0f))
            fail("material '" + printable(src.name) + "': alphaCutoff " +
                 shown(src.alphaCutoff) + " is outside 0 to 1");
        mat.texture = texture(src.pbrMetallicRoughness.baseColorTexture.index,
                              mat.alpha_mode != SSG_ALPHA_OPAQUE);
        mat.texcoord = uv_set(src.pbrMetallicRoughness.baseColorTexture);
        /* a normal map on the base colour's texture coordinates (or alone on its own):
           the mesh keeps one uv set */
        const tinygltf::NormalTextureInfo &nt = src.normalTexture;
        mat.normal_texture = -1;
        mat.normal_scale = (float)nt.scale;
        if (nt.index >= 0 && (mat.texture < 0 || uv_set(nt) == mat.texcoord)) {
            mat.normal_texture = texture(nt.index, false, false);
            mat.texcoord = uv_set(nt);
        }
        read_emission(src, mat);
        materials.push_back(mat);
        uv_transforms.push_back(read_uv_transform(src, who));
    }
}

/* The alpha channel of a decoded image with one (gray + alpha, RGBA; linear: glTF's alpha
   is not sRGB-encoded) as the texture's coverage plane; an image without one stays
   opaque. */
void Materials::add_alpha(Tex &tex, const tinygltf::Image &img) const
{
    if (!tex.alpha.empty() || (img.component != 2 && img.component != 4))
        return;
    size_t px = (size_t)img.width * (size_t)img.height, bytes = img.bits == 16 ? 2 : 1;
    tex.alpha.resize(px);
    for (size_t i = 0; i < px; i++) {
        size_t at = i * (size_t)img.component + (size_t)img.component - 1;
        uint16_t u = img.image[at];
        if (bytes == 2)
            std::memcpy(&u, &img.image[at * 2], 2);
        tex.alpha[i] = (float)u / (bytes == 2 ? 65535.0f : 255.0f);
    }
}

/* The image of glTF texture `gltf_index`, checked. */
static const tinygltf::Image &texture_image(const tinygltf::Model &m, int gltf_index)
{
    int source = m.textures[(size_t)gltf_index].source;
    if (source < 0 || (size_t)source >= m.images.size())
        fail("texture " + std::to_string(gltf_index) + " has no valid image");
    return m.images[(size_t)source];
}

/* Decodes glTF texture `gltf_index` once; baseColor textures are sRGB-encoded (glTF 2.0
 * spec, 3.9.2), so 8- and 16-bit values are converted to linear here; a normal map is data
 * (srgb false: the stored values, scaled to [0, 1]). keep_alpha: a masked material reads
 * it, so its alpha channel comes along (also when an opaque material decoded it first). */
int Materials::texture(int gltf_index, bool keep_alpha, bool srgb)
{
    if (gltf_index < 0)
        return -1;
    if ((size_t)gltf_index >= m.textures.size())
        fail("texture " + std::to_string(gltf_index) + " does not exist");
    std::vector<int> &slots = srgb ? texture_slot : data_slot;
    if (slots[(size_t)gltf_index] >= 0) {
        int slot = slots[(size_t)gltf_index];
        if (keep_alpha)
            add_alpha(textures[(size_t)slot], texture_image(m, gltf_index));
        return slot;
    }
    const tinygltf::Image &img = texture_image(m, gltf_index);
    int source = m.textures[(size_t)gltf_index].source;
    size_t bytes = img.bits == 16 ? 2 : 1;
    size_t px = (size_t)img.width * (size_t)img.height;
    if (img.width <= 0 || img.height <= 0 || img.component < 1 || img.component > 4 ||
        (img.bits != 8 && img.bits != 16) || img.image.size() < px * (size_t)img.component * bytes)
        fail("image " + std::to_string(source) + " ('" + img.uri + "') was not decoded: "
             "the file is missing or not an image tinygltf reads (PNG, JPEG, ...)");
    float lut[256];
    for (int i = 0; i < 256; i++)
        lut[i] = srgb ? srgb_to_linear((float)i / 255.0f) : (float)i / 255.0f;
    Tex tex{img.width, img.height, std::vector<float>(px * 3), {}};
    for (size_t i = 0; i < px; i++)
        for (int c = 0; c < 3; c++) {
            size_t at = i * (size_t)img.component + (size_t)(img.component < 3 ? 0 : c);
            float v;
            if (bytes == 1) {
                v = lut[img.image[at]];
            } else {
                uint16_t u;
                std::memcpy(&u, &img.image[at * 2], 2);
                v = srgb ? srgb_to_linear((float)u / 65535.0f) : (float)u / 65535.0f;
            }
            tex.rgb[i * 3 + (size_t)c] = v;
        }
    if (keep_alpha)
        add_alpha(tex, img);
    textures.push_back(std::move(tex));
    slots[(size_t)gltf_index] = (int)textures.size() - 1;
    return slots[(size_t)gltf_index];
}


} // namespace gltf_adapter
