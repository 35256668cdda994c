#pragma once
// A bounding volume hierarchy over a scene's triangles, parallelograms and spheres: W-wide
// nodes (W = 4 or 8) with their children's boxes stored SoA, leaves of at most 8 primitives of
// one kind, and the primitives copied into leaf order in the layout the SIMD tests read.
//
// Built by binned SAH over all three axes (Wald 2007, "On fast construction of SAH-based
// bounding volume hierarchies") into a binary tree, then collapsed into wide nodes by opening
// the largest child first (as Embree's BVH4/8 builders do). The build is deterministic: every
// decision depends on the primitives alone and the wide nodes are laid out by one walk from the
// root, so the tree is the same for any thread count and images stay bit-identical.
//
// Boxes are padded outward by a bound on the rounding error of the primitive tests, so a hit
// the flat kernels report is never in a box the traversal rejects (see bvh_boxes.h).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/base/aligned_vector.h"
#include "core/scene/scene.h"
#include "kernels/accel/bvh_primitives.h"
#include "kernels/accel/bvh_view.h"
#include "kernels/primitives/triangle_rows.h"

namespace wt {

class ThreadPool;

// Scenes with at most this many parallelograms test them beside the tree (BvhView::beside).
constexpr uint32_t kBvhMostBeside = 16;
// Trees of more bytes (nodes and leaf blocks) are walked with prefetches (BvhView::prefetch_pushed).
// A tree that mostly stays in the caches pays for the instructions and gains nothing; chosen
// between two trees measured on either side (bench/README.md, "Issue 18: the build against
// Embree's; prefetching for shadow rays").
constexpr std::size_t kBvhPrefetchBytes = std::size_t(16) << 20;

struct BvhBuildOptions {
    int node_width = 8;     // children per node: 4 or 8
    int max_leaf_size = 8;  // primitives per leaf, 1 ... 8
    int threads = 0;        // 0: one per hardware thread; the tree is the same for any count
    // Up to kBvhMostBeside parallelograms tested flat beside the tree instead of in it.
    bool parallelograms_beside = true;
};

struct BvhStats {
    std::size_t primitive_count = 0;  // primitives in the tree (slivers, never hit, are left out)
    std::size_t beside_count = 0;     // parallelograms tested beside it
    std::size_t node_count = 0;
    std::size_t leaf_count = 0;
    uint32_t max_depth = 0;
    double sah_cost = 0.0;           // expected node and primitive tests per ray (see bvh_build.cpp)
    double build_seconds = 0.0;
    std::size_t node_bytes = 0;       // the wide nodes
    std::size_t primitive_bytes = 0;  // the leaf-ordered primitive copies and their ids
};

class Bvh {
public:
    Bvh() = default;
    const BvhStats& stats() const { return stats_; }
    int node_width() const { return node_width_; }

private:
    friend Bvh build_bvh(const TriangleSoA&, const SphereSoA&, TriangleTest, const glm::vec3&, const BvhBuildOptions&, ThreadPool*);
    friend BvhView bvh_view(const Bvh&);

    int node_width_ = 8;
    uint32_t root_ = kBvhEmptyChild;
    AlignedVector<BvhNode<4>> nodes4_;  // the one of the two that node_width_ names
    AlignedVector<BvhNode<8>> nodes8_;
    BvhPrimitives primitives_;
    TriangleRows beside_;  // the scene's first stats_.beside_count entries, its parallelograms
    BvhStats stats_;
};

// Builds on `pool` when given (the renderer's), else on a pool of options.threads threads.
// Throws std::invalid_argument for bad options or a scene too large to index.
Bvh build_bvh(const Scene& scene, const BvhBuildOptions& options = {}, ThreadPool* pool = nullptr);
// Over any primitive arrays (an instanced mesh's, in object space). `eye`: the point farthest
// from the origin, per axis, that rays start from, which sizes the boxes' rounding pad.
Bvh build_bvh(const TriangleSoA& triangles, const SphereSoA& spheres, TriangleTest test, const glm::vec3& eye,
              const BvhBuildOptions& options, ThreadPool* pool);

BvhView bvh_view(const Bvh& bvh);

}  // namespace wt

