#pragma once
// Ray(s) against triangles and parallelograms for N lanes: Moller-Trumbore on the precomputed
// scaled normal, and the watertight test of Woop, Benthin & Wald. The scalar versions, which
// explain the arithmetic, are in primitive_intersect.h; these return the same bits.

#include <cstdint>
#include <type_traits>

#include "core/base/accuracy.h"
#include "kernels/primitives/lanes.h"
#include "kernels/primitives/soa_views.h"

namespace wt::packet {
inline namespace WT_SIMD_ISA {

// What the triangle test needs to know about the ray(s), computed once per packet or ray.
template <TriangleTest T, int N>
struct TriangleRays;

template <int N>
struct TriangleRays<TriangleTest::moller_trumbore, N> {
    Vec3<N> o, d;
    [[gnu::always_inline]] TriangleRays(const Vec3<N>& origin, const Vec3<N>& direction) : o(origin), d(direction) {}
};

// Watertight: per lane, the axis permutation (as masks) and the shear of watertight_ray().
template <int N>
struct TriangleRays<TriangleTest::watertight, N> {
    Vec3<N> o;
    vbool<N> kx0, kx1, ky0, ky1, kz0, kz1;
    vfloat<N> sx, sy, sz;

    [[gnu::always_inline]] TriangleRays(const Vec3<N>& origin, const Vec3<N>& d) : o(origin) {
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

// A Moller-Trumbore triangle from a BVH leaf, which keeps no normal (bvh_view.h): its scaled
// normal is cross(e1, e2) in glm::cross's order, the bits the flat arrays store.
template <int N>
WT_KERNEL_INLINE TriangleLanes<N> with_scaled_normal(const Vec3<N>& v0, const Vec3<N>& e1, const Vec3<N>& e2) {
    return {v0, e1, e2, cross(e1, e2)};
}

template <TriangleTest T, int N>
WT_KERNEL_INLINE TriangleLanes<N> broadcast_triangle(const TriangleView& t, uint32_t i) {
    if constexpr (T == TriangleTest::watertight)
        return {broadcast<N>(t.v0x, t.v0y, t.v0z, i), broadcast<N>(t.v1x, t.v1y, t.v1z, i), broadcast<N>(t.v2x, t.v2y, t.v2z, i), {}};
    else
        return {broadcast<N>(t.v0x, t.v0y, t.v0z, i), broadcast<N>(t.e1x, t.e1y, t.e1z, i), broadcast<N>(t.e2x, t.e2y, t.e2z, i),
                broadcast<N>(t.nx, t.ny, t.nz, i)};
}

template <TriangleTest T, int N>
WT_KERNEL_INLINE TriangleLanes<N> load_triangles(const TriangleView& t, uint32_t first, int count) {
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
WT_KERNEL_INLINE void for_each_planar_range(const TriangleView& tri, F&& f) {
    const uint32_t parallelograms = T == TriangleTest::moller_trumbore ? tri.parallelogram_count : 0u;
    const uint32_t split = parallelograms < tri.count ? parallelograms : tri.count;  // a view cut short stays in bounds
    f(PlanarShape<Planar::parallelogram>{}, 0u, split);
    f(PlanarShape<Planar::triangle>{}, split, tri.count);
}

// Moller-Trumbore with the precomputed scaled normal, as intersect_triangle() in
// primitive_intersect.h (which explains the rearrangement). A lane hits when t is in (0, tmax)
// and the barycentrics are inside; den == 0 (parallel ray, degenerate triangle) and NaNs never hit.
template <Planar P, int N>
WT_KERNEL_INLINE vbool<N> intersect_triangles(const TriangleRays<TriangleTest::moller_trumbore, N>& r, const TriangleLanes<N>& tri,
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
    // (moving it last is measurably faster on AVX-512 incoherent closest hits: bench/README.md).
    const vfloat<N> zero(0.0f);
    vbool<N> below_far_edges;
    if constexpr (P == Planar::parallelogram)
        below_far_edges = (h.u_num <= h.den) & (h.v_num <= h.den);
    else
        below_far_edges = h.u_num + h.v_num <= h.den;
    const vbool<N> inside = (h.u_num >= zero) & (h.v_num >= zero) & below_far_edges & (h.t > zero);
    return inside & (h.t < tmax);
}

// The lanes of e (= px*qy - py*qx in float) that came out exactly 0, recomputed in double.
// Out of line: it runs for a handful of rays in a million, and inlined it would crowd the loop.
template <int N>
[[gnu::noinline]] vfloat<N> edge_function_retry(vfloat<N> e, vfloat<N> px, vfloat<N> py, vfloat<N> qx, vfloat<N> qy,
                                                uint32_t zero_lanes) {
    alignas(64) float out[N], a[N], b[N], c[N], d[N];
    vfloat<N>::storeu(out, e), vfloat<N>::storeu(a, px), vfloat<N>::storeu(b, qy), vfloat<N>::storeu(c, py),
        vfloat<N>::storeu(d, qx);
    for (; zero_lanes; zero_lanes &= zero_lanes - 1) {
        const int l = __builtin_ctz(zero_lanes);
        out[l] = float(double(a[l]) * double(b[l]) - double(c[l]) * double(d[l]));
    }
    return vfloat<N>::loadu(out);
}

// px*qy - py*qx, recomputed in double in the lanes where float gives exactly 0 (as
// edge_function() in primitive_intersect.h). Only `active` lanes are retried, so padding
// lanes never cost a fallback.
template <int N>
WT_KERNEL_INLINE vfloat<N> edge_function(const vfloat<N>& px, const vfloat<N>& py, const vfloat<N>& qx, const vfloat<N>& qy,
                                         const vbool<N>& active) {
    const vfloat<N> e = px * qy - py * qx;
    const uint32_t zero_lanes = simd::movemask(active & (e == vfloat<N>(0.0f)));
    if (__builtin_expect(zero_lanes == 0, 1)) return e;
    return edge_function_retry<N>(e, px, py, qx, qy, zero_lanes);
}

// Woop, Benthin & Wald 2013, as intersect_triangle_watertight() in primitive_intersect.h.
// Triangles only (for_each_planar_range gives it an empty parallelogram range).
template <Planar, int N>
WT_KERNEL_INLINE vbool<N> intersect_triangles(const TriangleRays<TriangleTest::watertight, N>& r, const TriangleLanes<N>& tri,
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

}  // namespace WT_SIMD_ISA
}  // namespace wt::packet
