#include "core/checkpoint/checkpoint_settings.h"

#include <cstdio>

namespace wt {

namespace {

// Nine significant digits tell every float apart: the clamp and the threshold as they were
// parsed, not rounded.
std::string exact(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(v));
    return text;
}

}  // namespace

std::vector<NamedSetting> image_settings(const RenderSettings& s) {
    std::vector<NamedSetting> settings = {
        {"seed", std::to_string(s.seed)},
        {"shadow_rays", std::to_string(s.shadow_rays)},
        {"max_bounces", std::to_string(s.max_bounces)},
        {"rr_start_bounce", std::to_string(s.rr_start_bounce)},
        {"triangle_test", name_of(s.accuracy.triangles)},
        {"sphere_test", name_of(s.accuracy.spheres)},
        {"fresnel", name_of(s.accuracy.fresnel)},
        {"sampler", name_of(s.estimator.sampler)},
        {"light_sampling", name_of(s.estimator.light_sampling)},
        {"clamp_indirect", exact(s.estimator.clamp_indirect)},
        {"caustics", name_of(s.estimator.caustics)},
        {"light_paths_per_pixel", exact(s.estimator.light_paths_per_pixel)},
        {"adaptive_threshold", exact(s.adaptive.threshold)},
    };
    // The minimum changes nothing while adaptive sampling is off, so it does not keep such a
    // render from being resumed with another.
    if (s.adaptive.enabled()) settings.push_back({"adaptive_min_spp", std::to_string(s.adaptive.min_spp)});
    // The filter only when it is not the unit box, which every render had before there was a choice;
    // one token ("mitchell/4"), as the format's settings are.
    if (!s.filter.is_unit_box())
        settings.push_back({"filter", std::string(name_of(s.filter.kind)) + "/" + exact(s.filter.width)});
    // Multiple scattering only when on, which no render before it was.
    if (s.accuracy.multiple_scattering != MultipleScattering::none)
        settings.push_back({"multiple_scattering", name_of(s.accuracy.multiple_scattering)});
    // The light selection only when not automatic, the default (which is area, as every render
    // before the choice was, unless the scene has many emitters of different radiance).
    if (s.estimator.light_selection != LightSelection::automatic)
        settings.push_back({"light_selection", name_of(s.estimator.light_selection)});
    // Likewise the photons' radius, which only the photons read.
    if (s.estimator.caustics == CausticPaths::photons)
        settings.push_back({"photon_radius", exact(s.estimator.photon_radius)});
    return settings;
}

namespace {

const NamedSetting* find(const std::vector<NamedSetting>& settings, const std::string& name) {
    for (const NamedSetting& s : settings)
        if (s.name == name) return &s;
    return nullptr;
}

}  // namespace

std::vector<std::string> setting_differences(const std::vector<NamedSetting>& a, const std::string& a_label,
                                             const std::vector<NamedSetting>& b, const std::string& b_label) {
    std::vector<std::string> lines;
    for (const NamedSetting& s : a) {
        const NamedSetting* other = find(b, s.name);
        if (!other) lines.push_back(s.name + ": " + a_label + " " + s.value + ", " + b_label + " has no such setting");
        else if (other->value != s.value)
            lines.push_back(s.name + ": " + a_label + " " + s.value + ", " + b_label + " " + other->value);
    }
    for (const NamedSetting& s : b)
        if (!find(a, s.name)) lines.push_back(s.name + ": " + a_label + " has no such setting, " + b_label + " " + s.value);
    return lines;
}

}  // namespace wt
