#pragma once
// Triangles (Moller-Trumbore or watertight) and spheres (quadratic or cancellation-free) for N
// lanes, written once over simd::vfloat<N> and instantiated per width in the per-ISA
// translation units, and per accuracy setting as template parameters.
//
// The arithmetic is exactly the scalar code's (primitive_intersect.h): the same products, sums in
// the same order, one IEEE division, and no fused multiply-add (the build passes
// -ffp-contract=off and this file calls no madd). Every width on every ISA therefore returns
// the same bits as the scalar code, so an image is identical whichever kernels rendered it.
// That cost about 8% end to end against an FMA version (hexroom 200x200, 16 spp, one thread,
// AVX-512: 0.83-0.84 s with FMA against 0.90-0.97 s without, three runs each), and buys exact
// tests: with FMA, t differed from the textbook by up to 7e-6 relative on grazing rays, in
// either direction, and primitives flipped at shared edges.
//
// Everything lives in an ISA-specific inline namespace (see simd/isa.h), so the copies
// compiled for different instruction sets never get merged by the linker.

#include <cstdint>
#include <limits>

#include "core/accuracy.h"
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
// The component of a chosen by a per-lane axis index, given as the masks "index is 0" and
// "index is 1" (else 2).
template <int N>
inline vfloat<N> pick(const Vec3<N>& a, const vbool<N>& is0, const vbool<N>& is1) {
    return simd::select(is0, a.x, simd::select(is1, a.y, a.z));
}

// What the triangle test needs to know about the ray(s), computed once per packet or ray.
template <TriangleTest T, int N>
struct TriangleRays;

template <int N>
struct TriangleRays<TriangleTest::moller_trumbore, N> {
    Vec3<N> o, d;
    TriangleRays(const Vec3<N>& origin, const Vec3<N>& direction) : o(origin), d(direction) {}
};

// Watertight: per lane, the axis permutation (as masks) and the shear of watertight_ray().
template <int N>
struct TriangleRays<TriangleTest::watertight, N> {
    Vec3<N> o;
    vbool<N> kx0, kx1, ky0, ky1, kz0, kz1;
    vfloat<N> sx, sy, sz;

    TriangleRays(const Vec3<N>& origin, const Vec3<N>& d) : o(origin) {
        const vfloat<N> ax = simd::abs(d.x), ay = simd::abs(d.y), az = simd::abs(d.z);
        const vbool<N> x_over_y = ax > ay;
        kz0 = x_over_y & (ax > az);
        kz1 = ~x_over_y & (ay > az);
        const vbool<N> kz2 = ~(kz0 | kz1);
        // kx = kz + 1 and ky = kx + 1 (mod 3), swapped when the ray runs down its dominant axis.
        const vfloat<N> dz = pick(d, kz0, kz1);
        const vbool<N> flip = dz < vfloat<N>(0.0f);
        const vbool<N> kx0_plain = kz2, kx1_plain = kz0, ky0_plain = kz1, ky1_plain = kz2;
        kx0 = (flip & ky0_plain) | (~flip & kx0_plain);
        kx1 = (flip & ky1_plain) | (~flip & kx1_plain);
        ky0 = (flip & kx0_plain) | (~flip & ky0_plain);
        ky1 = (flip & kx1_plain) | (~flip & ky1_plain);
        sx = pick(d, kx0, kx1) / dz;
        sy = pick(d, ky0, ky1) / dz;
        sz = vfloat<N>(1.0f) / dz;
    }
};

// Triangle data as each test reads it: v0 and the edges for Moller-Trumbore, the three
// vertices for the watertight test.
template <int N>
struct TriangleLanes {
    Vec3<N> p0, p1, p2;
};

template <TriangleTest T, int N>
inline TriangleLanes<N> broadcast_triangle(const TriangleView& t, uint32_t i) {
    if constexpr (T == TriangleTest::watertight)
        return {broadcast<N>(t.v0x, t.v0y, t.v0z, i), broadcast<N>(t.v1x, t.v1y, t.v1z, i), broadcast<N>(t.v2x, t.v2y, t.v2z, i)};
    else
        return {broadcast<N>(t.v0x, t.v0y, t.v0z, i), broadcast<N>(t.e1x, t.e1y, t.e1z, i), broadcast<N>(t.e2x, t.e2y, t.e2z, i)};
}

