#pragma once
// The knobs `wavetrace tradeoff` sweeps: each a scene setting that trades time for error, the
// values tried besides the scene's own, and how to set one. Adding a knob is adding one row to
// the table in tradeoff_knobs.cpp.

#include <string>
#include <vector>

#include "core/description/scene_description.h"

namespace wt {

struct Knob {
    const char* name;                 // the scene file's render key (and the CLI flag, with dashes)
    std::vector<const char*> values;  // tried one at a time, with everything else as the scene says
    // Whether a value can change what the image converges to (a truncated path, an approximate
    // Fresnel, a clamp), rather than only how fast: the tool then reports the fit's floor as bias.
    bool can_bias;
    // Sets `value` (one of `values`) in the settings.
    void (*apply)(RenderSettings& settings, const std::string& value);
    // The setting's current value, written as `values` are; a value equal to it is not tried again.
    std::string (*current)(const RenderSettings& settings);
};

const std::vector<Knob>& tradeoff_knobs();

// Throws std::invalid_argument naming the unknown name and listing the known ones.
const Knob& tradeoff_knob(const std::string& name);

}  // namespace wt
