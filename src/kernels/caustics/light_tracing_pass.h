#pragma once
// The light paths of a range of samples, traced on the render's threads and splatted into the
// film. Splats land anywhere in the image, not in the tile a worker owns, so each worker collects
// its splats in a buffer of its own and adds them to the film under a lock when the buffer fills
// and at the end. The film's sums are exact (fixed_point.h), so the order the buffers arrive in
// changes nothing: the image is the same bits for any thread count.
//
// With the wavefront integrator the paths of a work item advance together through queues, their
// rays traced by the SIMD kernels of the intersect and shadow stages; with the reference
// integrator one path at a time by the scalar code. Both run LightPathTracer's vertex code.
//
// When the scene merges photons, the same paths also leave their photons in the photon maps of
// the samples traced (kernels/photons/photon_maps.h), each work item's in its own list, in light
// path key order either way.

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "core/film/film.h"
#include "core/system/thread_pool.h"
#include "kernels/caustics/light_path.h"
#include "kernels/photons/photon_maps.h"
#include "kernels/wavefront/stages.h"

namespace wt {

struct LightPathWorkspace;
struct ShadeKernels;

class LightTracingPass {
public:
    // Light paths per work item: they advance together through one worker's queues.
    static constexpr uint64_t kPathsPerItem = 2048;
    // Splats a worker collects before it takes the film's lock.
    static constexpr std::size_t kBufferedSplats = 1 << 14;
    // The splat buffer and, for the wavefront, the queues of one worker.
    static std::size_t bytes_per_worker();

    LightTracingPass(const Scene& scene, const BvhView* bvh, int threads);
    ~LightTracingPass();

    // Traces every light path of samples [sample_begin, sample_end) and adds their splats and the
    // samples' count to `film` (which must have splat channels); counts go to counts[worker].
    // `wavefront`: the kernels and what they trace against, or null to trace one path at a time.
    // `photons` (the scene merges photons): starts their batch for these samples and fills it.
    void render(Film& film, uint32_t sample_begin, uint32_t sample_end, ThreadPool& pool, std::vector<RayCounts>& counts,
                const IntersectContext* wavefront, PhotonMaps* photons = nullptr);

private:
    void trace_item_wavefront(const IntersectContext& context, const ShadeKernels& shade, uint32_t sample, uint64_t first,
                              uint64_t end, LightPathWorkspace& ws, std::vector<CameraSplat>& splats, PhotonList* photons,
                              RayCounts& counts) const;
    void flush(Film& film, std::vector<CameraSplat>& buffer, RayCounts& counts);

    const Scene& scene_;
    LightPathTracer tracer_;
    uint64_t paths_per_sample_;
    std::vector<std::vector<CameraSplat>> buffers_;  // one per worker, kept between passes
    std::vector<std::unique_ptr<LightPathWorkspace>> workspaces_;  // one per worker, made on first use
    std::mutex film_mutex_;
};

}  // namespace wt
