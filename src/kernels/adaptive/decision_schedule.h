#pragma once
// When adaptive sampling decides which pixels stop: once every pixel still sampled has `min_spp`
// samples, and then whenever it has a multiple of `adaptive_decision_step` above that. Fixed
// sample counts, never the time-sized passes of a progressive render, so the decisions (and
// the image) are a function of the scene, the seed and the settings alone, however a render
// is cut into passes, interrupted and resumed.
//
// 16 is Cycles' adaptive step (its Integrator::get_adaptive_sampling, Blender 3.x); like its,
// the decisions after the first fall on multiples of 16, so a stopped pixel holds whole blocks
// of 16 of its stratified (0, 2)-sequence. A decision costs one pass over the film (a few
// hundred instructions per pixel), 16 samples thousands each: under 1 %, while a pixel stops
// at most 15 samples after it could have (with decisions at powers of two, up to twice its
// samples).

#include <cstdint>

#include "core/description/adaptive_settings.h"

namespace wt {

constexpr uint32_t adaptive_decision_step = 16;

// Whether the rule runs when `samples` samples of every pixel still sampled are done (before
// sample `samples` is rendered).
inline bool is_decision_point(const AdaptiveSettings& s, uint32_t samples) {
    const uint32_t min = uint32_t(s.min_spp);
    return samples == min || (samples > min && samples % adaptive_decision_step == 0);
}

// The first decision point after `samples`.
inline uint32_t next_decision_point(const AdaptiveSettings& s, uint32_t samples) {
    const uint32_t min = uint32_t(s.min_spp);
    if (samples < min) return min;
    return (samples / adaptive_decision_step + 1) * adaptive_decision_step;
}

}  // namespace wt
