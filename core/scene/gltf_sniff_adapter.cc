/* gltf_sniff_adapter.cc - ssg_gltf_sniff (gltf.h): the version a glTF declares and whether
 * it needs Draco, read from its JSON with nlohmann::json (the parser tinygltf itself uses)
 * before tinygltf sees it, so a glTF 1.0 file can go to Assimp (model.h) and a Draco one
 * gets a plain message instead of tinygltf's accessor complaints. Never throws. */
#include "scene/gltf.h"

#include <cstdint>
#include <cstring>
#include <string>

#include <nlohmann/json.hpp>

namespace {

using nlohmann::json;

/* The JSON text of a .glb: its first chunk, which the format requires to be JSON. */
bool glb_json(const char *data, size_t len, const char **text, size_t *text_len)
{
    uint32_t chunk_len, chunk_type;
    if (len < 20)
        return false;
    std::memcpy(&chunk_len, data + 12, 4);
    std::memcpy(&chunk_type, data + 16, 4);
    if (chunk_type != 0x4E4F534Au || chunk_len > len - 20) /* "JSON" */
        return false;
    *text = data + 20;
    *text_len = chunk_len;
    return true;
}

bool names_draco(const json &list)
{
    if (!list.is_array())
        return false;
    for (const json &e : list)
        if (e.is_string() && e.get<std::string>() == "KHR_draco_mesh_compression")
            return true;
    return false;
}

int major_of(const json &doc)
{
    auto asset = doc.find("asset");
    if (asset == doc.end() || !asset->is_object())
        return 0;
    auto version = asset->find("version");
    if (version == asset->end() || !version->is_string())
        return 0;
    std::string v = version->get<std::string>();
    return v.empty() || v[0] < '1' || v[0] > '9' ? 0 : v[0] - '0';
}

} // namespace

extern "C" void ssg_gltf_sniff(const char *data, size_t len, int *major, int *draco)
{
    *major = 0;
    *draco = 0;
    const char *text = data;
    size_t text_len = len;
    bool binary = len >= 12 && std::memcmp(data, "glTF", 4) == 0;
    if (binary) {
        uint32_t version;
        std::memcpy(&version, data + 4, 4);
        *major = version <= 9 ? (int)version : 0; /* a glTF 1.0 .glb carries 1 here */
        if (!glb_json(data, len, &text, &text_len))
            return;
    }
    try {
        json doc = json::parse(text, text + text_len, nullptr, false);
        if (!doc.is_object())
            return;
        if (!binary)
            *major = major_of(doc);
        *draco = names_draco(doc.value("extensionsUsed", json::array())) ||
                 names_draco(doc.value("extensionsRequired", json::array()));
    } catch (...) {
        /* not glTF JSON: the loader that reads it says what is wrong */
    }
}
