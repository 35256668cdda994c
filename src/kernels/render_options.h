#pragma once
// How a render runs: the integrator, threads, tiles and batches, the kernels, the acceleration
// structure and the AOVs. The scene file's settings say what is rendered; these, how. Apart from
// the renderer, the memory estimate and the tools' options take them, without the renderer.

#include <cstddef>
#include <cstdint>
#include <optional>

#include "core/film/aov.h"
#include "kernels/accel/accel_choice.h"
#include "kernels/accel/bvh.h"
#include "kernels/isa/intersect_kernels.h"

namespace wt {

enum class Integrator { wavefront, reference };

struct RenderOptions {
    Integrator integrator = Integrator::wavefront;
    int threads = 0;                 // 0: one per hardware thread
    int tile_size = 16;              // pixels per tile side
    std::size_t batch_paths = 2048;  // camera paths per wavefront batch: queues sized to stay in L2
    // With photons, the light paths whose photons are held at once (PhotonMaps::samples_per_batch):
    // memory, never the image.
    uint64_t photon_batch_paths = uint64_t(1) << 18;
    std::optional<Isa> isa;          // intersection kernels; empty: the best this CPU runs
    Accel accel = Accel::automatic;  // never changes the image, only how fast it comes
    BvhBuildOptions bvh;             // when a BVH is built (its `threads` is ignored: the render's are used)
    // AOVs to render: the film must have exactly aov_film_channels(aovs) as its extra channels.
    AovSelection aovs;
};

}  // namespace wt
