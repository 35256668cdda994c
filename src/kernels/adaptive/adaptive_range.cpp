#include "kernels/adaptive/adaptive_range.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "kernels/adaptive/decision_schedule.h"
#include "kernels/adaptive/stopping_rule.h"

namespace wt {

void prepare_adaptive_state(Film& film, SampleRange range) {
    AdaptiveState& state = film.adaptive();
    if (state.empty()) {
        if (range.begin != 0)
            throw std::invalid_argument("adaptive sampling: a render with it must start at sample 0 (its stopping "
                                        "decisions need every sample before them), not at sample " +
                                        std::to_string(range.begin));
        state.stopped_at.assign(film.pixel_total(), AdaptiveState::still_sampling);
        state.next_sample = 0;
        return;
    }
    if (state.stopped_at.size() != film.pixel_total())
        throw std::invalid_argument("adaptive sampling: the film's state does not have one entry per pixel");
    if (state.next_sample != range.begin)
        throw std::invalid_argument("adaptive sampling: the film holds samples up to " + std::to_string(state.next_sample) +
                                    ", and the render asks to continue from sample " + std::to_string(range.begin));
}

void render_adaptive_range(Film& film, const AdaptiveSettings& settings, SampleRange range, ThreadPool* pool,
                           const std::function<void(SampleRange)>& render_piece) {
    prepare_adaptive_state(film, range);
    AdaptiveState& state = film.adaptive();
    for (uint32_t begin = range.begin; begin < range.end;) {
        if (is_decision_point(settings, begin)) apply_stopping_rule(film, settings, begin, pool);
        const uint32_t end = std::min(range.end, next_decision_point(settings, begin));
        render_piece({begin, end});
        state.next_sample = begin = end;
    }
}

void sampled_pixels_of_tile(const AdaptiveState& state, const Tile& tile, int image_width, std::vector<uint32_t>& out) {
    out.clear();
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x) {
            const uint32_t pixel = uint32_t(y) * uint32_t(image_width) + uint32_t(x);
            if (state.sampling(pixel)) out.push_back(pixel);
        }
}

}  // namespace wt
