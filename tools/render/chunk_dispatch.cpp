#include "tools/render/chunk_dispatch.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

namespace wt {

uint32_t chunk_size(SampleRange samples, int ranks) { return std::max(1u, samples.size() / uint32_t(4 * ranks)); }

bool ChunkQueue::take(SampleRange& out) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (next_ >= end_) return false;
    out = {next_, std::min(end_, next_ + chunk_)};
    next_ = out.end;
    return true;
}

void ChunkQueue::close() {
    std::lock_guard<std::mutex> lock(mutex_);
    next_ = end_;
}

void check_coverage(std::vector<RankRanges> all, SampleRange samples) {
    std::vector<std::pair<SampleRange, int>> chunks;
    for (const RankRanges& r : all)
        for (const SampleRange& s : r.ranges) chunks.push_back({s, r.rank});
    std::sort(chunks.begin(), chunks.end(), [](const auto& a, const auto& b) { return a.first.begin < b.first.begin; });
    uint32_t covered = samples.begin;
    for (const auto& [range, rank] : chunks) {
        if (range.begin != covered)
            throw std::runtime_error("MPI: the ranks' films do not hold samples " + std::to_string(samples.begin) + ":" +
                                     std::to_string(samples.end) + " exactly once (rank " + std::to_string(rank) +
                                     " has " + std::to_string(range.begin) + ":" + std::to_string(range.end) +
                                     " after sample " + std::to_string(covered) + "): no image written");
        covered = range.end;
    }
    if (covered != samples.end)
        throw std::runtime_error("MPI: the ranks' films end at sample " + std::to_string(covered) + " of " +
                                 std::to_string(samples.end) + ": no image written");
}

ChunkDispatch::ChunkDispatch(SampleRange samples, int ranks, bool quiet, std::function<void(SampleRange)> render)
    : queue_(samples, chunk_size(samples, ranks)), total_(samples.size()), quiet_(quiet), working_(ranks - 1) {
    local_ = std::thread([this, render = std::move(render)] {
        try {
            for (SampleRange r; queue_.take(r);) {
                render(r);
                local_ranges_.push_back(r);
                chunk_done(0, r);
            }
        } catch (...) {
            local_failure_ = std::current_exception();
        }
    });
}

ChunkDispatch::~ChunkDispatch() {
    stop();
    if (local_.joinable()) local_.join();
}

SampleRange ChunkDispatch::answer(int rank, SampleRange done) {
    if (done.end > done.begin) chunk_done(rank, done);
    SampleRange next{0, 0};
    if (!queue_.take(next)) --working_;
    return next;
}

std::vector<SampleRange> ChunkDispatch::finish_local() {
    local_.join();
    if (local_failure_) std::rethrow_exception(local_failure_);
    return local_ranges_;
}

uint32_t ChunkDispatch::samples_done() {
    std::lock_guard<std::mutex> lock(progress_mutex_);
    return done_;
}

void ChunkDispatch::chunk_done(int rank, SampleRange r) {
    std::lock_guard<std::mutex> lock(progress_mutex_);
    done_ += r.size();
    if (!quiet_)
        std::fprintf(stderr, "wavetrace: MPI: rank %d rendered samples %u:%u (%u of %u spp done)\n", rank, r.begin, r.end,
                     done_, total_);
}

}  // namespace wt
