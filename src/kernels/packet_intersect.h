#pragma once
// Triangles (Moller-Trumbore or watertight) and spheres (quadratic or cancellation-free) for N
// lanes, written once over simd::vfloat<N> and instantiated per width in the per-ISA
// translation units, and per accuracy setting as template parameters.
//
// The arithmetic is exactly the scalar code's (primitive_intersect.h): the same products, sums in
// the same order, the same IEEE divisions, and no fused multiply-add (the build passes
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
#include <type_traits>

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

// Triangle data as each test reads it: v0, the edges and the scaled normal for
// Moller-Trumbore, the three vertices for the watertight test (n unused).
template <int N>
struct TriangleLanes {
    Vec3<N> p0, p1, p2, n;
};

// One primitive test per lane. The barycentrics stay a numerator and a denominator until the
// closest hit is known, so a ray pays two divisions for its u, v instead of two per primitive.
template <int N>
struct LaneHits {
    vfloat<N> t, u_num, v_num, den;
};

template <int N>
inline LaneHits<N> select(const vbool<N>& m, const LaneHits<N>& a, const LaneHits<N>& b) {
    return {simd::select(m, a.t, b.t), simd::select(m, a.u_num, b.u_num), simd::select(m, a.v_num, b.v_num),
            simd::select(m, a.den, b.den)};
}

// What a sphere hit (or no hit) keeps: u = v = 0 / 1.
template <int N>
inline LaneHits<N> sphere_hits(const vfloat<N>& t) {
    return {t, vfloat<N>(0.0f), vfloat<N>(0.0f), vfloat<N>(1.0f)};
}

template <TriangleTest T, int N>
inline TriangleLanes<N> broadcast_triangle(const TriangleView& t, uint32_t i) {
    if constexpr (T == TriangleTest::watertight)
        return {broadcast<N>(t.v0x, t.v0y, t.v0z, i), broadcast<N>(t.v1x, t.v1y, t.v1z, i), broadcast<N>(t.v2x, t.v2y, t.v2z, i), {}};
    else
        return {broadcast<N>(t.v0x, t.v0y, t.v0z, i), broadcast<N>(t.e1x, t.e1y, t.e1z, i), broadcast<N>(t.e2x, t.e2y, t.e2z, i),
                broadcast<N>(t.nx, t.ny, t.nz, i)};
}

template <TriangleTest T, int N>
inline TriangleLanes<N> load_triangles(const TriangleView& t, uint32_t first, int count) {
    if constexpr (T == TriangleTest::watertight)
        return {load_partial<N>(t.v0x, t.v0y, t.v0z, first, count), load_partial<N>(t.v1x, t.v1y, t.v1z, first, count),
                load_partial<N>(t.v2x, t.v2y, t.v2z, first, count), {}};
    else
        return {load_partial<N>(t.v0x, t.v0y, t.v0z, first, count), load_partial<N>(t.e1x, t.e1y, t.e1z, first, count),
                load_partial<N>(t.e2x, t.e2y, t.e2z, first, count), load_partial<N>(t.nx, t.ny, t.nz, first, count)};
}

// The two planar shapes TriangleSoA holds (parallelograms first, then triangles), as a
// template argument so each range of the loop gets its own straight-line inside test.
enum class Planar { parallelogram, triangle };
template <Planar P>
using PlanarShape = std::integral_constant<Planar, P>;

// Calls f(shape, begin, end) for the parallelogram entries, then for the triangles. Only
// Moller-Trumbore scenes have parallelograms (build_scene splits quads for the watertight test).
template <TriangleTest T, typename F>
inline void for_each_planar_range(const TriangleView& tri, F&& f) {
    const uint32_t parallelograms = T == TriangleTest::moller_trumbore ? tri.parallelogram_count : 0u;
    const uint32_t split = parallelograms < tri.count ? parallelograms : tri.count;  // a view cut short stays in bounds
    f(PlanarShape<Planar::parallelogram>{}, 0u, split);
    f(PlanarShape<Planar::triangle>{}, split, tri.count);
}

