/* imageio_adapter.cc - reading and writing image files with OpenImageIO 2.4 (imageio.h,
 * ssg_image_read in ssgraph.h). The only C++ here is the OpenImageIO calls and the
 * try/catch that keeps exceptions inside; everything the rest of ssgraph sees is C.
 *
 * Pixels cross in bands of scanlines (BAND_ROWS rows of interleaved floats) so a big file
 * never needs a second full-size buffer next to the planar image. */
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

extern "C" {
#include "io/exr_guard.h"
#include "graph/image.h"
#include "lang/files.h"
#include "io/imageio.h"
#include "lang/diag.h"
}

using OIIO::ImageInput;
using OIIO::ImageOutput;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

namespace {

/* Rows moved per OpenImageIO call: several 16-line ZIP blocks, which OpenEXR compresses
   on its own threads in parallel (deterministically: blocks are independent), while the
   interleaved staging buffer stays small (1920 wide, 18 channels: 8.8 MB). */
const int BAND_ROWS = 64;

/* ---- colour ------------------------------------------------------------------------ */

/* IEC 61966-2-1 transfer functions. */
float srgb_encode(float v)
{
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

float srgb_decode(float c)
{
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

/* Tone curve of an exposure-scaled value v. Inputs are capped at 1e4 so the rational
   curves never see inf/inf; every curve is already at 1 (to float precision) long before. */
float tonemap_scaled(enum ssg_tonemap tonemap, float v)
{
    if (!(v > 0.0f)) /* negative, zero, NaN */
        return 0.0f;
    v = std::min(v, 1e4f);
    float d;
    switch (tonemap) {
    case SSG_TONEMAP_REINHARD:
        d = v / (1.0f + v);
        break;
    case SSG_TONEMAP_ACES: /* Narkowicz, "ACES Filmic Tone Mapping Curve", 2015 */
        d = (v * (2.51f * v + 0.03f)) / (v * (2.43f * v + 0.59f) + 0.14f);
        break;
    case SSG_TONEMAP_CLAMP:
    default:
        d = v;
        break;
    }
    return std::min(d, 1.0f);
}

unsigned char to_srgb8(enum ssg_tonemap tonemap, float scale, float x)
{
    float s = srgb_encode(tonemap_scaled(tonemap, x * scale));
    int code = (int)(s * 255.0f + 0.5f);
    return (unsigned char)std::max(0, std::min(255, code));
}

/* ---- small helpers ----------------------------------------------------------------- */

/* Reports an error caught from OpenImageIO or the C++ runtime. */
enum ssg_err report_exception(struct ssg_diags *diags, const char *path, enum ssg_err code,
                              const char *what)
{
    ssg_diag_file(diags, code, path, "%s", what);
    return code;
}

/* The message of an ImageInput/ImageOutput error, or OpenImageIO's global one; clears both
   so OpenImageIO never prints them itself later. */
template <class T> std::string oiio_error(const T *io)
{
    std::string msg = io ? io->geterror() : std::string();
    std::string global = OIIO::geterror();
    if (msg.empty())
        msg = global;
    if (msg.empty())
        msg = "unknown OpenImageIO error";
    std::replace(msg.begin(), msg.end(), '\n', ' ');
    return msg;
}

/* ---- reading ----------------------------------------------------------------------- */

/* Position of a channel-name suffix in the canonical order of its layer (R,G,B,A or
   X,Y,Z,W); 4 for anything else, which then keeps the file's order. */
int suffix_rank(const std::string &suffix)
{
    static const char *const orders[2][4] = {{"R", "G", "B", "A"}, {"X", "Y", "Z", "W"}};
    for (const auto &order : orders)
        for (int i = 0; i < 4; i++)
            if (suffix == order[i])
                return i;
    return 4;
}

/* The part of a channel name after the layer prefix, or NULL if the channel is not in the
   layer. The main layer (empty name) holds the names without a dot. */
const char *layer_suffix(const std::string &channel, const std::string &layer)
{
    if (layer.empty())
        return channel.find('.') == std::string::npos ? channel.c_str() : nullptr;
    if (channel.size() <= layer.size() + 1 || channel.compare(0, layer.size(), layer) != 0 ||
        channel[layer.size()] != '.')
        return nullptr;
    const char *rest = channel.c_str() + layer.size() + 1;
    return std::strchr(rest, '.') ? nullptr : rest;
}

/* Indices of the channels to read, in canonical order. */
std::vector<int> select_channels(const ImageSpec &spec, const char *layer)
{
    std::string name = layer ? layer : "";
    std::vector<int> idx;
    for (int c = 0; c < spec.nchannels; c++)
        if (layer_suffix(spec.channelnames[c], name))
            idx.push_back(c);
    if (idx.empty() && name.empty()) /* no unnamed channels: the whole file */
        for (int c = 0; c < spec.nchannels; c++)
            idx.push_back(c);
    auto rank = [&](int c) {
        const char *suffix = layer_suffix(spec.channelnames[c], name);
        return suffix ? suffix_rank(suffix) : 4;
    };
    std::stable_sort(idx.begin(), idx.end(), [&](int a, int b) { return rank(a) < rank(b); });
    return idx;
}

/* "main, ao, normal": the layers of a file, for the message about a missing one. */
std::string layer_list(const ImageSpec &spec)
{
    std::vector<std::string> names;
    for (const auto &ch : spec.channelnames) {
        size_t dot = ch.rfind('.');
        std::string layer = dot == std::string::npos ? "(unnamed)" : ch.substr(0, dot);
        if (std::find(names.begin(), names.end(), layer) == names.end())
            names.push_back(layer);
    }
    std::string out;
    for (const auto &n : names)
        out += (out.empty() ? "" : ", ") + n;
    return out;
}

/* A missing or unreadable file is an I/O error, not an image error: tell them apart before
   OpenImageIO, whose messages do not say which it was. A FIFO, a device or anything but a
   regular file of a sane size is refused here (files.h): /dev/zero would never end. */
enum ssg_err check_readable(const char *path, struct ssg_diags *diags)
{
    char why[320];
    int fd;
    enum ssg_err e = ssg_input_open(path, SSG_MAX_IMAGE_BYTES, &fd, why, sizeof why);
    if (e) {
        ssg_diag_file(diags, e, path, "cannot read image: %s", why);
        return e;
    }
    /* OpenEXR believes its header's sizes before it finds the file's end (exr_guard.h). */
    int sane = ssg_exr_guard(fd, why, sizeof why);
    close(fd);
    if (!sane) {
        ssg_diag_file(diags, SSG_E_IMAGE, path, "not a readable image: %s", why);
        return SSG_E_IMAGE;
    }
    return SSG_OK;
}

/* Copies the selected channels of an interleaved band (chbegin..chend of the file) into
   the planar image, decoding sRGB where asked. */
void scatter_band(const std::vector<float> &band, int nread, int chbegin,
                  const std::vector<int> &idx, const std::vector<char> &decode, int y0,
                  int rows, struct ssg_image *im)
{
    size_t w = (size_t)im->width;
    for (size_t k = 0; k < idx.size(); k++) {
        float *plane = ssg_image_plane(im, (int)k);
        int src = idx[k] - chbegin;
        for (int r = 0; r < rows; r++) {
            const float *in = band.data() + (size_t)r * w * (size_t)nread + (size_t)src;
            float *dst = plane + (size_t)(y0 + r) * w;
            for (size_t x = 0; x < w; x++)
                dst[x] = in[x * (size_t)nread];
            if (decode[k])
                for (size_t x = 0; x < w; x++)
                    dst[x] = srgb_decode(dst[x]);
        }
    }
}

/* A tiled file (OpenEXR allows tiles as well as scanlines): each selected channel is read
   whole, straight into its plane. OpenImageIO 2.4's read_scanlines divides by zero on
   tiled files, and read_image reads either layout. */
enum ssg_err read_tiled(ImageInput *in, const char *path, const std::vector<int> &idx,
                        const std::vector<char> &decode, struct ssg_image *im,
                        struct ssg_diags *diags)
{
    size_t pixels = (size_t)im->width * (size_t)im->height;
    for (size_t k = 0; k < idx.size(); k++) {
        float *plane = ssg_image_plane(im, (int)k);
        if (!in->read_image(0, 0, idx[k], idx[k] + 1, TypeDesc::FLOAT, plane)) {
            ssg_diag_file(diags, SSG_E_IMAGE, path, "cannot decode image: %s",
                          oiio_error(in).c_str());
            return SSG_E_IMAGE;
        }
        if (decode[k])
            for (size_t i = 0; i < pixels; i++)
                plane[i] = srgb_decode(plane[i]);
    }
    return SSG_OK;
}

enum ssg_err read_pixels(ImageInput *in, const char *path, const std::vector<int> &idx,
                         struct ssg_image *im, struct ssg_diags *diags)
{
    const ImageSpec &spec = in->spec();
    int chbegin = *std::min_element(idx.begin(), idx.end());
    int chend = *std::max_element(idx.begin(), idx.end()) + 1;
    int nread = chend - chbegin;
    /* Files tagged sRGB (8-bit PNG, JPEG) hold display-encoded colour; alpha never is. */
    bool srgb = OIIO::Strutil::iequals(spec.get_string_attribute("oiio:ColorSpace"), "sRGB");
    std::vector<char> decode(idx.size());
    for (size_t k = 0; k < idx.size(); k++)
        decode[k] = srgb && idx[k] != spec.alpha_channel;
    if (spec.tile_width > 0)
        return read_tiled(in, path, idx, decode, im, diags);
    /* The channel range read may hold many unwanted channels: keep the band under 64 MB. */
    size_t row_floats = (size_t)spec.width * (size_t)nread;
    int band_rows =
        (int)std::max<size_t>(1, std::min<size_t>(BAND_ROWS, (16u << 20) / row_floats));
    std::vector<float> band(row_floats * (size_t)band_rows);
    for (int y0 = 0; y0 < spec.height; y0 += band_rows) {
        int rows = std::min(band_rows, spec.height - y0);
        if (!in->read_scanlines(0, 0, spec.y + y0, spec.y + y0 + rows, spec.z, chbegin, chend,
                                TypeDesc::FLOAT, band.data())) {
            ssg_diag_file(diags, SSG_E_IMAGE, path, "cannot decode image: %s",
                          oiio_error(in).c_str());
            return SSG_E_IMAGE;
        }
        scatter_band(band, nread, chbegin, idx, decode, y0, rows, im);
    }
    return SSG_OK;
}

/* No image format packs more than MAX_RATIO bytes of float pixels into a byte of file
   (zlib's limit is about 1032:1 of its input; a constant 8192^2 half EXR is 1800:1 of our
   floats): a header that declares more, a 23-byte file claiming a gigabyte of pixels
   (found by fuzz_image), is refused before the image is allocated. */
const double MAX_RATIO = 65536.0, SLACK_BYTES = 64.0 * 1024 * 1024;

bool plausible_size(const char *path, const ImageSpec &spec, int nch, struct ssg_diags *diags)
{
    struct stat st;
    double pixels = (double)spec.width * (double)spec.height * nch * sizeof(float);
    if (stat(path, &st) != 0 || pixels <= (double)st.st_size * MAX_RATIO + SLACK_BYTES)
        return true;
    ssg_diag_file(diags, SSG_E_IMAGE, path, "not a readable image: its header declares %d x %d "
                  "pixels, far more than a file of %lld bytes can hold (truncated or forged)",
                  spec.width, spec.height, (long long)st.st_size);
    return false;
}

enum ssg_err read_image(const char *path, const char *layer, struct ssg_image **out,
                        struct ssg_diags *diags)
{
    enum ssg_err err = check_readable(path, diags);
    if (err)
        return err;
    /* Alpha stays as stored (unassociated in PNG): premultiplying before the sRGB decode
       below would decode the wrong values. */
    ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    std::unique_ptr<ImageInput> in = ImageInput::open(path, &config);
    if (!in) {
        ssg_diag_file(diags, SSG_E_IMAGE, path, "not a readable image: %s",
                      oiio_error<ImageInput>(nullptr).c_str());
        return SSG_E_IMAGE;
    }
    const ImageSpec &spec = in->spec();
    if (spec.deep || spec.depth > 1) {
        ssg_diag_file(diags, SSG_E_IMAGE, path, "deep and volume images are not supported");
        return SSG_E_IMAGE;
    }
    std::vector<int> idx = select_channels(spec, layer);
    if (idx.empty()) {
        ssg_diag_file(diags, SSG_E_CHANNELS, path, "no layer '%s' (layers in the file: %s)",
                      layer ? layer : "(unnamed)", layer_list(spec).c_str());
        return SSG_E_CHANNELS;
    }
    int nch = (int)idx.size();
    /* Files hold what ports read (1 to 4 channels): a multi-layer EXR read whole is a
       mistake to report here, not a many-channel image to load. */
    if (nch > 4 || !ssg_image_size_ok(spec.width, spec.height, nch)) {
        ssg_diag_file(diags, SSG_E_SIZE, path,
                      "unsupported image size %d x %d with %d channels (expected at most %d "
                      "pixels a side, %d pixels and 1..4 channels)",
                      spec.width, spec.height, nch, SSG_IMAGE_MAX_SIDE, SSG_IMAGE_MAX_PIXELS);
        return SSG_E_SIZE;
    }
    if (!plausible_size(path, spec, nch, diags))
        return SSG_E_IMAGE;
    struct ssg_image *im = ssg_image_create(spec.width, spec.height, nch);
    if (!im) {
        ssg_diag_file(diags, SSG_E_NOMEM, path, "out of memory for a %d x %d image",
                      spec.width, spec.height);
        return SSG_E_NOMEM;
    }
    err = read_pixels(in.get(), path, idx, im, diags);
    in->close();
    if (err) {
        ssg_image_destroy(&im);
        return err;
    }
    *out = im;
    return SSG_OK;
}

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

/* Where each EXR channel's values come from. */
struct ExrSource {
    std::vector<const float *> planes; /* one per channel, in channel order */
    int width;
};

void fill_exr_band(const void *user, int y0, int rows, void *band)
{
    const ExrSource *s = (const ExrSource *)user;
    size_t n = s->planes.size(), w = (size_t)s->width;
    float *dst = (float *)band;
    for (int r = 0; r < rows; r++) {
        size_t row = (size_t)(y0 + r) * w;
        float *line = dst + (size_t)r * w * n;
        for (size_t c = 0; c < n; c++)
            for (size_t x = 0; x < w; x++)
                line[x * n + c] = s->planes[c][row + x];
    }
}

bool is_main(const struct ssg_exr_layer &l)
{
    return !l.name || !l.name[0];
}

/* Channel suffixes of a layer, or NULL when its channel count does not fit. */
const char *const *layer_suffixes(const struct ssg_exr_layer &l)
{
    static const char *const gray[] = {"Y"}, *const rgba[] = {"R", "G", "B", "A"},
                             *const xyz[] = {"X", "Y", "Z"};
    const char *const *rgb = rgba;
    int ch = l.image->channels;
    if (is_main(l))
        return ch == 1 ? gray : ch >= 2 && ch <= 4 ? rgba : nullptr;
    switch (l.kind) {
    case SSG_LAYER_SCALAR: return ch == 1 ? gray : nullptr;
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

enum ssg_err stage_exr(const char *path, const struct ssg_exr_layer *layers, int count,
                       enum ssg_exr_compression compression, struct ssg_tmp *t,
                       struct ssg_diags *diags)
{
    enum ssg_err err = check_layers(path, layers, count, diags);
    if (err)
        return err;
    ExrSource src;
    src.width = layers[0].image->width;
    std::vector<std::string> names;
    for (int i = 0; i < count; i++) {
        const char *const *suffixes = layer_suffixes(layers[i]);
        for (int c = 0; c < layers[i].image->channels; c++) {
            std::string prefix = is_main(layers[i]) ? "" : std::string(layers[i].name) + ".";
            names.push_back(prefix + suffixes[c]);
            src.planes.push_back(ssg_image_plane(layers[i].image, c));
        }
    }
    ImageSpec spec(src.width, layers[0].image->height, (int)names.size(), TypeDesc::FLOAT);
    spec.channelnames = names;
    spec.attribute("compression", compression_name(compression));
    /* OpenImageIO stamps the current time as capDate unless DateTime is set: an empty one
       keeps the bytes the same from run to run. */
    spec.attribute("DateTime", "");
    if (ssg_tmp_create(path, ".exr", "image", t, diags))
        return SSG_E_IO;
    return write_staged(spec, TypeDesc::FLOAT, fill_exr_band, &src, t, diags);
}

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
                line[x * n + c] = to_srgb8(s->tonemap, s->scale, plane[x]);
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
    if (ssg_tmp_create(path, ".png", "image", t, diags))
        return SSG_E_IO;
    return write_staged(spec, TypeDesc::UINT8, fill_png_band, &src, t, diags);
}

} /* namespace */

/* ---- the C interface ------------------------------------------------------------------ */

extern "C" float ssg_tonemap_apply(enum ssg_tonemap tonemap, float exposure, float x)
{
    return tonemap_scaled(tonemap, x * std::exp2(exposure));
}

extern "C" unsigned char ssg_tonemap_to_srgb8(enum ssg_tonemap tonemap, float exposure, float x)
{
    return to_srgb8(tonemap, std::exp2(exposure), x);
}

extern "C" enum ssg_err ssg_image_read(const char *path, const char *layer,
                                       struct ssg_image **out, struct ssg_diags *diags)
{
    if (out)
        *out = nullptr;
    if (!path || !out) {
        ssg_diag_file(diags, SSG_E_IO, path ? path : "", "no file name or no output given");
        return SSG_E_IO;
    }
    try {
        return read_image(path, layer && layer[0] ? layer : nullptr, out, diags);
    } catch (const std::bad_alloc &) {
        return report_exception(diags, path, SSG_E_NOMEM, "out of memory while reading");
    } catch (const std::exception &e) {
        return report_exception(diags, path, SSG_E_IMAGE, e.what());
    } catch (...) {
        return report_exception(diags, path, SSG_E_IMAGE, "unknown error while reading");
    }
}

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

extern "C" enum ssg_err ssg_exr_stage(const char *path, const struct ssg_exr_layer *layers,
                                      int count, enum ssg_exr_compression compression,
                                      struct ssg_tmp *t, struct ssg_diags *diags)
{
    return guarded_stage(path, t, diags, [&] {
        return stage_exr(path, layers, count, compression, t, diags);
    });
}

extern "C" enum ssg_err ssg_png_stage(const char *path, const struct ssg_image *image,
                                      enum ssg_tonemap tonemap, float exposure,
                                      struct ssg_tmp *t, struct ssg_diags *diags)
{
    return guarded_stage(path, t, diags, [&] {
        return stage_png(path, image, tonemap, exposure, t, diags);
    });
}

extern "C" enum ssg_err ssg_exr_write(const char *path, const struct ssg_exr_layer *layers,
                                      int count, struct ssg_diags *diags)
{
    return ssg_exr_write_compressed(path, layers, count, SSG_EXR_ZIP, diags);
}

extern "C" enum ssg_err ssg_exr_write_compressed(const char *path,
                                                 const struct ssg_exr_layer *layers, int count,
                                                 enum ssg_exr_compression compression,
                                                 struct ssg_diags *diags)
{
    struct ssg_tmp t;
    enum ssg_err e = ssg_exr_stage(path, layers, count, compression, &t, diags);
    return e ? e : ssg_tmp_commit(&t, 1, diags);
}

extern "C" enum ssg_err ssg_png_write(const char *path, const struct ssg_image *image,
                                      enum ssg_tonemap tonemap, float exposure,
                                      struct ssg_diags *diags)
{
    struct ssg_tmp t;
    enum ssg_err e = ssg_png_stage(path, image, tonemap, exposure, &t, diags);
    return e ? e : ssg_tmp_commit(&t, 1, diags);
}
