#pragma once
// Width 8: vbool<8>, vint<8>, vfloat<8> on AVX2 + FMA (__m256 / __m256i).
//
// Masks are lane masks in an __m256 (all-ones / all-zeros per lane); see vbool.h for why.
// AVX2 has everything natively: masked load/store (vmaskmov, fault-suppressing), gathers,
// 8 x 32-bit integer ops, FMA. Compiled into the AVX-512 TU too, where it uses rcp14/rsqrt14
// and reaches FMA through the AVX-512VL intrinsics (GCC's -mavx512f does not imply -mfma).

#if !defined(__AVX2__)
#error "simd8_avx2.h needs -mavx2 -mfma (include simd/simd.h, which only includes it when allowed)"
#endif

#include "simd/intrinsics.h"

#include <cstdint>

#include "simd/isa.h"
#include "simd/simd4_sse.h"
#include "simd/vbool.h"
#include "simd/vfloat.h"
#include "simd/vint.h"

namespace wt::simd {
inline namespace WT_SIMD_ISA {

// ---------------------------------------------------------------------------------------------
// vbool<8>

template <>
struct vbool<8> {
    static constexpr int N = 8;
    __m256 v;  // per lane all-ones (true) or all-zeros (false)

    vbool() = default;
    explicit vbool(__m256 m) : v(m) {}
    explicit vbool(bool b) : v(_mm256_castsi256_ps(_mm256_set1_epi32(b ? -1 : 0))) {}
    static vbool from_bits(uint32_t bits) {
        const __m256i lane_bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
        const __m256i b = _mm256_and_si256(_mm256_set1_epi32(static_cast<int>(bits)), lane_bit);
        return vbool(_mm256_castsi256_ps(_mm256_cmpeq_epi32(b, lane_bit)));
    }

    bool operator[](int i) const { return (_mm256_movemask_ps(v) >> i) & 1; }
};

inline vbool<8> operator&(vbool<8> a, vbool<8> b) { return vbool<8>(_mm256_and_ps(a.v, b.v)); }
inline vbool<8> operator|(vbool<8> a, vbool<8> b) { return vbool<8>(_mm256_or_ps(a.v, b.v)); }
inline vbool<8> operator^(vbool<8> a, vbool<8> b) { return vbool<8>(_mm256_xor_ps(a.v, b.v)); }
inline vbool<8> operator~(vbool<8> a) { return a ^ vbool<8>(true); }
inline vbool<8> andnot(vbool<8> a, vbool<8> b) { return vbool<8>(_mm256_andnot_ps(b.v, a.v)); }
inline vbool<8> operator==(vbool<8> a, vbool<8> b) {
    return vbool<8>(_mm256_castsi256_ps(_mm256_cmpeq_epi32(_mm256_castps_si256(a.v), _mm256_castps_si256(b.v))));
}
inline vbool<8> operator!=(vbool<8> a, vbool<8> b) { return a ^ b; }
inline vbool<8>& operator&=(vbool<8>& a, vbool<8> b) { return a = a & b; }
inline vbool<8>& operator|=(vbool<8>& a, vbool<8> b) { return a = a | b; }
inline vbool<8>& operator^=(vbool<8>& a, vbool<8> b) { return a = a ^ b; }

inline uint32_t movemask(vbool<8> m) { return static_cast<uint32_t>(_mm256_movemask_ps(m.v)); }
inline bool any(vbool<8> m) { return movemask(m) != 0; }
inline bool all(vbool<8> m) { return movemask(m) == 0xFF; }
inline bool none(vbool<8> m) { return movemask(m) == 0; }
inline int popcount(vbool<8> m) { return __builtin_popcount(movemask(m)); }

// ---------------------------------------------------------------------------------------------
// vint<8>

template <>
struct vint<8> {
    static constexpr int N = 8;
    __m256i v;

    vint() = default;
    vint(__m256i x) : v(x) {}
    vint(int32_t x) : v(_mm256_set1_epi32(x)) {}

    static vint step() { return _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7); }

    static vint load(const int32_t* p) { return _mm256_load_si256(reinterpret_cast<const __m256i*>(p)); }
    static vint loadu(const int32_t* p) { return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)); }
    static void store(int32_t* p, vint x) { _mm256_store_si256(reinterpret_cast<__m256i*>(p), x.v); }
    static void storeu(int32_t* p, vint x) { _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), x.v); }

    // vpmaskmovd: masked-off lanes read as 0, are not written, and never fault.
    static vint load_masked(vbool<8> m, const int32_t* p) {
        return _mm256_maskload_epi32(p, _mm256_castps_si256(m.v));
    }
    static void store_masked(vbool<8> m, int32_t* p, vint x) {
        _mm256_maskstore_epi32(p, _mm256_castps_si256(m.v), x.v);
    }
    static vint load_partial(const int32_t* p, int count, vint fill);
    static void store_partial(int32_t* p, vint x, int count);

    static vint gather(const int32_t* base, vint idx) { return _mm256_i32gather_epi32(base, idx.v, 4); }
    static vint gather(vbool<8> m, const int32_t* base, vint idx) {
        return _mm256_mask_i32gather_epi32(_mm256_setzero_si256(), base, idx.v, _mm256_castps_si256(m.v), 4);
    }

    int32_t operator[](int i) const {
        alignas(32) int32_t lanes[8];
        store(lanes, *this);
        return lanes[i & 7];
    }
};

