/* imageio_write_adapter.cc - writing image files with OpenImageIO 2.4 (imageio.h): the
 * multi-layer float EXR and the tone-mapped 8-bit PNG preview, each staged in a temporary
 * file (files.h) and renamed into place. Separate from reading (imageio_adapter.cc) because
 * the two share nothing but imageio_adapter.h: writing is about layer names, compression,
 * tone mapping and catching every write error, reading about layers, channels and files
 * that lie. No C++ exception leaves this file.
 *
 * Pixels cross in bands of scanlines (BAND_ROWS rows of interleaved values) so a big image
 * never needs a second full-size buffer next to the planar one. */
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

extern "C" {
#include "graph/image.h"
#include "lang/files.h"
#include "io/imageio.h"
#include "lang/diag.h"
#include "io/tonemap.h"
}

#include "io/imageio_adapter.h"

using OIIO::ImageOutput;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

namespace {

/* ---- writing ----------------------------------------------------------------------- */

/* Fills `band` with `rows` interleaved scanlines starting at y0. */
using FillBand = void (*)(const void *user, int y0, int rows, void *band);

/* Writes spec into the staged temporary t (files.h), through a FILE* of ours that
   OpenImageIO writes via an I/O proxy: so every write error (a full disk, a file size
   limit) is seen here, which OpenImageIO's PNG writer would otherwise drop. On return t
   is closed and synced (SSG_OK) or discarded. */
enum ssg_err write_staged(const ImageSpec &spec, TypeDesc format, FillBand fill,
                          const void *user, struct ssg_tmp *t, struct ssg_diags *diags)
{
    std::string why;
    FILE *f = fdopen(t->fd, "wb");
    if (!f) {
        ssg_diag_file(diags, SSG_E_IO, t->target, "cannot write image: %s",
                      std::strerror(errno));
        ssg_tmp_discard(t, 1);
        return SSG_E_IO;
    }
    t->fd = -1; /* f owns the descriptor now */
    try {
        OIIO::Filesystem::IOFile proxy(f, OIIO::Filesystem::IOProxy::Write);
        std::unique_ptr<ImageOutput> out = ImageOutput::create(t->path);
        bool ok = out && out->supports("ioproxy") && out->set_ioproxy(&proxy) &&
                  out->open(t->path, spec);
        size_t row_bytes = (size_t)spec.width * (size_t)spec.nchannels * format.size();
        std::vector<unsigned char> band(ok ? row_bytes * BAND_ROWS : 0);
        for (int y0 = 0; ok && y0 < spec.height; y0 += BAND_ROWS) {
            int rows = std::min(BAND_ROWS, spec.height - y0);
            fill(user, y0, rows, band.data());
            ok = out->write_scanlines(y0, y0 + rows, 0, format, band.data());
        }
        ok = ok && out->close();
        if (!ok)
            why = out ? oiio_error(out.get()) : "no writer for this format";
    } catch (const std::bad_alloc &) {
        why = "out of memory";
    } catch (const std::exception &e) {
        why = e.what()[0] ? e.what() : "unknown C++ exception";
    } catch (...) {
        why = "unknown C++ exception";
    }
    bool flushed = fflush(f) == 0 && !ferror(f) && fsync(fileno(f)) == 0;
    int saved = errno;
    flushed = (fclose(f) == 0) && flushed;
    if (why.empty() && !flushed)
        why = std::strerror(saved ? saved : errno);
    if (!why.empty()) {
        ssg_diag_file(diags, SSG_E_IO, t->target, "cannot write image: %s", why.c_str());
        ssg_tmp_discard(t, 1);
        return SSG_E_IO;
    }
    return SSG_OK;
}

/* Where each EXR channel's values come from: pixel i of a channel is base[i * step]
   (step 1 for a planar image's plane, the file's channel count for an interleaved one). */
struct ExrChannel {
    const float *base;
    size_t step;
};
struct ExrSource {
    std::vector<ExrChannel> channels; /* in channel order */
    int width;
};

void fill_exr_band(const void *user, int y0, int rows, void *band)
{
    const ExrSource *s = (const ExrSource *)user;
    size_t n = s->channels.size(), w = (size_t)s->width;
    float *dst = (float *)band;
    for (int r = 0; r < rows; r++) {
        size_t row = (size_t)(y0 + r) * w;
        float *line = dst + (size_t)r * w * n;
        for (size_t c = 0; c < n; c++) {
            const float *src = s->channels[c].base;
            size_t step = s->channels[c].step;
            for (size_t x = 0; x < w; x++)
                line[x * n + c] = src[(row + x) * step];
        }
    }
}

bool is_main(const struct ssg_exr_layer &l)
{
    return !l.name || !l.name[0];
}

/* The scalar layer `depth` is OpenEXR's depth channel: a bare Z, as Blender and Nuke
   read depth (imageio_adapter.cc reads it back under the layer name). */
bool is_depth(const struct ssg_exr_layer &l)
{
    return !is_main(l) && l.kind == SSG_LAYER_SCALAR && std::strcmp(l.name, "depth") == 0;
}

/* Channel suffixes of a layer, or NULL when its channel count does not fit. */
const char *const *layer_suffixes(const struct ssg_exr_layer &l)
{
    static const char *const gray[] = {"Y"}, *const rgba[] = {"R", "G", "B", "A"},
                             *const xyz[] = {"X", "Y", "Z"}, *const z[] = {"Z"};
    const char *const *rgb = rgba;
    int ch = l.image->channels;
    if (is_main(l))
        return ch == 1 ? gray : ch >= 2 && ch <= 4 ? rgba : nullptr;
    switch (l.kind) {
    case SSG_LAYER_SCALAR: return ch == 1 ? (is_depth(l) ? z : gray) : nullptr;
    case SSG_LAYER_VECTOR: return ch == 3 ? xyz : nullptr;
    case SSG_LAYER_COLOR: return ch == 3 ? rgb : nullptr;
    }
    return nullptr;
}

/* Checks the layers against each other; reports every problem. */
enum ssg_err check_layers(const char *path, const struct ssg_exr_layer *layers, int count,
                          struct ssg_diags *diags)
{
    enum ssg_err first = SSG_OK;
    auto fail = [&](enum ssg_err code) {
        if (!first)
            first = code;
    };
    if (count < 1) {
        ssg_diag_file(diags, SSG_E_VALUE, path, "no layers to write");
        return SSG_E_VALUE;
    }
    for (int i = 0; i < count; i++) {
        const struct ssg_exr_layer &l = layers[i];
        const char *name = is_main(l) ? "(main)" : l.name;
        if (!l.image || !l.image->data) {
            ssg_diag_file(diags, SSG_E_VALUE, path, "layer '%s' has no image", name);
            fail(SSG_E_VALUE);
            continue;
        }
        if (l.image->width != layers[0].image->width ||
            l.image->height != layers[0].image->height) {
            ssg_diag_file(diags, SSG_E_SIZE, path, "layer '%s' is %d x %d, expected %d x %d",
                          name, l.image->width, l.image->height, layers[0].image->width,
                          layers[0].image->height);
            fail(SSG_E_SIZE);
        }
        if (!layer_suffixes(l)) {
            ssg_diag_file(diags, SSG_E_CHANNELS, path,
                          "layer '%s' has %d channels, expected %s", name, l.image->channels,
                          is_main(l) ? "1 to 4" : l.kind == SSG_LAYER_SCALAR ? "1" : "3");
            fail(SSG_E_CHANNELS);
        }
        if (!is_main(l) && std::strchr(l.name, '.')) {
            ssg_diag_file(diags, SSG_E_VALUE, path, "layer name '%s' contains a '.'", name);
            fail(SSG_E_VALUE);
        }
        for (int j = 0; j < i; j++)
            if (is_main(l) == is_main(layers[j]) &&
                (is_main(l) || std::strcmp(l.name, layers[j].name) == 0)) {
                ssg_diag_file(diags, SSG_E_DUPLICATE, path, "layer '%s' is given twice", name);
                fail(SSG_E_DUPLICATE);
                break;
            }
    }
    return first;
}

const char *compression_name(enum ssg_exr_compression c)
{
    switch (c) {
    case SSG_EXR_NONE: return "none";
    case SSG_EXR_RLE: return "rle";
    case SSG_EXR_PIZ: return "piz";
    case SSG_EXR_ZIP: break;
    }
    /* ZIP at zlib level 1: on the frame's float layers it is about a third faster than
       the default level for files about 1.5% larger. */
    return "zip:1";
}

/* The run's metadata (imageio.h, struct ssg_exr_meta) as header attributes. OpenEXR
   keeps them sorted by name, so their order never depends on ours. */
void add_meta(ImageSpec &spec, const struct ssg_exr_meta &m)
{
    const TypeDesc v3f(TypeDesc::FLOAT, TypeDesc::VEC3, TypeDesc::VECTOR);
    const TypeDesc v2i(TypeDesc::INT, TypeDesc::VEC2);
    spec.attribute("software", "ssgraph " SSG_VERSION);
    if (m.graph)
        spec.attribute("ssgraph:graph", m.graph);
    if (m.scene && m.scene[0])
        spec.attribute("ssgraph:scene", m.scene);
    if (m.lights && m.lights[0])
        spec.attribute("ssgraph:lights", m.lights);
    if (m.set_count > 0)
        spec.attribute("ssgraph:overrides", TypeDesc(TypeDesc::STRING, m.set_count), m.sets);
    spec.attribute("ssgraph:seed", std::to_string((unsigned long long)m.seed));
    const int size[2] = {m.width, m.height};
    spec.attribute("ssgraph:frame_size", v2i, size);
    spec.attribute("ssgraph:guard", m.guard);
    spec.attribute("ssgraph:fov", m.fov_y);
    spec.attribute("ssgraph:near", m.near_z);
    spec.attribute("ssgraph:far", m.far_z);
    if (!m.has_camera)
        return;
    spec.attribute("ssgraph:camera_position", v3f, m.position);
    spec.attribute("ssgraph:camera_target", v3f, m.target);
    spec.attribute("ssgraph:camera_up", v3f, m.up);
    spec.attribute("worldToCamera", OIIO::TypeMatrix44, m.world_to_camera);
    spec.attribute("worldToNDC", OIIO::TypeMatrix44, m.world_to_ndc);
}

enum ssg_err stage_exr(const char *path, const struct ssg_exr_layer *layers, int count,
                       enum ssg_exr_compression compression, const struct ssg_exr_meta *meta,
                       struct ssg_tmp *t, struct ssg_diags *diags)
{
    enum ssg_err err = check_layers(path, layers, count, diags);
    if (err)
        return err;
    ExrSource src;
    src.width = layers[0].image->width;
    std::vector<std::string> names;
    for (int i = 0; i < count; i++) {
        const char *const *suffixes = layer_suffixes(layers[i]);
        bool bare = is_main(layers[i]) || is_depth(layers[i]);
        for (int c = 0; c < layers[i].image->channels; c++) {
            std::string prefix = bare ? "" : std::string(layers[i].name) + ".";
            names.push_back(prefix + suffixes[c]);
            src.channels.push_back({ssg_image_plane(layers[i].image, c), 1});
        }
    }
    ImageSpec spec(src.width, layers[0].image->height, (int)names.size(), TypeDesc::FLOAT);
    spec.channelnames = names;
    spec.attribute("compression", compression_name(compression));
    /* OpenImageIO stamps the current time as capDate unless DateTime is set: an empty one
       keeps the bytes the same from run to run. */
    spec.attribute("DateTime", "");
    if (meta)
        add_meta(spec, *meta);
    if (ssg_tmp_create(path, ".exr", "image", t, diags))
        return SSG_E_IO;
    return write_staged(spec, TypeDesc::FLOAT, fill_exr_band, &src, t, diags);
}

/* ---- joining views (ssg_exr_views_join) -------------------------------------------- */

/* One view's file, read whole: its header and interleaved float pixels. */
struct ViewFile {
    ImageSpec spec;
    std::vector<float> pixels;
};

enum ssg_err read_view(const char *path, ViewFile &v, struct ssg_diags *diags)
{
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) {
        ssg_diag_file(diags, SSG_E_IMAGE, path, "cannot read a view: %s",
                      oiio_error<OIIO::ImageInput>(nullptr).c_str());
        return SSG_E_IMAGE;
    }
    v.spec = in->spec();
    v.pixels.resize((size_t)v.spec.width * (size_t)v.spec.height * (size_t)v.spec.nchannels);
    bool ok = in->read_image(0, 0, 0, v.spec.nchannels, TypeDesc::FLOAT, v.pixels.data());
    std::string why = ok ? "" : oiio_error(in.get());
    in->close();
    if (!ok) {
        ssg_diag_file(diags, SSG_E_IMAGE, path, "cannot decode a view: %s", why.c_str());
        return SSG_E_IMAGE;
    }
    return SSG_OK;
}

