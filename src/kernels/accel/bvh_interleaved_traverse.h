#pragma once
// Several rays' walks through a tree far larger than the caches, taken a step at a time in
// turn, so the cache misses of one walk overlap the work of the others.
//
// A single walk spends most of its time waiting: the first load of each node and of each leaf
// block misses, and the walk cannot know what it will load next before that load returns.
// K walks are independent, so each step ends by asking for the lines of what its walk visits
// next (prefetch_ref) and hands over to the next walk; by the time the turn comes
// back, those lines are on their way or there. The idea is that of interleaved lookups in
// database indexes (Chen, Ailamaki, Gibbons and Mowry, "Improving hash join performance through
// prefetching", ICDE 2004; Psaropoulos et al., "Interleaving with coroutines", VLDB 2017),
// applied to the same walk (walk_step, bvh_traverse.h) one ray at a time takes: every ray visits
// the same nodes and leaves in the same order, so its answer is the same bits.

#include <cstdint>
#include <new>

#include "kernels/accel/bvh_traverse.h"
#include "kernels/accel/bvh_view.h"
#include "kernels/accel/query.h"
#include "kernels/accel/single_ray.h"
#include "kernels/primitives/soa_views.h"

namespace wt::packet {
inline namespace WT_SIMD_ISA {

// Walks in flight: enough steps of other walks to cover a miss to memory, few enough that
// their rays and the tops of their stacks stay in L1.
inline constexpr int kInterleavedWalks = 8;

// One ray in flight: what trace_one keeps in registers, kept here between its steps.
template <TriangleTest T, Query Q, int W, int V, int L>
struct RayInFlight {
    uint32_t index;  // in the queue
    SingleRay<L> ray;
    TriangleRays<T, L> tri_ray;
    BoxRay<V> box_ray;
    SingleRayState<Q, L> state;
    uint32_t ref;  // the walk's (walk_step, bvh_traverse.h)
    int top = 0;
    WalkStack stack;

    WT_KERNEL_INLINE RayInFlight(const BvhView& bvh, const RayView& rays, uint32_t i)
        : index(i),
          ray(broadcast_ray<L>(rays, i)),
          tri_ray(ray.o, ray.d),
          box_ray(rays, i),
          state(ray.tmax),
          ref(bvh.root) {}
};

// As trace_bvh_rays (bvh_traverse.h), the walks of kInterleavedWalks rays at a time.
template <Query Q, TriangleTest T, SphereTest S, int W, int MaxWidth>
void trace_bvh_rays_interleaved(const BvhView& bvh, const RayView& rays, QueryOutput<Q> out) {
    constexpr int V = kNodeLanes<W, MaxWidth>, L = kLeafLanes<MaxWidth>;
    using Walker = RayInFlight<T, Q, W, V, L>;
    const BvhNode<W>* nodes = static_cast<const BvhNode<W>*>(bvh.nodes);
    // Raw storage: each slot is constructed anew for every ray it takes.
    alignas(Walker) unsigned char storage[kInterleavedWalks][sizeof(Walker)];
    Walker* flight[kInterleavedWalks];
    uint32_t next = 0;
    // Starts ray `next` in `slot`, its walk's first step being the root (which stays cached).
    const auto start = [&](unsigned char* slot) __attribute__((always_inline)) {
        Walker* w = new (slot) Walker(bvh, rays, next++);
        if constexpr (Q == Query::closest) test_beside<T>(bvh, w->tri_ray, w->state);  // never done() for closest
        return w;
    };
    int live = 0;
    for (; live < kInterleavedWalks && next < rays.count; ++live) flight[live] = start(storage[live]);
    while (live > 0) {
        for (int k = 0; k < live;) {
            Walker& w = *flight[k];
            const auto test = [&](uint32_t ref) __attribute__((always_inline)) {
                test_leaf<T, S, L>(bvh, ref, w.ray, w.tri_ray, w.state);
            };
            const auto prefetch_leaf = [&](uint32_t ref) __attribute__((always_inline)) { prefetch_leaf_block<T>(bvh, ref); };
            if (walk_step<Q, W, V, Q == Query::any>(nodes, w.ref, w.top, w.stack, w.box_ray, w.state, test, prefetch_leaf)) {
                prefetch_ref<W>(nodes, w.ref, prefetch_leaf);
                ++k;
                continue;
            }
            if constexpr (Q == Query::any)
                if (!w.state.done()) test_beside<T>(bvh, w.tri_ray, w.state);
            w.state.write(out, w.index);
            unsigned char* slot = reinterpret_cast<unsigned char*>(&w);
            if (next < rays.count) {
                flight[k] = start(slot);
                ++k;
            } else {
                flight[k] = flight[--live];  // k's turn goes to the last walk, which has not had this round's
            }
        }
    }
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::packet
