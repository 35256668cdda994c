#pragma once
// Adaptive sampling's rule, applied to the whole film at a decision point: a pixel still
// sampled is *unconverged* when its error (pixel_error.h) is not below the threshold; the
// unconverged set is dilated by one pixel in x and in y (a 3x3 box, as Cycles filters its
// convergence flags in x, then y), and every pixel still sampled outside it stops here.
//
// So a pixel stops only when it and its eight neighbours have all converged: an error estimate
// from a few samples is itself noisy, and an unconverged neighbour says the region is not
// done. Stops are final (Cycles lets a stopped pixel resume when a neighbour later turns
// unconverged): each pixel then holds a prefix of its samples, [0, stop) of its stratified
// sequence, and its state is one number. Stopped pixels count as converged: they were when they
// stopped, and their sums no longer change.
//
// The rule is a function of the film's exact sums, evaluated per pixel, so it is the same for
// any thread count, tile size or split of the render into passes.

#include <cstdint>

#include "core/description/adaptive_settings.h"
#include "core/film/film.h"
#include "core/system/thread_pool.h"

namespace wt {

// At decision point `samples` (every pixel still sampled holds samples [0, samples)): marks the
// pixels that stop in film.adaptive() (stopped_at = samples) and returns how many did. The
// state must have one entry per pixel. Rows are shared out over `pool` when given.
uint32_t apply_stopping_rule(Film& film, const AdaptiveSettings& settings, uint32_t samples, ThreadPool* pool = nullptr);

}  // namespace wt