/* OpenEXR's multi-view channel name: the view goes before the last component
   (layer.view.channel), so "R" -> "right.R" and "ao.Y" -> "ao.right.Y". */
std::string view_channel(const std::string &channel, const std::string &view)
{
    size_t dot = channel.rfind('.');
    if (dot == std::string::npos)
        return view + "." + channel;
    return channel.substr(0, dot + 1) + view + channel.substr(dot);
}

/* What the file itself says about the image and OpenImageIO adds on reading: rewritten
   from the channels and compression, never copied between views. */
bool header_own(const std::string &name)
{
    return name.rfind("oiio:", 0) == 0 || name.rfind("openexr:", 0) == 0 ||
           name == "compression" || name == "PixelAspectRatio" ||
           name == "screenWindowCenter" || name == "screenWindowWidth" || name == "multiView";
}

bool same_value(const OIIO::ParamValue &a, const OIIO::ParamValue &b)
{
    return a.type() == b.type() && a.nvalues() == b.nvalues() &&
           std::memcmp(a.data(), b.data(), a.datasize()) == 0;
}

/* The default view's attributes, then each other view's that differ, as ssgraph:VIEW:NAME
   (the `ssgraph:` of NAME dropped: ssgraph:right:camera_position). */
void join_attributes(ImageSpec &out, const std::vector<ViewFile> &v,
                     const char *const *views)
{
    for (const OIIO::ParamValue &p : v[0].spec.extra_attribs)
        if (!header_own(p.name().string()))
            out.attribute(p.name().string(), p.type(), p.data());
    for (size_t k = 1; k < v.size(); k++)
        for (const OIIO::ParamValue &p : v[k].spec.extra_attribs) {
            std::string name = p.name().string();
            const OIIO::ParamValue *base = v[0].spec.find_attribute(name);
            if (header_own(name) || (base && same_value(*base, p)))
                continue;
            if (name.rfind("ssgraph:", 0) == 0)
                name = name.substr(8);
            out.attribute("ssgraph:" + std::string(views[k]) + ":" + name, p.type(),
                          p.data());
        }
}

