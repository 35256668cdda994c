#pragma once
// One ray at a time through the wide BVH (bvh.h), written once for both queries and both node
// widths: the ray is tested against all W children of a node with vfloat loads, the children it
// enters are visited nearest first (closest hit) and a leaf is one SoA primitive test
// (single_ray.h), so a leaf returns exactly what the flat kernels return for its primitives.
//
// Nothing the flat kernels hit is lost: the far slab distance is scaled by 1 + 2 gamma(3) (Ize,
// "Robust BVH Ray Traversal", JCGT 2013) against the rounding of the slab arithmetic, and boxes
// are padded by 64 float steps of the scene's coordinates (bvh_boxes.h), more than both the
// primitive tests' rounding and that of the slab distances in their FMA form bound/d - o/d,
// whose o/d is rounded once per ray (a step of |o| along the ray at most).

#include <cstdint>
#include <type_traits>

#include "core/base/accuracy.h"
#include "kernels/accel/bvh_view.h"
#include "kernels/accel/query.h"
#include "kernels/accel/single_ray.h"
#include "kernels/primitives/lanes.h"
#include "kernels/primitives/soa_views.h"

namespace wt::packet {
inline namespace WT_SIMD_ISA {

// 1 + 2 gamma(3), gamma(n) = n u / (1 - n u), u = 2^-24 (Ize 2013, section 3), rounded up.
inline constexpr float kRobustFarScale = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f) + 0x1p-23f;

// The ray as the box test reads it: the origin, 1/d, and per axis which bound row is the near
// one (min when the direction is positive, max when it is negative, by its sign bit, so -0
// pairs with 1/-0 = -inf consistently).
template <int V>
struct BoxRay {
    vfloat<V> o_inv_d[3], inv_d[3];  // slab distance t = bound * inv_d - o_inv_d: one FMA
    int near_row[3], far_row[3];

