#include "kernels/wavefront/wavefront_renderer.h"

#include <utility>

#include "kernels/wavefront/stages.h"

namespace wt {

void render_wavefront_tile(const Scene& scene, const IntersectContext& context, const Tile& tile, uint32_t sample_begin,
                           uint32_t sample_end, std::size_t batch_paths, const AovSelection& aovs,
                           WavefrontWorkspace& ws, Film& film, RayCounts& counts) {
    const bool with_aovs = aovs.needs_path_data();
    const uint32_t step = samples_per_batch(tile, batch_paths, sample_end - sample_begin);
    for (uint32_t begin = sample_begin; begin < sample_end; begin += step) {
        const uint32_t end = std::min(sample_end, begin + step);
        generate_camera_rays(scene, tile, begin, end, ws.paths, ws.rays);
        counts.camera_rays += ws.rays.count;
        const std::size_t batch_size = ws.rays.count;

        for (uint32_t bounce = 0; ws.rays.count > 0; ++bounce) {
            intersect_closest_stage(context, ws.rays, ws.hits, bounce == 0);
            shade_stage(scene, bounce, ws.rays, ws.hits, ws.paths, ws.next_rays, ws.shadows);
            shadow_stage(context, ws.shadows, ws.paths);
            counts.shadow_rays += ws.shadows.count;
            counts.bounce_rays += ws.next_rays.count;
            std::swap(ws.rays, ws.next_rays);
        }

        // Slots are sample-major, so every pixel receives its samples in ascending order.
        for (uint32_t slot = 0; slot < batch_size; ++slot) {
            ++counts.samples;
            float extra[Film::max_extra_channels];
            if (with_aovs) aov_sample_values(aovs, ws.paths.first_surface[slot], extra);
            if (!film.add_sample(ws.paths.pixel[slot], ws.paths.radiance(slot), with_aovs ? extra : nullptr))
                ++counts.nonfinite_samples;
        }
    }
}

}  // namespace wt