enum ssg_err stage_views(const char *path, const char *const *views, const char *const *files,
                         int count, struct ssg_tmp *t, struct ssg_diags *diags)
{
    std::vector<ViewFile> v((size_t)(count > 0 ? count : 0));
    for (int k = 0; k < count; k++) {
        enum ssg_err e = read_view(files[k], v[k], diags);
        if (e)
            return e;
        if (v[k].spec.width != v[0].spec.width || v[k].spec.height != v[0].spec.height) {
            ssg_diag_file(diags, SSG_E_SIZE, files[k], "view '%s' is %d x %d, the default "
                          "view %d x %d", views[k], v[k].spec.width, v[k].spec.height,
                          v[0].spec.width, v[0].spec.height);
            return SSG_E_SIZE;
        }
    }
    if (count < 2) {
        ssg_diag_file(diags, SSG_E_VALUE, path, "a multi-view EXR needs at least 2 views");
        return SSG_E_VALUE;
    }
    ExrSource src;
    src.width = v[0].spec.width;
    std::vector<std::string> names;
    for (int k = 0; k < count; k++) {
        size_t n = (size_t)v[k].spec.nchannels;
        for (size_t c = 0; c < n; c++) {
            const std::string &ch = v[k].spec.channelnames[c];
            names.push_back(k ? view_channel(ch, views[k]) : ch);
            src.channels.push_back({v[k].pixels.data() + c, n});
        }
    }
    ImageSpec spec(src.width, v[0].spec.height, (int)names.size(), TypeDesc::FLOAT);
    spec.channelnames = names;
    spec.attribute("compression", v[0].spec.get_string_attribute("compression", "zip"));
    spec.attribute("DateTime", "");
    spec.attribute("multiView", TypeDesc(TypeDesc::STRING, count), views);
    join_attributes(spec, v, views);
    if (ssg_tmp_create(path, ".exr", "image", t, diags))
        return SSG_E_IO;
    return write_staged(spec, TypeDesc::FLOAT, fill_exr_band, &src, t, diags);
}

