#pragma once
// The flat primitive list, no acceleration structure: for a scene of a few dozen primitives
// (the hexroom has 19 planar tests and 4 spheres) this beats any tree. Two layouts:
//   ray packets   N rays of the queue against one primitive at a time (primitive broadcast);
//                 what the renderer uses for small scenes
//   prim packets  one ray against N primitives at a time (SoA loads), the BVH's leaf test run
//                 over the whole list
// Both give the same bits; bench_intersect measures which is faster.

#include <cstdint>

#include "kernels/accel/query.h"
#include "kernels/accel/single_ray.h"
#include "kernels/primitives/lanes.h"
#include "kernels/primitives/sphere_lanes.h"
#include "kernels/primitives/triangle_lanes.h"
#include "kernels/primitives/soa_views.h"

namespace wt::packet {
inline namespace WT_SIMD_ISA {

template <int N>
struct RayPacket {
    Vec3<N> o, d;
    vfloat<N> tmax;
    vbool<N> active;  // lanes past the end of the queue are off
    int count;
};

template <int N>
WT_KERNEL_INLINE RayPacket<N> load_rays(const RayView& rays, uint32_t first) {
    RayPacket<N> r;
    r.count = lanes_left<N>(rays.count, first);
    r.o = load_partial<N>(rays.ox, rays.oy, rays.oz, first, r.count);
    r.d = load_partial<N>(rays.dx, rays.dy, rays.dz, first, r.count);
    r.tmax = rays.tmax ? vfloat<N>::load_partial(rays.tmax + first, r.count, vfloat<N>(kInfinity)) : vfloat<N>(kInfinity);
    r.active = vint<N>::step() < vint<N>(r.count);
    return r;
}

// What a packet's query has found so far, per lane.
template <Query Q, int N>
struct PacketState;

template <int N>
struct PacketState<Query::closest, N> {
    LaneHits<N> best;
    vint<N> best_prim;
    explicit PacketState(const RayPacket<N>& r) : best(sphere_hits(r.tmax)), best_prim(-1) {}
    // Primitives come in id order, so the strict < of the test keeps the smallest id of equal t.
    const vfloat<N>& limit() const { return best.t; }
    bool done() const { return false; }
    // Branch-free: with incoherent rays "no lane hit this primitive" is a coin flip, and
    // the mispredicted branch cost more than the selects it skipped (bench/README.md).
    [[gnu::always_inline]] void record(const vbool<N>& hit, const LaneHits<N>& h, const vint<N>& id) {
        best = select(hit, h, best);
        best_prim = simd::select(hit, id, best_prim);
    }
    void write(const HitView& hits, uint32_t first, int count) const {
        const vfloat<N> best_t = simd::select(best_prim == vint<N>(-1), vfloat<N>(kInfinity), best.t);
        vfloat<N>::store_partial(hits.t + first, best_t, count);
        vfloat<N>::store_partial(hits.u + first, best.u_num / best.den, count);
        vfloat<N>::store_partial(hits.v + first, best.v_num / best.den, count);
        vint<N>::store_partial(reinterpret_cast<int32_t*>(hits.prim + first), best_prim, count);
    }
};

template <int N>
struct PacketState<Query::any, N> {
    vbool<N> blocked, inactive;
    vfloat<N> tmax;
    explicit PacketState(const RayPacket<N>& r) : blocked(false), inactive(~r.active), tmax(r.tmax) {}
    const vfloat<N>& limit() const { return tmax; }
    bool done() const { return simd::all(blocked | inactive); }
    [[gnu::always_inline]] void record(const vbool<N>& hit, const LaneHits<N>&, const vint<N>&) { blocked |= hit; }
    void write(uint8_t* occluded, uint32_t first, int count) const {
        const uint32_t bits = simd::movemask(blocked);
        for (int lane = 0; lane < count; ++lane) occluded[first + uint32_t(lane)] = uint8_t((bits >> lane) & 1u);
    }
};

template <Query Q, TriangleTest T, SphereTest S, int N>
void raypacket_brute_force(const SceneView& scene, const RayView& rays, QueryOutput<Q> out) {
    const TriangleView& tri = scene.triangles;
    const SphereView& sph = scene.spheres;
    for (uint32_t first = 0; first < rays.count; first += N) {
        const RayPacket<N> r = load_rays<N>(rays, first);
        const TriangleRays<T, N> tr(r.o, r.d);
        PacketState<Q, N> state(r);
        // The primitive id rides along as a vector (one add) rather than a broadcast of i,
        // which the compiler turned into three moves.
        vint<N> prim(0);
        for_each_planar_range<T>(tri, [&](auto shape, uint32_t begin, uint32_t end) {
            for (uint32_t i = begin; i < end && !state.done(); ++i) {
                LaneHits<N> h;
                const vbool<N> hit =
                    intersect_triangles<shape.value>(tr, broadcast_triangle<T, N>(tri, i), r.active, state.limit(), h);
                state.record(hit, h, prim);
                if constexpr (Q == Query::closest) prim += vint<N>(1);
            }
        });
        for (uint32_t i = 0; i < sph.count && !state.done(); ++i) {
            vfloat<N> t;
            const vbool<N> hit = intersect_spheres<S>(r.o, r.d, broadcast<N>(sph.cx, sph.cy, sph.cz, i),
                                                      vfloat<N>(sph.radius[i]), state.limit(), t);
            state.record(hit, sphere_hits(t), vint<N>(int32_t(sph.first_prim + i)));
        }
        state.write(out, first, r.count);
    }
}

template <Query Q, TriangleTest T, SphereTest S, int N>
void primpacket_brute_force(const SceneView& scene, const RayView& rays, QueryOutput<Q> out) {
    const TriangleView& tri = scene.triangles;
    const SphereView& sph = scene.spheres;
    for (uint32_t ray = 0; ray < rays.count; ++ray) {
        const SingleRay<N> r = broadcast_ray<N>(rays, ray);
        const TriangleRays<T, N> tr(r.o, r.d);
        SingleRayState<Q, N> state(r.tmax);
        for_each_planar_range<T>(tri, [&](auto shape, uint32_t begin, uint32_t end) {
            test_planar_run<shape.value>(tr, FlatTriangles<T>{tri, begin}, end - begin, state);
        });
        test_sphere_run<S>(r, FlatSpheres{sph, 0}, sph.count, state);
        state.write(out, ray);
    }
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::packet