    [[gnu::always_inline]] BoxRay(const RayView& rays, uint32_t i) {
        const float o_[3] = {rays.ox[i], rays.oy[i], rays.oz[i]};
        const float d_[3] = {rays.dx[i], rays.dy[i], rays.dz[i]};
        for (int a = 0; a < 3; ++a) {
            const float inv = 1.0f / d_[a];
            inv_d[a] = vfloat<V>(inv);
            o_inv_d[a] = vfloat<V>(o_[a] * inv);
            const bool negative = __builtin_signbit(d_[a]);
            near_row[a] = 2 * a + int(negative);
            far_row[a] = 2 * a + 1 - int(negative);
        }
    }
};

// Which children the ray enters at t in [0, limit]; their entry distances go to t_near.
// A slab that comes out NaN (inf - inf: a direction with a zero component, 1/d infinite, and a
// bound or origin at 0 or infinite) is dropped by the NaN rule of simd::min / max (NaN first
// loses), which only widens the interval.
template <int W, int V>
WT_KERNEL_INLINE uint32_t enter_children(const BvhNode<W>& node, const BoxRay<V>& r, float limit, float* t_near) {
    uint32_t mask = 0;
    for (int c = 0; c < W; c += V) {
        vfloat<V> near[3], far[3];
        for (int a = 0; a < 3; ++a) {
            near[a] = simd::msub(vfloat<V>::loadu(&node.bounds[r.near_row[a]][c]), r.inv_d[a], r.o_inv_d[a]);
            far[a] = simd::msub(vfloat<V>::loadu(&node.bounds[r.far_row[a]][c]), r.inv_d[a], r.o_inv_d[a]);
        }
        const vfloat<V> enter = simd::max(simd::max(near[0], near[1]), simd::max(near[2], vfloat<V>(0.0f)));
        const vfloat<V> leave =
            simd::min(simd::min(simd::min(far[0], far[1]), far[2]) * vfloat<V>(kRobustFarScale), vfloat<V>(limit));
        mask |= simd::movemask(enter <= leave) << c;
        vfloat<V>::storeu(t_near + c, enter);
    }
    return mask;
}

template <TriangleTest T, SphereTest S, int L, typename State>
WT_KERNEL_INLINE void test_leaf(const BvhView& bvh, uint32_t ref, const SingleRay<L>& ray, const TriangleRays<T, L>& tri_ray,
                      State& state) {
    const uint32_t first = ref & kBvhFirstMask;
    const uint32_t count = ((ref >> kBvhCountShift) & 7u) + 1u;
    constexpr uint32_t rows = T == TriangleTest::watertight ? kWatertightRows : kMollerTrumboreRows;
    const float* block = bvh.leaves + std::size_t(first) * rows;
    const TriangleBlock<T> triangles{block, count};
    switch (BvhLeafKind((ref >> kBvhKindShift) & 3u)) {
        case BvhLeafKind::parallelogram:
            // Only Moller-Trumbore scenes have parallelograms (build_scene splits quads otherwise).
            if constexpr (T == TriangleTest::moller_trumbore)
                test_planar_run<Planar::parallelogram>(tri_ray, triangles, count, state);
            break;
        case BvhLeafKind::triangle:
            test_planar_run<Planar::triangle>(tri_ray, triangles, count, state);
            break;
        case BvhLeafKind::sphere:
            test_sphere_run<S>(ray, SphereBlock{block, count}, count, state);
            break;
        default:  // kBvhEmptyChild: the root of a scene with nothing to hit
            break;
    }
}

// Descending by distance, so the nearest child is on top of the stack. At most W entries.
// Ref: a child reference, or one with what the walk keeps beside it (bvh_packet_traverse.h).
template <typename Ref>
WT_KERNEL_INLINE void sort_far_to_near(Ref* refs, float* t, int count) {
    for (int i = 1; i < count; ++i) {
        const Ref r = refs[i];
        const float ti = t[i];
        int j = i - 1;
        for (; j >= 0 && t[j] < ti; --j) refs[j + 1] = refs[j], t[j + 1] = t[j];
        refs[j + 1] = r, t[j + 1] = ti;
    }
}

// Asks for all of an inner node's cache lines, ahead of its visit.
template <int W>
WT_KERNEL_INLINE void prefetch_node(const BvhNode<W>* nodes, uint32_t ref) {
    const char* p = reinterpret_cast<const char*>(nodes + ref);
    for (int line = 0; line < int(sizeof(BvhNode<W>)) / 64; ++line) __builtin_prefetch(p + 64 * line);
}

struct NoLeafPrefetch {
    void operator()(uint32_t) const {}
};

// The entries a walk has left for later, with their entry distances (the walk's `top` counts them).
struct WalkStack {
    uint32_t ref[kBvhStackSize];
    float t[kBvhStackSize];
};

// Asks for the lines of `child`: all of an inner node's, or prefetch_leaf(child) for a leaf.
template <int W, typename PrefetchLeaf>
WT_KERNEL_INLINE void prefetch_ref(const BvhNode<W>* nodes, uint32_t child, PrefetchLeaf&& prefetch_leaf) {
    if (!(child & kBvhLeafBit)) prefetch_node<W>(nodes, child);
    else if (child != kBvhEmptyChild) prefetch_leaf(child);
}

// One ray's walk of one tree, a node visit or a leaf test at a time: nearest child first for
// closest hits, test_leaf(ref) at each leaf it reaches, over when the state says so. The flat
// tree's leaves are primitive blocks; the instances' top level's leaves are instances, each of
// which walks its mesh's tree the same way. traverse_tree takes the steps of one walk in a row;
// bvh_interleaved_traverse.h takes those of several walks in turn.
//
// One step visits `ref` and moves it to what comes next; false when the walk is over. `ref`
// and `top` are the caller's, so a walk taken in one go keeps them in registers.
//
// Prefetch: an occlusion walk asks for the lines of each child it pushes (prefetch_leaf(ref)
// for a leaf's block). Its stack is not sorted, and unless a blocker is found every entry is
// visited, so the lines are wanted soon; asking while pushing lets the misses of a node's
// entered children overlap. A closest-hit walk may skip its far entries, and does not ask.
// A template argument, not a run-time flag: the walks of trees that fit in the caches stay
// exactly as they were.
template <Query Q, int W, int V, bool Prefetch, typename State, typename TestLeaf, typename PrefetchLeaf>
WT_KERNEL_INLINE bool walk_step(const BvhNode<W>* nodes, uint32_t& ref, int& top, WalkStack& stack, const BoxRay<V>& box_ray,
                                State& state, TestLeaf&& test_leaf, PrefetchLeaf&& prefetch_leaf) {
    const auto prefetch = [&](uint32_t child) __attribute__((always_inline)) {
        if constexpr (Q == Query::any && Prefetch) prefetch_ref<W>(nodes, child, prefetch_leaf);
    };
    if (!(ref & kBvhLeafBit)) {
        const BvhNode<W>& node = nodes[ref];
        alignas(64) float t_near[W];
        uint32_t mask = enter_children<W, V>(node, box_ray, state.closest, t_near);
        if (mask) {
            int c = __builtin_ctz(mask);
            mask &= mask - 1;
            if (!mask) {  // one child entered: no stack traffic
                ref = node.child[c];
                return true;
            }
            const int second = __builtin_ctz(mask);
            if (!(mask & (mask - 1))) {  // two: go to the nearer, keep the farther
                const bool first_nearer = !(t_near[second] < t_near[c]);
                const int near = first_nearer ? c : second, far = first_nearer ? second : c;
                stack.ref[top] = node.child[far], stack.t[top] = t_near[far], ++top;
                prefetch(node.child[far]);
                ref = node.child[near];
                return true;
            }
            const int base = top;
            stack.ref[top] = node.child[c], stack.t[top] = t_near[c], ++top;
            prefetch(node.child[c]);
            for (; mask; mask &= mask - 1) {
                c = __builtin_ctz(mask);
                stack.ref[top] = node.child[c], stack.t[top] = t_near[c], ++top;
                prefetch(node.child[c]);
            }
            // Nearest first pays for the closest hit: what it finds culls the rest. An
            // occlusion query stops at any blocker, so it skips the sort.
            if constexpr (Q == Query::closest) sort_far_to_near(stack.ref + base, stack.t + base, top - base);
            ref = stack.ref[--top];
            return true;
        }
    } else {
        test_leaf(ref);
        if (state.done()) return false;
    }
    // Next entry still nearer than the closest hit so far (entries were pushed with
    // t_near <= the closest at that time; a hit since may have passed them).
    do {
        if (top == 0) return false;
        --top;
    } while (!(stack.t[top] <= state.closest));
    ref = stack.ref[top];
    return true;
}

// One ray's walk of the tree `tree_nodes` from child reference `root`, its steps in a row.
template <Query Q, int W, int V, bool Prefetch = false, typename State, typename TestLeaf, typename PrefetchLeaf = NoLeafPrefetch>
WT_KERNEL_INLINE void traverse_tree(const void* tree_nodes, uint32_t root, const BoxRay<V>& box_ray, State& state,
                                    TestLeaf&& test_leaf, PrefetchLeaf prefetch_leaf = {}) {
    const BvhNode<W>* nodes = static_cast<const BvhNode<W>*>(tree_nodes);
    WalkStack stack;
    uint32_t ref = root;
    int top = 0;
    while (walk_step<Q, W, V, Prefetch>(nodes, ref, top, stack, box_ray, state, test_leaf, prefetch_leaf)) {
    }
}

// The parallelograms beside the tree (bvh_view.h): tested first for closest hits, where the wall
// a ray hits bounds its walk; last for any hits, whose walk they cannot shorten, so rays the
// tree blocks never test them.
template <TriangleTest T, int L, typename State>
WT_KERNEL_INLINE void test_beside(const BvhView& bvh, const TriangleRays<T, L>& tri_ray, State& state) {
    if constexpr (T == TriangleTest::moller_trumbore)
        if (bvh.beside_count > 0)
            test_planar_run<Planar::parallelogram>(tri_ray, FlatTriangles<T>{bvh.beside, 0}, bvh.beside_count, state);
}

// Asks for a leaf's whole block (the leaf test reads every row), line by line from the line
// holding its first byte: a block need not start on a line.
template <TriangleTest T>
WT_KERNEL_INLINE void prefetch_leaf_block(const BvhView& bvh, uint32_t ref) {
    constexpr uint32_t rows = T == TriangleTest::watertight ? kWatertightRows : kMollerTrumboreRows;
    const uint32_t count = ((ref >> kBvhCountShift) & 7u) + 1u;
    const uintptr_t block = reinterpret_cast<uintptr_t>(bvh.leaves + std::size_t(ref & kBvhFirstMask) * rows);
    const uintptr_t end = block + count * rows * uint32_t(sizeof(float));
    for (uintptr_t line = block & ~uintptr_t(63); line < end; line += 64) __builtin_prefetch(reinterpret_cast<const void*>(line));
}

// Prefetch: walk with prefetches (traverse_tree; chosen per queue from BvhView::prefetch_pushed).
template <TriangleTest T, SphereTest S, Query Q, int W, int V, int L, bool Prefetch = false, typename State>
WT_KERNEL_INLINE void trace_one(const BvhView& bvh, const RayView& rays, uint32_t i, State& state) {
    const SingleRay<L> ray = broadcast_ray<L>(rays, i);
    const TriangleRays<T, L> tri_ray(ray.o, ray.d);
    if constexpr (Q == Query::closest) {
        test_beside<T>(bvh, tri_ray, state);
        if (state.done()) return;
    }
    const BoxRay<V> box_ray(rays, i);
    traverse_tree<Q, W, V, Prefetch>(
        bvh.nodes, bvh.root, box_ray, state,
        [&](uint32_t ref) __attribute__((always_inline)) { test_leaf<T, S, L>(bvh, ref, ray, tri_ray, state); },
        [&](uint32_t ref) __attribute__((always_inline)) { prefetch_leaf_block<T>(bvh, ref); });
    if constexpr (Q == Query::any)
        if (!state.done()) test_beside<T>(bvh, tri_ray, state);
}

// Lanes of a leaf test (a leaf holds at most 8 primitives) and of a node's box test, for
// kernels at most MaxWidth wide.
template <int MaxWidth>
inline constexpr int kLeafLanes = MaxWidth < int(kBvhMaxLeafSize) ? MaxWidth : int(kBvhMaxLeafSize);
template <int W, int MaxWidth>
inline constexpr int kNodeLanes = MaxWidth < W ? MaxWidth : W;

// Each ray of the queue by itself: its query state from its tmax, trace(i, state), its answer.
template <Query Q, int MaxWidth, typename Trace>
WT_KERNEL_INLINE void for_each_ray(const RayView& rays, QueryOutput<Q> out, Trace&& trace) {
    for (uint32_t i = 0; i < rays.count; ++i) {
        SingleRayState<Q, kLeafLanes<MaxWidth>> state(rays.tmax ? rays.tmax[i] : kInfinity);
        trace(i, state);
        state.write(out, i);
    }
}

template <Query Q, TriangleTest T, SphereTest S, int W, int MaxWidth, bool Prefetch>
void trace_bvh_rays(const BvhView& bvh, const RayView& rays, QueryOutput<Q> out) {
    for_each_ray<Q, MaxWidth>(rays, out, [&](uint32_t i, auto& state) __attribute__((always_inline)) {
        trace_one<T, S, Q, W, kNodeLanes<W, MaxWidth>, kLeafLanes<MaxWidth>, Prefetch>(bvh, rays, i, state);
    });
}

// Calls f(std::integral_constant<int, W>) for the tree's node width W.
template <typename F>
WT_KERNEL_INLINE void with_node_width(const BvhView& bvh, F&& f) {
    if (bvh.node_width == 4)
        f(std::integral_constant<int, 4>{});
    else
        f(std::integral_constant<int, 8>{});
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::packet
