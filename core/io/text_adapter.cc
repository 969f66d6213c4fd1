// text_adapter.cc - ssg_text_draw (text.h) through OpenImageIO's ImageBufAlgo::render_text:
// the text is rendered into a small RGBA buffer, which is then laid over the planar float
// image on a darkened box.
#include <OpenImageIO/imagebufalgo.h>

extern "C" {
#include "lang/diag.h"
#include "io/text.h"
}
#include "io/oiio_host.h"

using namespace OIIO;

namespace {
const char *const FONT = "DejaVuSans";

/* Lays the label over the image: its box darkened to a third, then the white text, so it
   reads on bright and dark images alike. */
void composite(struct ssg_image *im, const ImageBuf &label, int x0, int y0)
{
    const ImageSpec &s = label.spec();
    std::vector<float> px((size_t)s.width * s.height * 4);
    label.get_pixels(ROI(0, s.width, 0, s.height, 0, 1, 0, 4), TypeDesc::FLOAT, px.data());
    size_t plane = (size_t)im->width * im->height;
    for (int pass = 0; pass < 2; pass++)
        for (int y = 0; y < s.height; y++)
            for (int x = 0; x < s.width; x++) {
                int ix = x0 + x, iy = y0 + y;
                if (ix < 0 || iy < 0 || ix >= im->width || iy >= im->height)
                    continue;
                float a = px[((size_t)y * s.width + x) * 4 + 3];
                size_t at = (size_t)iy * im->width + ix;
                for (int c = 0; c < 3; c++) {
                    float *d = &im->data[c * plane + at];
                    *d = pass ? a + *d * (1.0f - a) : *d * (1.0f / 3.0f);
                }
            }
}
} // namespace

enum ssg_err ssg_oiio_text_draw(struct ssg_image *im, int x, int y, int size, const char *text,
                               struct ssg_diags *diags)
{
    ROI box = ImageBufAlgo::text_size(text, size, FONT);
    if (!box.defined()) {
        ssg_diag_file(diags, SSG_E_BACKEND, "<labels>",
                      "cannot draw labels: no TrueType font '%s' found (Debian: "
                      "fonts-dejavu-core), or set labels=false", FONT);
        return SSG_E_BACKEND;
    }
    const int pad = 3;
    ImageBuf label(ImageSpec(box.width() + 2 * pad, box.height() + 2 * pad, 4, TypeDesc::FLOAT));
    ImageBufAlgo::zero(label);
    const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    if (!ImageBufAlgo::render_text(label, pad - box.xbegin, pad - box.ybegin, text, size, FONT,
                                   white, ImageBufAlgo::TextAlignX::Left,
                                   ImageBufAlgo::TextAlignY::Baseline)) {
        ssg_diag_file(diags, SSG_E_BACKEND, "<labels>", "cannot draw the label '%s': %s", text,
                      label.geterror().c_str());
        return SSG_E_BACKEND;
    }
    composite(im, label, x, y);
    return SSG_OK;
}
