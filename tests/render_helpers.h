#pragma once
// Rendering a scene description into a film in one call, for the integrator tests.

#include <optional>
#include <string>

#include <cmath>
#include <functional>
#include <iostream>

#include <gtest/gtest.h>

#include "core/film/film.h"
#include "core/scene/scene.h"
#include "kernels/renderer.h"
#include "statistics.h"

namespace wt::test {

struct RenderedFilm {
    Film film;
    RenderResult result;
};

inline RenderedFilm render_film(const SceneDescription& description, Integrator integrator, int threads = 2,
                                int tile_size = 16, std::size_t batch_paths = 2048, std::optional<Isa> isa = {},
                                Accel accel = Accel::automatic, int bvh_width = 8) {
    const Scene scene = build_scene(description);
    RenderOptions options;
    options.accel = accel;
    options.bvh.node_width = bvh_width;
    options.integrator = integrator;
    options.threads = threads;
    options.tile_size = tile_size;
    options.batch_paths = batch_paths;
    options.isa = isa;
    RenderedFilm out{Film(description.settings.width, description.settings.height, render_film_channels(scene, options.aovs)), {}};
    out.result = render(scene, options, out.film);
    return out;
}

// An empty film for a render of `scene` (with light tracing, its splat channels).
inline Film film_for(const Scene& scene, const AovSelection& aovs = {}) {
    return Film(scene.settings.width, scene.settings.height, render_film_channels(scene, aovs));
}

// `film` is the same bits rendered with 3 threads, the reference integrator, odd tiles and
// batches, the scalar kernels, and the BVH with either integrator.
inline void expect_same_film_for_any_schedule(const SceneDescription& d, const Film& film) {
    EXPECT_TRUE(film == render_film(d, Integrator::wavefront, 3).film);
    EXPECT_TRUE(film == render_film(d, Integrator::reference, 2).film);
    EXPECT_TRUE(film == render_film(d, Integrator::wavefront, 2, 5, 97).film);  // tiles and batches
    EXPECT_TRUE(film == render_film(d, Integrator::wavefront, 2, 16, 2048, Isa::scalar).film);
    EXPECT_TRUE(film == render_film(d, Integrator::wavefront, 2, 16, 2048, {}, Accel::bvh).film);
    EXPECT_TRUE(film == render_film(d, Integrator::reference, 2, 16, 2048, {}, Accel::bvh).film);
}

// Every sum (radiance, squares, extra channels) and count.
inline bool films_bit_identical(const Film& a, const Film& b) { return a == b; }

// The command that replays one sample, printed by failing tests.
inline std::string replay_command(const std::string& scene, const SceneDescription& d, uint32_t pixel, uint32_t sample) {
    return "build/bin/wavetrace render " + scene + " --width " + std::to_string(d.settings.width) + " --height " +
           std::to_string(d.settings.height) + " --spp " + std::to_string(d.settings.spp) + " --shadow-rays " +
           std::to_string(d.settings.shadow_rays) + " --seed " + std::to_string(d.settings.seed) + " --debug-sample " +
           std::to_string(pixel % uint32_t(d.settings.width)) + "," + std::to_string(pixel / uint32_t(d.settings.width)) +
           "," + std::to_string(sample);
}

// Two independent renders of the same scene: a two-sample z-test per pixel and channel, with a
// binomial allowance for chance failures (caustic paths make some pixels heavy-tailed, so a
// pixel's own variance is occasionally underestimated), then the same test on the image sums.
// `replay` names the command that reproduces a failing pixel.
inline void expect_films_agree(const Film& a, const Film& b, const std::function<std::string(uint32_t)>& replay) {
    const int pixels = a.width() * a.height();
    const double per_test_alpha = 1e-3;
    const double z = normal_two_sided_quantile(per_test_alpha);
    const int allowed = binomial_upper_bound(3 * pixels, per_test_alpha, 1e-6);
    int failures = 0;
    glm::dvec3 diff_sum(0.0), var_sum(0.0);
    for (uint32_t p = 0; p < uint32_t(pixels); ++p) {
        const glm::dvec3 d = a.pixel_mean(p) - b.pixel_mean(p);
        const glm::dvec3 v = a.pixel_sample_variance(p) / double(a.pixel_count(p)) +
                             b.pixel_sample_variance(p) / double(b.pixel_count(p));
        for (int c = 0; c < 3; ++c) {
            if (std::fabs(d[c]) > z * std::sqrt(v[c]) + 1e-9) {
                ++failures;
                std::cerr << "pixel " << p << " channel " << c << " differs by " << d[c] << " (sd " << std::sqrt(v[c])
                          << "); replay: " << replay(p) << "\n";
            }
        }
        diff_sum += d;
        var_sum += v;
    }
    EXPECT_LE(failures, allowed);
    for (int c = 0; c < 3; ++c) EXPECT_LE(std::fabs(diff_sum[c]), 4.5 * std::sqrt(var_sum[c])) << "channel " << c;
}

}  // namespace wt::test