// Moller-Trumbore with the precomputed scaled normal, as intersect_triangle() in
// primitive_intersect.h (which explains the rearrangement). A lane hits when t is in (0, tmax)
// and the barycentrics are inside; den == 0 (parallel ray, degenerate triangle) and NaNs never hit.
template <Planar P, int N>
inline vbool<N> intersect_triangles(const TriangleRays<TriangleTest::moller_trumbore, N>& r, const TriangleLanes<N>& tri,
                                    const vbool<N>&, const vfloat<N>& tmax, LaneHits<N>& h) {
    const Vec3<N>&v0 = tri.p0, &e1 = tri.p1, &e2 = tri.p2, &n = tri.n;
    const vfloat<N> den = dot(r.d, n);
    const Vec3<N> c = v0 - r.o;
    const Vec3<N> cr = cross(c, r.d);
    h.den = simd::abs(den);
    h.u_num = simd::flip_sign(dot(e2, cr), den);
    h.v_num = -simd::flip_sign(dot(e1, cr), den);
    h.t = dot(c, n) / den;  // the same bits as flip_sign(c.n, den) / |den|: IEEE division is sign-symmetric
    // No den != 0 test: with den = 0, t is +-inf or NaN and fails 0 < t < tmax anyway. The
    // test against tmax (in the closest-hit loop, the closest hit so far, carried from
    // primitive to primitive) is and-ed in last: GCC turns the and-ed compares into a chain of
    // masked compares, and with tmax first the loop-carried dependency ran through all of them
    // (moving it last gained about 15 % on AVX-512 incoherent closest hits, interleaved runs).
    const vfloat<N> zero(0.0f);
    vbool<N> below_far_edges;
    if constexpr (P == Planar::parallelogram)
        below_far_edges = (h.u_num <= h.den) & (h.v_num <= h.den);
    else
        below_far_edges = h.u_num + h.v_num <= h.den;
    const vbool<N> inside = (h.u_num >= zero) & (h.v_num >= zero) & below_far_edges & (h.t > zero);
    return inside & (h.t < tmax);
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
// Triangles only (for_each_planar_range gives it an empty parallelogram range).
template <Planar, int N>
inline vbool<N> intersect_triangles(const TriangleRays<TriangleTest::watertight, N>& r, const TriangleLanes<N>& tri,
                                    const vbool<N>& active, const vfloat<N>& tmax, LaneHits<N>& h) {
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
    h.t = scaled_t / det;
    h.u_num = w1;
    h.v_num = w2;
    h.den = det;
    return ~mixed_signs & (det != zero) & (h.t > zero) & (h.t < tmax);
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
        LaneHits<N> best = sphere_hits(r.tmax);
        vint<N> best_prim(-1), prim(0);
        // Branch-free: with incoherent rays "no lane hit this primitive" is a coin flip, and
        // the mispredicted branch cost more than the selects it skipped (bench/README.md).
        // The primitive id rides along as a vector (one add) rather than a broadcast of i,
        // which the compiler turned into three moves.
        for_each_planar_range<T>(tri, [&](auto shape, uint32_t begin, uint32_t end) {
            for (uint32_t i = begin; i < end; ++i, prim += vint<N>(1)) {
                LaneHits<N> h;
                const vbool<N> hit =
                    intersect_triangles<shape.value>(tr, broadcast_triangle<T, N>(tri, i), r.active, best.t, h);
                best = select(hit, h, best);
                best_prim = simd::select(hit, prim, best_prim);
            }
        });
        for (uint32_t i = 0; i < sph.count; ++i) {
            vfloat<N> t;
            const vbool<N> hit = intersect_spheres<S>(r.o, r.d, broadcast<N>(sph.cx, sph.cy, sph.cz, i),
                                                                 vfloat<N>(sph.radius[i]), best.t, t);
            best = select(hit, sphere_hits(t), best);
            best_prim = simd::select(hit, vint<N>(int32_t(sph.first_prim + i)), best_prim);
        }
        const vfloat<N> best_t = simd::select(best_prim == vint<N>(-1), vfloat<N>(kInfinity), best.t);
        vfloat<N>::store_partial(hits.t + first, best_t, r.count);
        vfloat<N>::store_partial(hits.u + first, best.u_num / best.den, r.count);
        vfloat<N>::store_partial(hits.v + first, best.v_num / best.den, r.count);
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
        for_each_planar_range<T>(tri, [&](auto shape, uint32_t begin, uint32_t end) {
            for (uint32_t i = begin; i < end && !simd::all(blocked | inactive); ++i) {
                LaneHits<N> h;
                blocked |= intersect_triangles<shape.value>(tr, broadcast_triangle<T, N>(tri, i), r.active, r.tmax, h);
            }
        });
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
        LaneHits<N> best = sphere_hits(vfloat<N>(r.tmax));
        vint<N> best_prim(-1);
        for_each_planar_range<T>(tri, [&](auto shape, uint32_t begin, uint32_t end) {
            for (uint32_t first = begin; first < end; first += N) {
                const int n = lanes_left<N>(end, first);
                const vbool<N> lanes = vint<N>::step() < vint<N>(n);
                LaneHits<N> h;
                const vbool<N> hit =
                    lanes & intersect_triangles<shape.value>(tr, load_triangles<T, N>(tri, first, n), lanes, best.t, h);
                best = select(hit, h, best);
                best_prim = simd::select(hit, vint<N>::step() + vint<N>(int32_t(first)), best_prim);
            }
        });
        for (uint32_t first = 0; first < sph.count; first += N) {
            const int n = lanes_left<N>(sph.count, first);
            vfloat<N> t;
            const vfloat<N> radius = vfloat<N>::load_partial(sph.radius + first, n, vfloat<N>(0.0f));
            const vbool<N> hit = (vint<N>::step() < vint<N>(n)) &
                                 intersect_spheres<S>(r.o, r.d, load_partial<N>(sph.cx, sph.cy, sph.cz, first, n), radius,
                                                      best.t, t);
            best = select(hit, sphere_hits(t), best);
            best_prim = simd::select(hit, vint<N>::step() + vint<N>(int32_t(sph.first_prim + first)), best_prim);
        }
        // Closest over the lanes; on an exact tie the lowest primitive id wins, as in the scalar loop.
        const float closest = simd::reduce_min(best.t);
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
        for_each_planar_range<T>(tri, [&](auto shape, uint32_t begin, uint32_t end) {
            for (uint32_t first = begin; first < end && !blocked; first += N) {
                const int n = lanes_left<N>(end, first);
                const vbool<N> lanes = vint<N>::step() < vint<N>(n);
                LaneHits<N> h;
                blocked = simd::any(lanes &
                                    intersect_triangles<shape.value>(tr, load_triangles<T, N>(tri, first, n), lanes, tmax, h));
            }
        });
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
