#pragma once
// Entry point: renders a scene into a film with either integrator on a pool of threads.

#include <cstddef>
#include <optional>

#include "core/film/film.h"
#include "core/scene.h"
#include "kernels/accel/accel_choice.h"
#include "kernels/accel/bvh.h"
#include "kernels/isa/intersect_kernels.h"
#include "kernels/render_stats.h"

namespace wt {

enum class Integrator { wavefront, reference };

struct RenderOptions {
    Integrator integrator = Integrator::wavefront;
    int threads = 0;                 // 0: one per hardware thread
    int tile_size = 16;              // pixels per tile side
    std::size_t batch_paths = 2048;  // camera paths per wavefront batch: queues sized to stay in L2
    std::optional<Isa> isa;          // intersection kernels; empty: the best this CPU runs
    Accel accel = Accel::automatic;  // never changes the image, only how fast it comes
    BvhBuildOptions bvh;             // when a BVH is built (its `threads` is ignored: the render's are used)
};

struct RenderResult {
    RayCounts counts;
    double seconds = 0.0;  // wall time of the rendering itself (no loading, no writing)
    int threads = 1;
    Isa isa = Isa::scalar;  // kernels the wavefront integrator used
    Accel accel = Accel::brute;  // what `automatic` resolved to
    BvhStats bvh;                // when accel is bvh: the tree's size and build time
};

// The film must match the scene's resolution. Deterministic: the same scene (including seed)
// gives a bit-identical film for any thread count, tile size and batch size.
RenderResult render(const Scene& scene, const RenderOptions& options, Film& film);

int default_thread_count();

}  // namespace wt
