#pragma once
// The lane types every intersection test and traversal is written over: three vfloat<N> as a
// vector, the products in glm's order, and the per-lane hit record. N lanes are N rays against
// one primitive (a ray packet) or one ray against N primitives (a leaf or a chunk of the flat
// list); the arithmetic does not care which.
//
// The arithmetic is exactly the scalar code's (primitive_intersect.h): the same products, sums in
// the same order, the same IEEE divisions, and no fused multiply-add (the build passes
// -ffp-contract=off and nothing here calls madd). Every width on every ISA therefore returns
// the same bits as the scalar code, so an image is identical whichever kernels rendered it.
// The price is a few per cent against FMA (bench/README.md); what it buys is exact tests: with
// FMA, t differed from the textbook by up to 7e-6 relative on grazing rays, in either
// direction, and primitives flipped at shared edges.
//
// Everything lives in an ISA-specific inline namespace (see simd/isa.h), so the copies
// compiled for different instruction sets never get merged by the linker.

#include <cstdint>
#include <limits>

#include "simd/simd.h"

// For the functions of the per-ray and per-primitive hot loops. A translation unit holds every
// query, layout, accuracy option and node width of its ISA, and past GCC's unit-growth limits
// it stops inlining: the primitive tests then became calls taking their vectors through memory
// (measured as +4 % instructions on the SSE4 ray-packet loop and more in the BVH leaves).
#define WT_KERNEL_INLINE [[gnu::always_inline]] inline

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
WT_KERNEL_INLINE Vec3<N> operator-(const Vec3<N>& a, const Vec3<N>& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}

// The products and subtraction order of glm::cross.
template <int N>
WT_KERNEL_INLINE Vec3<N> cross(const Vec3<N>& a, const Vec3<N>& b) {
    return {a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y};
}

// The order of glm::dot: (x*x' + y*y') + z*z'.
template <int N>
WT_KERNEL_INLINE vfloat<N> dot(const Vec3<N>& a, const Vec3<N>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

template <int N>
WT_KERNEL_INLINE Vec3<N> broadcast(const float* x, const float* y, const float* z, uint32_t i) {
    return {vfloat<N>(x[i]), vfloat<N>(y[i]), vfloat<N>(z[i])};
}

template <int N>
WT_KERNEL_INLINE Vec3<N> load_partial(const float* x, const float* y, const float* z, uint32_t first, int count) {
    const vfloat<N> zero(0.0f);
    return {vfloat<N>::load_partial(x + first, count, zero), vfloat<N>::load_partial(y + first, count, zero),
            vfloat<N>::load_partial(z + first, count, zero)};
}

// The component of a chosen by a per-lane axis index, given as the masks "index is 0" and
// "index is 1" (else 2).
template <int N>
WT_KERNEL_INLINE vfloat<N> pick(const Vec3<N>& a, const vbool<N>& is0, const vbool<N>& is1) {
    return simd::select(is0, a.x, simd::select(is1, a.y, a.z));
}

// One primitive test per lane. The barycentrics stay a numerator and a denominator until the
// closest hit is known, so a ray pays two divisions for its u, v instead of two per primitive.
template <int N>
struct LaneHits {
    vfloat<N> t, u_num, v_num, den;
};

template <int N>
WT_KERNEL_INLINE LaneHits<N> select(const vbool<N>& m, const LaneHits<N>& a, const LaneHits<N>& b) {
    return {simd::select(m, a.t, b.t), simd::select(m, a.u_num, b.u_num), simd::select(m, a.v_num, b.v_num),
            simd::select(m, a.den, b.den)};
}

// What a sphere hit (or no hit) keeps: u = v = 0 / 1.
template <int N>
WT_KERNEL_INLINE LaneHits<N> sphere_hits(const vfloat<N>& t) {
    return {t, vfloat<N>(0.0f), vfloat<N>(0.0f), vfloat<N>(1.0f)};
}

inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

}  // namespace WT_SIMD_ISA
}  // namespace wt::packet
