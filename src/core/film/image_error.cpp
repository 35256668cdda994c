#include "core/film/image_error.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <OpenImageIO/imagebufalgo.h>

namespace wt {

namespace {

std::string size_text(const RgbImage& i) { return std::to_string(i.width) + "x" + std::to_string(i.height); }

// OpenImageIO only reads these buffers (ImageBuf has no const wrapping constructor).
OIIO::ImageBuf wrap(const RgbImage& image) {
    const OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
    return OIIO::ImageBuf(spec, const_cast<float*>(image.rgb.data()));
}

// Pixels the mask drops set to 0 in a copy, so they add nothing to OpenImageIO's sums.
RgbImage keep_only(const RgbImage& image, const std::vector<uint8_t>& kept) {
    RgbImage masked = image;
    for (std::size_t p = 0; p < kept.size(); ++p)
        if (!kept[p]) masked.rgb[3 * p] = masked.rgb[3 * p + 1] = masked.rgb[3 * p + 2] = 0.0f;
    return masked;
}

double psnr_of(double rmse) { return rmse > 0.0 ? 20.0 * std::log10(1.0 / rmse) : std::numeric_limits<double>::infinity(); }

// RMSE and the worst pixel are OpenImageIO's compare over the channel range; its mean runs over
// every pixel, so with a mask the mean square is rescaled from all pixels to the kept ones.
void fill_from_compare(ErrorMetrics& m, const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, int chbegin, int chend,
                       double pixels_all, double pixels_kept) {
    OIIO::ROI roi = a.roi();
    roi.chbegin = chbegin, roi.chend = chend;
    // Thresholds no difference reaches: compare() flags `error` for any failed pixel, and we want
    // only the sums from it. One thread: the images are small and the caller may be timing a render.
    const float never = std::numeric_limits<float>::max();
    const OIIO::ImageBufAlgo::CompareResults r = OIIO::ImageBufAlgo::compare(a, b, never, never, 0.0f, 0.0f, roi, 1);
    if (r.error) throw std::runtime_error("image_error: OpenImageIO compare failed: " + OIIO::geterror());
    m.rmse = r.rms_error * std::sqrt(pixels_all / pixels_kept);
    m.psnr = psnr_of(m.rmse);
    m.max_error = r.maxerror;
    m.max_x = r.maxx, m.max_y = r.maxy, m.max_channel = r.maxc;
}

}  // namespace

std::vector<uint8_t> pixels_kept_by(const RgbImage& mask) {
    std::vector<uint8_t> kept(mask.pixel_count());
    for (std::size_t p = 0; p < kept.size(); ++p) kept[p] = mask.rgb[3 * p] != 0.0f;
    return kept;
}

ImageErrorReport image_error(const RgbImage& image, const RgbImage& reference, const std::vector<uint8_t>* kept) {
    if (image.width != reference.width || image.height != reference.height)
        throw std::invalid_argument("the image is " + size_text(image) + " but the reference is " + size_text(reference));
    if (kept && kept->size() != image.pixel_count())
        throw std::invalid_argument("the mask has " + std::to_string(kept->size()) + " pixels, the images " +
                                    std::to_string(image.pixel_count()));

    ImageErrorReport report;
    std::array<double, 3> rel_sum{}, image_sum{}, reference_sum{};
    for (std::size_t p = 0; p < image.pixel_count(); ++p) {
        if (kept && !(*kept)[p]) continue;
        ++report.pixels;
        for (std::size_t c = 0; c < 3; ++c) {
            const double x = image.rgb[3 * p + c], r = reference.rgb[3 * p + c];
            rel_sum[c] += (x - r) * (x - r) / (r * r + 0.01);
            image_sum[c] += x;
            reference_sum[c] += r;
        }
    }
    if (report.pixels == 0) throw std::invalid_argument("the mask keeps no pixel (every first-channel value is 0)");

    const RgbImage masked_image = kept ? keep_only(image, *kept) : RgbImage();
    const RgbImage masked_reference = kept ? keep_only(reference, *kept) : RgbImage();
    const OIIO::ImageBuf a = wrap(kept ? masked_image : image);
    const OIIO::ImageBuf b = wrap(kept ? masked_reference : reference);
    const double all = double(image.pixel_count()), n = double(report.pixels);
    const auto ratio = [](double x, double r) { return r != 0.0 ? x / r : std::numeric_limits<double>::quiet_NaN(); };
    for (int c = 0; c < 3; ++c) {
        ErrorMetrics& m = report.channel[std::size_t(c)];
        fill_from_compare(m, a, b, c, c + 1, all, n);
        m.rel_mse = rel_sum[std::size_t(c)] / n;
        m.mean_ratio = ratio(image_sum[std::size_t(c)], reference_sum[std::size_t(c)]);
    }
    ErrorMetrics& o = report.overall;
    fill_from_compare(o, a, b, 0, 3, all, n);
    o.rel_mse = (rel_sum[0] + rel_sum[1] + rel_sum[2]) / (3.0 * n);
    o.mean_ratio = ratio(image_sum[0] + image_sum[1] + image_sum[2], reference_sum[0] + reference_sum[1] + reference_sum[2]);
    return report;
}

}  // namespace wt
