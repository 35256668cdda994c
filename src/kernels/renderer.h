#pragma once
// Entry point: renders a scene into a film with either integrator on a pool of threads.
// A RenderSession owns what outlives one range of samples (threads, the BVH, the workers'
// queues), so progressive passes, resumed renders and sample ranges of a split render pay for
// them once; `render` is a session used for all of the scene's samples.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/film/aov.h"
#include "core/film/film.h"
#include "core/scene/scene.h"
#include "core/system/thread_pool.h"
#include "kernels/accel/accel_choice.h"
#include "kernels/accel/bvh.h"
#include "kernels/accel/bvh_view.h"
#include "kernels/accel/scene_bvh.h"
#include "kernels/isa/intersect_kernels.h"
#include "kernels/work/render_stats.h"
#include "kernels/work/sample_range.h"
#include "kernels/render_options.h"
#include "kernels/work/tiles.h"

namespace wt {

struct RenderResult {
    RayCounts counts;
    double seconds = 0.0;  // wall time of the rendering itself (no loading, no BVH build, no writing)
    int threads = 1;
    Isa isa = Isa::scalar;  // kernels the wavefront integrator used
    Accel accel = Accel::brute;  // what `automatic` resolved to
    BvhStats bvh;                // when accel is bvh: the tree's size and build time
    // With instances: how many, and the bytes of their meshes' trees (each once) and of the
    // top level with the instances' records.
    std::size_t instance_count = 0;
    std::size_t instanced_mesh_bytes = 0, instance_bytes = 0;
    uint64_t photon_maps_built = 0;  // with photons: the samples whose photons some camera path gathered
};

struct WavefrontWorkspace;
class FlatScene;
struct IntersectContext;
class LightTracingPass;
class PhotonMaps;

// The film channels a render of `scene` with `aovs` needs: the AOVs' (aov_film_channels), then the
// splat channels when the scene light-traces its caustics (Film::splat_channels).
std::vector<std::string> render_film_channels(const Scene& scene, const AovSelection& aovs);

class RenderSession {
public:
    // Checks the options against the scene and builds the BVH when the render uses one.
    RenderSession(const Scene& scene, const RenderOptions& options);
    ~RenderSession();
    RenderSession(const RenderSession&) = delete;
    RenderSession& operator=(const RenderSession&) = delete;

    // Adds samples `range` of every pixel to the film (which must match the scene's resolution
    // and have render_film_channels(scene, options.aovs)), and their light paths' splats. Each pixel receives them in ascending order;
    // since the film's sums are exact, the film ends the same bits however a render is cut into
    // ranges, for any thread count, tile size and batch size. `tile_done(samples)`, if given, is called by the worker
    // that finished a tile with the number of samples it added: from several threads at once.
    //
    // With adaptive sampling (the scene's settings.adaptive), only pixels still sampled get the
    // samples, the stopping rule runs at the decision points inside the range
    // (kernels/adaptive/), and its state is in film.adaptive(): the render must start at sample
    // 0 and each range continue where the film's ended (std::invalid_argument otherwise).
    // `tile_done` then counts a stopped pixel's samples as done too, so progress reaches 100 %.
    void render_samples(Film& film, SampleRange range, const std::function<void(uint64_t samples)>& tile_done = {});

    // Counts and rendering time of every range so far.
    RenderResult result() const;
    const Scene& scene() const { return scene_; }

private:
    // One parallel pass over the tiles for `range`: every pixel, or with `adaptive` those it
    // says are still sampled.
    void render_tiles(Film& film, SampleRange range, const std::function<void(uint64_t)>& tile_done,
                      const AdaptiveState* adaptive);
    // render_tiles, and with photons the light paths of the range first, batch by batch.
    void render_camera_paths(Film& film, SampleRange range, const std::function<void(uint64_t)>& tile_done,
                             const AdaptiveState* adaptive);
    // The light paths of `range` (splats, and with `photons` the photons of a batch).
    void trace_light_paths(Film& film, SampleRange range, PhotonMaps* photons);
    IntersectContext intersect_context() const;

    const Scene& scene_;
    RenderOptions options_;
    int threads_;
    Isa isa_;
    Accel accel_;
    std::vector<Tile> tiles_;
    ThreadPool pool_;
    const IntersectKernels* kernels_;
    SceneBvh bvh_;
    std::unique_ptr<FlatScene> flat_;  // the flat kernels' rows, only when the scene is not traced through bvh_
    std::vector<RayCounts> counts_;
    // Created by the worker that uses it, on first use, so its pages live near that core.
    std::vector<std::unique_ptr<WavefrontWorkspace>> workspaces_;
    std::unique_ptr<LightTracingPass> light_tracing_;  // only when the scene light-traces caustics
    std::unique_ptr<PhotonMaps> photons_;              // only when it merges photons too
    std::vector<std::vector<uint32_t>> sampled_pixels_;  // per worker: a tile's pixels still sampled (adaptive)
    double seconds_ = 0.0;
};

// All of the scene's samples (settings.spp) in one range.
RenderResult render(const Scene& scene, const RenderOptions& options, Film& film);

int default_thread_count();

}  // namespace wt
