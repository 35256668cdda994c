#pragma once
// What `wavetrace render` does at the boundaries between passes: progress, and actions repeated
// every so many seconds of rendering (the images with --write-every, and whatever else wants an
// honest N-spp film: checkpoints, the error against a reference).

#include <functional>
#include <vector>

#include "kernels/progressive_render.h"
#include "tools/render/progress_display.h"

namespace wt {

class RenderPassHooks : public PassObserver {
public:
    using Action = std::function<void(const Film& film, const PassReport& report)>;

    explicit RenderPassHooks(ProgressDisplay& progress) : progress_(progress) {}

    // Runs `action` at the first pass boundary at least `interval` seconds after its last run
    // (0: every boundary). Not after the last pass: the command writes its final results then.
    void every(double interval, Action action) { actions_.push_back({interval, std::move(action), 0.0}); }

    void samples_done(uint64_t samples) override { progress_.samples_done(samples); }
    bool pass_done(const Film& film, const PassReport& report) override;

private:
    struct Periodic {
        double interval;
        Action action;
        double last_run;
    };
    ProgressDisplay& progress_;
    std::vector<Periodic> actions_;
};

}  // namespace wt
