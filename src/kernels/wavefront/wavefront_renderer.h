#pragma once
// Runs the wavefront stages over one tile: a range of the tile's samples are cut into batches of about
// `batch_paths` camera paths; each batch is generated, then intersect -> shade -> shadow repeat
// until no ray is left, then its radiance goes to the film in sample order.

#include "core/film/aov.h"
#include "core/film/film.h"
#include "core/scene/scene.h"
#include "kernels/queues/ray_queues.h"
#include "kernels/work/render_stats.h"
#include "kernels/wavefront/stages.h"
#include "kernels/work/tiles.h"

namespace wt {

// How many samples of every pixel of the tile one batch holds (at least 1), of `samples` wanted.
inline uint32_t samples_per_batch(const Tile& tile, std::size_t batch_paths, uint32_t samples) {
    const std::size_t per_batch = std::max<std::size_t>(1, batch_paths / std::size_t(tile.pixel_count()));
    return uint32_t(std::min<std::size_t>(per_batch, samples));
}

// Samples [sample_begin, sample_end) of every pixel of the tile, with the AOVs the film has
// channels for (the workspace must then have been made with_aovs); `photons`: the photon maps
// of the samples' batch when the scene merges photons, else null.
void render_wavefront_tile(const Scene& scene, const IntersectContext& context, const Tile& tile, uint32_t sample_begin,
                           uint32_t sample_end, std::size_t batch_paths, const AovSelection& aovs,
                           WavefrontWorkspace& workspace, Film& film, RayCounts& counts, const PhotonMaps* photons);

// The same for some of the tile's pixels (at least one): adaptive sampling's pixels still sampled.
void render_wavefront_pixels(const Scene& scene, const IntersectContext& context, const Tile& tile, TilePixels pixels,
                             uint32_t sample_begin, uint32_t sample_end, std::size_t batch_paths,
                             const AovSelection& aovs, WavefrontWorkspace& workspace, Film& film, RayCounts& counts,
                             const PhotonMaps* photons);

}  // namespace wt
