#include "kernels/accel/bvh.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "core/system/thread_pool.h"
#include "kernels/accel/bvh_boxes.h"
#include "kernels/accel/bvh_collapse.h"
#include "kernels/accel/sah_builder.h"
#include "kernels/primitives/triangle_rows.h"

namespace wt {
namespace {

// Slivers are stored collapsed onto their first vertex (geometry_soa.h): no test can hit them,
// so they stay out of the tree.
bool never_hit(const TriangleSoA& t, std::size_t i) { return t.i1[i] == t.i0[i] && t.i2[i] == t.i0[i]; }

PrimRef make_ref(const Box& box, uint32_t id, BvhLeafKind kind) {
    PrimRef r;
    _mm_store_ps(r.lo, box.lo);
    _mm_store_ps(r.hi, box.hi);
    r.id = id;
    r.kind = uint8_t(kind);
    return r;
}

PrimRef triangle_ref(const TriangleSoA& t, std::size_t i) {
    // The corners as the tests see them: v0 + u e1 + v e2 over the triangle or the unit
    // square, and the vertices the watertight test reads.
    Box box;
    const auto [v0, e1, e2] = t.corner(i);
    box.extend_point(v0), box.extend_point(t.has_vertices() ? t.position(t.i1[i]) : v0 + e1);
    box.extend_point(t.has_vertices() ? t.position(t.i2[i]) : v0 + e2);
    box.extend_point(v0 + e1), box.extend_point(v0 + e2);
    const bool parallelogram = t.is_parallelogram(i);
    if (parallelogram) box.extend_point(v0 + e1 + e2);
    return make_ref(box, uint32_t(i), parallelogram ? BvhLeafKind::parallelogram : BvhLeafKind::triangle);
}

// In scene id order, in parallel over fixed chunks: count what each chunk keeps, then fill.
// The first `beside` triangles stay out (tested beside the tree).
PrimRefs primitive_refs(const TriangleSoA& t, const SphereSoA& s, uint32_t beside, ThreadPool& pool) {
    constexpr std::size_t kChunk = 1 << 16;
    const std::size_t chunks = (t.size() + kChunk - 1) / kChunk;
    std::vector<std::size_t> kept(chunks + 1, 0);
    pool.parallel_for(chunks, [&](std::size_t c, int) {
        for (std::size_t i = c * kChunk; i < std::min(t.size(), (c + 1) * kChunk); ++i) kept[c + 1] += i >= beside && !never_hit(t, i);
    });
    for (std::size_t c = 0; c < chunks; ++c) kept[c + 1] += kept[c];
    PrimRefs refs(kept[chunks] + s.size());
    pool.parallel_for(chunks, [&](std::size_t c, int) {
        std::size_t out = kept[c];
        for (std::size_t i = c * kChunk; i < std::min(t.size(), (c + 1) * kChunk); ++i)
            if (i >= beside && !never_hit(t, i)) refs[out++] = triangle_ref(t, i);
    });
    for (std::size_t i = 0; i < s.size(); ++i) {
        const glm::vec3 c = s.center(i), r(s.radius[i]);
        Box box;
        box.extend_point(c - r), box.extend_point(c + r);
        refs[kept[chunks] + i] = make_ref(box, uint32_t(t.size() + i), BvhLeafKind::sphere);
    }
    return refs;
}

// The leaves' primitive data, in parallel over fixed chunks of leaves. `ids`: the scene ids in
// leaf order (a leaf reference's first primitive indexes it).
void fill_leaf_blocks(const TriangleSoA& t, const SphereSoA& s, const std::vector<uint32_t>& ids,
                      const std::vector<uint32_t>& leaves, BvhPrimitives& primitives, ThreadPool& pool) {
    primitives.resize(ids.size());
    constexpr std::size_t kLeavesPerJob = 4096;
    const auto each_triangle_of = [&](std::size_t leaf, auto&& visit) {
        const uint32_t first = leaves[leaf] & kBvhFirstMask;
        const uint32_t count = ((leaves[leaf] >> kBvhCountShift) & 7u) + 1u;
        for (uint32_t k = first; k < first + count; ++k)
            if (ids[k] < t.size()) visit(ids[k]);
    };
    // A triangle's rows are read through its vertex indices, two dependent cache misses in leaf
    // order (which is not id order): the indices are fetched two leaves ahead, the vertices one.
    const auto prefetch_indices = [&](uint32_t id) {
        __builtin_prefetch(&t.i0[id]), __builtin_prefetch(&t.i1[id]), __builtin_prefetch(&t.i2[id]);
    };
    const auto prefetch_vertices = [&](uint32_t id) {
        for (const uint32_t v : {t.i0[id], t.i1[id], t.i2[id]})
            __builtin_prefetch(&t.px[v]), __builtin_prefetch(&t.py[v]), __builtin_prefetch(&t.pz[v]);
    };
    pool.parallel_for((leaves.size() + kLeavesPerJob - 1) / kLeavesPerJob, [&](std::size_t job, int) {
        const std::size_t end = std::min(leaves.size(), (job + 1) * kLeavesPerJob);
        for (std::size_t i = job * kLeavesPerJob; i < end; ++i) {
            if (i + 2 < end) each_triangle_of(i + 2, prefetch_indices);
            if (i + 1 < end) each_triangle_of(i + 1, prefetch_vertices);
            const uint32_t first = leaves[i] & kBvhFirstMask;
            const uint32_t count = ((leaves[i] >> kBvhCountShift) & 7u) + 1u;
            primitives.fill_leaf(t, s, first, ids.data() + first, count);
        }
    });
}

// The wide nodes, and the leaves' references for fill_leaf_blocks.
template <int W>
uint32_t collapse(const BinaryTree& tree, const PrimRefs& refs, float pad, AlignedVector<BvhNode<W>>& nodes,
                  std::vector<uint32_t>& leaves, BvhStats& stats) {
    nodes.reserve(refs.size() / 4 + 1);
    WideCollapser<W> c(tree, pad, nodes);
    const uint32_t root = c.emit(tree.root);
    leaves = std::move(c.leaves);
    stats.leaf_count = leaves.size();
    stats.node_count = nodes.size();
    // Expected node visits plus primitive tests of a ray that hits the scene's box (the SAH of
    // the wide tree with unit costs): what the build options trade against build time.
    const double root_area = std::max(double(tree.nodes[tree.root].box().half_area()), 1e-30);
    stats.sah_cost = (c.node_area_sum + c.leaf_area_sum) / root_area;
    return root;
}

}  // namespace

Bvh build_bvh(const Scene& scene, const BvhBuildOptions& options, ThreadPool* pool) {
    return build_bvh(scene.triangles, scene.spheres, scene.settings.accuracy.triangles, scene.camera.eye(), options, pool);
}

Bvh build_bvh(const TriangleSoA& triangles, const SphereSoA& spheres, TriangleTest test, const glm::vec3& eye,
              const BvhBuildOptions& options, ThreadPool* pool) {
    if (!triangles.serves(test))
        throw std::invalid_argument(std::string("BVH: the triangles were stored for another triangle test than ") + name_of(test));
    if (options.node_width != 4 && options.node_width != 8)
        throw std::invalid_argument("BVH: node width must be 4 or 8, got " + std::to_string(options.node_width));
    if (options.max_leaf_size < 1 || options.max_leaf_size > int(kBvhMaxLeafSize))
        throw std::invalid_argument("BVH: leaf size must be 1 ... 8, got " + std::to_string(options.max_leaf_size));
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<ThreadPool> own_pool;
    if (!pool) {
        const int threads = options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
        own_pool = std::make_unique<ThreadPool>(threads);
        pool = own_pool.get();
    }

    Bvh bvh;
    bvh.node_width_ = options.node_width;
    bvh.primitives_.test = test;
    // A few parallelograms (a room's walls) are tested beside the tree, from rows of their own.
    const bool beside = options.parallelograms_beside && test == TriangleTest::moller_trumbore &&
                        triangles.parallelogram_count > 0 && triangles.parallelogram_count <= kBvhMostBeside;
    if (beside) {
        bvh.beside_ = triangle_rows(triangles, triangles.parallelogram_count);
        bvh.stats_.beside_count = triangles.parallelogram_count;
    }
    PrimRefs refs = primitive_refs(triangles, spheres, uint32_t(bvh.stats_.beside_count), *pool);
    const std::size_t primitive_count = refs.size();
    if (primitive_count > kBvhMaxLeafPrimitives)
        throw std::invalid_argument("BVH: " + std::to_string(primitive_count) + " primitives, more than the " +
                                    std::to_string(kBvhMaxLeafPrimitives) + " its leaf references can index");
    if (primitive_count > 0) {
        std::vector<uint32_t> leaves, ids(primitive_count);
        {
            SahSettings sah;
            sah.max_leaf_size = uint32_t(options.max_leaf_size);
            const BinaryTree tree = build_binary_sah(refs, sah, *pool);
            // The wide tree is no deeper than the binary one it is collapsed from.
            if (tree.max_depth * uint32_t(options.node_width - 1) + 1 > uint32_t(kBvhStackSize))
                throw std::invalid_argument("BVH: tree too deep for the traversal stack (" + std::to_string(tree.max_depth) +
                                            " levels)");
            bvh.stats_.max_depth = tree.max_depth;
            const float pad = rounding_pad(tree.nodes[tree.root].box(), eye);
            bvh.root_ = options.node_width == 4 ? collapse<4>(tree, refs, pad, bvh.nodes4_, leaves, bvh.stats_)
                                                : collapse<8>(tree, refs, pad, bvh.nodes8_, leaves, bvh.stats_);
            for (std::size_t i = 0; i < primitive_count; ++i) ids[i] = refs[i].id;
            // The binary tree and the references (36 bytes a primitive) go before the leaf
            // blocks are allocated: the build's peak of memory is while they are filled.
            PrimRefs().swap(refs);
        }
        fill_leaf_blocks(triangles, spheres, ids, leaves, bvh.primitives_, *pool);
    } else {
        // Nothing to hit: the root is one node whose every slot is empty, which the traversals
        // walk as any node, instead of a leaf reference that names no block. (A ray with a zero
        // direction component can still enter an empty slot through the slab test's NaN: the
        // leaf test then ignores it, but forms its pointer first; clang's UBSan reports that.)
        const auto add_empty_root = [&](auto& nodes) {
            nodes.emplace_back();
            for (int row = 0; row < 6; ++row)  // min rows +inf, max rows -inf: an empty box
                for (float& bound : nodes[0].bounds[row]) bound = (row & 1) ? -INFINITY : INFINITY;
            for (uint32_t& child : nodes[0].child) child = kBvhEmptyChild;
        };
        if (options.node_width == 4) add_empty_root(bvh.nodes4_);
        else add_empty_root(bvh.nodes8_);
        bvh.root_ = 0;
    }
    bvh.stats_.primitive_count = primitive_count;
    bvh.stats_.node_bytes = bvh.nodes4_.size() * sizeof(BvhNode<4>) + bvh.nodes8_.size() * sizeof(BvhNode<8>);
    bvh.stats_.primitive_bytes = bvh.primitives_.bytes();
    bvh.stats_.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return bvh;
}

BvhView bvh_view(const Bvh& bvh) {
    BvhView v;
    v.node_width = uint32_t(bvh.node_width_);
    v.nodes = bvh.node_width_ == 4 ? static_cast<const void*>(bvh.nodes4_.data()) : static_cast<const void*>(bvh.nodes8_.data());
    v.root = bvh.root_;
    v.max_depth = bvh.stats_.max_depth;
    v.leaves = bvh.primitives_.blocks.data();
    v.leaf_rows = bvh.primitives_.rows();
    v.leaf_vertices = bvh.primitives_.test == TriangleTest::watertight;
    v.beside = triangle_view(bvh.beside_);
    v.beside_count = uint32_t(bvh.stats_.beside_count);
    v.prefetch_pushed = bvh.stats_.node_bytes + bvh.stats_.primitive_bytes > kBvhPrefetchBytes;
    return v;
}

}  // namespace wt