inline vint<8> operator+(vint<8> a, vint<8> b) { return _mm256_add_epi32(a.v, b.v); }
inline vint<8> operator-(vint<8> a, vint<8> b) { return _mm256_sub_epi32(a.v, b.v); }
inline vint<8> operator*(vint<8> a, vint<8> b) { return _mm256_mullo_epi32(a.v, b.v); }
inline vint<8> operator-(vint<8> a) { return _mm256_sub_epi32(_mm256_setzero_si256(), a.v); }
inline vint<8> operator&(vint<8> a, vint<8> b) { return _mm256_and_si256(a.v, b.v); }
inline vint<8> operator|(vint<8> a, vint<8> b) { return _mm256_or_si256(a.v, b.v); }
inline vint<8> operator^(vint<8> a, vint<8> b) { return _mm256_xor_si256(a.v, b.v); }
inline vint<8> operator~(vint<8> a) { return _mm256_xor_si256(a.v, _mm256_set1_epi32(-1)); }

// Shift-by-register: n >= 32 (or negative, seen as huge) gives 0 / the sign, as width 1.
inline vint<8> operator<<(vint<8> a, int n) { return _mm256_sll_epi32(a.v, _mm_cvtsi32_si128(n)); }
inline vint<8> operator>>(vint<8> a, int n) { return _mm256_sra_epi32(a.v, _mm_cvtsi32_si128(n)); }
inline vint<8> srl(vint<8> a, int n) { return _mm256_srl_epi32(a.v, _mm_cvtsi32_si128(n)); }

inline vint<8>& operator+=(vint<8>& a, vint<8> b) { return a = a + b; }
inline vint<8>& operator-=(vint<8>& a, vint<8> b) { return a = a - b; }
inline vint<8>& operator*=(vint<8>& a, vint<8> b) { return a = a * b; }
inline vint<8>& operator&=(vint<8>& a, vint<8> b) { return a = a & b; }
inline vint<8>& operator|=(vint<8>& a, vint<8> b) { return a = a | b; }
inline vint<8>& operator^=(vint<8>& a, vint<8> b) { return a = a ^ b; }

inline vbool<8> operator==(vint<8> a, vint<8> b) { return vbool<8>(_mm256_castsi256_ps(_mm256_cmpeq_epi32(a.v, b.v))); }
inline vbool<8> operator>(vint<8> a, vint<8> b) { return vbool<8>(_mm256_castsi256_ps(_mm256_cmpgt_epi32(a.v, b.v))); }
inline vbool<8> operator<(vint<8> a, vint<8> b) { return b > a; }
inline vbool<8> operator!=(vint<8> a, vint<8> b) { return ~(a == b); }
inline vbool<8> operator<=(vint<8> a, vint<8> b) { return ~(a > b); }
inline vbool<8> operator>=(vint<8> a, vint<8> b) { return ~(b > a); }

inline vint<8> select(vbool<8> m, vint<8> a, vint<8> b) {
    return _mm256_blendv_epi8(b.v, a.v, _mm256_castps_si256(m.v));  // canonical masks
}
inline vint<8> min(vint<8> a, vint<8> b) { return _mm256_min_epi32(a.v, b.v); }
inline vint<8> max(vint<8> a, vint<8> b) { return _mm256_max_epi32(a.v, b.v); }

namespace detail {
inline vbool<8> first_lanes8(int count) { return vint<8>::step() < vint<8>(count); }
}  // namespace detail

inline vint<8> vint<8>::load_partial(const int32_t* p, int count, vint fill) {
    if (count >= 8) return loadu(p);
    const vbool<8> m = detail::first_lanes8(count);
    return select(m, load_masked(m, p), fill);
}
inline void vint<8>::store_partial(int32_t* p, vint x, int count) {
    if (count >= 8) return storeu(p, x);
    store_masked(detail::first_lanes8(count), p, x);
}

// ---------------------------------------------------------------------------------------------
// vfloat<8>

template <>
struct vfloat<8> {
    static constexpr int N = 8;
    static constexpr bool fused_madd = WT_SIMD_FUSED_MADD != 0;
    __m256 v;

    vfloat() = default;
    vfloat(__m256 x) : v(x) {}
    vfloat(float x) : v(_mm256_set1_ps(x)) {}

