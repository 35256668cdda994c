#pragma once
// Ray(s) against spheres for N lanes: the textbook quadratic or the cancellation-free form of
// Ray Tracing Gems ch. 7, as intersect_sphere() and intersect_sphere_cancellation_free() in
// primitive_intersect.h, with the same bits.

#include "core/base/accuracy.h"
#include "kernels/primitives/lanes.h"

namespace wt::packet {
inline namespace WT_SIMD_ISA {

// The textbook quadratic: t = -b -+ sqrt(b^2 - c), the far root for origins inside.
template <SphereTest S, int N>
WT_KERNEL_INLINE vbool<N> intersect_spheres(const Vec3<N>& o, const Vec3<N>& d, const Vec3<N>& center, const vfloat<N>& r,
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

}  // namespace WT_SIMD_ISA
}  // namespace wt::packet
