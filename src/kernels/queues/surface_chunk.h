#pragma once
// The surface points (SurfacePoint, core/scene/scene.h) of a chunk of a shade stage's hits,
// computed N at a time by the surface kernel (kernels/shading/surface_points.h) before the shade
// loop reads them, in scenes whose every hit is on a flat triangle or a sphere (no vertex
// normals, no instances: Scene::flat_surfaces()). One hit at a time, the triangle's normal (a
// cross product, a square root, three divisions) and the sphere's (a square root, a division)
// were dependent chains in every iteration of the loop.

#include <cstddef>
#include <cstdint>

#include "core/base/aligned_vector.h"
#include "core/scene/scene.h"

namespace wt {

// Whether surface_at's work for every hit of the scene is the surface kernel's.
inline bool has_flat_surfaces_only(const Scene& scene) { return scene.shading_normals.empty() && scene.instances.empty(); }

struct SurfaceChunk {
    // Hits per chunk: a multiple of every width; the chunk stays in L1.
    static constexpr std::size_t kSize = 256;

    AlignedVector<float> px, py, pz, ex, ey, ez, nx, ny, nz;
    AlignedVector<uint32_t> material;

    SurfaceChunk() {
        for (auto* a : {&px, &py, &pz, &ex, &ey, &ez, &nx, &ny, &nz}) a->resize(kSize);
        material.resize(kSize);
    }
    static constexpr std::size_t kBytes = kSize * 10 * 4;

    // Hit `k` of the chunk, as surface_at gives it for a flat triangle or a sphere.
    SurfacePoint at(std::size_t k) const {
        SurfacePoint s;
        s.position = {px[k], py[k], pz[k]};
        s.error = {ex[k], ey[k], ez[k]};
        s.normal = {nx[k], ny[k], nz[k]};
        s.shading_normal = s.normal;
        s.material = material[k];
        s.smooth = false;
        return s;
    }
};

}  // namespace wt
