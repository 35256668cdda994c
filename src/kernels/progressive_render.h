#pragma once
// A render in passes over the whole image: after each pass every pixel has the same number of
// samples, so the film is an honest N-spp image there, to show, write, checkpoint or stop at.
// Passes double the image's sample count (1, 1, 2, 4, ... spp) for quick previews, until a
// pass would take longer than `pass_seconds`; with a time limit, no pass starts that the
// measured speed says would end past it, except the first, which always runs. Where the
// passes fall never changes the image: each pixel still receives its samples in ascending
// order into exact sums (core/film/film.h).

#include <atomic>
#include <cstdint>
#include <functional>

#include "core/film/film.h"
#include "kernels/renderer.h"

namespace wt {

struct ProgressiveOptions {
    // Samples of every pixel to add. The film may hold earlier samples already (a resumed
    // render): `film_first_sample` is the first of those, so the film's spp is
    // range.begin - film_first_sample before the first pass.
    SampleRange samples;
    uint32_t film_first_sample = 0;
    double time_limit = 0.0;    // seconds of rendering; 0: none
    double pass_seconds = 2.0;  // longest a pass should take, once the speed is known
    // Set (e.g. by a signal handler) to end the render at the next pass boundary.
    const std::atomic<bool>* stop = nullptr;
    // Seconds since an arbitrary start; steady_clock unless a test provides its own.
    std::function<double()> clock;
};

struct PassReport {
    uint32_t pass = 0;        // 0, 1, ...
    SampleRange pass_samples; // the samples this pass added
    uint32_t film_spp = 0;    // every pixel's sample count after the pass (adaptive sampling: the most any has)
    double seconds = 0.0;     // since the progressive render started
    bool last = false;        // the render's samples are all done (a time limit or a stop may end it earlier)
};

// What a caller sees of a progressive render. Both hooks run on the render's threads.
class PassObserver {
public:
    virtual ~PassObserver() = default;
    // A tile finished `samples` samples: called by several workers at once, keep it cheap.
    virtual void samples_done(uint64_t /*samples*/) {}
    // Between passes, with no worker running. Return false to stop the render here.
    virtual bool pass_done(const Film& /*film*/, const PassReport& /*report*/) { return true; }
};

enum class StopReason { finished, time_limit, interrupted, observer };

struct ProgressiveResult {
    uint32_t end_sample = 0;  // samples [options.samples.begin, end_sample) were added
    uint32_t passes = 0;
    double seconds = 0.0;
    StopReason reason = StopReason::finished;
};

// Size of the next pass, or 0 to stop because the time limit would be passed. `film_spp`: the
// film's samples per pixel so far; `seconds_per_spp`: measured time of one sample of every
// pixel (0 before the first pass). Pure, so the schedule is testable without a clock.
uint32_t next_pass_size(uint32_t film_spp, uint32_t samples_left, double seconds_per_spp, double pass_seconds,
                        double seconds_left);

ProgressiveResult render_progressive(RenderSession& session, Film& film, const ProgressiveOptions& options,
                                     PassObserver* observer = nullptr);

}  // namespace wt
