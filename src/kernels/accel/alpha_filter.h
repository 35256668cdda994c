#pragma once
// The alpha test inside traversal, as Embree's intersection filter functions and pbrt-v4's
// alpha-tested triangles do it: a candidate hit on a cut-out (glTF alphaMode MASK) or on a
// stochastically transparent surface (BLEND) that the material lets through is dropped before
// the query records it, so the walk goes on to what lies behind, for closest hits (camera and
// bounce rays) and any hits (shadow rays) alike, and no ray is ever re-spawned at a cut-out.
//
// Only scenes with alpha-tested materials instantiate this (BvhView::alpha_keeps set); every
// other scene runs the kernels it ran before. The test itself is out of line
// (core/scene/alpha_test.h): it reads materials and textures, and is compiled once so every ISA
// takes the same decision from the same (primitive, u, v, ray).

#include <cstdint>
#include <cstring>

#include "kernels/accel/bvh_traverse.h"
#include "kernels/accel/bvh_view.h"
#include "kernels/accel/instance_traverse.h"
#include "kernels/accel/query.h"
#include "kernels/accel/single_ray.h"
#include "kernels/primitives/soa_views.h"

namespace wt::packet {
inline namespace WT_SIMD_ISA {

// The ray's origin and direction bits folded into one key (each word mixed in with a
// multiply by the 64-bit golden ratio, splitmix64's increment): the ray is a function of
// (seed, pixel, sample, bounce, dimension), so the key, and every BLEND coin drawn from it,
// is the same whatever the thread, ISA, pass or resume.
WT_KERNEL_INLINE uint64_t alpha_ray_key(const RayView& rays, uint32_t i) {
    const float words[6] = {rays.ox[i], rays.oy[i], rays.oz[i], rays.dx[i], rays.dy[i], rays.dz[i]};
    uint64_t key = 0;
    for (float w : words) {
        uint32_t bits;
        std::memcpy(&bits, &w, sizeof bits);
        key = (key ^ bits) * 0x9E3779B97F4A7C15ull;
        key ^= key >> 29;
    }
    return key;
}

// A SingleRayState whose candidates pass the alpha test before they are recorded.
template <Query Q, int N>
struct AlphaRayState : SingleRayState<Q, N> {
    using Base = SingleRayState<Q, N>;
    AlphaKeepsHit keeps;
    const void* context;
    uint64_t key;

    [[gnu::always_inline]] AlphaRayState(const BvhView& bvh, const RayView& rays, uint32_t i)
        : Base(rays.tmax ? rays.tmax[i] : kInfinity), keeps(bvh.alpha_keeps), context(bvh.alpha_context),
          key(alpha_ray_key(rays, i)) {}

    // The barycentrics are divided out as SingleRayState::write divides the winner's, so the
    // test sees the (u, v) the shade stage will.
    [[gnu::always_inline]] void record(vbool<N> hit, const LaneHits<N>& h, const vint<N>& ids) {
        for (uint32_t bits = simd::movemask(hit); bits; bits &= bits - 1) {
            const int lane = __builtin_ctz(bits);
            const float u = h.u_num[lane] / h.den[lane], v = h.v_num[lane] / h.den[lane];
            if (!keeps(context, uint32_t(ids[lane]), u, v, key)) hit = hit & (vint<N>::step() != vint<N>(lane));
        }
        Base::record(hit, h, ids);
    }
};

// The kernel table's BVH entries for a scene with alpha-tested materials: every ray by itself
// (the packet walk records whole packets), through the instances too if there are any.
template <Query Q, TriangleTest T, SphereTest S, int W, int MaxWidth>
void trace_alpha_rays(const BvhView& bvh, const RayView& rays, QueryOutput<Q> out) {
    constexpr int V = kNodeLanes<W, MaxWidth>, L = kLeafLanes<MaxWidth>;
    for (uint32_t i = 0; i < rays.count; ++i) {
        AlphaRayState<Q, L> state(bvh, rays, i);
        if (bvh.instances) trace_instanced_one<T, S, Q, W, V, L>(bvh, rays, i, state);
        else trace_one<T, S, Q, W, V, L>(bvh, rays, i, state);
        state.write(out, i);
    }
}

template <Query Q, TriangleTest T, SphereTest S, int MaxWidth>
void alpha_bvh_query(const BvhView& bvh, const RayView& rays, QueryOutput<Q> out) {
    with_node_width(bvh, [&](auto width) { trace_alpha_rays<Q, T, S, width.value, MaxWidth>(bvh, rays, out); });
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::packet
