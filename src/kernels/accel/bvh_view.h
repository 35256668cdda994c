#pragma once
// The BVH as the per-ISA traversal kernels read it: plain structs and constants, no inline
// functions and no STL (see soa_views.h for why the per-ISA translation units must not share
// inline code with the rest of the program).
//
// A node has W children (W = 4 or 8) whose boxes are stored axis by axis, W floats per bound,
// so one ray is tested against all W boxes with vfloat loads. The six bound rows are
// (min x, max x, min y, max y, min z, max z): a ray picks its near and far row per axis once,
// from the signs of its direction, and the box test has no per-lane min/max of the slabs
// (madmann91/bvh's octant trick).

#include <cstdint>

#include "kernels/primitives/soa_views.h"

namespace wt {

template <int W>
struct alignas(64) BvhNode {
    float bounds[6][W];  // rows: min x, max x, min y, max y, min z, max z; an empty slot is +inf..-inf
    uint32_t child[W];   // an inner node's index, or a leaf (kBvhLeafBit set), or kBvhEmptyChild
};

// A child reference: an inner node's index in the node array, or a leaf packed as
//   bit 31: leaf, bits 29-30: kind (BvhLeafKind), bits 26-28: primitive count - 1,
//   bits 0-25: index of its first primitive in leaf order (its block, below, starts there).
// Leaves hold one kind only, so the leaf test runs one straight-line primitive test.
enum class BvhLeafKind : uint32_t { parallelogram = 0, triangle = 1, sphere = 2 };
constexpr uint32_t kBvhLeafBit = 1u << 31;
constexpr uint32_t kBvhKindShift = 29;
constexpr uint32_t kBvhCountShift = 26;
constexpr uint32_t kBvhFirstMask = (1u << kBvhCountShift) - 1;
constexpr uint32_t kBvhMaxLeafSize = 8;
constexpr uint32_t kBvhEmptyChild = 0xFFFFFFFFu;  // kind 3: no primitive kind; its box is empty, so it is never entered
constexpr uint32_t kBvhMaxLeafPrimitives = kBvhFirstMask + 1;  // in one tree: 67,108,864
// Entries a traversal stack can need: the deepest path times the W - 1 siblings each node on it
// may leave behind, plus one. build_bvh refuses a tree deeper than this allows.
constexpr int kBvhStackSize = 1024;

// Leaf primitives are stored leaf by leaf, each leaf as one block: its k primitives row by row,
// k floats per row, the last row of the block their scene ids (as uint32 bits). A leaf test
// reads one small contiguous block (6.5 cache lines for 8 triangles) with the same SoA loads
// the flat kernels use on their arrays, instead of one cache line from each of 12 arrays.
// Every primitive has `leaf_rows` floats; a leaf whose first primitive has index i starts at
// float i * leaf_rows. A sphere leaf's block uses only its first kSphereRows rows.
// A Moller-Trumbore leaf holds no scaled normal: the leaf test takes cross(e1, e2) again, in
// glm::cross's order (lanes.h), so the same bits as the flat arrays' stored normal. In a tree
// far larger than the caches a walk waits for a leaf's lines, not for its arithmetic, and three
// rows fewer are a quarter fewer lines (6.5 to 5 for 8 triangles).
constexpr uint32_t kMollerTrumboreRows = 10;  // v0 xyz, e1 xyz, e2 xyz, id
constexpr uint32_t kWatertightRows = 10;      // v0 xyz, v1 xyz, v2 xyz, id
constexpr uint32_t kSphereRows = 5;           // centre xyz, radius, id

struct InstanceView;

// Whether a candidate hit on primitive `prim` at barycentrics (u, v) counts, for a scene with
// alpha-tested materials (core/scene/alpha_test.h: glTF's alphaMode MASK and BLEND). ray_key
// is the ray's own bits hashed (alpha_filter.h), the random number of a BLEND coin. Compiled
// once, outside the per-ISA kernels, so every ISA takes the same decisions.
using AlphaKeepsHit = bool (*)(const void* context, uint32_t prim, float u, float v, uint64_t ray_key);

struct BvhView {
    const void* nodes;    // BvhNode<node_width>[]
    uint32_t node_width;  // 4 or 8
    uint32_t root;        // child reference of the root (a leaf for a scene that fits in one)
    uint32_t max_depth;   // deepest leaf, in nodes: bounds the traversal stack
    const float* leaves;  // leaf blocks
    uint32_t leaf_rows;   // kMollerTrumboreRows or kWatertightRows, as the scene's triangle test
    bool leaf_vertices;   // the leaves hold v0 v1 v2 (watertight), not v0 e1 e2 (Moller-Trumbore)
    // The scene's instances (two-level traversal, instance_traverse.h), or null: a scene
    // without instances traces this tree alone, as before instances existed.
    const InstanceView* instances = nullptr;
    // The scene's parallelograms when it has only a few (its walls, floor and lights): tested
    // flat, SIMD, beside the tree, and left out of it. Boxes that big would each cover most of
    // the tree, and every ray would walk into them. Closest hits test them before the walk (the
    // one a ray hits bounds it), any hits after it. The BVH's copy of their rows (Bvh::beside_),
    // ids [0, beside_count). 0: the tree holds them.
    TriangleView beside{};
    uint32_t beside_count = 0;
    // The tree is far larger than the caches (kBvhPrefetchBytes): an occlusion walk asks for
    // each child's lines as it pushes it, so the misses of the siblings it will visit next
    // overlap instead of each waiting its turn (bvh_traverse.h).
    bool prefetch_pushed = false;
    // A scene with alpha-tested materials: every candidate hit is asked about first
    // (alpha_filter.h), one ray at a time. Null otherwise, and then no kernel asks.
    AlphaKeepsHit alpha_keeps = nullptr;
    const void* alpha_context = nullptr;
};

// One placement as the traversal reads it: world -> object (rows of the inverse's linear part
// and translation), the mesh whose tree it enters, and the id of that mesh's triangle 0.
struct InstanceRecord {
    float to_object[3][4];
    uint32_t mesh;
    uint32_t first_id;
};

// The top level: a tree of the same node width over the instances' world boxes, whose leaves
// index `records` (kept in leaf order) as the bottom level's index leaf blocks; and each mesh's
// own tree, in object space, its leaf ids counted from 0.
struct InstanceView {
    const void* nodes;  // BvhNode<node_width>[]
    uint32_t root;
    const InstanceRecord* records;
    const BvhView* meshes;
};

}  // namespace wt
