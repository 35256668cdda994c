#pragma once
// The kernel table's BVH entries: which walk a scene's rays take, chosen per queue from what the
// scene holds (its view's pointers), so each scene runs only the code it needs.

#include "kernels/accel/alpha_filter.h"
#include "kernels/accel/bvh_interleaved_traverse.h"
#include "kernels/accel/bvh_packet_traverse.h"
#include "kernels/accel/bvh_traverse.h"
#include "kernels/accel/bvh_view.h"
#include "kernels/accel/instance_traverse.h"
#include "kernels/accel/query.h"

namespace wt::packet {
inline namespace WT_SIMD_ISA {

// A plain tree: trees that fit in the caches are walked one ray at a time, as they always were;
// larger ones (BvhView::prefetch_pushed) several rays at a time (bvh_interleaved_traverse.h).
template <Query Q, TriangleTest T, SphereTest S, int MaxWidth>
void bvh_query(const BvhView& bvh, const RayView& rays, QueryOutput<Q> out) {
    with_node_width(bvh, [&](auto width) {
        if (bvh.prefetch_pushed) return trace_bvh_rays_interleaved<Q, T, S, width.value, MaxWidth>(bvh, rays, out);
        trace_bvh_rays<Q, T, S, width.value, MaxWidth, false>(bvh, rays, out);
    });
}

// A scene with alpha-tested materials asks the alpha test about each candidate hit, one ray at
// a time (alpha_filter.h). A scene with instances takes the two-level walk one ray at a time
// (also for the coherent rays the packet walk would take); one without either, the walk it took
// before instances existed (Packets: camera rays N at a time).
template <Query Q, TriangleTest T, SphereTest S, int N, bool Packets>
void scene_bvh_query(const BvhView& bvh, const RayView& rays, QueryOutput<Q> out) {
    if (bvh.alpha_keeps)
        alpha_bvh_query<Q, T, S, N>(bvh, rays, out);
    else if (bvh.instances)
        with_node_width(bvh, [&](auto width) { trace_instanced_rays<Q, T, S, width.value, N>(bvh, rays, out); });
    else if constexpr (Packets)
        bvh_packet_query<Q, T, S, N>(bvh, rays, out);
    else
        bvh_query<Q, T, S, N>(bvh, rays, out);
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::packet
