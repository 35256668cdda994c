#pragma once
// Pixel reconstruction by filter importance sampling (Ernst, Stamminger & Greiner, "Filter
// Importance Sampling", 2006; pbrt-v4's FilterSampler and Cycles do the same): a pixel's value is
// the integral of the image against the filter centred on it, and instead of weighting each
// sample by the filter (which spreads a sample over several pixels and needs a second pass to
// normalise), the sample's position is drawn from the filter, so every sample has weight one and
// adds to its own pixel only, even where it lands beyond that pixel's square. The film stays a
// sum of exact fixed-point values, one per sample, and so deterministic.
//
// The filters are separable and non-negative; each axis is tabulated once as a piecewise-constant
// density over kBins bins, which is then the filter exactly: the camera draws offsets from it by
// inverting its piecewise-linear distribution, and light tracing's splats (choose_pixel) weigh
// pixels by the same density, so the two estimators agree on one image, not on two approximations
// of it. The box needs no table: offset = u * width, shifted to the centre, which for width 1 is
// u itself, the bits of a render before there were filters.

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

    // The sample's position relative to its pixel's top-left corner, from a uniform point of the
    // unit square: in [0.5 - radius, 0.5 + radius) on each axis.
    glm::vec2 offset(glm::vec2 u) const {
        if (tabulated_) return {0.5f + sample_axis(u.x), 0.5f + sample_axis(u.y)};
        return {u.x * width_ + shift_, u.y * width_ + shift_};
    }

    float radius() const { return 0.5f * width_; }
    // How far beyond the image a sample of a border pixel may land.
    float margin() const { return radius() > 0.5f ? radius() - 0.5f : 0.0f; }
    bool is_unit_box() const { return !tabulated_ && width_ == 1.0f; }

    // The density of a sample's offset from its pixel's centre along one axis (it integrates to 1).
    float density(float d) const;

    // Light tracing's splat at film coordinate `x` (one axis) goes to one pixel: pixel P with
    // probability density(x - centre_P) / sum, from the uniform `u`, and carries `weight` = the
    // sum over the candidate pixels, so pixel P receives density(x - centre_P) on average, as its
    // camera samples do. `pixel` may lie outside the image (the caller drops it then).
    struct AxisChoice {
        int pixel;
        float weight;
    };
    AxisChoice choose_pixel(float x, float u) const;

private:
    float sample_axis(float u) const;

    bool tabulated_ = false;
    float width_ = 1.0f, shift_ = 0.0f;
    float bin_width_ = 0.0f;
    std::array<float, kBins> density_{};  // per bin, integrating to 1 over [-radius, radius)
    std::array<float, kBins + 1> cdf_{};  // cdf_[0] = 0, cdf_[kBins] = 1
};

}  // namespace wt
