#pragma once
// Which of every pixel's samples a piece of work renders: the unit passes, resumes, split renders
// and adaptive sampling's decision points cut a render into.

#include <cstdint>

namespace wt {

// Samples [begin, end) of every pixel.
struct SampleRange {
    uint32_t begin = 0, end = 0;
    uint32_t size() const { return end - begin; }
};

}  // namespace wt
