#include "kernels/progressive_render.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace wt {

uint32_t next_pass_size(uint32_t film_spp, uint32_t samples_left, double seconds_per_spp, double pass_seconds,
                        double seconds_left) {
    if (samples_left == 0) return 0;
    double size = std::max<double>(1, film_spp);  // doubles the image's spp: 1, 1, 2, 4, ...
    if (seconds_per_spp > 0.0) {
        size = std::min(size, std::max(1.0, std::floor(pass_seconds / seconds_per_spp)));
        const double fits = std::floor(seconds_left / seconds_per_spp);
        if (fits < 1.0) return 0;
        size = std::min(size, fits);
    }
    return uint32_t(std::min<double>(size, samples_left));
}

ProgressiveResult render_progressive(RenderSession& session, Film& film, const ProgressiveOptions& options,
                                     PassObserver* observer) {
    const auto start = std::chrono::steady_clock::now();
    const std::function<double()> clock = options.clock ? options.clock : [start] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    const double t0 = clock();
    const auto interrupted = [&] { return options.stop && options.stop->load(); };
    std::function<void(uint64_t)> tile_done;
    if (observer) tile_done = [observer](uint64_t samples) { observer->samples_done(samples); };

    ProgressiveResult result;
    result.end_sample = options.samples.begin;
    const double no_limit = std::numeric_limits<double>::infinity();
    while (result.end_sample < options.samples.end) {
        if (interrupted()) {
            result.reason = StopReason::interrupted;
            break;
        }
        const double elapsed = clock() - t0;
        const uint32_t rendered = result.end_sample - options.samples.begin;
        const double seconds_per_spp = rendered > 0 ? elapsed / rendered : 0.0;
        const double seconds_left = options.time_limit > 0.0 ? options.time_limit - elapsed : no_limit;
        // The first pass always runs: a 0-spp image is no image, and only a measured pass says
        // what fits. Checking the clock before it made a short limit depend on start-up time
        // (a sanitizer build's took longer than the limit and rendered nothing).
        if (rendered > 0 && seconds_left <= 0.0) {
            result.reason = StopReason::time_limit;
            break;
        }
        const uint32_t size = next_pass_size(result.end_sample - options.film_first_sample,
                                             options.samples.end - result.end_sample, seconds_per_spp,
                                             options.pass_seconds, seconds_left);
        if (size == 0) {
            result.reason = StopReason::time_limit;
            break;
        }
        const SampleRange pass{result.end_sample, result.end_sample + size};
        session.render_samples(film, pass, tile_done);
        result.end_sample = pass.end;
        const PassReport report{result.passes++, pass, pass.end - options.film_first_sample, clock() - t0,
                                pass.end == options.samples.end};
        if (observer && !observer->pass_done(film, report)) {
            result.reason = StopReason::observer;
            break;
        }
    }
    // A stop that arrives during the last pass still ends a finished render as finished.
    result.seconds = clock() - t0;
    return result;
}

}  // namespace wt
