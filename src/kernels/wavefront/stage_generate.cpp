#include <algorithm>

#include "core/path/path_vertex.h"
#include "kernels/wavefront/stages.h"

namespace wt {

namespace {

template <typename E>
inline void generate_path(const Scene& scene, uint32_t pixel, uint32_t s, uint32_t slot, PathTable& paths, RayQueue& rays) {
    const PathSeed path = path_seed<E>(scene, pixel, s);
    paths.pixel[slot] = pixel;
    paths.sample[slot] = s;
    paths.key[slot] = path.key;
    paths.radiance_r[slot] = paths.radiance_g[slot] = paths.radiance_b[slot] = 0.0f;
    const CameraRay camera = camera_ray<E>(scene, pixel, path);
    paths.filter_weight[slot] = camera.weight;
    // Emission seen from the camera counts in full (no light sample competes: bsdf_pdf 0).
    rays.push<E::mis>(PathContinuation{camera.ray, glm::vec3(1.0f), true, false, 0.0f}, slot);
}

template <typename E>
void generate_queue(const Scene& scene, const Tile& tile, uint32_t sample_begin, uint32_t sample_end, PathTable& paths,
                    RayQueue& rays) {
    const uint32_t width = uint32_t(scene.settings.width);
    rays.count = 0;
    uint32_t slot = 0;
    for (uint32_t s = sample_begin; s < sample_end; ++s)
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x, ++slot)
                generate_path<E>(scene, uint32_t(y) * width + uint32_t(x), s, slot, paths, rays);
    if (!paths.first_surface.empty()) std::fill_n(paths.first_surface.begin(), slot, FirstSurface{});
}

template <typename E>
void generate_queue(const Scene& scene, TilePixels pixels, uint32_t sample_begin, uint32_t sample_end, PathTable& paths,
                    RayQueue& rays) {
    rays.count = 0;
    uint32_t slot = 0;
    for (uint32_t s = sample_begin; s < sample_end; ++s)
        for (std::size_t i = 0; i < pixels.count; ++i, ++slot) generate_path<E>(scene, pixels.index[i], s, slot, paths, rays);
    if (!paths.first_surface.empty()) std::fill_n(paths.first_surface.begin(), slot, FirstSurface{});
}

}  // namespace

void generate_camera_rays(const Scene& scene, const Tile& tile, uint32_t sample_begin, uint32_t sample_end,
                          PathTable& paths, RayQueue& rays) {
    with_estimator(scene.settings.estimator, [&](auto estimator) {
        generate_queue<decltype(estimator)>(scene, tile, sample_begin, sample_end, paths, rays);
    });
}

void generate_camera_rays(const Scene& scene, TilePixels pixels, uint32_t sample_begin, uint32_t sample_end,
                          PathTable& paths, RayQueue& rays) {
    with_estimator(scene.settings.estimator, [&](auto estimator) {
        generate_queue<decltype(estimator)>(scene, pixels, sample_begin, sample_end, paths, rays);
    });
}

}  // namespace wt
