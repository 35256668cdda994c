#include "tools/tradeoff/tradeoff_sweep.h"

#include <algorithm>

#include "core/film/film.h"
#include "core/scene/scene.h"
#include "kernels/renderer.h"

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
    const std::size_t levels = plan.spp.size();
    std::vector<Measurement> measurements(configurations.size() * levels);
    std::vector<std::vector<double>> seconds(measurements.size());
    // Round after round over every configuration, not one configuration's repeats in a row: a
    // shared machine's load drifts over minutes, and interleaving spreads the drift over all.
    for (int round = 0; round < plan.repeats; ++round)
        for (std::size_t i = 0; i < configurations.size(); ++i) {
            description.settings = configurations[i].settings;
            Scene scene = build_scene(description);
            description.settings = scene_settings;
            for (std::size_t level = 0; level < levels; ++level) {
                scene.settings.spp = plan.spp[level];
                Film film(scene.settings.width, scene.settings.height, render_film_channels(scene, plan.render.aovs));
                const std::size_t k = i * levels + level;
                seconds[k].push_back(render(scene, plan.render, film).seconds);
                Measurement& m = measurements[k];
                if (round == 0) {  // every round renders the same bits (same seed)
                    m.configuration = i;
                    m.spp = plan.spp[level];
                    m.error = image_error({film.width(), film.height(), film.resolve()}, reference).overall;
                }
                if (round + 1 < plan.repeats) continue;
                std::vector<double> sorted = seconds[k];
                std::sort(sorted.begin(), sorted.end());
                m.seconds = sorted[sorted.size() / 2];
                m.seconds_min = sorted.front();
                m.seconds_max = sorted.back();
                report(m);
            }
        }
    return measurements;
}

}  // namespace wt
