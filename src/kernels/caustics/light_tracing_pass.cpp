#include "kernels/caustics/light_tracing_pass.h"

#include <stdexcept>

namespace wt {

namespace {
// Light paths per work item: large enough that handing out items costs nothing, small enough
// that two workers share a sample's paths evenly.
constexpr uint64_t kPathsPerItem = 4096;
}  // namespace

LightTracingPass::LightTracingPass(const Scene& scene, const BvhView* bvh, int threads)
    : tracer_(scene, bvh), paths_per_sample_(light_paths_per_sample(scene.settings)), buffers_(std::size_t(threads)) {}

void LightTracingPass::flush(Film& film, std::vector<CameraSplat>& buffer, RayCounts& counts) {
    {
        const std::lock_guard<std::mutex> lock(film_mutex_);
        for (const CameraSplat& s : buffer)
            if (!film.add_splat(s.pixel, s.value)) ++counts.dropped_splats;
    }
    buffer.clear();
}

void LightTracingPass::render(Film& film, uint32_t sample_begin, uint32_t sample_end, ThreadPool& pool,
                              std::vector<RayCounts>& counts) {
    if (!film.has_splats()) throw std::invalid_argument("render: light tracing needs a film with splat channels");
    if (sample_end <= sample_begin) return;
    const uint64_t items_per_sample = (paths_per_sample_ + kPathsPerItem - 1) / kPathsPerItem;
    const uint64_t items = items_per_sample * (sample_end - sample_begin);
    pool.parallel_for(std::size_t(items), [&](std::size_t item, int worker) {
        const uint32_t sample = sample_begin + uint32_t(item / items_per_sample);
        const uint64_t first = (item % items_per_sample) * kPathsPerItem;
        const uint64_t end = std::min(paths_per_sample_, first + kPathsPerItem);
        RayCounts& c = counts[std::size_t(worker)];
        std::vector<CameraSplat>& buffer = buffers_[std::size_t(worker)];
        for (uint64_t path = first; path < end; ++path) {
            tracer_.trace(path, sample, c, buffer);
            if (buffer.size() >= kBufferedSplats) flush(film, buffer, c);
        }
        c.light_paths += end - first;
    });
    for (std::size_t w = 0; w < buffers_.size(); ++w) flush(film, buffers_[w], counts[w]);
    film.add_splat_samples(sample_end - sample_begin);
}

}  // namespace wt
