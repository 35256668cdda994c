#pragma once
// Rendering a scene description into a film in one call, for the integrator tests.

#include <optional>
#include <string>

#include "core/film.h"
#include "core/scene.h"
#include "kernels/renderer.h"

namespace wt::test {

struct RenderedFilm {
    Film film;
    RenderResult result;
};

inline RenderedFilm render_film(const SceneDescription& description, Integrator integrator, int threads = 2,
                                int tile_size = 16, std::size_t batch_paths = 2048, std::optional<Isa> isa = {}) {
    const Scene scene = build_scene(description);
    RenderOptions options;
    options.integrator = integrator;
    options.threads = threads;
    options.tile_size = tile_size;
    options.batch_paths = batch_paths;
    options.isa = isa;
    RenderedFilm out{Film(description.settings.width, description.settings.height), {}};
    out.result = render(scene, options, out.film);
    return out;
}

inline bool films_bit_identical(const Film& a, const Film& b) {
    if (a.width() != b.width() || a.height() != b.height()) return false;
    for (uint32_t p = 0; p < uint32_t(a.width() * a.height()); ++p) {
        if (a.pixel_count(p) != b.pixel_count(p) || a.pixel_sum(p) != b.pixel_sum(p)) return false;
    }
    return true;
}

// The command that replays one sample, printed by failing tests.
inline std::string replay_command(const std::string& scene, const SceneDescription& d, uint32_t pixel, uint32_t sample) {
    return "build/bin/wavetrace render " + scene + " --width " + std::to_string(d.settings.width) + " --height " +
           std::to_string(d.settings.height) + " --spp " + std::to_string(d.settings.spp) + " --shadow-rays " +
           std::to_string(d.settings.shadow_rays) + " --seed " + std::to_string(d.settings.seed) + " --debug-sample " +
           std::to_string(pixel % uint32_t(d.settings.width)) + "," + std::to_string(pixel / uint32_t(d.settings.width)) +
           "," + std::to_string(sample);
}

}  // namespace wt::test
