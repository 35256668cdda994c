#include "core/image_metrics/image_metrics.h"

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>


namespace wt {

namespace {

std::string size_text(const RgbImage& i) { return std::to_string(i.width) + "x" + std::to_string(i.height); }

double psnr_of(double rmse) { return rmse > 0.0 ? 20.0 * std::log10(1.0 / rmse) : std::numeric_limits<double>::infinity(); }

// Sums in double over the kept pixels of one channel range, as OpenImageIO's compare does (its
// results are what the tests check these against; core does not link OpenImageIO).
struct Sums {
    double squares = 0.0, relative = 0.0, image = 0.0, reference = 0.0;
    ErrorMetrics worst;
};

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
    std::array<Sums, 3> sums;
    for (std::size_t p = 0; p < image.pixel_count(); ++p) {
        if (kept && !(*kept)[p]) continue;
        ++report.pixels;
        for (std::size_t c = 0; c < 3; ++c) {
            const double x = image.rgb[3 * p + c], r = reference.rgb[3 * p + c], d = x - r;
            Sums& s = sums[c];
            s.squares += d * d;
            s.relative += d * d / (r * r + 0.01);
            s.image += x;
            s.reference += r;
            if (std::fabs(d) > s.worst.max_error) {
                s.worst.max_error = std::fabs(d);
                s.worst.max_x = int(p % std::size_t(image.width)), s.worst.max_y = int(p / std::size_t(image.width));
                s.worst.max_channel = int(c);
            }
        }
    }
    if (report.pixels == 0) throw std::invalid_argument("the mask keeps no pixel (every first-channel value is 0)");

    const double n = double(report.pixels);
    const auto ratio = [](double x, double r) { return r != 0.0 ? x / r : std::numeric_limits<double>::quiet_NaN(); };
    const auto finish = [&](ErrorMetrics& m, const Sums& s, double values) {
        m.max_error = s.worst.max_error, m.max_x = s.worst.max_x, m.max_y = s.worst.max_y, m.max_channel = s.worst.max_channel;
        m.rmse = std::sqrt(s.squares / values);
        m.psnr = psnr_of(m.rmse);
        m.rel_mse = s.relative / values;
        m.mean_ratio = ratio(s.image, s.reference);
    };
    Sums all;
    for (std::size_t c = 0; c < 3; ++c) {
        finish(report.channel[c], sums[c], n);
        all.squares += sums[c].squares, all.relative += sums[c].relative;
        all.image += sums[c].image, all.reference += sums[c].reference;
        // The first channel to reach the overall worst keeps it, as in a scan of all values.
        if (sums[c].worst.max_error > all.worst.max_error) all.worst = sums[c].worst;
    }
    finish(report.overall, all, 3.0 * n);
    return report;
}

}  // namespace wt
