#pragma once
// The trade tool's measurements: each configuration rendered in-process (wt::render) at each spp,
// timed over repeats, and its error taken against the reference.

#include <functional>
#include <string>
#include <vector>

#include "core/image_io/rgb_image.h"
#include "core/image_metrics/image_metrics.h"
#include "core/description/scene_description.h"
#include "kernels/render_options.h"
#include "tools/tradeoff/tradeoff_knobs.h"

namespace wt {

struct Configuration {
    std::string name;         // "base", or "knob=value"
    std::string knob, value;  // empty for the base
    bool can_bias = false;
    RenderSettings settings;
};

// The base (the scene's settings) first, then each knob's values one at a time, skipping a value
// equal to the base's.
std::vector<Configuration> tradeoff_configurations(const RenderSettings& base, const std::vector<const Knob*>& knobs);

struct Measurement {
    std::size_t configuration = 0;  // index into the configurations
    int spp = 0;
    double seconds = 0.0;                          // median of the repeats (render only: no loading, no BVH build)
    double seconds_min = 0.0, seconds_max = 0.0;  // their spread
    ErrorMetrics error;                           // overall; the same for every repeat (same seed)
};

struct SweepPlan {
    std::vector<int> spp;  // ascending
    int repeats = 3;  // rounds over all configurations; the median time is kept
    RenderOptions render;
};

// `description` is rebuilt into a scene per configuration (the accuracy options decide how the
// scene is built); its settings are left as they were. `report` is told of each measurement once
// its last repeat is done. Measurements are in configuration order, spp ascending within each.
std::vector<Measurement> run_sweep(SceneDescription& description, const std::vector<Configuration>& configurations,
                                   const SweepPlan& plan, const RgbImage& reference,
                                   const std::function<void(const Measurement&)>& report);

}  // namespace wt
