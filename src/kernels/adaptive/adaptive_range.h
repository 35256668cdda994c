#pragma once
// A range of an adaptive render's samples: cut at the decision points inside it
// (decision_schedule.h), the stopping rule applied at each over the whole film, and each piece
// rendered for the pixels still sampled. Where the range starts and ends does not matter: the
// rule at sample d runs exactly once, at the start of whichever range holds d, on a film that
// holds samples [0, d) of every pixel still sampled. So a render is the same bits whether it
// is one range or many (passes, a resume).

#include <cstdint>
#include <functional>
#include <vector>

#include "core/description/adaptive_settings.h"
#include "core/film/film.h"
#include "core/system/thread_pool.h"
#include "kernels/work/sample_range.h"
#include "kernels/work/tiles.h"

namespace wt {

// Gives a film without adaptive state one (every pixel sampled) for a render starting at
// sample 0, and checks that a film with one continues where it ended. Throws
// std::invalid_argument otherwise: a render that starts later (a part of a split render)
// lacks the samples its decisions need.
void prepare_adaptive_state(Film& film, SampleRange range);

// `render_piece(piece)` renders samples `piece` of the pixels film.adaptive() says are still
// sampled; it is called for consecutive pieces covering `range`. Calls prepare_adaptive_state.
void render_adaptive_range(Film& film, const AdaptiveSettings& settings, SampleRange range, ThreadPool* pool,
                           const std::function<void(SampleRange piece)>& render_piece);

// The pixels of `tile` still sampled, in scanline order, into `out` (cleared first).
void sampled_pixels_of_tile(const AdaptiveState& state, const Tile& tile, int image_width, std::vector<uint32_t>& out);

}  // namespace wt
