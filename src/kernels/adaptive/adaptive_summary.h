#pragma once
// What adaptive sampling did, for the render summary: how many pixels stopped, and the samples
// per pixel rendered on average (dropped non-finite samples included: they were rendered).

#include <cstdint>

#include "core/film/adaptive_state.h"

namespace wt {

struct AdaptiveSummary {
    uint64_t pixels = 0, stopped = 0;
    double mean_spp = 0.0;
};

inline AdaptiveSummary summarize_adaptive(const AdaptiveState& state) {
    AdaptiveSummary s;
    s.pixels = state.stopped_at.size();
    double samples = 0.0;
    for (std::size_t p = 0; p < state.stopped_at.size(); ++p) {
        s.stopped += !state.sampling(p);
        samples += state.samples_of(p);
    }
    s.mean_spp = s.pixels ? samples / double(s.pixels) : 0.0;
    return s;
}

}  // namespace wt
