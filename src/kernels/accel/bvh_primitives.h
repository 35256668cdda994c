#pragma once
// The scene's primitives copied into BVH leaf blocks (bvh_view.h), holding only what the
// scene's primitive tests read (v0 and the edges for Moller-Trumbore, whose leaf test takes
// their cross product itself; the three vertices for the watertight test; centre and radius for spheres) and each one's scene
// id, so a leaf test returns the flat kernels' bits.

#include <cstddef>
#include <cstdint>

#include "core/base/accuracy.h"
#include "core/base/aligned_vector.h"
#include "core/scene/scene.h"
#include "kernels/accel/bvh_view.h"

namespace wt {

class ThreadPool;

struct BvhPrimitives {
    TriangleTest test = TriangleTest::moller_trumbore;
    UninitialisedVector<float> blocks;  // every float written by fill_leaf

    uint32_t rows() const { return test == TriangleTest::watertight ? kWatertightRows : kMollerTrumboreRows; }
    void resize(std::size_t primitives) { blocks.resize(primitives * rows()); }
    // Writes the block of the leaf whose primitives, scene ids ids[0 .. count), start at index
    // `first`; all of one kind. Read straight from the scene's indexed triangles: a copy of
    // every primitive's rows in id order would gather faster, but would be one more copy of the
    // geometry alive at the build's peak of memory.
    void fill_leaf(const TriangleSoA& triangles, const SphereSoA& spheres, uint32_t first, const uint32_t* ids, uint32_t count);
    std::size_t bytes() const { return blocks.size() * sizeof(float); }
};

}  // namespace wt
