/* imageio_adapter.cc - reading image files with OpenImageIO 2.4 (ssg_image_read in
 * ssgraph.h, imageio.h), inside the module (oiio_module.h), for every format the library
 * does not read itself: EXR and PNG never come here (formats.h), JPEG, HDR, TIFF, ... do.
 * The only C++ here is the OpenImageIO calls and the try/catch that keeps exceptions
 * inside; everything the rest of ssgraph sees is C.
 *
 * Pixels cross in bands of scanlines (BAND_ROWS rows of interleaved floats) so a big file
 * never needs a second full-size buffer next to the planar image. */
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

extern "C" {
#include "graph/image.h"
#include "lang/files.h"
#include "io/imageio.h"
#include "lang/diag.h"
}

#include "io/imageio_adapter.h"

using OIIO::ImageInput;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

namespace {

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

/* OpenEXR's depth channel Z (bare, or VIEW.Z in a multi-view file) is what the writer
   makes of the layer `depth` (imageio_write_adapter.cc): layer "depth" reads it when the
   file has no depth.* channels, "depth.VIEW" reads VIEW.Z. -1 when absent. */
int depth_channel(const ImageSpec &spec, const std::string &layer)
{
    if (layer != "depth" && layer.rfind("depth.", 0) != 0)
        return -1;
    std::string want = layer == "depth" ? "Z" : layer.substr(6) + ".Z";
    for (int c = 0; c < spec.nchannels; c++)
        if (spec.channelnames[c] == want)
            return c;
    return -1;
}

/* Indices of the channels to read, in canonical order. In a layer that holds Z but no X
   (an image beside its depth: R,G,B,Z), Z is the depth channel, not the image's. */
std::vector<int> select_channels(const ImageSpec &spec, const char *layer)
{
    std::string name = layer ? layer : "";
    std::vector<int> idx;
    int z = -1;
    bool x = false;
    for (int c = 0; c < spec.nchannels; c++) {
        const char *suffix = layer_suffix(spec.channelnames[c], name);
        if (!suffix)
            continue;
        idx.push_back(c);
        z = std::strcmp(suffix, "Z") == 0 ? c : z;
        x = x || std::strcmp(suffix, "X") == 0;
    }
    if (z >= 0 && !x && idx.size() > 1)
        idx.erase(std::find(idx.begin(), idx.end(), z));
    int depth = idx.empty() ? depth_channel(spec, name) : -1;
    if (depth >= 0)
        idx.push_back(depth);
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
        std::string layer = ch == "Z" ? "depth" : dot == std::string::npos ? "(unnamed)"
                                                                            : ch.substr(0, dot);
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
    close(fd);
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

} /* namespace */

/* ---- the C interface ------------------------------------------------------------------ */

/* A C++ exception from reading becomes a diagnostic. */
template <class F> enum ssg_err guarded_read(const char *path, struct ssg_diags *diags, F read)
{
    try {
        return read();
    } catch (const std::bad_alloc &) {
        return report_exception(diags, path, SSG_E_NOMEM, "out of memory while reading");
    } catch (const std::exception &e) {
        return report_exception(diags, path, SSG_E_IMAGE, e.what());
    } catch (...) {
        return report_exception(diags, path, SSG_E_IMAGE, "unknown error while reading");
    }
}

enum ssg_err ssg_oiio_image_read(const char *path, const char *layer, struct ssg_image **out,
                                 struct ssg_diags *diags)
{
    if (out)
        *out = nullptr;
    if (!path || !out) {
        ssg_diag_file(diags, SSG_E_IO, path ? path : "", "no file name or no output given");
        return SSG_E_IO;
    }
    return guarded_read(path, diags, [&] {
        return read_image(path, layer && layer[0] ? layer : nullptr, out, diags);
    });
}
