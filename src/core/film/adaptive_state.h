#pragma once
// What adaptive sampling has decided so far, per pixel: the sample at which each stopped, or
// that it is still sampled. Kept explicitly, beside the film's sums, because the film's counts
// cannot tell it: they exclude dropped non-finite samples (fixed_point.h), so a pixel with
// fewer samples than the render may have stopped or may have dropped a NaN. A checkpoint
// stores it (core/checkpoint/checkpoint_format.h), so a resumed render continues with the
// same decisions.
//
// Empty for a render without adaptive sampling, which then neither allocates nor reads it.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace wt {

struct AdaptiveState {
    static constexpr uint32_t still_sampling = UINT32_MAX;

    // Per pixel, rows top to bottom: the sample at which the pixel stopped (it holds samples
    // [0, stopped_at) of the render), or still_sampling.
    std::vector<uint32_t> stopped_at;
    // The render's samples [0, next_sample) are done for every pixel still sampled: an
    // adaptive render continues from exactly here, since its decisions need every sample
    // before them.
    uint32_t next_sample = 0;

    bool empty() const { return stopped_at.empty(); }
    bool sampling(std::size_t pixel) const { return stopped_at[pixel] == still_sampling; }
    // Samples [0, samples_of(p)) of pixel p were rendered (some may have been dropped).
    uint32_t samples_of(std::size_t pixel) const {
        return sampling(pixel) ? next_sample : stopped_at[pixel];
    }
    bool operator==(const AdaptiveState& o) const { return stopped_at == o.stopped_at && next_sample == o.next_sample; }
};

}  // namespace wt
