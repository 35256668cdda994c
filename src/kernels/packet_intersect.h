#pragma once
// Moller-Trumbore triangles and quadratic spheres for N lanes, written once over
// simd::vfloat<N> and instantiated per width in the per-ISA translation units.
//
// The arithmetic is exactly the textbook's (primitive_intersect.h): the same products, sums in
// the same order, one IEEE division, and no fused multiply-add (the build passes
// -ffp-contract=off and this file calls no madd). Every width on every ISA therefore returns
// the same bits as the scalar code, so an image is identical whichever kernels rendered it.
// That costs about 8% end to end against an FMA version (bench/README.md), and buys exact
// tests: with FMA, t differed from the textbook by up to 7e-6 relative on grazing rays, in
// either direction, and primitives flipped at shared edges.
//
// Everything lives in an ISA-specific inline namespace (see simd/isa.h), so the copies
// compiled for different instruction sets never get merged by the linker.

#include <cstdint>
#include <limits>

#include "kernels/intersect_kernels.h"
#include "kernels/soa_views.h"
#include "simd/simd.h"

namespace wt::packet {
inline namespace WT_SIMD_ISA {

using simd::vbool;
using simd::vfloat;
using simd::vint;

template <int N>
struct Vec3 {
    vfloat<N> x, y, z;
};

template <int N>
inline Vec3<N> operator-(const Vec3<N>& a, const Vec3<N>& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}

// The products and subtraction order of glm::cross.
template <int N>
inline Vec3<N> cross(const Vec3<N>& a, const Vec3<N>& b) {
    return {a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y};
}

// The order of glm::dot: (x*x' + y*y') + z*z'.
template <int N>
inline vfloat<N> dot(const Vec3<N>& a, const Vec3<N>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

template <int N>
inline Vec3<N> broadcast(const float* x, const float* y, const float* z, uint32_t i) {
    return {vfloat<N>(x[i]), vfloat<N>(y[i]), vfloat<N>(z[i])};
}

template <int N>
inline Vec3<N> load_partial(const float* x, const float* y, const float* z, uint32_t first, int count) {
    const vfloat<N> zero(0.0f);
    return {vfloat<N>::load_partial(x + first, count, zero), vfloat<N>::load_partial(y + first, count, zero),
            vfloat<N>::load_partial(z + first, count, zero)};
}

// Ray(s) o + t d against triangle(s) v0, e1, e2. A lane hits when t is in (0, tmax) and the
// barycentrics are inside; det == 0 (parallel ray, degenerate triangle) and NaNs never hit.
template <int N>
inline vbool<N> intersect_triangle(const Vec3<N>& o, const Vec3<N>& d, const Vec3<N>& v0, const Vec3<N>& e1,
                                   const Vec3<N>& e2, const vfloat<N>& tmax, vfloat<N>& t, vfloat<N>& u,
                                   vfloat<N>& v) {
    const Vec3<N> p = cross(d, e2);
    const vfloat<N> det = dot(e1, p);
    const vfloat<N> inv_det = vfloat<N>(1.0f) / det;
    const Vec3<N> s = o - v0;
    u = dot(s, p) * inv_det;
    const Vec3<N> q = cross(s, e1);
    v = dot(d, q) * inv_det;
    t = dot(e2, q) * inv_det;
    const vfloat<N> zero(0.0f), one(1.0f);
    return (det != zero) & (u >= zero) & (u <= one) & (v >= zero) & (u + v <= one) & (t > zero) & (t < tmax);
}

// Ray(s) against sphere(s): t = -b -+ sqrt(b^2 - c), the far root for origins inside.
template <int N>
inline vbool<N> intersect_sphere(const Vec3<N>& o, const Vec3<N>& d, const Vec3<N>& center, const vfloat<N>& r,
                                 const vfloat<N>& tmax, vfloat<N>& t) {
    const Vec3<N> oc = o - center;
    const vfloat<N> b = dot(oc, d);
    const vfloat<N> c = dot(oc, oc) - r * r;
    const vfloat<N> discriminant = b * b - c;
    const vfloat<N> root = simd::sqrt(discriminant);
    const vfloat<N> near_t = -b - root;
    const vfloat<N> zero(0.0f);
    t = simd::select(near_t > zero, near_t, -b + root);
    return (discriminant >= zero) & (t > zero) & (t < tmax);
}

inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

// ---- N rays against one primitive at a time -------------------------------------------------

template <int N>
struct RayPacket {
    Vec3<N> o, d;
    vfloat<N> tmax;
    vbool<N> active;  // lanes past the end of the queue are off
    int count;
};

template <int N>
inline RayPacket<N> load_rays(const RayView& rays, uint32_t first) {
    RayPacket<N> r;
    r.count = int(rays.count - first < uint32_t(N) ? rays.count - first : uint32_t(N));
    r.o = load_partial<N>(rays.ox, rays.oy, rays.oz, first, r.count);
    r.d = load_partial<N>(rays.dx, rays.dy, rays.dz, first, r.count);
    r.tmax = rays.tmax ? vfloat<N>::load_partial(rays.tmax + first, r.count, vfloat<N>(kInfinity)) : vfloat<N>(kInfinity);
    r.active = vint<N>::step() < vint<N>(r.count);
    return r;
}

template <int N>
void closest_raypacket(const SceneView& scene, const RayView& rays, const HitView& hits) {
    const TriangleView& tri = scene.triangles;
    const SphereView& sph = scene.spheres;
    for (uint32_t first = 0; first < rays.count; first += N) {
        const RayPacket<N> r = load_rays<N>(rays, first);
        vfloat<N> best_t = r.tmax, best_u(0.0f), best_v(0.0f);
        vint<N> best_prim(-1);
        for (uint32_t i = 0; i < tri.count; ++i) {
            vfloat<N> t, u, v;
            const vbool<N> hit = intersect_triangle(r.o, r.d, broadcast<N>(tri.v0x, tri.v0y, tri.v0z, i),
                                                    broadcast<N>(tri.e1x, tri.e1y, tri.e1z, i),
                                                    broadcast<N>(tri.e2x, tri.e2y, tri.e2z, i), best_t, t, u, v);
            if (simd::none(hit)) continue;
            best_t = simd::select(hit, t, best_t);
            best_u = simd::select(hit, u, best_u);
            best_v = simd::select(hit, v, best_v);
            best_prim = simd::select(hit, vint<N>(int32_t(i)), best_prim);
        }
        for (uint32_t i = 0; i < sph.count; ++i) {
            vfloat<N> t;
            const vbool<N> hit = intersect_sphere(r.o, r.d, broadcast<N>(sph.cx, sph.cy, sph.cz, i),
                                                  vfloat<N>(sph.radius[i]), best_t, t);
            if (simd::none(hit)) continue;
            best_t = simd::select(hit, t, best_t);
            best_u = simd::select(hit, vfloat<N>(0.0f), best_u);
            best_v = simd::select(hit, vfloat<N>(0.0f), best_v);
            best_prim = simd::select(hit, vint<N>(int32_t(sph.first_prim + i)), best_prim);
        }
        best_t = simd::select(best_prim == vint<N>(-1), vfloat<N>(kInfinity), best_t);
        vfloat<N>::store_partial(hits.t + first, best_t, r.count);
        vfloat<N>::store_partial(hits.u + first, best_u, r.count);
        vfloat<N>::store_partial(hits.v + first, best_v, r.count);
        vint<N>::store_partial(reinterpret_cast<int32_t*>(hits.prim + first), best_prim, r.count);
    }
}

template <int N>
void any_raypacket(const SceneView& scene, const RayView& rays, uint8_t* occluded) {
    const TriangleView& tri = scene.triangles;
    const SphereView& sph = scene.spheres;
    for (uint32_t first = 0; first < rays.count; first += N) {
        const RayPacket<N> r = load_rays<N>(rays, first);
        vbool<N> blocked(false);
        const vbool<N> inactive = ~r.active;
        for (uint32_t i = 0; i < tri.count && !simd::all(blocked | inactive); ++i) {
            vfloat<N> t, u, v;
            blocked |= intersect_triangle(r.o, r.d, broadcast<N>(tri.v0x, tri.v0y, tri.v0z, i),
                                          broadcast<N>(tri.e1x, tri.e1y, tri.e1z, i),
                                          broadcast<N>(tri.e2x, tri.e2y, tri.e2z, i), r.tmax, t, u, v);
        }
        for (uint32_t i = 0; i < sph.count && !simd::all(blocked | inactive); ++i) {
            vfloat<N> t;
            blocked |= intersect_sphere(r.o, r.d, broadcast<N>(sph.cx, sph.cy, sph.cz, i), vfloat<N>(sph.radius[i]),
                                        r.tmax, t);
        }
        const uint32_t bits = simd::movemask(blocked);
        for (int lane = 0; lane < r.count; ++lane) occluded[first + uint32_t(lane)] = uint8_t((bits >> lane) & 1u);
    }
}

// ---- one ray against N primitives at a time ------------------------------------------------

template <int N>
struct SingleRay {
    Vec3<N> o, d;
    float tmax;
};

template <int N>
inline SingleRay<N> broadcast_ray(const RayView& rays, uint32_t i) {
    return {broadcast<N>(rays.ox, rays.oy, rays.oz, i), broadcast<N>(rays.dx, rays.dy, rays.dz, i),
            rays.tmax ? rays.tmax[i] : kInfinity};
}

template <int N>
inline int lanes_left(uint32_t count, uint32_t first) {
    return int(count - first < uint32_t(N) ? count - first : uint32_t(N));
}

template <int N>
void closest_primpacket(const SceneView& scene, const RayView& rays, const HitView& hits) {
    const TriangleView& tri = scene.triangles;
    const SphereView& sph = scene.spheres;
    for (uint32_t ray = 0; ray < rays.count; ++ray) {
        const SingleRay<N> r = broadcast_ray<N>(rays, ray);
        // Each lane keeps the closest of the primitives it saw (its own strict <, in index
        // order, like the scalar loop); the lanes are reduced once at the end.
        vfloat<N> best_t(r.tmax), best_u(0.0f), best_v(0.0f);
        vint<N> best_prim(-1);
        for (uint32_t first = 0; first < tri.count; first += N) {
            const int n = lanes_left<N>(tri.count, first);
            vfloat<N> t, u, v;
            const vbool<N> hit = (vint<N>::step() < vint<N>(n)) &
                                 intersect_triangle(r.o, r.d, load_partial<N>(tri.v0x, tri.v0y, tri.v0z, first, n),
                                                    load_partial<N>(tri.e1x, tri.e1y, tri.e1z, first, n),
                                                    load_partial<N>(tri.e2x, tri.e2y, tri.e2z, first, n), best_t, t, u, v);
            best_t = simd::select(hit, t, best_t);
            best_u = simd::select(hit, u, best_u);
            best_v = simd::select(hit, v, best_v);
            best_prim = simd::select(hit, vint<N>::step() + vint<N>(int32_t(first)), best_prim);
        }
        for (uint32_t first = 0; first < sph.count; first += N) {
            const int n = lanes_left<N>(sph.count, first);
            vfloat<N> t;
            const vfloat<N> radius = vfloat<N>::load_partial(sph.radius + first, n, vfloat<N>(0.0f));
            const vbool<N> hit = (vint<N>::step() < vint<N>(n)) &
                                 intersect_sphere(r.o, r.d, load_partial<N>(sph.cx, sph.cy, sph.cz, first, n), radius,
                                                  best_t, t);
            best_t = simd::select(hit, t, best_t);
            best_u = simd::select(hit, vfloat<N>(0.0f), best_u);
            best_v = simd::select(hit, vfloat<N>(0.0f), best_v);
            best_prim = simd::select(hit, vint<N>::step() + vint<N>(int32_t(sph.first_prim + first)), best_prim);
        }
        // Closest over the lanes; on an exact tie the lowest primitive id wins, as in the scalar loop.
        const float closest = simd::reduce_min(best_t);
        uint32_t candidates = simd::movemask((best_t == vfloat<N>(closest)) & (best_prim != vint<N>(-1)));
        int winner = -1;
        for (; candidates; candidates &= candidates - 1) {
            const int lane = __builtin_ctz(candidates);
            if (winner < 0 || best_prim[lane] < best_prim[winner]) winner = lane;
        }
        if (winner < 0) {
            hits.t[ray] = kInfinity, hits.u[ray] = 0.0f, hits.v[ray] = 0.0f, hits.prim[ray] = UINT32_MAX;
        } else {
            hits.t[ray] = best_t[winner], hits.u[ray] = best_u[winner], hits.v[ray] = best_v[winner];
            hits.prim[ray] = uint32_t(best_prim[winner]);
        }
    }
}

template <int N>
void any_primpacket(const SceneView& scene, const RayView& rays, uint8_t* occluded) {
    const TriangleView& tri = scene.triangles;
    const SphereView& sph = scene.spheres;
    for (uint32_t ray = 0; ray < rays.count; ++ray) {
        const SingleRay<N> r = broadcast_ray<N>(rays, ray);
        const vfloat<N> tmax(r.tmax);
        bool blocked = false;
        for (uint32_t first = 0; first < tri.count && !blocked; first += N) {
            const int n = lanes_left<N>(tri.count, first);
            vfloat<N> t, u, v;
            blocked = simd::any((vint<N>::step() < vint<N>(n)) &
                                intersect_triangle(r.o, r.d, load_partial<N>(tri.v0x, tri.v0y, tri.v0z, first, n),
                                                   load_partial<N>(tri.e1x, tri.e1y, tri.e1z, first, n),
                                                   load_partial<N>(tri.e2x, tri.e2y, tri.e2z, first, n), tmax, t, u, v));
        }
        for (uint32_t first = 0; first < sph.count && !blocked; first += N) {
            const int n = lanes_left<N>(sph.count, first);
            vfloat<N> t;
            const vfloat<N> radius = vfloat<N>::load_partial(sph.radius + first, n, vfloat<N>(0.0f));
            blocked = simd::any((vint<N>::step() < vint<N>(n)) &
                                intersect_sphere(r.o, r.d, load_partial<N>(sph.cx, sph.cy, sph.cz, first, n), radius, tmax, t));
        }
        occluded[ray] = blocked;
    }
}

template <int N>
constexpr IntersectKernels make_intersect_kernels(Isa isa) {
    return {isa, N, &closest_raypacket<N>, &closest_primpacket<N>, &any_raypacket<N>, &any_primpacket<N>};
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::packet
