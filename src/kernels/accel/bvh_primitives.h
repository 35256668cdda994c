#pragma once
// The scene's primitives copied into BVH leaf order, leaf by leaf in the block layout of
// bvh_view.h, holding only what the scene's primitive tests read (v0, the edges and the scaled
// normal for Moller-Trumbore; the three vertices for the watertight test; centre and radius for
// spheres) and each one's scene id, so a leaf test returns the flat kernels' bits.

#include <cstddef>
#include <cstdint>

#include "core/accuracy.h"
#include "core/aligned_vector.h"
#include "core/scene.h"
#include "kernels/accel/bvh_view.h"

namespace wt {

struct BvhPrimitives {
    TriangleTest test = TriangleTest::moller_trumbore;
    AlignedVector<float> planar, spheres;
    uint32_t planar_count = 0, sphere_count = 0;

    uint32_t planar_rows() const { return test == TriangleTest::watertight ? kWatertightRows : kMollerTrumboreRows; }
    // Room for `planar` planar primitives and `spheres` spheres.
    void reserve(std::size_t planar_prims, std::size_t sphere_prims);
    // Appends one leaf: scene primitives ids[0 .. count), all planar or all spheres.
    void append_leaf(const Scene& scene, const uint32_t* ids, uint32_t count, bool sphere);
    std::size_t bytes() const { return (planar.size() + spheres.size()) * sizeof(float); }
};

}  // namespace wt
