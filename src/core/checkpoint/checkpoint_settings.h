#pragma once
// The render settings that change the image, by name, as a checkpoint stores them, and the
// comparison that says which differ ("seed: checkpoint 7, scene 8"). A setting added to
// RenderSettings that changes the image is one line in image_settings(); settings that never
// change the bits (threads, ISA, acceleration structure, tile size, integrator) are not here.

#include <string>
#include <vector>

#include "core/description/scene_description.h"

namespace wt {

struct NamedSetting {
    std::string name, value;  // neither holds white space
    bool operator==(const NamedSetting& o) const { return name == o.name && value == o.value; }
};

// Every image-changing setting but the resolution (the film's own size) and spp: no sampler's
// samples depend on the spp (core/sampling/samplers.h), so spp is only the sample range.
std::vector<NamedSetting> image_settings(const RenderSettings& settings);

// One line per setting whose value differs or that only one side has, in `a`'s order, e.g.
// "seed: checkpoint 7, scene 8" for labels "checkpoint" and "scene".
std::vector<std::string> setting_differences(const std::vector<NamedSetting>& a, const std::string& a_label,
                                             const std::vector<NamedSetting>& b, const std::string& b_label);

}  // namespace wt