    static vfloat load(const float* p) { return _mm256_load_ps(p); }
    static vfloat loadu(const float* p) { return _mm256_loadu_ps(p); }
    static void store(float* p, vfloat x) { _mm256_store_ps(p, x.v); }
    static void storeu(float* p, vfloat x) { _mm256_storeu_ps(p, x.v); }

    static vfloat load_masked(vbool<8> m, const float* p) {
        return _mm256_maskload_ps(p, _mm256_castps_si256(m.v));
    }
    static void store_masked(vbool<8> m, float* p, vfloat x) {
        _mm256_maskstore_ps(p, _mm256_castps_si256(m.v), x.v);
    }
    static vfloat load_partial(const float* p, int count, vfloat fill) {
        if (count >= 8) return loadu(p);
        const vbool<8> m = detail::first_lanes8(count);
        return _mm256_blendv_ps(fill.v, load_masked(m, p).v, m.v);
    }
    static void store_partial(float* p, vfloat x, int count) {
        if (count >= 8) return storeu(p, x);
        store_masked(detail::first_lanes8(count), p, x);
    }

    static vfloat gather(const float* base, vint<8> idx) { return _mm256_i32gather_ps(base, idx.v, 4); }
    static vfloat gather(vbool<8> m, const float* base, vint<8> idx) {
        return _mm256_mask_i32gather_ps(_mm256_setzero_ps(), base, idx.v, m.v, 4);
    }

    float operator[](int i) const {
        alignas(32) float lanes[8];
        store(lanes, *this);
        return lanes[i & 7];
    }
};

inline vfloat<8> operator+(vfloat<8> a, vfloat<8> b) { return _mm256_add_ps(a.v, b.v); }
inline vfloat<8> operator-(vfloat<8> a, vfloat<8> b) { return _mm256_sub_ps(a.v, b.v); }
inline vfloat<8> operator*(vfloat<8> a, vfloat<8> b) { return _mm256_mul_ps(a.v, b.v); }
inline vfloat<8> operator/(vfloat<8> a, vfloat<8> b) { return _mm256_div_ps(a.v, b.v); }
inline vfloat<8> operator-(vfloat<8> a) { return _mm256_xor_ps(a.v, _mm256_set1_ps(-0.0f)); }
inline vfloat<8>& operator+=(vfloat<8>& a, vfloat<8> b) { return a = a + b; }
inline vfloat<8>& operator-=(vfloat<8>& a, vfloat<8> b) { return a = a - b; }
inline vfloat<8>& operator*=(vfloat<8>& a, vfloat<8> b) { return a = a * b; }
inline vfloat<8>& operator/=(vfloat<8>& a, vfloat<8> b) { return a = a / b; }

#if defined(__FMA__)
inline vfloat<8> madd(vfloat<8> a, vfloat<8> b, vfloat<8> c) { return _mm256_fmadd_ps(a.v, b.v, c.v); }
inline vfloat<8> msub(vfloat<8> a, vfloat<8> b, vfloat<8> c) { return _mm256_fmsub_ps(a.v, b.v, c.v); }
inline vfloat<8> nmadd(vfloat<8> a, vfloat<8> b, vfloat<8> c) { return _mm256_fnmadd_ps(a.v, b.v, c.v); }
inline vfloat<8> nmsub(vfloat<8> a, vfloat<8> b, vfloat<8> c) { return _mm256_fnmsub_ps(a.v, b.v, c.v); }
#elif defined(__AVX512VL__)
// Same vfmadd instructions, reached through the AVX-512VL intrinsics (all lanes enabled).
inline vfloat<8> madd(vfloat<8> a, vfloat<8> b, vfloat<8> c) { return _mm256_mask_fmadd_ps(a.v, 0xFF, b.v, c.v); }
inline vfloat<8> msub(vfloat<8> a, vfloat<8> b, vfloat<8> c) { return _mm256_mask_fmsub_ps(a.v, 0xFF, b.v, c.v); }
inline vfloat<8> nmadd(vfloat<8> a, vfloat<8> b, vfloat<8> c) { return _mm256_mask_fnmadd_ps(a.v, 0xFF, b.v, c.v); }
inline vfloat<8> nmsub(vfloat<8> a, vfloat<8> b, vfloat<8> c) { return _mm256_mask_fnmsub_ps(a.v, 0xFF, b.v, c.v); }
#else
#error "simd8_avx2.h: isa.h admits AVX2 only together with FMA or AVX-512VL"
#endif

