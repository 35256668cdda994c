#pragma once
// The scene's primitives copied into BVH leaf order, holding only what the scene's primitive
// tests read (v0, the edges and the scaled normal for Moller-Trumbore; the three vertices for
// the watertight test; centre and radius for spheres) and each one's scene id. A leaf is then a
// contiguous run, loaded with the same SoA loads as the flat kernels and returning their bits.

#include <cstddef>
#include <cstdint>

#include "core/accuracy.h"
#include "core/aligned_vector.h"
#include "core/scene.h"
#include "kernels/accel/bvh_view.h"

namespace wt {

struct BvhPrimitives {
    TriangleTest test = TriangleTest::moller_trumbore;
    AlignedVector<float> v0x, v0y, v0z, e1x, e1y, e1z, e2x, e2y, e2z, nx, ny, nz;  // Moller-Trumbore
    AlignedVector<float> v1x, v1y, v1z, v2x, v2y, v2z;                            // watertight (and v0)
    AlignedVector<uint32_t> planar_prim;  // leaf-order index -> scene primitive id
    AlignedVector<float> cx, cy, cz, radius;
    AlignedVector<uint32_t> sphere_prim;

    uint32_t planar_count() const { return uint32_t(planar_prim.size()); }
    uint32_t sphere_count() const { return uint32_t(sphere_prim.size()); }
    // Appends scene primitive `id` (a triangle or parallelogram if below the triangle count).
    void append(const Scene& scene, uint32_t id);
    std::size_t bytes() const;
    TriangleView planar_view() const;
    SphereView sphere_view() const;
};

}  // namespace wt
