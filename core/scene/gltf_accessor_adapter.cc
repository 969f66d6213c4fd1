/* gltf_accessor_adapter.cc - reading glTF accessors (gltf_adapter.h): the one place
 * where bytes of a glTF's buffers are read, so the bounds and overflow checks that keep a
 * forged count, stride or offset from reading outside its buffer sit together, apart
 * from the scene flattening in gltf_adapter.cc. Problems are thrown as Failure. */
#include "scene/gltf_adapter.h"

#include <cmath>
#include <cstring>

namespace gltf_adapter {

namespace {

/* Bounds-checked view of one accessor's elements. */
struct AccessorView {
    const unsigned char *data;
    size_t count;
    size_t stride;
    int component_type;
    int components;
    bool normalized;
};

std::string accessor_name(int index)
{
    return "accessor " + std::to_string(index);
}

/* Elements one accessor may hold: a scene takes at most 16 M triangles (scene_build.h),
   so 64 M vertices or indices is past anything it could use; the limit keeps a forged
   count from asking for gigabytes before anything is read. */
const size_t MAX_ACCESSOR_ELEMENTS = (size_t)64 << 20;

/* a + b and a * b into *out; false when they overflow size_t (a forged count or offset). */
bool add_ok(size_t a, size_t b, size_t *out)
{
    return !__builtin_add_overflow(a, b, out);
}

bool mul_ok(size_t a, size_t b, size_t *out)
{
    return !__builtin_mul_overflow(a, b, out);
}

AccessorView view_accessor(const tinygltf::Model &model, int index)
{
    if (index < 0 || (size_t)index >= model.accessors.size())
        fail(accessor_name(index) + " does not exist");
    const tinygltf::Accessor &acc = model.accessors[(size_t)index];
    if (acc.sparse.isSparse)
        fail(accessor_name(index) + " is sparse (not supported)");
    if (acc.bufferView < 0 || (size_t)acc.bufferView >= model.bufferViews.size())
        fail(accessor_name(index) + " has no valid bufferView");
    const tinygltf::BufferView &bv = model.bufferViews[(size_t)acc.bufferView];
    if (bv.buffer < 0 || (size_t)bv.buffer >= model.buffers.size())
        fail(accessor_name(index) + ": bufferView names a missing buffer");
    const std::vector<unsigned char> &buf = model.buffers[(size_t)bv.buffer].data;
    int stride = acc.ByteStride(bv);
    int comp_size = tinygltf::GetComponentSizeInBytes((uint32_t)acc.componentType);
    int comps = tinygltf::GetNumComponentsInType((uint32_t)acc.type);
    if (stride <= 0 || comp_size <= 0 || comps <= 0)
        fail(accessor_name(index) + " has an invalid type or stride");
    size_t elem = (size_t)comp_size * (size_t)comps;
    if ((size_t)stride < elem)
        fail(accessor_name(index) + ": byteStride " + std::to_string(stride) +
             " is smaller than its element of " + std::to_string(elem) + " bytes");
    if (acc.count > MAX_ACCESSOR_ELEMENTS)
        fail(accessor_name(index) + " has " + std::to_string(acc.count) +
             " elements (expected at most " + std::to_string(MAX_ACCESSOR_ELEMENTS) + ")");
    /* Every byte the accessor reads lies inside its view, and the view inside its buffer,
       computed without overflow whatever the file claims. */
    size_t need = 0, view_end = 0, span = 0;
    bool ok = acc.count == 0 ||
              (mul_ok(acc.count - 1, (size_t)stride, &span) && add_ok(span, elem, &span) &&
               add_ok(span, acc.byteOffset, &need));
    ok = ok && add_ok(bv.byteOffset, bv.byteLength, &view_end) && view_end <= buf.size() &&
         need <= bv.byteLength;
    if (!ok)
        fail(accessor_name(index) + " reads past the end of its buffer (count " +
             std::to_string(acc.count) + ", stride " + std::to_string(stride) +
             "; a missing or short .bin, or a forged count?)");
    return {buf.data() + bv.byteOffset + acc.byteOffset, acc.count, (size_t)stride,
            acc.componentType, comps, acc.normalized};
}

double read_component(const unsigned char *p, int type, bool normalized)
{
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: { float f; std::memcpy(&f, p, 4); return f; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0 : p[0];
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        double v = (signed char)p[0];
        return normalized ? std::fmax(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t u; std::memcpy(&u, p, 2); return normalized ? u / 65535.0 : u;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        int16_t s; std::memcpy(&s, p, 2);
        return normalized ? std::fmax(s / 32767.0, -1.0) : s;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { uint32_t u; std::memcpy(&u, p, 4); return u; }
    default: fail("unsupported component type " + std::to_string(type));
    }
}

} // namespace

std::vector<float> read_floats(const tinygltf::Model &model, int index, int components)
{
    AccessorView v = view_accessor(model, index);
    if (v.components != components)
        fail(accessor_name(index) + " has " + std::to_string(v.components) +
             " components, expected " + std::to_string(components));
    int size = tinygltf::GetComponentSizeInBytes((uint32_t)v.component_type);
    std::vector<float> out(v.count * (size_t)components);
    for (size_t i = 0; i < v.count; i++) {
        for (int c = 0; c < components; c++) {
            float x = (float)read_component(v.data + i * v.stride + (size_t)(c * size),
                                            v.component_type, v.normalized);
            /* NaN or infinity in a vertex would vanish into the ray tracer (or poison the
               bounds and the camera): refused, with where it is. */
            if (!std::isfinite(x))
                fail(accessor_name(index) + " element " + std::to_string(i) + " component " +
                     std::to_string(c) + " is " + (std::isnan(x) ? "NaN" : "infinite") +
                     " (expected finite values)");
            out[i * (size_t)components + (size_t)c] = x;
        }
    }
    return out;
}

std::vector<uint32_t> read_indices(const tinygltf::Model &model, int index)
{
    AccessorView v = view_accessor(model, index);
    int t = v.component_type;
    if (v.components != 1 || (t != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                              t != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                              t != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
        fail(accessor_name(index) + " is not a scalar unsigned index accessor");
    std::vector<uint32_t> out(v.count);
    for (size_t i = 0; i < v.count; i++)
        out[i] = (uint32_t)read_component(v.data + i * v.stride, t, false);
    return out;
}

} // namespace gltf_adapter
