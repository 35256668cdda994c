#pragma once
// Pixel reconstruction by filter importance sampling (Ernst, Stamminger & Greiner, "Filter
// Importance Sampling", 2006; pbrt-v4's FilterSampler and Cycles do the same): a pixel's value is
// the integral of the image against the filter centred on it, and instead of weighting each
// sample by the filter (which spreads a sample over several pixels and needs a second pass to
// normalise), the sample's position is drawn from the filter, so every sample adds to its own
// pixel only, even where it lands beyond that pixel's square. The film stays a sum of exact
// fixed-point values, one per sample, and so deterministic.
//
// The filters are separable; each axis is tabulated once as a piecewise-constant function over
// kBins bins, which is then the filter exactly: the camera draws offsets in proportion to its
// absolute value by inverting the piecewise-linear distribution of |f|, and light tracing's
// splats (choose_pixel) weigh pixels by the same density, so the two estimators agree on one
// image, not on two approximations of it. A non-negative filter's samples have weight one. A
// filter with negative lobes (Mitchell-Netravali) is sampled by |f| and each sample carries
// sign(f) * integral |f| / integral f (pbrt-v4's FilterSampler): the estimate of the integral
// against f / integral f, whose mean is still the image's for a constant image. The box needs no
// table: offset = u * width, shifted to the centre, which for width 1 is u itself, the bits of a
// render before there were filters.

#include <algorithm>
#include <array>
#include <cstdint>

#include <glm/vec2.hpp>

#include "core/description/pixel_filter_settings.h"

namespace wt {

class PixelFilter {
public:
    static constexpr int kBins = 256;

    PixelFilter() = default;
    explicit PixelFilter(const PixelFilterSettings& settings);

    // A camera sample: its position relative to its pixel's top-left corner, in
    // [0.5 - radius, 0.5 + radius) on each axis, and the weight its radiance is multiplied by
    // (1, or -1 times a constant, for a non-negative filter exactly 1).
    struct Sample {
        glm::vec2 offset;
        float weight;
    };
    // From a uniform point of the unit square.
    Sample sample(glm::vec2 u) const {
        if (!tabulated_) return {{u.x * width_ + shift_, u.y * width_ + shift_}, 1.0f};
        const AxisSample x = sample_axis(u.x), y = sample_axis(u.y);
        return {{0.5f + x.offset, 0.5f + y.offset}, x.weight * y.weight};
    }
    glm::vec2 offset(glm::vec2 u) const { return sample(u).offset; }

    float radius() const { return 0.5f * width_; }
    // How far beyond the image a sample of a border pixel may land.
    float margin() const { return radius() > 0.5f ? radius() - 0.5f : 0.0f; }
    bool is_unit_box() const { return !tabulated_ && width_ == 1.0f; }

    // The density of a sample's offset from its pixel's centre along one axis (it integrates to
    // 1): |value(d)| / integral |value|, the filter itself for a non-negative one.
    float density(float d) const;
    // The filter along one axis, scaled to integrate to 1; negative in Mitchell's lobes.
    float value(float d) const;
    // Whether some of the filter is negative, so that samples carry weights other than 1.
    bool has_negative_lobes() const { return abs_over_signed_ != 1.0f; }

    // Light tracing's splat at film coordinate `x` (one axis) goes to one pixel: pixel P with
    // probability density(x - centre_P) / sum, from the uniform `u`, and carries `weight` = the
    // sum over the candidate pixels times the chosen pixel's camera-sample weight (its sign times
    // integral |f| / integral f), so pixel P receives value(x - centre_P) on average, as its
    // camera samples do. `pixel` may lie outside the image (the caller drops it then).
    struct AxisChoice {
        int pixel;
        float weight;
    };
    AxisChoice choose_pixel(float x, float u) const;

private:
    struct AxisSample {
        float offset;  // from the pixel's centre
        float weight;
    };
    AxisSample sample_axis(float u) const;
    int bin_of(float d) const { return std::min(kBins - 1, int((d + radius()) / bin_width_)); }

    bool tabulated_ = false;
    float width_ = 1.0f, shift_ = 0.0f;
    float bin_width_ = 0.0f;
    std::array<float, kBins> density_{};  // per bin, |f| integrating to 1 over [-radius, radius)
    std::array<float, kBins> weight_{};   // per bin, sign(f) * abs_over_signed_: a sample's weight
    float abs_over_signed_ = 1.0f;        // integral |f| / integral f, along one axis
    std::array<float, kBins + 1> cdf_{};  // cdf_[0] = 0, cdf_[kBins] = 1
};

}  // namespace wt