template <TriangleTest T, int N>
inline TriangleLanes<N> load_triangles(const TriangleView& t, uint32_t first, int count) {
    if constexpr (T == TriangleTest::watertight)
        return {load_partial<N>(t.v0x, t.v0y, t.v0z, first, count), load_partial<N>(t.v1x, t.v1y, t.v1z, first, count),
                load_partial<N>(t.v2x, t.v2y, t.v2z, first, count)};
    else
        return {load_partial<N>(t.v0x, t.v0y, t.v0z, first, count), load_partial<N>(t.e1x, t.e1y, t.e1z, first, count),
                load_partial<N>(t.e2x, t.e2y, t.e2z, first, count)};
}

// Moller-Trumbore. A lane hits when t is in (0, tmax) and the barycentrics are inside;
// det == 0 (parallel ray, degenerate triangle) and NaNs never hit.
template <int N>
inline vbool<N> intersect_triangles(const TriangleRays<TriangleTest::moller_trumbore, N>& r, const TriangleLanes<N>& tri,
                                    const vbool<N>&, const vfloat<N>& tmax, vfloat<N>& t, vfloat<N>& u, vfloat<N>& v) {
    const Vec3<N>&v0 = tri.p0, &e1 = tri.p1, &e2 = tri.p2;
    const Vec3<N> p = cross(r.d, e2);
    const vfloat<N> det = dot(e1, p);
    const vfloat<N> inv_det = vfloat<N>(1.0f) / det;
    const Vec3<N> s = r.o - v0;
    u = dot(s, p) * inv_det;
    const Vec3<N> q = cross(s, e1);
    v = dot(r.d, q) * inv_det;
    t = dot(e2, q) * inv_det;
    const vfloat<N> zero(0.0f), one(1.0f);
    return (det != zero) & (u >= zero) & (u <= one) & (v >= zero) & (u + v <= one) & (t > zero) & (t < tmax);
}

// px*qy - py*qx, recomputed in double in the lanes where float gives exactly 0 (as
// edge_function() in primitive_intersect.h). Only `active` lanes are retried, so padding
// lanes never cost a fallback.
template <int N>
inline vfloat<N> edge_function(const vfloat<N>& px, const vfloat<N>& py, const vfloat<N>& qx, const vfloat<N>& qy,
                               const vbool<N>& active) {
    const vfloat<N> e = px * qy - py * qx;
    uint32_t zero_lanes = simd::movemask(active & (e == vfloat<N>(0.0f)));
    if (zero_lanes == 0) return e;
    alignas(64) float out[N], a[N], b[N], c[N], d[N];
    vfloat<N>::storeu(out, e), vfloat<N>::storeu(a, px), vfloat<N>::storeu(b, qy), vfloat<N>::storeu(c, py),
        vfloat<N>::storeu(d, qx);
    for (; zero_lanes; zero_lanes &= zero_lanes - 1) {
        const int l = __builtin_ctz(zero_lanes);
        out[l] = float(double(a[l]) * double(b[l]) - double(c[l]) * double(d[l]));
    }
    return vfloat<N>::loadu(out);
}

// Woop, Benthin & Wald 2013, as intersect_triangle_watertight() in primitive_intersect.h.
template <int N>
inline vbool<N> intersect_triangles(const TriangleRays<TriangleTest::watertight, N>& r, const TriangleLanes<N>& tri,
                                    const vbool<N>& active, const vfloat<N>& tmax, vfloat<N>& t, vfloat<N>& u,
                                    vfloat<N>& v) {
    const Vec3<N> a = tri.p0 - r.o, b = tri.p1 - r.o, c = tri.p2 - r.o;
    const vfloat<N> az = pick(a, r.kz0, r.kz1), bz = pick(b, r.kz0, r.kz1), cz = pick(c, r.kz0, r.kz1);
    const vfloat<N> ax = pick(a, r.kx0, r.kx1) - r.sx * az, ay = pick(a, r.ky0, r.ky1) - r.sy * az;
    const vfloat<N> bx = pick(b, r.kx0, r.kx1) - r.sx * bz, by = pick(b, r.ky0, r.ky1) - r.sy * bz;
    const vfloat<N> cx = pick(c, r.kx0, r.kx1) - r.sx * cz, cy = pick(c, r.ky0, r.ky1) - r.sy * cz;
    const vfloat<N> w0 = edge_function(cx, cy, bx, by, active);
    const vfloat<N> w1 = edge_function(ax, ay, cx, cy, active);
    const vfloat<N> w2 = edge_function(bx, by, ax, ay, active);
    const vfloat<N> zero(0.0f);
    const vbool<N> mixed_signs = ((w0 < zero) | (w1 < zero) | (w2 < zero)) & ((w0 > zero) | (w1 > zero) | (w2 > zero));
    const vfloat<N> det = w0 + w1 + w2;
    const vfloat<N> scaled_t = w0 * (r.sz * az) + w1 * (r.sz * bz) + w2 * (r.sz * cz);
    const vfloat<N> inv_det = vfloat<N>(1.0f) / det;
    t = scaled_t * inv_det;
    u = w1 * inv_det;
    v = w2 * inv_det;
    return ~mixed_signs & (det != zero) & (t > zero) & (t < tmax);
}

