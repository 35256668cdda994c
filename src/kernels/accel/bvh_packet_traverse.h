#pragma once
// N rays at a time through the wide BVH, for coherent rays (camera rays): the packet visits a
// node when any of its active rays enters a child's box, and a leaf's primitives are tested
// against all N rays at once, one primitive broadcast at a time, as the flat ray-packet kernels
// do; a leaf of triangles that few of the rays entered, ray by ray against all its triangles
// at once, as the single-ray walk does. Incoherent rays would split the packet at once and pay
// for N rays at every node; they use one ray at a time (bvh_traverse.h). Returns the same bits as the other kernels: the same
// primitive tests, ties on t broken by primitive id, and the same conservative box test
// (Ize's far-slab factor, boxes padded for rounding).

#include <cstdint>
#include <type_traits>

#include "core/base/accuracy.h"
#include "kernels/accel/brute_force.h"
#include "kernels/accel/bvh_traverse.h"
#include "kernels/accel/bvh_view.h"
#include "kernels/accel/query.h"
#include "kernels/accel/single_ray.h"
#include "kernels/primitives/lanes.h"
#include "kernels/primitives/sphere_lanes.h"
#include "kernels/primitives/triangle_lanes.h"

namespace wt::packet {
inline namespace WT_SIMD_ISA {

// What a packet's query has found so far when the primitives come in tree order, not id order:
// closest hits compare (t, id) pairs, so a lane accepts a t equal to its best and lets the id
// decide. `reach()` is how far each lane still looks, for culling boxes.
template <Query Q, int N>
struct TreePacketState;

template <int N>
struct TreePacketState<Query::closest, N> : PacketState<Query::closest, N> {
    using Base = PacketState<Query::closest, N>;
    vfloat<N> tmax, limit_;

    [[gnu::always_inline]] explicit TreePacketState(const RayPacket<N>& r) : Base(r), tmax(r.tmax), limit_(r.tmax) {}
    const vfloat<N>& limit() const { return limit_; }
    const vfloat<N>& reach() const { return this->best.t; }
    [[gnu::always_inline]] void record(const vbool<N>& hit, const LaneHits<N>& h, const vint<N>& id) {
        const vbool<N> better = hit & ((h.t < this->best.t) | ((h.t == this->best.t) & (id < this->best_prim)));
        this->best = select(better, h, this->best);
        this->best_prim = simd::select(better, id, this->best_prim);
        // The float after the best t (finite and positive once a lane has a hit), so an equal
        // t still competes on its id; strictly below tmax while the lane has none.
        const vfloat<N> next_up = simd::asFloat(simd::asInt(this->best.t) + vint<N>(1));
        limit_ = simd::select(this->best_prim == vint<N>(-1), tmax, next_up);
    }
};

template <int N>
struct TreePacketState<Query::any, N> : PacketState<Query::any, N> {
    using PacketState<Query::any, N>::PacketState;
    const vfloat<N>& reach() const { return this->tmax; }
};

// One primitive of a leaf block, broadcast to every lane.
template <int N>
WT_KERNEL_INLINE Vec3<N> block_row(const float* block, uint32_t k, uint32_t row, uint32_t lane) {
    const float* p = block + row * k + lane;
    return {vfloat<N>(p[0]), vfloat<N>(p[k]), vfloat<N>(p[2 * k])};
}

WT_KERNEL_INLINE int32_t block_id(const float* block, uint32_t k, uint32_t id_row, uint32_t lane) {
    int32_t id;
    __builtin_memcpy(&id, block + id_row * k + lane, sizeof id);
    return id;
}

template <TriangleTest T, SphereTest S, Query Q, int N>
WT_KERNEL_INLINE void test_leaf_packet(const BvhView& bvh, uint32_t ref, const RayPacket<N>& r, const TriangleRays<T, N>& tr,
                                       TreePacketState<Q, N>& state) {
    constexpr uint32_t rows = T == TriangleTest::watertight ? kWatertightRows : kMollerTrumboreRows;
    const uint32_t first = ref & kBvhFirstMask;
    const uint32_t k = ((ref >> kBvhCountShift) & 7u) + 1u;
    const float* block = bvh.leaves + std::size_t(first) * rows;
    const BvhLeafKind kind = BvhLeafKind((ref >> kBvhKindShift) & 3u);
    if (kind == BvhLeafKind::sphere) {
        for (uint32_t l = 0; l < k && !state.done(); ++l) {
            vfloat<N> t;
            const vbool<N> hit = intersect_spheres<S>(r.o, r.d, block_row<N>(block, k, 0, l), vfloat<N>(block[3 * k + l]),
                                                      state.limit(), t);
            state.record(r.active & hit, sphere_hits(t), vint<N>(block_id(block, k, kSphereRows - 1, l)));
        }
        return;
    }
    auto test = [&](auto shape) {
        for (uint32_t l = 0; l < k && !state.done(); ++l) {
            TriangleLanes<N> tri;
            if constexpr (T == TriangleTest::watertight)
                tri = {block_row<N>(block, k, 0, l), block_row<N>(block, k, 3, l), block_row<N>(block, k, 6, l), {}};
            else
                tri = with_scaled_normal(block_row<N>(block, k, 0, l), block_row<N>(block, k, 3, l), block_row<N>(block, k, 6, l));
            LaneHits<N> h;
            const vbool<N> hit = intersect_triangles<shape.value>(tr, tri, r.active, state.limit(), h);
            state.record(r.active & hit, h, vint<N>(block_id(block, k, rows - 1, l)));
        }
    };
    if (kind == BvhLeafKind::triangle) test(PlanarShape<Planar::triangle>{});
    else if constexpr (T == TriangleTest::moller_trumbore)
        if (kind == BvhLeafKind::parallelogram) test(PlanarShape<Planar::parallelogram>{});
}

// One lane of a packet as test_planar_run's state (single_ray.h): a leaf's triangles against that
// lane's ray alone, every hit recorded into the packet's state as the packet's own test records
// it. The same primitive test per ray and triangle, and the same (t, id) comparison: the same bits.
// The limit is the lane's, read again after each group of triangles tested together; a hit past a
// nearer one of the same group loses in record.
template <int N>
struct PacketLane {
    TreePacketState<Query::closest, N>& packet;
    int index;
    vbool<N> lane;
    float limit;

    [[gnu::always_inline]] PacketLane(TreePacketState<Query::closest, N>& p, int i)
        : packet(p), index(i), lane(vint<N>::step() == vint<N>(i)), limit(p.limit()[i]) {}
    bool done() const { return false; }
    template <int L>
    [[gnu::always_inline]] void record(const vbool<L>& hit, const LaneHits<L>& h, const vint<L>& ids) {
        for (uint32_t bits = simd::movemask(hit); bits; bits &= bits - 1) {
            const int j = __builtin_ctz(bits);
            packet.record(lane, {vfloat<N>(h.t[j]), vfloat<N>(h.u_num[j]), vfloat<N>(h.v_num[j]), vfloat<N>(h.den[j])},
                          vint<N>(ids[j]));
        }
        limit = packet.limit()[index];
    }
};

// A leaf of triangles whose box few of the packet's lanes entered (`lanes`, a bit per lane): each
// of those rays against all the leaf's triangles at once (the single-ray leaf test), in place of
// every triangle against all N lanes. Deep in the tree a camera packet's rays spread over several
// leaves, so most leaves are entered by a few lanes.
template <TriangleTest T, int N>
WT_KERNEL_INLINE void test_leaf_lanes(const BvhView& bvh, uint32_t ref, const RayPacket<N>& r, uint32_t lanes,
                                      TreePacketState<Query::closest, N>& state) {
    constexpr int L = kLeafLanes<N>;
    constexpr uint32_t rows = T == TriangleTest::watertight ? kWatertightRows : kMollerTrumboreRows;
    const uint32_t count = ((ref >> kBvhCountShift) & 7u) + 1u;
    const TriangleBlock<T> triangles{bvh.leaves + std::size_t(ref & kBvhFirstMask) * rows, count};
    for (; lanes; lanes &= lanes - 1) {
        const int i = __builtin_ctz(lanes);
        const Vec3<L> o{vfloat<L>(r.o.x[i]), vfloat<L>(r.o.y[i]), vfloat<L>(r.o.z[i])};
        const Vec3<L> d{vfloat<L>(r.d.x[i]), vfloat<L>(r.d.y[i]), vfloat<L>(r.d.z[i])};
        PacketLane<N> lane(state, i);
        test_planar_run<Planar::triangle>(TriangleRays<T, L>(o, d), triangles, count, lane);
    }
}

// Leaves of triangles entered by at most this many lanes take test_leaf_lanes: a ray against a
// leaf costs about what one triangle against the packet costs, and a leaf holds up to 8
// (bench/README.md, "Issue 18: leaves ray by ray in the packet walk", has the choice measured).
inline constexpr int kFewLanes = 4;

template <Query Q, TriangleTest T, SphereTest S, int W, int N>
void trace_bvh_packets(const BvhView& bvh, const RayView& rays, QueryOutput<Q> out) {
    // Whether leaves entered by few lanes take test_leaf_lanes: for closest hits (occlusion
    // packets stop at a blocker, and renders send none), and packets of more than one lane.
    constexpr bool kLaneLeaves = Q == Query::closest && N > 1;
    const BvhNode<W>* nodes = static_cast<const BvhNode<W>*>(bvh.nodes);
    for (uint32_t first = 0; first < rays.count; first += N) {
        const RayPacket<N> r = load_rays<N>(rays, first);
        const TriangleRays<T, N> tr(r.o, r.d);
        const vfloat<N> inv_d[3] = {vfloat<N>(1.0f) / r.d.x, vfloat<N>(1.0f) / r.d.y, vfloat<N>(1.0f) / r.d.z};
        const vfloat<N> o_inv_d[3] = {r.o.x * inv_d[0], r.o.y * inv_d[1], r.o.z * inv_d[2]};
        // Per lane, which bound is the near one: the max when the direction's sign bit is set,
        // as the single-ray traversal picks its rows. (min/max of the two slab distances would
        // not do: with a zero component one of them is NaN and the other infinite, and the NaN
        // rule would keep the infinity as the entry distance.)
        const vbool<N> negative[3] = {simd::asInt(r.d.x) < vint<N>(0), simd::asInt(r.d.y) < vint<N>(0),
                                      simd::asInt(r.d.z) < vint<N>(0)};
        TreePacketState<Q, N> state(r);
        // The parallelograms beside the tree (bvh_view.h), each broadcast to the packet: first for
        // closest hits, whose walk the walls bound; last for any hits, whose walk they cannot
        // shorten, so rays the tree blocks never test them.
        const auto test_beside = [&]() __attribute__((always_inline)) {
            if constexpr (T == TriangleTest::moller_trumbore)
                for (uint32_t k = 0; k < bvh.beside_count && !state.done(); ++k) {
                    LaneHits<N> h;
                    const vbool<N> hit = intersect_triangles<Planar::parallelogram>(
                        tr, broadcast_triangle<T, N>(bvh.beside, k), r.active, state.limit(), h);
                    state.record(r.active & hit, h, vint<N>(int32_t(k)));
                }
        };
        const auto walk = [&]() __attribute__((always_inline)) {
            // Closest hits of packets wider than one lane (kLaneLeaves) keep, per entry, the lanes
            // that entered the child's box, in the high half above its reference, so that the two
            // move together in the sort.
            std::conditional_t<kLaneLeaves, uint64_t, uint32_t> stack_ref[kBvhStackSize];
            float stack_t[kBvhStackSize];
            int top = 0;
            uint32_t ref = bvh.root;
            [[maybe_unused]] uint32_t lanes = simd::movemask(r.active);  // those that entered ref's box
            const auto pop = [&](int entry) __attribute__((always_inline)) {
                ref = uint32_t(stack_ref[entry]);
                if constexpr (kLaneLeaves) lanes = uint32_t(stack_ref[entry] >> 32);
            };
            for (;;) {
                if (!(ref & kBvhLeafBit)) {
                    const BvhNode<W>& node = nodes[ref];
                    const vfloat<N> reach = state.reach();
                    const int base = top;
                    for (int c = 0; c < W; ++c) {
                        if (node.child[c] == kBvhEmptyChild) continue;
                        vfloat<N> enter(0.0f), leave(kInfinity);
                        for (int a = 0; a < 3; ++a) {
                            const vfloat<N> t0 = simd::msub(vfloat<N>(node.bounds[2 * a][c]), inv_d[a], o_inv_d[a]);
                            const vfloat<N> t1 = simd::msub(vfloat<N>(node.bounds[2 * a + 1][c]), inv_d[a], o_inv_d[a]);
                            // A NaN slab distance (inf - inf) is dropped: max/min return their second operand then.
                            enter = simd::max(simd::select(negative[a], t1, t0), enter);
                            leave = simd::min(simd::select(negative[a], t0, t1), leave);
                        }
                        leave = simd::min(leave * vfloat<N>(kRobustFarScale), reach);
                        const vbool<N> entered = r.active & (enter <= leave);
                        if (simd::none(entered)) continue;
                        if constexpr (kLaneLeaves) stack_ref[top] = uint64_t(simd::movemask(entered)) << 32 | node.child[c];
                        else stack_ref[top] = node.child[c];
                        stack_t[top] = simd::reduce_min(simd::select(entered, enter, vfloat<N>(kInfinity)));
                        ++top;
                    }
                    if (top > base) {
                        if constexpr (Q == Query::closest) sort_far_to_near(stack_ref + base, stack_t + base, top - base);
                        pop(--top);
                        continue;
                    }
                } else {
                    bool by_lane = false;
                    if constexpr (kLaneLeaves)
                        by_lane = BvhLeafKind((ref >> kBvhKindShift) & 3u) == BvhLeafKind::triangle &&
                                  __builtin_popcount(lanes) <= kFewLanes;
                    if (!by_lane) test_leaf_packet<T, S, Q, N>(bvh, ref, r, tr, state);
                    else if constexpr (kLaneLeaves) test_leaf_lanes<T, N>(bvh, ref, r, lanes, state);
                    if (state.done()) break;
                }
                // The farthest any active lane still looks: entries beyond it cannot matter.
                const float reach = simd::reduce_max(simd::select(r.active, state.reach(), vfloat<N>(-kInfinity)));
                bool next = false;
                while (top > 0 && !next) next = stack_t[--top] <= reach;
                if (!next) break;
                pop(top);
            }
        };
        if constexpr (Q == Query::closest) test_beside();
        if (!state.done()) walk();
        if constexpr (Q == Query::any)
            if (!state.done()) test_beside();
        state.write(out, first, r.count);
    }
}

// The packet traversal at this ISA's widest vector, for both node widths.
template <Query Q, TriangleTest T, SphereTest S, int N>
void bvh_packet_query(const BvhView& bvh, const RayView& rays, QueryOutput<Q> out) {
    with_node_width(bvh, [&](auto width) { trace_bvh_packets<Q, T, S, width.value, N>(bvh, rays, out); });
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::packet
