#include "kernels/adaptive/stopping_rule.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "kernels/adaptive/pixel_error.h"

namespace wt {

namespace {

// fn(y) for every row, on the pool's threads when there is one.
template <typename Fn>
void for_each_row(int height, ThreadPool* pool, Fn&& fn) {
    if (!pool) {
        for (int y = 0; y < height; ++y) fn(y);
        return;
    }
    pool->parallel_for(std::size_t(height), [&](std::size_t y, int) { fn(int(y)); });
}

}  // namespace

uint32_t apply_stopping_rule(Film& film, const AdaptiveSettings& settings, uint32_t samples, ThreadPool* pool) {
    AdaptiveState& state = film.adaptive();
    if (state.stopped_at.size() != film.pixel_total())
        throw std::invalid_argument("adaptive sampling: the film's state does not have one entry per pixel");
    const int width = film.width(), height = film.height();
    const std::size_t w = std::size_t(width);

    std::vector<uint8_t> unconverged(film.pixel_total(), 0);
    for_each_row(height, pool, [&](int y) {
        for (std::size_t p = std::size_t(y) * w, end = p + w; p < end; ++p)
            unconverged[p] = state.sampling(p) && !(pixel_error(film, uint32_t(p)) < double(settings.threshold));
    });

    // Each row writes only its own pixels' state, after every row's flags are known.
    std::vector<uint32_t> stopped_in_row(std::size_t(height), 0);
    for_each_row(height, pool, [&](int y) {
        const int y0 = std::max(0, y - 1), y1 = std::min(height - 1, y + 1);
        for (int x = 0; x < width; ++x) {
            const std::size_t p = std::size_t(y) * w + std::size_t(x);
            if (!state.sampling(p)) continue;
            const int x0 = std::max(0, x - 1), x1 = std::min(width - 1, x + 1);
            bool keep = false;
            for (int ny = y0; ny <= y1 && !keep; ++ny)
                for (int nx = x0; nx <= x1; ++nx)
                    if (unconverged[std::size_t(ny) * w + std::size_t(nx)]) {
                        keep = true;
                        break;
                    }
            if (keep) continue;
            state.stopped_at[p] = samples;
            ++stopped_in_row[std::size_t(y)];
        }
    });
    return std::accumulate(stopped_in_row.begin(), stopped_in_row.end(), 0u);
}

}  // namespace wt
