#include "tradeoff_sweep.h"

#include <algorithm>

#include "core/film/film.h"
#include "core/scene.h"

namespace wt {

std::vector<Configuration> tradeoff_configurations(const RenderSettings& base, const std::vector<const Knob*>& knobs) {
    std::vector<Configuration> configurations = {{"base", "", "", false, base}};
    for (const Knob* knob : knobs)
        for (const char* value : knob->values) {
            if (knob->current(base) == value) continue;
            Configuration c{std::string(knob->name) + "=" + value, knob->name, value, knob->can_bias, base};
            knob->apply(c.settings, value);
            configurations.push_back(c);
        }
    return configurations;
}

std::vector<Measurement> run_sweep(SceneDescription& description, const std::vector<Configuration>& configurations,
                                   const SweepPlan& plan, const RgbImage& reference,
                                   const std::function<void(const Measurement&)>& report) {
    const RenderSettings scene_settings = description.settings;
    std::vector<Measurement> measurements;
    for (std::size_t i = 0; i < configurations.size(); ++i) {
        description.settings = configurations[i].settings;
        Scene scene = build_scene(description);
        description.settings = scene_settings;
        for (int spp : plan.spp) {
            scene.settings.spp = spp;
            std::vector<double> seconds;
            RgbImage image{scene.settings.width, scene.settings.height, {}};
            for (int r = 0; r < plan.repeats; ++r) {
                Film film(scene.settings.width, scene.settings.height);
                seconds.push_back(render(scene, plan.render, film).seconds);
                if (r == 0) image.rgb = film.resolve();  // every repeat renders the same bits
            }
            std::sort(seconds.begin(), seconds.end());
            Measurement m;
            m.configuration = i;
            m.spp = spp;
            m.seconds = seconds[seconds.size() / 2];
            m.seconds_min = seconds.front();
            m.seconds_max = seconds.back();
            m.error = image_error(image, reference).overall;
            measurements.push_back(m);
            report(m);
        }
    }
    return measurements;
}

}  // namespace wt