// The textbook quadratic: t = -b -+ sqrt(b^2 - c), the far root for origins inside.
template <SphereTest S, int N>
inline vbool<N> intersect_spheres(const Vec3<N>& o, const Vec3<N>& d, const Vec3<N>& center, const vfloat<N>& r,
                                  const vfloat<N>& tmax, vfloat<N>& t) {
    const vfloat<N> zero(0.0f);
    if constexpr (S == SphereTest::quadratic) {
        const Vec3<N> oc = o - center;
        const vfloat<N> b = dot(oc, d);
        const vfloat<N> c = dot(oc, oc) - r * r;
        const vfloat<N> discriminant = b * b - c;
        const vfloat<N> root = simd::sqrt(discriminant);
        const vfloat<N> near_t = -b - root;
        t = simd::select(near_t > zero, near_t, -b + root);
        return (discriminant >= zero) & (t > zero) & (t < tmax);
    } else {
        // Ray Tracing Gems ch. 7, as intersect_sphere_cancellation_free().
        const Vec3<N> f = o - center;
        const vfloat<N> b = dot(f, d);
        const Vec3<N> closest{f.x - b * d.x, f.y - b * d.y, f.z - b * d.z};
        const vfloat<N> discriminant = r * r - dot(closest, closest);
        const vfloat<N> c = dot(f, f) - r * r;
        const vint<N> sign_bit(INT32_MIN);
        const vfloat<N> signed_root = simd::asFloat((simd::asInt(simd::sqrt(discriminant)) & ~sign_bit) | (simd::asInt(b) & sign_bit));
        const vfloat<N> q = -b - signed_root;
        const vfloat<N> t0 = c / q, t1 = q;
        const vbool<N> first_nearer = t0 < t1;
        const vfloat<N> near_t = simd::select(first_nearer, t0, t1), far_t = simd::select(first_nearer, t1, t0);
        t = simd::select(near_t > zero, near_t, far_t);
        return (discriminant >= zero) & (t > zero) & (t < tmax);
    }
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

template <TriangleTest T, SphereTest S, int N>
void closest_raypacket(const SceneView& scene, const RayView& rays, const HitView& hits) {
    const TriangleView& tri = scene.triangles;
    const SphereView& sph = scene.spheres;
    for (uint32_t first = 0; first < rays.count; first += N) {
        const RayPacket<N> r = load_rays<N>(rays, first);
        const TriangleRays<T, N> tr(r.o, r.d);
        vfloat<N> best_t = r.tmax, best_u(0.0f), best_v(0.0f);
        vint<N> best_prim(-1);
        // Branch-free: with incoherent rays "no lane hit this primitive" is a coin flip, and
        // the mispredicted branch cost more than the four selects it skipped (bench/README.md).
        for (uint32_t i = 0; i < tri.count; ++i) {
            vfloat<N> t, u, v;
            const vbool<N> hit = intersect_triangles(tr, broadcast_triangle<T, N>(tri, i), r.active, best_t, t, u, v);
            best_t = simd::select(hit, t, best_t);
            best_u = simd::select(hit, u, best_u);
            best_v = simd::select(hit, v, best_v);
            best_prim = simd::select(hit, vint<N>(int32_t(i)), best_prim);
        }
        for (uint32_t i = 0; i < sph.count; ++i) {
            vfloat<N> t;
            const vbool<N> hit = intersect_spheres<S>(r.o, r.d, broadcast<N>(sph.cx, sph.cy, sph.cz, i),
                                                                 vfloat<N>(sph.radius[i]), best_t, t);
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

template <TriangleTest T, SphereTest S, int N>
void any_raypacket(const SceneView& scene, const RayView& rays, uint8_t* occluded) {
    const TriangleView& tri = scene.triangles;
    const SphereView& sph = scene.spheres;
    for (uint32_t first = 0; first < rays.count; first += N) {
        const RayPacket<N> r = load_rays<N>(rays, first);
        const TriangleRays<T, N> tr(r.o, r.d);
        vbool<N> blocked(false);
        const vbool<N> inactive = ~r.active;
        for (uint32_t i = 0; i < tri.count && !simd::all(blocked | inactive); ++i) {
            vfloat<N> t, u, v;
            blocked |= intersect_triangles(tr, broadcast_triangle<T, N>(tri, i), r.active, r.tmax, t, u, v);
        }
        for (uint32_t i = 0; i < sph.count && !simd::all(blocked | inactive); ++i) {
            vfloat<N> t;
            blocked |= intersect_spheres<S>(r.o, r.d, broadcast<N>(sph.cx, sph.cy, sph.cz, i), vfloat<N>(sph.radius[i]),
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

template <TriangleTest T, SphereTest S, int N>
void closest_primpacket(const SceneView& scene, const RayView& rays, const HitView& hits) {
    const TriangleView& tri = scene.triangles;
    const SphereView& sph = scene.spheres;
    for (uint32_t ray = 0; ray < rays.count; ++ray) {
        const SingleRay<N> r = broadcast_ray<N>(rays, ray);
        const TriangleRays<T, N> tr(r.o, r.d);
        // Each lane keeps the closest of the primitives it saw (its own strict <, in index
        // order, like the scalar loop); the lanes are reduced once at the end.
        vfloat<N> best_t(r.tmax), best_u(0.0f), best_v(0.0f);
        vint<N> best_prim(-1);
        for (uint32_t first = 0; first < tri.count; first += N) {
            const int n = lanes_left<N>(tri.count, first);
            const vbool<N> lanes = vint<N>::step() < vint<N>(n);
            vfloat<N> t, u, v;
            const vbool<N> hit = lanes & intersect_triangles(tr, load_triangles<T, N>(tri, first, n), lanes, best_t, t, u, v);
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
                                 intersect_spheres<S>(r.o, r.d, load_partial<N>(sph.cx, sph.cy, sph.cz, first, n), radius,
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

template <TriangleTest T, SphereTest S, int N>
void any_primpacket(const SceneView& scene, const RayView& rays, uint8_t* occluded) {
    const TriangleView& tri = scene.triangles;
    const SphereView& sph = scene.spheres;
    for (uint32_t ray = 0; ray < rays.count; ++ray) {
        const SingleRay<N> r = broadcast_ray<N>(rays, ray);
        const TriangleRays<T, N> tr(r.o, r.d);
        const vfloat<N> tmax(r.tmax);
        bool blocked = false;
        for (uint32_t first = 0; first < tri.count && !blocked; first += N) {
            const int n = lanes_left<N>(tri.count, first);
            const vbool<N> lanes = vint<N>::step() < vint<N>(n);
            vfloat<N> t, u, v;
            blocked = simd::any(lanes & intersect_triangles(tr, load_triangles<T, N>(tri, first, n), lanes, tmax, t, u, v));
        }
        for (uint32_t first = 0; first < sph.count && !blocked; first += N) {
            const int n = lanes_left<N>(sph.count, first);
            vfloat<N> t;
            const vfloat<N> radius = vfloat<N>::load_partial(sph.radius + first, n, vfloat<N>(0.0f));
            blocked = simd::any((vint<N>::step() < vint<N>(n)) &
                                intersect_spheres<S>(r.o, r.d, load_partial<N>(sph.cx, sph.cy, sph.cz, first, n), radius, tmax, t));
        }
        occluded[ray] = blocked;
    }
}

template <TriangleTest T, SphereTest S, int N>
constexpr IntersectKernels make_kernels(Isa isa) {
    return {isa, N, &closest_raypacket<T, S, N>, &closest_primpacket<T, S, N>, &any_raypacket<T, S, N>, &any_primpacket<T, S, N>};
}

// One table entry per accuracy combination, in the order kernel_variant() indexes them:
// (Moller-Trumbore, quadratic), (MT, cancellation-free), (watertight, quadratic), (watertight, c.-f.).
template <int N>
struct KernelVariants {
    IntersectKernels variants[kKernelVariantCount];
};

template <int N>
constexpr KernelVariants<N> make_intersect_kernels(Isa isa) {
    return {{make_kernels<TriangleTest::moller_trumbore, SphereTest::quadratic, N>(isa),
             make_kernels<TriangleTest::moller_trumbore, SphereTest::cancellation_free, N>(isa),
             make_kernels<TriangleTest::watertight, SphereTest::quadratic, N>(isa),
             make_kernels<TriangleTest::watertight, SphereTest::cancellation_free, N>(isa)}};
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::packet
