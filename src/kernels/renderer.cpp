#include "kernels/renderer.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/thread_pool.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/memory_estimate.h"
#include "kernels/reference_integrator.h"
#include "kernels/wavefront/tiles.h"
#include "kernels/wavefront/wavefront_renderer.h"

namespace wt {

int default_thread_count() { return std::max(1u, std::thread::hardware_concurrency()); }

RenderResult render(const Scene& scene, const RenderOptions& options, Film& film) {
    if (film.width() != scene.settings.width || film.height() != scene.settings.height)
        throw std::invalid_argument("render: film resolution does not match the scene's");
    if (options.tile_size < 1) throw std::invalid_argument("render: tile size must be at least 1");
    if (options.batch_paths < 1) throw std::invalid_argument("render: batch size must be at least 1");

    const int threads = options.threads > 0 ? options.threads : default_thread_count();
    const std::vector<Tile> tiles = make_tiles(scene.settings.width, scene.settings.height, options.tile_size);
    std::vector<RayCounts> counts(static_cast<std::size_t>(threads));
    // Created by the worker that uses it, on first use, so its pages live near that core.
    std::vector<std::unique_ptr<WavefrontWorkspace>> workspaces(static_cast<std::size_t>(threads));

    if (scene.settings.accuracy.triangles == TriangleTest::watertight && scene.triangles.parallelogram_count > 0)
        throw std::invalid_argument("render: the watertight triangle test cannot render parallelograms; build the scene "
                                    "with the accuracy settings it is rendered with");

    const Isa isa = options.isa.value_or(best_supported_isa());
    ThreadPool pool(threads);
    const IntersectKernels& kernels = intersect_kernels(isa, scene.settings.accuracy);
    const Accel accel = resolve_accel(options.accel, scene.primitive_count(), kernels.width);
    Bvh bvh;
    BvhView bvh_tree;
    if (accel == Accel::bvh) {
        bvh = build_bvh(scene, options.bvh, &pool);
        bvh_tree = bvh_view(bvh);
    }
    const BvhView* tree = accel == Accel::bvh ? &bvh_tree : nullptr;
    const IntersectContext context{scene_view(scene), &kernels, tree};

    const auto start = std::chrono::steady_clock::now();
    pool.parallel_for(tiles.size(), [&](std::size_t item, int worker) {
        const Tile& tile = tiles[item];
        RayCounts& c = counts[std::size_t(worker)];
        if (options.integrator == Integrator::reference) {
            render_reference_tile(scene, tile, film, c, tree);
            return;
        }
        auto& ws = workspaces[std::size_t(worker)];
        if (!ws) {
            const RenderSettings& s = scene.settings;
            const std::size_t capacity = workspace_paths(s.width, s.height, s.spp, options.tile_size, options.batch_paths);
            ws = std::make_unique<WavefrontWorkspace>(capacity, std::size_t(s.shadow_rays));
        }
        render_wavefront_tile(scene, context, tile, options.batch_paths, *ws, film, c);
    });
    const auto stop = std::chrono::steady_clock::now();

    RenderResult result;
    for (const RayCounts& c : counts) result.counts += c;
    result.seconds = std::chrono::duration<double>(stop - start).count();
    result.threads = threads;
    result.isa = isa;
    result.accel = accel;
    result.bvh = bvh.stats();
    return result;
}

}  // namespace wt
