#pragma once
// Adaptive sampling's two settings (README, "Adaptive sampling"): pixels whose estimated error
// is below `threshold`, with every neighbour's, stop taking samples; none stops before
// `min_spp`. The rule and its schedule are in kernels/adaptive/; the per-pixel state a render
// keeps is core/film/adaptive_state.h.

namespace wt {

struct AdaptiveSettings {
    // Largest per-pixel error (kernels/adaptive/pixel_error.h) at which a pixel may stop; 0 is
    // off, and the render is then exactly the render without adaptive sampling.
    float threshold = 0.0f;
    // No pixel stops before it has this many samples (at least 2: a variance needs two).
    int min_spp = 16;

    bool enabled() const { return threshold > 0.0f; }
};

constexpr int adaptive_min_spp_lowest = 2;

}  // namespace wt
