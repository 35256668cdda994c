#pragma once
// A linear RGB image in memory: what the error metrics compare and what image files are read into.

#include <cstddef>
#include <vector>

namespace wt {

struct RgbImage {
    int width = 0, height = 0;
    std::vector<float> rgb;  // width * height * 3, interleaved, rows top to bottom

    std::size_t pixel_count() const { return std::size_t(width) * std::size_t(height); }
};

}  // namespace wt
