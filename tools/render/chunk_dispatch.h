#pragma once
// Rank 0's hand-out of sample chunks in an MPI render (mpi_render.cpp), without MPI: its own
// renderer takes chunks on a thread of its own, while the thread that talks to the other ranks
// answers their requests from the same queue. Kept apart from the messages so that a test can
// run the two threads under ThreadSanitizer (mpirun under TSan is impractical: OpenMPI is not
// instrumented).

#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "kernels/work/sample_range.h"

namespace wt {

// Chunks small enough that the ranks finish close together, large enough that a chunk's
// fixed costs (a message, the tiles' start) stay small: about 4 per rank, at least 1 sample.
uint32_t chunk_size(SampleRange samples, int ranks);

// The chunks of `samples` not yet handed out, `chunk` samples each (the last one shorter).
// Safe to take from on several threads at once.
class ChunkQueue {
public:
    ChunkQueue(SampleRange samples, uint32_t chunk) : next_(samples.begin), end_(samples.end), chunk_(chunk) {}
    // The next chunk in `out`; false once every chunk is handed out or the queue is closed.
    bool take(SampleRange& out);
    // Hands out nothing more (after a failure, so no one starts a chunk that will not be used).
    void close();

private:
    std::mutex mutex_;
    uint32_t next_, end_, chunk_;
};

// The chunks one rank rendered, as it reports them.
struct RankRanges {
    int rank;
    std::vector<SampleRange> ranges;
};

// Throws std::runtime_error, naming the first rank whose chunk leaves a gap or overlaps, unless
// the chunks of every rank cover `samples` exactly once: else the image would claim samples it
// lacks.
void check_coverage(std::vector<RankRanges> all, SampleRange samples);

// Rank 0's side of the render. Construction starts the local thread, which calls `render` with
// one chunk after another until none is left; answer() serves the other ranks from the calling
// thread, which alone calls answer() and remote_ranks_working(). `ranks` counts rank 0.
class ChunkDispatch {
public:
    ChunkDispatch(SampleRange samples, int ranks, bool quiet, std::function<void(SampleRange)> render);
    // stop(), then waits for the local thread: on a failure of the messages, rank 0 waits for
    // its chunk in hand only.
    ~ChunkDispatch();
    ChunkDispatch(const ChunkDispatch&) = delete;
    ChunkDispatch& operator=(const ChunkDispatch&) = delete;

    // Whether some rank other than 0 has not yet been told to stop.
    bool remote_ranks_working() const { return working_ > 0; }
    // Rank `rank` (not 0) rendered `done` (empty on its first request) and asks for more: the
    // next chunk, or an empty range, which tells it to stop.
    SampleRange answer(int rank, SampleRange done);
    // Waits for the local thread, rethrows what `render` threw there, and returns the chunks
    // rank 0 rendered, in order.
    std::vector<SampleRange> finish_local();
    // Hands out nothing more: the local thread ends after its chunk, and every rank that asks
    // is told to stop.
    void stop() { queue_.close(); }
    // Samples every rank reported done, rank 0's included.
    uint32_t samples_done();

private:
    void chunk_done(int rank, SampleRange r);

    ChunkQueue queue_;
    const uint32_t total_;
    const bool quiet_;
    int working_;
    std::mutex progress_mutex_;
    uint32_t done_ = 0;
    std::vector<SampleRange> local_ranges_;  // the local thread's alone until it is joined
    std::exception_ptr local_failure_;
    std::thread local_;
};

}  // namespace wt
