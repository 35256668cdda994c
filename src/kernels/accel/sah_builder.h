#pragma once
// The binary tree the wide BVH is collapsed from: binned SAH over all three axes (Wald 2007,
// "On fast construction of SAH-based bounding volume hierarchies"), leaves of one primitive kind.
//
// Deterministic: every split depends on the primitives alone (bin counts and boxes are sums and
// min/max, exact in any order), so the tree's shape is the same for any thread count. Node
// indices are handed out by an atomic counter and so depend on the schedule; nothing downstream
// sees them, since the wide nodes are laid out by a walk from the root (bvh_build.cpp).

#include <cstdint>
#include <memory>
#include <vector>

#include "core/base/aligned_vector.h"
#include "kernels/accel/bvh_boxes.h"

namespace wt {

class ThreadPool;

// A primitive as the builder sees it: its box, its scene id, its kind (BvhLeafKind) and the bin
// the last binning put it in on each axis (the partition that follows reads it instead of
// computing it again), laid out so each half loads as one SSE register. 32 bytes, moved by the
// partitions.
struct alignas(16) PrimRef {
    float lo[3];
    uint32_t id;
    float hi[3];
    uint8_t kind;
    uint8_t bin[3];

    // The corners with their fourth lanes zeroed. Those lanes hold the id, the kind and the
    // bins, which read as floats are mostly denormals (every id below 2^23), and arithmetic on
    // a denormal takes a microcode assist of a hundred cycles or more on Intel cores: carried
    // into the boxes and centroids, they slowed every split search (bench/README.md, "Issue
    // 18: the build against Embree's").
    __m128 lo_xyz() const { return _mm_and_ps(_mm_load_ps(lo), xyz_mask()); }
    __m128 hi_xyz() const { return _mm_and_ps(_mm_load_ps(hi), xyz_mask()); }
    Box box() const { return Box::of(lo_xyz(), hi_xyz()); }
    __m128 centroid_times_two() const { return _mm_add_ps(lo_xyz(), hi_xyz()); }

private:
    static __m128 xyz_mask() { return _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0)); }
};

// Filled in parallel, every element written: not zeroed first on one thread.
using PrimRefs = UninitialisedVector<PrimRef>;

// Plain registers rather than a Box, so an array of them is not initialised when allocated:
// the builder allocates room for 2n - 1 nodes and touches only those it makes.
struct BinaryNode {
    __m128 lo, hi;          // the box
    uint32_t first, count;  // a leaf: refs [first, first + count); count == 0 for an inner node
    union {
        uint32_t left;       // an inner node's children: left and right
        uint32_t leaf_kind;  // a leaf's BvhLeafKind, so the collapse need not read it from a ref
    };
    uint32_t right;
    bool is_leaf() const { return count > 0; }
    Box box() const { return Box::of(lo, hi); }
};

// Costs of the surface-area heuristic. A leaf is tested `leaf_block` primitives at a time (one
// 8-lane SIMD test on AVX2 and AVX-512), so its cost is its number of blocks, not of primitives:
// with the classic per-primitive cost the builder split down to leaves of about two triangles
// and the tree had three times the nodes. Chosen by measurement (bench/README.md): leaves
// counted in blocks of 8 and a node visit costing one block test gave the fastest traversal of
// those tried, and the fastest build, since the tree stops splitting earlier.
struct SahSettings {
    uint32_t max_leaf_size = 8;
    uint32_t leaf_block = 8;  // a power of two
    float node_cost = 1.0f;       // one visit of a binary node, in block tests
    float primitive_cost = 1.0f;  // one block test
};

struct BinaryTree {
    std::unique_ptr<BinaryNode[]> nodes;
    uint32_t root = 0;
    uint32_t max_depth = 0;  // in nodes, root = 1
};

// Reorders `refs` so every leaf is a contiguous run.
BinaryTree build_binary_sah(PrimRefs& refs, const SahSettings& settings, ThreadPool& pool);

}  // namespace wt
