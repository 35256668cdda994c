#pragma once
// The light paths of a range of samples, traced on the render's threads and splatted into the
// film. Splats land anywhere in the image, not in the tile a worker owns, so each worker collects
// its splats in a buffer of its own and adds them to the film under a lock when the buffer fills
// and at the end. The film's sums are exact (fixed_point.h), so the order the buffers arrive in
// changes nothing: the image is the same bits for any thread count.

#include <cstdint>
#include <mutex>
#include <vector>

#include "core/film/film.h"
#include "core/thread_pool.h"
#include "kernels/caustics/light_path.h"

namespace wt {

class LightTracingPass {
public:
    // Splats a worker collects before it takes the film's lock.
    static constexpr std::size_t kBufferedSplats = 1 << 16;
    static constexpr std::size_t bytes_per_worker() { return kBufferedSplats * sizeof(CameraSplat); }

    LightTracingPass(const Scene& scene, const BvhView* bvh, int threads);

    // Traces every light path of samples [sample_begin, sample_end) and adds their splats and the
    // samples' count to `film` (which must have splat channels); counts go to counts[worker].
    void render(Film& film, uint32_t sample_begin, uint32_t sample_end, ThreadPool& pool, std::vector<RayCounts>& counts);

private:
    void flush(Film& film, std::vector<CameraSplat>& buffer, RayCounts& counts);

    LightPathTracer tracer_;
    uint64_t paths_per_sample_;
    std::vector<std::vector<CameraSplat>> buffers_;  // one per worker, kept between passes
    std::mutex film_mutex_;
};

}  // namespace wt
