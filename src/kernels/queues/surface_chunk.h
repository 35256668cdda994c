#pragma once
// The surface points (SurfacePoint, core/scene/scene.h) of a chunk of a shade stage's hits,
// computed N at a time by the surface kernel (kernels/shading/surface_points.h) before the shade
// loop reads them, for the hits on the triangles and spheres of the scene's own lists
// (surface_kernel_ids); an instance's hits are surface_at's, one at a time, as they were
// before the kernel (placing a point needs its instance's transforms, and each instanced mesh
// has its own arrays to gather from). One hit at a time, the triangle's normal (a cross
// product, a square root, three divisions), its interpolated vertex normal (three gathers of a
// normal, a square root, three divisions) and the sphere's normal (a square root, a division)
// were dependent chains in every iteration of the loop.

#include <cstddef>
#include <cstdint>

#include "core/base/aligned_vector.h"
#include "core/scene/scene.h"

namespace wt {

// The ids whose surface points the surface kernel computes: [0, this), the scene's own triangles
// and spheres (the instances' ids come after them, scene_instances.h).
inline uint32_t surface_kernel_ids(const Scene& scene) { return uint32_t(scene.triangles.size() + scene.spheres.size()); }

struct SurfaceChunk {
    // Hits per chunk: a multiple of every width; the chunk stays in L1.
    static constexpr std::size_t kSize = 256;

    AlignedVector<float> px, py, pz, ex, ey, ez, nx, ny, nz;
    AlignedVector<uint32_t> material;
    // The shading normals and SurfacePoint::smooth, written only in a scene with vertex normals
    // (`shading_normals`); elsewhere the shading normal is the normal.
    AlignedVector<float> snx, sny, snz;
    AlignedVector<uint32_t> smooth;
    bool shading_normals = false;

    SurfaceChunk() {
        for (auto* a : {&px, &py, &pz, &ex, &ey, &ez, &nx, &ny, &nz, &snx, &sny, &snz}) a->resize(kSize);
        material.resize(kSize), smooth.resize(kSize);
    }
    static constexpr std::size_t kBytes = kSize * 14 * 4;

    // Hit `k` of the chunk, as surface_at gives it.
    SurfacePoint at(std::size_t k) const {
        SurfacePoint s;
        s.position = {px[k], py[k], pz[k]};
        s.error = {ex[k], ey[k], ez[k]};
        s.normal = {nx[k], ny[k], nz[k]};
        s.shading_normal = s.normal;
        s.material = material[k];
        s.smooth = false;
        if (shading_normals) {
            s.shading_normal = {snx[k], sny[k], snz[k]};
            s.smooth = smooth[k] != 0;
        }
        return s;
    }
};

}  // namespace wt
