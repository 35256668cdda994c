#include "kernels/wavefront/wavefront_renderer.h"

#include <utility>

#include "kernels/wavefront/stages.h"

namespace wt {

namespace {

// Samples ahead whose pixel sums are asked for while one is added: the film is far larger than
// the caches, and a batch's shading has pushed its tile's pixels out since their last add.
constexpr uint32_t kFilmPrefetchSlots = 8;

// Batches of `step` samples of the tile's pixels: `generate(begin, end)` fills the queue with
// their camera rays, sample-major.
template <typename Generate>
void render_batches(const Scene& scene, const IntersectContext& context, uint32_t sample_begin, uint32_t sample_end,
                    uint32_t step, const AovSelection& aovs, WavefrontWorkspace& ws, Film& film, RayCounts& counts,
                    const PhotonMaps* photons, Generate&& generate) {
    const bool with_aovs = aovs.needs_path_data();
    const ShadeKernels& shade_kernels_of_isa = shade_kernels(context.kernels->isa);
    for (uint32_t begin = sample_begin; begin < sample_end; begin += step) {
        const uint32_t end = std::min(sample_end, begin + step);
        generate(begin, end);
        counts.camera_rays += ws.rays.count;
        const std::size_t batch_size = ws.rays.count;

        for (uint32_t bounce = 0; ws.rays.count > 0; ++bounce) {
            intersect_closest_stage(context, ws.rays, ws.hits, bounce == 0);
            shade_stage(scene, shade_kernels_of_isa, bounce, ws.rays, ws.hits, ws.paths, ws.shade, ws.next_rays, ws.shadows,
                        photons);
            shadow_stage(context, ws.shadows, ws.paths);
            counts.shadow_rays += ws.shadows.count;
            counts.bounce_rays += ws.next_rays.count;
            std::swap(ws.rays, ws.next_rays);
        }

        // Slots are sample-major, so every pixel receives its samples in ascending order.
        for (uint32_t slot = 0; slot < batch_size; ++slot) {
            if (slot + kFilmPrefetchSlots < batch_size) film.prefetch_pixel(ws.paths.pixel[slot + kFilmPrefetchSlots]);
            ++counts.samples;
            float extra[Film::max_extra_channels];
            if (with_aovs) aov_sample_values(aovs, ws.paths.first_surface[slot], extra);
            if (!film.add_sample(ws.paths.pixel[slot], ws.paths.weighted_radiance(slot), with_aovs ? extra : nullptr))
                ++counts.nonfinite_samples;
        }
    }
}

}  // namespace

void render_wavefront_tile(const Scene& scene, const IntersectContext& context, const Tile& tile, uint32_t sample_begin,
                           uint32_t sample_end, std::size_t batch_paths, const AovSelection& aovs,
                           WavefrontWorkspace& ws, Film& film, RayCounts& counts, const PhotonMaps* photons) {
    const uint32_t step = samples_per_batch(tile, batch_paths, sample_end - sample_begin);
    render_batches(scene, context, sample_begin, sample_end, step, aovs, ws, film, counts, photons, [&](uint32_t b, uint32_t e) {
        generate_camera_rays(scene, tile, b, e, ws.paths, ws.rays);
    });
}

void render_wavefront_pixels(const Scene& scene, const IntersectContext& context, const Tile& tile, TilePixels pixels,
                             uint32_t sample_begin, uint32_t sample_end, std::size_t batch_paths,
                             const AovSelection& aovs, WavefrontWorkspace& ws, Film& film, RayCounts& counts,
                             const PhotonMaps* photons) {
    // The whole tile's batch, shared by fewer pixels: more of their samples per batch, and
    // never more paths than the workspace was sized for (memory_estimate.h).
    const uint32_t samples = sample_end - sample_begin;
    const std::size_t budget = std::size_t(tile.pixel_count()) * samples_per_batch(tile, batch_paths, samples);
    const uint32_t step = uint32_t(std::min<std::size_t>(samples, std::max<std::size_t>(1, budget / pixels.count)));
    render_batches(scene, context, sample_begin, sample_end, step, aovs, ws, film, counts, photons, [&](uint32_t b, uint32_t e) {
        generate_camera_rays(scene, pixels, b, e, ws.paths, ws.rays);
    });
}

}  // namespace wt
