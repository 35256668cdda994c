#pragma once
// How far a render is, on stderr. On a terminal: one line, redrawn at most four times a
// second, with percent done, samples/s, elapsed, time left and the image's spp. Otherwise (a
// log file, a pipe, a batch system): one plain line per pass. Off with -q.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

#include "kernels/progressive_render.h"

namespace wt {

enum class ProgressStyle { off, terminal, log };

// terminal if stderr is one, else log; off when quiet.
ProgressStyle progress_style_for_stderr(bool quiet);

class ProgressDisplay {
public:
    // The run adds samples [first_spp, target_spp) of each of `pixels` pixels, stopping early at
    // `time_limit` seconds (0: none).
    ProgressDisplay(ProgressStyle style, uint64_t pixels, uint32_t first_spp, uint32_t target_spp, double time_limit);

    // From the workers: a tile finished `samples` samples.
    void samples_done(uint64_t samples);
    void pass_done(const PassReport& report);
    // Ends the terminal line, so what follows starts on a line of its own.
    void finish();

private:
    std::string line(uint32_t film_spp) const;
    double elapsed() const;

    ProgressStyle style_;
    uint64_t total_samples_;
    uint32_t target_spp_;
    double time_limit_;
    std::chrono::steady_clock::time_point start_;
    std::atomic<uint64_t> done_{0};
    std::atomic<uint32_t> film_spp_;
    std::atomic<double> last_draw_{-1.0};
    std::mutex draw_;
    bool drawn_ = false;
};

}  // namespace wt
