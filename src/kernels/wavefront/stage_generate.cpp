#include <algorithm>

#include "core/path_vertex.h"
#include "kernels/wavefront/stages.h"

namespace wt {

void generate_camera_rays(const Scene& scene, const Tile& tile, uint32_t sample_begin, uint32_t sample_end,
                          PathTable& paths, RayQueue& rays) {
    const uint32_t width = uint32_t(scene.settings.width);
    rays.count = 0;
    uint32_t slot = 0;
    for (uint32_t s = sample_begin; s < sample_end; ++s) {
        for (int y = tile.y0; y < tile.y1; ++y) {
            for (int x = tile.x0; x < tile.x1; ++x, ++slot) {
                const uint32_t pixel = uint32_t(y) * width + uint32_t(x);
                const uint64_t key = path_key(scene.settings.seed, pixel, s);
                paths.pixel[slot] = pixel;
                paths.sample[slot] = s;
                paths.key[slot] = key;
                paths.radiance_r[slot] = paths.radiance_g[slot] = paths.radiance_b[slot] = 0.0f;
                rays.push(camera_ray(scene, pixel, s, key), glm::vec3(1.0f), slot, true);
            }
        }
    }
    if (!paths.first_surface.empty()) std::fill_n(paths.first_surface.begin(), slot, FirstSurface{});
}

}  // namespace wt
