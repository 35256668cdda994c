#pragma once
// Two-level traversal: the scene's own tree, then a tree over the instances' world boxes whose
// every leaf is an instance, entered by taking the ray into the instance's object space and
// walking its mesh's tree. Both levels are the one generic loop (traverse_tree in
// bvh_traverse.h) with another leaf test; the query state (closest distance so far, or the
// blocker found) is shared by every tree the ray walks.
//
// The object-space direction is L^-1 d, not normalised: a point o + t d in world space is
// o' + t d' in object space for the same t, so distances from every instance and from the
// scene's own primitives compare directly, the closest hit so far culls boxes in every tree,
// and a shadow ray's tmax needs no rescaling. (A unit object-space direction would measure t in
// object units: each instance's hits would have to be scaled back, and a scaled instance's
// boxes culled against the wrong distance.)
//
// The transform is plain float arithmetic in a fixed order (no FMA: -ffp-contract=off), so every
// ISA computes the same object-space ray and the images stay bit-identical across ISAs.

#include <cstdint>

#include "kernels/accel/bvh_traverse.h"
#include "kernels/accel/bvh_view.h"
#include "kernels/accel/query.h"
#include "kernels/accel/single_ray.h"
#include "kernels/primitives/soa_views.h"

namespace wt::packet {
inline namespace WT_SIMD_ISA {

struct ObjectRay {
    float o[3], d[3];
};

WT_KERNEL_INLINE ObjectRay object_ray(const InstanceRecord& r, const RayView& rays, uint32_t i) {
    const float o[3] = {rays.ox[i], rays.oy[i], rays.oz[i]};
    const float d[3] = {rays.dx[i], rays.dy[i], rays.dz[i]};
    ObjectRay out;
    for (int row = 0; row < 3; ++row) {
        const float* m = r.to_object[row];
        out.o[row] = m[0] * o[0] + m[1] * o[1] + m[2] * o[2] + m[3];
        out.d[row] = m[0] * d[0] + m[1] * d[1] + m[2] * d[2];
    }
    return out;
}

// A leaf block's triangles with their mesh-local ids moved into the scene's id space.
template <typename Source>
struct IdsFrom {
    const Source& source;
    int32_t first_id;
    template <int N>
    [[gnu::always_inline]] TriangleLanes<N> load(uint32_t c, int n) const {
        return source.template load<N>(c, n);
    }
    template <int N>
    [[gnu::always_inline]] vint<N> ids(uint32_t c, int n) const {
        return source.template ids<N>(c, n) + vint<N>(first_id);
    }
};

// An instanced mesh's leaf: triangles only (build_instances stores no parallelograms or spheres).
template <TriangleTest T, int L, typename State>
WT_KERNEL_INLINE void test_mesh_leaf(const BvhView& mesh, uint32_t ref, const TriangleRays<T, L>& tri_ray, uint32_t first_id,
                                     State& state) {
    if (BvhLeafKind((ref >> kBvhKindShift) & 3u) != BvhLeafKind::triangle) return;  // kBvhEmptyChild
    const uint32_t first = ref & kBvhFirstMask;
    const uint32_t count = ((ref >> kBvhCountShift) & 7u) + 1u;
    constexpr uint32_t rows = T == TriangleTest::watertight ? kWatertightRows : kMollerTrumboreRows;
    const TriangleBlock<T> block{mesh.leaves + std::size_t(first) * rows, count};
    test_planar_run<Planar::triangle>(tri_ray, IdsFrom<TriangleBlock<T>>{block, int32_t(first_id)}, count, state);
}

template <TriangleTest T, Query Q, int W, int V, int L, typename State>
WT_KERNEL_INLINE void trace_instance(const InstanceView& instances, const InstanceRecord& r, const RayView& rays, uint32_t i,
                                     State& state) {
    const ObjectRay local = object_ray(r, rays, i);
    const RayView one{&local.o[0], &local.o[1], &local.o[2], &local.d[0], &local.d[1], &local.d[2], nullptr, 1u};
    const SingleRay<L> ray = broadcast_ray<L>(one, 0);
    const TriangleRays<T, L> tri_ray(ray.o, ray.d);
    const BoxRay<V> box_ray(one, 0);
    const BvhView& mesh = instances.meshes[r.mesh];
    traverse_tree<Q, W, V>(mesh.nodes, mesh.root, box_ray, state, [&](uint32_t ref) __attribute__((always_inline)) {
        test_mesh_leaf<T, L>(mesh, ref, tri_ray, r.first_id, state);
    });
}

template <TriangleTest T, SphereTest S, Query Q, int W, int V, int L, typename State>
WT_KERNEL_INLINE void trace_instanced_one(const BvhView& bvh, const RayView& rays, uint32_t i, State& state) {
    trace_one<T, S, Q, W, V, L>(bvh, rays, i, state);  // the scene's own primitives
    if (state.done()) return;
    const InstanceView& instances = *bvh.instances;
    const BoxRay<V> box_ray(rays, i);
    traverse_tree<Q, W, V>(instances.nodes, instances.root, box_ray, state, [&](uint32_t ref) __attribute__((always_inline)) {
        if (ref == kBvhEmptyChild) return;  // no instance
        const uint32_t first = ref & kBvhFirstMask;
        const uint32_t end = first + ((ref >> kBvhCountShift) & 7u) + 1u;
        for (uint32_t k = first; k < end && !state.done(); ++k)
            trace_instance<T, Q, W, V, L>(instances, instances.records[k], rays, i, state);
    });
}

template <Query Q, TriangleTest T, SphereTest S, int W, int MaxWidth>
void trace_instanced_rays(const BvhView& bvh, const RayView& rays, QueryOutput<Q> out) {
    for_each_ray<Q, MaxWidth>(rays, out, [&](uint32_t i, auto& state) __attribute__((always_inline)) {
        trace_instanced_one<T, S, Q, W, kNodeLanes<W, MaxWidth>, kLeafLanes<MaxWidth>>(bvh, rays, i, state);
    });
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::packet
