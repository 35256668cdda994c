#pragma once
// The `filter` and `filter_width` render settings: which pixel reconstruction filter the samples'
// positions are drawn from (core/camera/pixel_filter.h).

#include <cstdint>
#include <optional>
#include <string>

namespace wt {

enum class FilterKind : uint8_t {
    box,              // uniform over a square filter_width pixels wide
    gaussian,         // exp(-x^2 / 2 sigma^2) minus its value at the edge, sigma = filter_width / 6
    blackman_harris,  // the four-term Blackman-Harris window over filter_width
    mitchell,         // Mitchell-Netravali cubic, B = C = 1/3, over filter_width; negative lobes
};

struct PixelFilterSettings {
    FilterKind kind = FilterKind::box;
    float width = 1.0f;  // in pixels, the filter's whole support along x and along y

    // The box of width 1, which every scene had before there was a choice: the same bits.
    bool is_unit_box() const { return kind == FilterKind::box && width == 1.0f; }
};

// The widest filter accepted, in pixels: beyond it a pixel's samples land mostly in other pixels'
// areas, which is a blur, not a reconstruction filter.
constexpr float kMaxFilterWidth = 16.0f;

// filter_width when the scene gives none: 1 for the box, 4 for Mitchell (its cubic's natural
// support, pbrt-v4's radius 2), 1.5 for the others (Cycles' default).
float default_filter_width(FilterKind kind);

const char* name_of(FilterKind);
std::optional<FilterKind> parse_filter_kind(const std::string&);

}  // namespace wt
