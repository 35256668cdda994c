#pragma once
// Width 1: vbool<1>, vint<1>, vfloat<1> in plain portable C++.
//
// This is the reference the other widths are tested against lane by lane, so every function
// here spells out the semantics the SIMD instructions have (see vfloat.h / vint.h) instead of
// using the nearest std:: function: min/max return the second operand on NaN like minps
// (std::min returns the first), to_int gives INT32_MIN out of range like cvttps2dq (a plain
// cast is UB), shifts by >= 32 are defined, integer arithmetic wraps.
// It compiles under every flag set; width-1 kernels are also the scalar fallback.

#include <cmath>
#include <cstdint>
#include <cstring>

#include "simd/isa.h"
#include "simd/vbool.h"
#include "simd/vfloat.h"
#include "simd/vint.h"

namespace wt::simd {
inline namespace WT_SIMD_ISA {

// Bit casts for scalars (C++17 has no std::bit_cast; memcpy compiles to a register move).
inline int32_t asInt(float f) {
    int32_t i;
    std::memcpy(&i, &f, sizeof i);
    return i;
}
inline float asFloat(int32_t i) {
    float f;
    std::memcpy(&f, &i, sizeof f);
    return f;
}

namespace detail {
// Shared clamp for the `count` of load_partial / store_partial.
inline int clamp_count(int count, int n) { return count < 0 ? 0 : (count > n ? n : count); }
}  // namespace detail

// ---------------------------------------------------------------------------------------------
// vbool<1>

template <>
struct vbool<1> {
    static constexpr int N = 1;
    bool v;

    vbool() = default;
    explicit vbool(bool b) : v(b) {}
    static vbool from_bits(uint32_t bits) { return vbool((bits & 1u) != 0); }

    bool operator[](int) const { return v; }
};

inline vbool<1> operator&(vbool<1> a, vbool<1> b) { return vbool<1>(a.v && b.v); }
inline vbool<1> operator|(vbool<1> a, vbool<1> b) { return vbool<1>(a.v || b.v); }
inline vbool<1> operator^(vbool<1> a, vbool<1> b) { return vbool<1>(a.v != b.v); }
inline vbool<1> operator~(vbool<1> a) { return vbool<1>(!a.v); }
inline vbool<1> andnot(vbool<1> a, vbool<1> b) { return vbool<1>(a.v && !b.v); }
inline vbool<1> operator==(vbool<1> a, vbool<1> b) { return vbool<1>(a.v == b.v); }
inline vbool<1> operator!=(vbool<1> a, vbool<1> b) { return vbool<1>(a.v != b.v); }
inline vbool<1>& operator&=(vbool<1>& a, vbool<1> b) { return a = a & b; }
inline vbool<1>& operator|=(vbool<1>& a, vbool<1> b) { return a = a | b; }
inline vbool<1>& operator^=(vbool<1>& a, vbool<1> b) { return a = a ^ b; }

inline bool any(vbool<1> m) { return m.v; }
inline bool all(vbool<1> m) { return m.v; }
inline bool none(vbool<1> m) { return !m.v; }
inline uint32_t movemask(vbool<1> m) { return m.v ? 1u : 0u; }
inline int popcount(vbool<1> m) { return m.v ? 1 : 0; }

// ---------------------------------------------------------------------------------------------
// vint<1>

template <>
struct vint<1> {
    static constexpr int N = 1;
    int32_t v;

    vint() = default;
    vint(int32_t x) : v(x) {}  // implicit broadcast, so `v + 1` works

    static vint step() { return vint(0); }

    static vint load(const int32_t* p) { return vint(*p); }
    static vint loadu(const int32_t* p) { return vint(*p); }
    static void store(int32_t* p, vint x) { *p = x.v; }
    static void storeu(int32_t* p, vint x) { *p = x.v; }
    static vint load_masked(vbool<1> m, const int32_t* p) { return vint(m.v ? *p : 0); }
    static void store_masked(vbool<1> m, int32_t* p, vint x) {
        if (m.v) *p = x.v;
    }
    static vint load_partial(const int32_t* p, int count, vint fill) {
        return count >= 1 ? vint(*p) : fill;
    }
    static void store_partial(int32_t* p, vint x, int count) {
        if (count >= 1) *p = x.v;
    }
    static vint gather(const int32_t* base, vint idx) { return vint(base[idx.v]); }
    static vint gather(vbool<1> m, const int32_t* base, vint idx) {
        return vint(m.v ? base[idx.v] : 0);
    }

    int32_t operator[](int) const { return v; }
};

namespace detail {
inline int32_t wrap(uint32_t u) { return static_cast<int32_t>(u); }  // modulo 2^32 (GCC)
inline uint32_t bits(int32_t i) { return static_cast<uint32_t>(i); }
}  // namespace detail

inline vint<1> operator+(vint<1> a, vint<1> b) { return detail::wrap(detail::bits(a.v) + detail::bits(b.v)); }
inline vint<1> operator-(vint<1> a, vint<1> b) { return detail::wrap(detail::bits(a.v) - detail::bits(b.v)); }
inline vint<1> operator*(vint<1> a, vint<1> b) { return detail::wrap(detail::bits(a.v) * detail::bits(b.v)); }
inline vint<1> operator-(vint<1> a) { return detail::wrap(0u - detail::bits(a.v)); }
inline vint<1> operator&(vint<1> a, vint<1> b) { return a.v & b.v; }
inline vint<1> operator|(vint<1> a, vint<1> b) { return a.v | b.v; }
inline vint<1> operator^(vint<1> a, vint<1> b) { return a.v ^ b.v; }
inline vint<1> operator~(vint<1> a) { return ~a.v; }

inline vint<1> operator<<(vint<1> a, int n) {
    return static_cast<uint32_t>(n) >= 32 ? 0 : detail::wrap(detail::bits(a.v) << n);
}
inline vint<1> operator>>(vint<1> a, int n) {  // arithmetic (GCC's >> on signed is)
    return static_cast<uint32_t>(n) >= 32 ? (a.v < 0 ? -1 : 0) : (a.v >> n);
}
inline vint<1> srl(vint<1> a, int n) {
    return static_cast<uint32_t>(n) >= 32 ? 0 : detail::wrap(detail::bits(a.v) >> n);
}

inline vint<1>& operator+=(vint<1>& a, vint<1> b) { return a = a + b; }
inline vint<1>& operator-=(vint<1>& a, vint<1> b) { return a = a - b; }
inline vint<1>& operator*=(vint<1>& a, vint<1> b) { return a = a * b; }
inline vint<1>& operator&=(vint<1>& a, vint<1> b) { return a = a & b; }
inline vint<1>& operator|=(vint<1>& a, vint<1> b) { return a = a | b; }
inline vint<1>& operator^=(vint<1>& a, vint<1> b) { return a = a ^ b; }

inline vbool<1> operator==(vint<1> a, vint<1> b) { return vbool<1>(a.v == b.v); }
inline vbool<1> operator!=(vint<1> a, vint<1> b) { return vbool<1>(a.v != b.v); }
inline vbool<1> operator<(vint<1> a, vint<1> b) { return vbool<1>(a.v < b.v); }
inline vbool<1> operator<=(vint<1> a, vint<1> b) { return vbool<1>(a.v <= b.v); }
inline vbool<1> operator>(vint<1> a, vint<1> b) { return vbool<1>(a.v > b.v); }
inline vbool<1> operator>=(vint<1> a, vint<1> b) { return vbool<1>(a.v >= b.v); }

inline vint<1> select(vbool<1> m, vint<1> a, vint<1> b) { return m.v ? a : b; }
inline vint<1> min(vint<1> a, vint<1> b) { return a.v < b.v ? a : b; }
inline vint<1> max(vint<1> a, vint<1> b) { return a.v > b.v ? a : b; }

// ---------------------------------------------------------------------------------------------
// vfloat<1>

template <>
struct vfloat<1> {
    static constexpr int N = 1;
    static constexpr bool fused_madd = WT_SIMD_FUSED_MADD != 0;
    float v;

    vfloat() = default;
    vfloat(float x) : v(x) {}  // implicit broadcast, so `v * 2.0f` works

    static vfloat load(const float* p) { return vfloat(*p); }
    static vfloat loadu(const float* p) { return vfloat(*p); }
    static void store(float* p, vfloat x) { *p = x.v; }
    static void storeu(float* p, vfloat x) { *p = x.v; }
    static vfloat load_masked(vbool<1> m, const float* p) { return vfloat(m.v ? *p : 0.0f); }
    static void store_masked(vbool<1> m, float* p, vfloat x) {
        if (m.v) *p = x.v;
    }
    static vfloat load_partial(const float* p, int count, vfloat fill) {
        return count >= 1 ? vfloat(*p) : fill;
    }
    static void store_partial(float* p, vfloat x, int count) {
        if (count >= 1) *p = x.v;
    }
    static vfloat gather(const float* base, vint<1> idx) { return vfloat(base[idx.v]); }
    static vfloat gather(vbool<1> m, const float* base, vint<1> idx) {
        return vfloat(m.v ? base[idx.v] : 0.0f);
    }

    float operator[](int) const { return v; }
};

inline vfloat<1> operator+(vfloat<1> a, vfloat<1> b) { return a.v + b.v; }
inline vfloat<1> operator-(vfloat<1> a, vfloat<1> b) { return a.v - b.v; }
inline vfloat<1> operator*(vfloat<1> a, vfloat<1> b) { return a.v * b.v; }
inline vfloat<1> operator/(vfloat<1> a, vfloat<1> b) { return a.v / b.v; }
inline vfloat<1> operator-(vfloat<1> a) { return asFloat(asInt(a.v) ^ INT32_MIN); }  // sign bit
inline vfloat<1>& operator+=(vfloat<1>& a, vfloat<1> b) { return a = a + b; }
inline vfloat<1>& operator-=(vfloat<1>& a, vfloat<1> b) { return a = a - b; }
inline vfloat<1>& operator*=(vfloat<1>& a, vfloat<1> b) { return a = a * b; }
inline vfloat<1>& operator/=(vfloat<1>& a, vfloat<1> b) { return a = a / b; }

// Fused when the TU has FMA (std::fma is then one vfmadd instruction), otherwise two
// roundings. Without FMA in the target the compiler cannot contract a*b+c, so the unfused
// form really is unfused; with FMA we never write a*b+c, so contraction cannot change it.
#if WT_SIMD_FUSED_MADD
inline vfloat<1> madd(vfloat<1> a, vfloat<1> b, vfloat<1> c) { return std::fma(a.v, b.v, c.v); }
inline vfloat<1> msub(vfloat<1> a, vfloat<1> b, vfloat<1> c) { return std::fma(a.v, b.v, -c.v); }
inline vfloat<1> nmadd(vfloat<1> a, vfloat<1> b, vfloat<1> c) { return std::fma(-a.v, b.v, c.v); }
inline vfloat<1> nmsub(vfloat<1> a, vfloat<1> b, vfloat<1> c) { return std::fma(-a.v, b.v, -c.v); }
#else
inline vfloat<1> madd(vfloat<1> a, vfloat<1> b, vfloat<1> c) { return a.v * b.v + c.v; }
inline vfloat<1> msub(vfloat<1> a, vfloat<1> b, vfloat<1> c) { return a.v * b.v - c.v; }
inline vfloat<1> nmadd(vfloat<1> a, vfloat<1> b, vfloat<1> c) { return c.v - a.v * b.v; }
inline vfloat<1> nmsub(vfloat<1> a, vfloat<1> b, vfloat<1> c) { return -(a.v * b.v) - c.v; }
#endif

// NaN or equal operands return b, exactly like minps/maxps (see vfloat.h).
inline vfloat<1> min(vfloat<1> a, vfloat<1> b) { return a.v < b.v ? a : b; }
inline vfloat<1> max(vfloat<1> a, vfloat<1> b) { return a.v > b.v ? a : b; }
inline vfloat<1> abs(vfloat<1> a) { return asFloat(asInt(a.v) & INT32_MAX); }
inline vfloat<1> sqrt(vfloat<1> a) { return std::sqrt(a.v); }
inline vfloat<1> rcp(vfloat<1> a) { return 1.0f / a.v; }
inline vfloat<1> rsqrt(vfloat<1> a) { return 1.0f / std::sqrt(a.v); }
inline vfloat<1> rcp_fast(vfloat<1> a) { return rcp(a); }      // no estimate instruction:
inline vfloat<1> rsqrt_fast(vfloat<1> a) { return rsqrt(a); }  // exact, within the bound
inline vfloat<1> floor(vfloat<1> a) { return std::floor(a.v); }
inline vfloat<1> ceil(vfloat<1> a) { return std::ceil(a.v); }

inline vbool<1> operator==(vfloat<1> a, vfloat<1> b) { return vbool<1>(a.v == b.v); }
inline vbool<1> operator!=(vfloat<1> a, vfloat<1> b) { return vbool<1>(a.v != b.v); }
inline vbool<1> operator<(vfloat<1> a, vfloat<1> b) { return vbool<1>(a.v < b.v); }
inline vbool<1> operator<=(vfloat<1> a, vfloat<1> b) { return vbool<1>(a.v <= b.v); }
inline vbool<1> operator>(vfloat<1> a, vfloat<1> b) { return vbool<1>(a.v > b.v); }
inline vbool<1> operator>=(vfloat<1> a, vfloat<1> b) { return vbool<1>(a.v >= b.v); }

inline vfloat<1> select(vbool<1> m, vfloat<1> a, vfloat<1> b) { return m.v ? a : b; }

inline float reduce_min(vfloat<1> a) { return a.v; }
inline float reduce_max(vfloat<1> a) { return a.v; }
inline float reduce_add(vfloat<1> a) { return a.v; }

inline vint<1> to_int(vfloat<1> a) {
    // The range test is false for NaN too. 2^31 itself is out of range; -2^31 is in.
    if (a.v >= -2147483648.0f && a.v < 2147483648.0f) return static_cast<int32_t>(a.v);
    return INT32_MIN;
}
inline vfloat<1> to_float(vint<1> a) { return static_cast<float>(a.v); }
inline vint<1> asInt(vfloat<1> a) { return asInt(a.v); }
inline vfloat<1> asFloat(vint<1> a) { return asFloat(a.v); }

using vbool1 = vbool<1>;
using vint1 = vint<1>;
using vfloat1 = vfloat<1>;

}  // namespace WT_SIMD_ISA
}  // namespace wt::simd