// vminps/vmaxps return the second operand when either is NaN or both are equal (+-0).
inline vfloat<8> min(vfloat<8> a, vfloat<8> b) { return _mm256_min_ps(a.v, b.v); }
inline vfloat<8> max(vfloat<8> a, vfloat<8> b) { return _mm256_max_ps(a.v, b.v); }
inline vfloat<8> abs(vfloat<8> a) { return _mm256_andnot_ps(_mm256_set1_ps(-0.0f), a.v); }
inline vfloat<8> sqrt(vfloat<8> a) { return _mm256_sqrt_ps(a.v); }
inline vfloat<8> rcp(vfloat<8> a) { return _mm256_div_ps(_mm256_set1_ps(1.0f), a.v); }
inline vfloat<8> rsqrt(vfloat<8> a) { return _mm256_div_ps(_mm256_set1_ps(1.0f), _mm256_sqrt_ps(a.v)); }
inline vfloat<8> floor(vfloat<8> a) { return _mm256_floor_ps(a.v); }
inline vfloat<8> ceil(vfloat<8> a) { return _mm256_ceil_ps(a.v); }

// Ordered-quiet predicates (false on NaN, like C++); != is unordered (true on NaN).
inline vbool<8> operator==(vfloat<8> a, vfloat<8> b) { return vbool<8>(_mm256_cmp_ps(a.v, b.v, _CMP_EQ_OQ)); }
inline vbool<8> operator!=(vfloat<8> a, vfloat<8> b) { return vbool<8>(_mm256_cmp_ps(a.v, b.v, _CMP_NEQ_UQ)); }
inline vbool<8> operator<(vfloat<8> a, vfloat<8> b) { return vbool<8>(_mm256_cmp_ps(a.v, b.v, _CMP_LT_OQ)); }
inline vbool<8> operator<=(vfloat<8> a, vfloat<8> b) { return vbool<8>(_mm256_cmp_ps(a.v, b.v, _CMP_LE_OQ)); }
inline vbool<8> operator>(vfloat<8> a, vfloat<8> b) { return vbool<8>(_mm256_cmp_ps(a.v, b.v, _CMP_GT_OQ)); }
inline vbool<8> operator>=(vfloat<8> a, vfloat<8> b) { return vbool<8>(_mm256_cmp_ps(a.v, b.v, _CMP_GE_OQ)); }

inline vfloat<8> select(vbool<8> m, vfloat<8> a, vfloat<8> b) { return _mm256_blendv_ps(b.v, a.v, m.v); }

// Estimate + one Newton-Raphson step; see simd4_sse.h for the NaN fix-up.
inline vfloat<8> rcp_fast(vfloat<8> a) {
#if defined(__AVX512VL__)
    const vfloat<8> r = _mm256_rcp14_ps(a.v);
#else
    const vfloat<8> r = _mm256_rcp_ps(a.v);
#endif
    const vfloat<8> refined = madd(r, nmadd(a, r, 1.0f), r);
    return select(refined != refined, r, refined);
}
inline vfloat<8> rsqrt_fast(vfloat<8> a) {
#if defined(__AVX512VL__)
    const vfloat<8> r = _mm256_rsqrt14_ps(a.v);
#else
    const vfloat<8> r = _mm256_rsqrt_ps(a.v);
#endif
    const vfloat<8> refined = madd(r * 0.5f, nmadd(a * r, r, 1.0f), r);
    return select(refined != refined, r, refined);
}

// Halving order: lane i < 4 = op(lane i, lane i + 4), then the 4-wide reduction.
inline float reduce_min(vfloat<8> a) {
    return reduce_min(vfloat<4>(_mm_min_ps(_mm256_castps256_ps128(a.v), _mm256_extractf128_ps(a.v, 1))));
}
inline float reduce_max(vfloat<8> a) {
    return reduce_max(vfloat<4>(_mm_max_ps(_mm256_castps256_ps128(a.v), _mm256_extractf128_ps(a.v, 1))));
}
inline float reduce_add(vfloat<8> a) {
    return reduce_add(vfloat<4>(_mm_add_ps(_mm256_castps256_ps128(a.v), _mm256_extractf128_ps(a.v, 1))));
}

// See simd4_sse.h: the select pins NaN / out-of-range lanes to INT32_MIN even when GCC
// constant-folds the conversion (which it does with saturating semantics).
inline vint<8> to_int(vfloat<8> a) {
    const vbool<8> in_range = (a >= vfloat<8>(-2147483648.0f)) & (a < vfloat<8>(2147483648.0f));
    return select(in_range, vint<8>(_mm256_cvttps_epi32(a.v)), vint<8>(INT32_MIN));
}
inline vfloat<8> to_float(vint<8> a) { return _mm256_cvtepi32_ps(a.v); }
inline vint<8> asInt(vfloat<8> a) { return _mm256_castps_si256(a.v); }
inline vfloat<8> asFloat(vint<8> a) { return _mm256_castsi256_ps(a.v); }

using vbool8 = vbool<8>;
using vint8 = vint<8>;
using vfloat8 = vfloat<8>;

}  // namespace WT_SIMD_ISA
}  // namespace wt::simd