/* zlib level of the PNG preview: a preview, not an archive. Level 1 instead of OpenImageIO's
   6 writes a 1280x720 frame in ~57 ms instead of ~86, for a file ~1.5x larger. */
const int PNG_LEVEL = 1;

struct PngSource {
    const struct ssg_image *image;
    enum ssg_tonemap tonemap;
    float scale; /* 2^exposure */
};

void fill_png_band(const void *user, int y0, int rows, void *band)
{
    const PngSource *s = (const PngSource *)user;
    size_t n = (size_t)s->image->channels, w = (size_t)s->image->width;
    unsigned char *dst = (unsigned char *)band;
    for (int r = 0; r < rows; r++) {
        size_t row = (size_t)(y0 + r) * w;
        unsigned char *line = dst + (size_t)r * w * n;
        for (size_t c = 0; c < n; c++) {
            const float *plane = ssg_image_plane(s->image, (int)c) + row;
            for (size_t x = 0; x < w; x++)
                line[x * n + c] = ssg_srgb8_scaled(s->tonemap, s->scale, plane[x]);
        }
    }
}

enum ssg_err stage_png(const char *path, const struct ssg_image *image,
                       enum ssg_tonemap tonemap, float exposure, struct ssg_tmp *t,
                       struct ssg_diags *diags)
{
    if (!image || !image->data || (image->channels != 1 && image->channels != 3)) {
        ssg_diag_file(diags, SSG_E_CHANNELS, path,
                      "a PNG preview needs a 1- or 3-channel image, got %d channels",
                      image ? image->channels : 0);
        return SSG_E_CHANNELS;
    }
    PngSource src = {image, tonemap, std::exp2(exposure)};
    ImageSpec spec(image->width, image->height, image->channels, TypeDesc::UINT8);
    /* Nothing time- or host-dependent: OpenImageIO writes a tIME chunk only from DateTime. */
    spec.erase_attribute("DateTime");
    spec.erase_attribute("Software");
    spec.attribute("png:compressionLevel", PNG_LEVEL);
    if (ssg_tmp_create(path, ".png", "image", t, diags))
        return SSG_E_IO;
    return write_staged(spec, TypeDesc::UINT8, fill_png_band, &src, t, diags);
}

} /* namespace */

