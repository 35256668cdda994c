#pragma once
// The scene's primitives copied into BVH leaf blocks (bvh_view.h), holding only what the
// scene's primitive tests read (v0, the edges and the scaled normal for Moller-Trumbore; the
// three vertices for the watertight test; centre and radius for spheres) and each one's scene
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
    AlignedVector<float> blocks;

    uint32_t rows() const { return test == TriangleTest::watertight ? kWatertightRows : kMollerTrumboreRows; }
    void resize(std::size_t primitives) { blocks.resize(primitives * rows()); }
    // A primitive's block rows but the id, record_size() floats. The builder writes every
    // primitive's record in scene id order, reading the scene's arrays in order, so that filling
    // the leaves, which visit the primitives in tree order, reads one record per primitive
    // instead of one cache line from each of a dozen arrays.
    uint32_t record_size() const { return rows() - 1; }
    void write_record(const TriangleSoA& triangles, const SphereSoA& spheres, std::size_t id, float* out) const;
    // Writes the block of the leaf whose primitives, scene ids ids[0 .. count), start at index
    // `first`; all of one kind.
    void fill_leaf(const float* records, uint32_t first, const uint32_t* ids, uint32_t count, bool spheres);
    std::size_t bytes() const { return blocks.size() * sizeof(float); }
};

}  // namespace wt
