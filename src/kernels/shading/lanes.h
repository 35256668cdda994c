#pragma once
// What the shade kernels (kernels/shading) share: three lanes of coordinates, and the scalar
// vertex code's helpers over N lanes with the scalar code's bits: glm's dot order, fmax_float's
// NaN rule (core/base/float_minmax.h), the ray offset and its ulp steps (core/base/ray_offset.h).

#include <cstddef>
#include <cstdint>
#include <limits>

#include "core/base/aligned_vector.h"
#include "simd/simd.h"

namespace wt::shading {
inline namespace WT_SIMD_ISA {

using simd::vbool;
using simd::vfloat;
using simd::vint;

template <int N>
struct Lanes3 {
    vfloat<N> x, y, z;
};

template <int N>
inline Lanes3<N> load3(const AlignedVector<float>& x, const AlignedVector<float>& y, const AlignedVector<float>& z,
                       std::size_t i) {
    return {vfloat<N>::load(x.data() + i), vfloat<N>::load(y.data() + i), vfloat<N>::load(z.data() + i)};
}

// glm::dot's order: (x + y) + z.
template <int N>
inline vfloat<N> dot(const Lanes3<N>& a, const Lanes3<N>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

template <int N>
inline Lanes3<N> select(vbool<N> m, const Lanes3<N>& a, const Lanes3<N>& b) {
    return {simd::select(m, a.x, b.x), simd::select(m, a.y, b.y), simd::select(m, a.z, b.z)};
}

template <int N>
inline Lanes3<N> negate(const Lanes3<N>& a) {
    return {-a.x, -a.y, -a.z};
}

// glm::normalize: v times 1 / sqrt(dot(v, v)).
template <int N>
inline Lanes3<N> normalized(const Lanes3<N>& v) {
    const vfloat<N> inverse_length = 1.0f / simd::sqrt(dot(v, v));
    return {v.x * inverse_length, v.y * inverse_length, v.z * inverse_length};
}

// reflect(d, n) (core/materials/fresnel.h): d - (2 dot(d, n)) n.
template <int N>
inline Lanes3<N> reflect(const Lanes3<N>& d, const Lanes3<N>& n) {
    const vfloat<N> twice = 2.0f * dot(d, n);
    return {d.x - twice * n.x, d.y - twice * n.y, d.z - twice * n.z};
}

// fmax_float / fmin_float (core/base/float_minmax.h): x when y is NaN, else maxss / minss.
template <int N>
inline vfloat<N> fmax_lanes(vfloat<N> x, vfloat<N> y) {
    return simd::select(y != y, x, simd::max(x, y));
}
template <int N>
inline vfloat<N> fmin_lanes(vfloat<N> x, vfloat<N> y) {
    return simd::select(y != y, x, simd::min(x, y));
}

// next_float_up / next_float_down (core/base/ray_offset.h).
template <int N>
inline vfloat<N> next_float_up(vfloat<N> v) {
    const vfloat<N> signed_zero_up = simd::select(v == 0.0f, vfloat<N>(0.0f), v);  // -0 steps as +0
    const vint<N> bits = simd::asInt(signed_zero_up);
    const vfloat<N> stepped = simd::asFloat(simd::select(signed_zero_up >= 0.0f, bits + vint<N>(1), bits - vint<N>(1)));
    return simd::select(v == std::numeric_limits<float>::infinity(), v, stepped);
}
template <int N>
inline vfloat<N> next_float_down(vfloat<N> v) {
    return -next_float_up<N>(-v);
}

// offset_ray_origin(p, error, n) (core/base/ray_offset.h). Always inlined: with three kernels
// calling it, GCC kept the scalar kernels' copy out of line, a call per lane.
template <int N>
[[gnu::always_inline]] inline Lanes3<N> offset_ray_origin(const Lanes3<N>& p, const Lanes3<N>& error, const Lanes3<N>& n) {
    const vfloat<N> distance = simd::abs(n.x) * error.x + simd::abs(n.y) * error.y + simd::abs(n.z) * error.z;
    const auto moved = [&](vfloat<N> coordinate, vfloat<N> normal) {
        const vfloat<N> offset = distance * normal;
        const vfloat<N> out = coordinate + offset;
        return simd::select(offset > 0.0f, next_float_up<N>(out), simd::select(offset < 0.0f, next_float_down<N>(out), out));
    };
    return {moved(p.x, n.x), moved(p.y, n.y), moved(p.z, n.z)};
}


// The normal on the side the incoming direction d arrives from: n where dot(d, n) < 0, else -n
// (sample_bsdf's and light_sampling_point's test).
template <int N>
inline Lanes3<N> facing(const Lanes3<N>& n, const Lanes3<N>& d) {
    return select(dot(d, n) < 0.0f, n, negate(n));
}

// shading_normal_facing (core/materials/shading_normal_bsdf.h): the shading normal s turned to
// the side of the facing geometric normal n.
template <int N>
inline Lanes3<N> shading_normal_facing(const Lanes3<N>& s, const Lanes3<N>& n) {
    return select(dot(s, n) < 0.0f, negate(s), s);
}

// oren_nayar_factor (core/materials/bsdf.h), from oren_nayar_terms' a and b.
template <int N>
inline vfloat<N> oren_nayar_factor(vfloat<N> a, vfloat<N> b, vfloat<N> cos_i, vfloat<N> cos_o, vfloat<N> wi_dot_wo) {
    const vfloat<N> projected = fmax_lanes<N>(0.0f, wi_dot_wo - cos_i * cos_o);
    return a + b * projected / fmax_lanes<N>(fmax_lanes<N>(cos_i, cos_o), 1e-7f);
}

// Lanes [i, i + N) of a per-entry flag byte, widened once per vector (the kernels test several
// of its bits), and the lanes with `bit` set.
template <int N>
inline vint<N> flag_lanes(const AlignedVector<uint8_t>& flags, std::size_t i) {
    alignas(64) int32_t widened[N];
    for (int lane = 0; lane < N; ++lane) widened[lane] = flags[i + lane];
    return vint<N>::load(widened);
}
template <int N>
inline vbool<N> has_flag(vint<N> flags, uint8_t bit) {
    return (flags & vint<N>(bit)) != vint<N>(0);
}

// The lanes of `m` among the first `count`, as bits (count may exceed N).
template <int N>
inline uint32_t lanes_below(vbool<N> m, std::size_t count) {
    return simd::movemask(m) & (count >= std::size_t(N) ? ~uint32_t(0) : uint32_t((uint64_t(1) << count) - 1));
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::shading