/* ---- the module's api (oiio_module.h); the C wrappers are in imageio_load.c ------------------------------------------------------------------ */

/* A C++ exception from staging becomes a diagnostic; the temporary goes with it. */
template <class F>
enum ssg_err guarded_stage(const char *path, struct ssg_tmp *t, struct ssg_diags *diags,
                           F stage)
{
    t->fd = t->lock_fd = -1;
    t->slot = -1;
    enum ssg_err e;
    try {
        return stage();
    } catch (const std::bad_alloc &) {
        e = report_exception(diags, path, SSG_E_NOMEM, "out of memory while writing");
    } catch (const std::exception &ex) {
        e = report_exception(diags, path, SSG_E_IO, ex.what());
    } catch (...) {
        e = report_exception(diags, path, SSG_E_IO, "unknown error while writing");
    }
    ssg_tmp_discard(t, 1);
    return e;
}

enum ssg_err ssg_oiio_exr_stage(const char *path, const struct ssg_exr_layer *layers, int count,
                                enum ssg_exr_compression compression,
                                const struct ssg_exr_meta *meta, struct ssg_tmp *t,
                                struct ssg_diags *diags)
{
    return guarded_stage(path, t, diags, [&] {
        return stage_exr(path, layers, count, compression, meta, t, diags);
    });
}

enum ssg_err ssg_oiio_views_stage(const char *path, const char *const *views,
                                  const char *const *files, int count, struct ssg_tmp *t,
                                  struct ssg_diags *diags)
{
    return guarded_stage(path, t, diags, [&] {
        return stage_views(path, views, files, count, t, diags);
    });
}

enum ssg_err ssg_oiio_png_stage(const char *path, const struct ssg_image *image,
                                enum ssg_tonemap tonemap, float exposure, struct ssg_tmp *t,
                                struct ssg_diags *diags)
{
    return guarded_stage(path, t, diags, [&] {
        return stage_png(path, image, tonemap, exposure, t, diags);
    });
}
