#pragma once
// One ray against N primitives at a time: a run of consecutive primitives of one kind (a BVH
// leaf, or a chunk of the flat list), tested with SoA loads, the answer kept per lane.
//
// Closest hits are compared as (t, primitive id) pairs, smallest first. The flat kernels visit
// primitives in id order and keep the first of equal distances, which is the smallest id; the
// BVH visits them in another order, and with the same rule returns the same primitive, so its
// answers are the flat kernels' bits even where two triangles sharing an edge are hit at one t.

#include <cstdint>
#include <cstring>

#include "kernels/accel/bvh_view.h"
#include "kernels/accel/query.h"
#include "kernels/primitives/lanes.h"
#include "kernels/primitives/sphere_lanes.h"
#include "kernels/primitives/triangle_lanes.h"
#include "kernels/primitives/soa_views.h"

namespace wt::packet {
inline namespace WT_SIMD_ISA {

template <int N>
struct SingleRay {
    Vec3<N> o, d;
    float tmax;
};

template <int N>
WT_KERNEL_INLINE SingleRay<N> broadcast_ray(const RayView& rays, uint32_t i) {
    return {broadcast<N>(rays.ox, rays.oy, rays.oz, i), broadcast<N>(rays.dx, rays.dy, rays.dz, i),
            rays.tmax ? rays.tmax[i] : kInfinity};
}

template <int N>
WT_KERNEL_INLINE int lanes_left(uint32_t end, uint32_t first) {
    return int(end - first < uint32_t(N) ? end - first : uint32_t(N));
}

// The next float above a positive finite x.
WT_KERNEL_INLINE float next_float_up(float x) {
    uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    ++bits;
    std::memcpy(&x, &bits, sizeof bits);
    return x;
}

// What one ray's query has found so far. `limit`: a primitive test counts hits at t < limit.
template <Query Q, int N>
struct SingleRayState;

template <int N>
struct SingleRayState<Query::closest, N> {
    LaneHits<N> best;
    vint<N> best_prim;
    float closest;  // the smallest t found (tmax while there is none): boxes beyond it are skipped
    float limit;    // tmax, then the float after `closest`, so an equal t still competes on its id

    [[gnu::always_inline]] explicit SingleRayState(float tmax)
        : best(sphere_hits(vfloat<N>(tmax))), best_prim(-1), closest(tmax), limit(tmax) {}

    bool done() const { return false; }

    [[gnu::always_inline]] void record(const vbool<N>& hit, const LaneHits<N>& h, const vint<N>& ids) {
        if (simd::none(hit)) return;
        const vbool<N> better = hit & ((h.t < best.t) | ((h.t == best.t) & (ids < best_prim)));
        best = select(better, h, best);
        best_prim = simd::select(better, ids, best_prim);
        closest = simd::reduce_min(best.t);
        limit = next_float_up(closest);
    }

    // The lane holding the smallest (t, id), its barycentrics divided out once.
    void write(const HitView& hits, uint32_t ray) const {
        uint32_t candidates = simd::movemask((best.t == vfloat<N>(closest)) & (best_prim != vint<N>(-1)));
        int winner = -1;
        for (; candidates; candidates &= candidates - 1) {
            const int lane = __builtin_ctz(candidates);
            if (winner < 0 || best_prim[lane] < best_prim[winner]) winner = lane;
        }
        if (winner < 0) {
            hits.t[ray] = kInfinity, hits.u[ray] = 0.0f, hits.v[ray] = 0.0f, hits.prim[ray] = UINT32_MAX;
        } else {
            hits.t[ray] = best.t[winner];
            hits.u[ray] = best.u_num[winner] / best.den[winner];
            hits.v[ray] = best.v_num[winner] / best.den[winner];
            hits.prim[ray] = uint32_t(best_prim[winner]);
        }
    }
};

template <int N>
struct SingleRayState<Query::any, N> {
    bool blocked = false;
    float closest;  // boxes beyond tmax are skipped
    float limit;

    explicit SingleRayState(float tmax) : closest(tmax), limit(tmax) {}

    bool done() const { return blocked; }
    [[gnu::always_inline]] void record(const vbool<N>& hit, const LaneHits<N>&, const vint<N>&) { blocked = blocked || simd::any(hit); }
    void write(uint8_t* occluded, uint32_t ray) const { occluded[ray] = blocked; }
};

// Where a run's primitives come from: the flat SoA arrays of the scene (ids consecutive from a
// base), or one BVH leaf block (bvh_view.h: rows of k floats, the ids in the last row).
template <TriangleTest T>
struct FlatTriangles {
    const TriangleView& tri;
    uint32_t first;
    template <int N>
    [[gnu::always_inline]] TriangleLanes<N> load(uint32_t c, int n) const {
        return load_triangles<T, N>(tri, first + c, n);
    }
    template <int N>
    [[gnu::always_inline]] vint<N> ids(uint32_t c, int) const {
        return vint<N>::step() + vint<N>(int32_t(first + c));
    }
};

template <TriangleTest T>
struct TriangleBlock {
    const float* block;
    uint32_t k;  // primitives in the leaf: the row length
    template <int N>
    [[gnu::always_inline]] Vec3<N> rows(uint32_t row, uint32_t c, int n) const {
        const float* p = block + row * k + c;
        const vfloat<N> zero(0.0f);
        return {vfloat<N>::load_partial(p, n, zero), vfloat<N>::load_partial(p + k, n, zero),
                vfloat<N>::load_partial(p + 2 * k, n, zero)};
    }
    template <int N>
    [[gnu::always_inline]] TriangleLanes<N> load(uint32_t c, int n) const {
        if constexpr (T == TriangleTest::watertight)
            return {rows<N>(0, c, n), rows<N>(3, c, n), rows<N>(6, c, n), {}};
        else
            return with_scaled_normal(rows<N>(0, c, n), rows<N>(3, c, n), rows<N>(6, c, n));
    }
    template <int N>
    [[gnu::always_inline]] vint<N> ids(uint32_t c, int n) const {
        constexpr uint32_t id_row = (T == TriangleTest::watertight ? kWatertightRows : kMollerTrumboreRows) - 1;
        return vint<N>::load_partial(reinterpret_cast<const int32_t*>(block + id_row * k + c), n, vint<N>(-1));
    }
};

struct FlatSpheres {
    const SphereView& sph;
    uint32_t first;
    template <int N>
    [[gnu::always_inline]] void load(uint32_t c, int n, Vec3<N>& center, vfloat<N>& radius) const {
        center = load_partial<N>(sph.cx, sph.cy, sph.cz, first + c, n);
        radius = vfloat<N>::load_partial(sph.radius + first + c, n, vfloat<N>(0.0f));
    }
    template <int N>
    [[gnu::always_inline]] vint<N> ids(uint32_t c, int) const {
        return vint<N>::step() + vint<N>(int32_t(sph.first_prim + first + c));
    }
};

struct SphereBlock {
    const float* block;
    uint32_t k;
    template <int N>
    [[gnu::always_inline]] void load(uint32_t c, int n, Vec3<N>& center, vfloat<N>& radius) const {
        const float* p = block + c;
        const vfloat<N> zero(0.0f);
        center = {vfloat<N>::load_partial(p, n, zero), vfloat<N>::load_partial(p + k, n, zero),
                  vfloat<N>::load_partial(p + 2 * k, n, zero)};
        radius = vfloat<N>::load_partial(p + 3 * k, n, zero);
    }
    template <int N>
    [[gnu::always_inline]] vint<N> ids(uint32_t c, int n) const {
        return vint<N>::load_partial(reinterpret_cast<const int32_t*>(block + (kSphereRows - 1) * k + c), n, vint<N>(-1));
    }
};

// `count` planar primitives of shape P from `source` against the ray, N at a time.
// `State` is a SingleRayState<Q, N>, or one that filters its candidates first (alpha_filter.h).
template <Planar P, TriangleTest T, int N, typename Source, typename State>
WT_KERNEL_INLINE void test_planar_run(const TriangleRays<T, N>& ray, const Source& source, uint32_t count, State& state) {
    for (uint32_t c = 0; c < count && !state.done(); c += N) {
        const int n = lanes_left<N>(count, c);
        const vbool<N> lanes = vint<N>::step() < vint<N>(n);
        LaneHits<N> h;
        const vbool<N> hit =
            lanes & intersect_triangles<P>(ray, source.template load<N>(c, n), lanes, vfloat<N>(state.limit), h);
        state.record(hit, h, source.template ids<N>(c, n));
    }
}

template <SphereTest S, int N, typename Source, typename State>
WT_KERNEL_INLINE void test_sphere_run(const SingleRay<N>& ray, const Source& source, uint32_t count, State& state) {
    for (uint32_t c = 0; c < count && !state.done(); c += N) {
        const int n = lanes_left<N>(count, c);
        Vec3<N> center;
        vfloat<N> radius, t;
        source.template load<N>(c, n, center, radius);
        const vbool<N> hit =
            (vint<N>::step() < vint<N>(n)) & intersect_spheres<S>(ray.o, ray.d, center, radius, vfloat<N>(state.limit), t);
        state.record(hit, sphere_hits(t), source.template ids<N>(c, n));
    }
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::packet
