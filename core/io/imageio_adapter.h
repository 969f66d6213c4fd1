/* imageio_adapter.h - private to the OpenImageIO module's reader (imageio_adapter.cc): the
 * band height, the sRGB decoding and the turning of OpenImageIO errors and C++ exceptions
 * into diagnostics. C++ only; included by no C file. Stateless, so safe from any thread. */
#ifndef SSG_IMAGEIO_ADAPTER_H
#define SSG_IMAGEIO_ADAPTER_H

#include <algorithm>
#include <cmath>
#include <string>

#include <OpenImageIO/imageio.h>

extern "C" {
#include "lang/diag.h"
}
#include "io/oiio_host.h"

namespace {

/* Rows moved per OpenImageIO call: enough for a codec to work in long runs, while the
   interleaved staging buffer stays small (1920 wide, 18 channels: 8.8 MB). */
const int BAND_ROWS = 64;

/* ---- colour ------------------------------------------------------------------------ */

/* IEC 61966-2-1 decoding to linear (the encoding is io/tonemap.h's). */
inline float srgb_decode(float c)
{
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

/* Reports an error caught from OpenImageIO or the C++ runtime. */
inline enum ssg_err report_exception(struct ssg_diags *diags, const char *path,
                                     enum ssg_err code, const char *what)
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

} /* namespace */

#endif
