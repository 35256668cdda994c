#pragma once
// Width 16: vbool<16>, vint<16>, vfloat<16> on AVX-512 (__mmask16 / __m512i / __m512).
//
// Masks are k-registers (__mmask16, one bit per lane), not vectors: AVX-512 compares write
// k-registers, and every AVX-512 instruction takes one as its write mask, so masked loads,
// stores, blends and gathers use them directly; mask logic (&, |, ~) is integer logic on 16
// bits, and movemask is free. See vbool.h.
// Only AVX-512F instructions are used here (so _mm512_xor_si512 on casts where the _ps form
// would need DQ); the TU is still required to enable F+DQ+BW+VL together (isa.h), because the
// compiler is free to use them in the 4- and 8-wide code of the same TU.

#if !defined(__AVX512F__)
#error "simd16_avx512.h needs -mavx512f -mavx512dq -mavx512bw -mavx512vl (include simd/simd.h)"
#endif

#include "simd/intrinsics.h"

#include <cstdint>

#include "simd/isa.h"
#include "simd/simd8_avx2.h"
#include "simd/vbool.h"
#include "simd/vfloat.h"
#include "simd/vint.h"

namespace wt::simd {
inline namespace WT_SIMD_ISA {

// ---------------------------------------------------------------------------------------------
// vbool<16>

template <>
struct vbool<16> {
    static constexpr int N = 16;
    __mmask16 v;  // bit i = lane i

    vbool() = default;
    explicit vbool(__mmask16 m) : v(m) {}
    explicit vbool(bool b) : v(b ? 0xFFFF : 0) {}
    static vbool from_bits(uint32_t bits) { return vbool(static_cast<__mmask16>(bits & 0xFFFFu)); }

    bool operator[](int i) const { return (v >> i) & 1; }
};

namespace detail {
inline vbool<16> kmask(unsigned bits) { return vbool<16>(static_cast<__mmask16>(bits & 0xFFFFu)); }
}  // namespace detail

inline vbool<16> operator&(vbool<16> a, vbool<16> b) { return detail::kmask(a.v & b.v); }
inline vbool<16> operator|(vbool<16> a, vbool<16> b) { return detail::kmask(a.v | b.v); }
inline vbool<16> operator^(vbool<16> a, vbool<16> b) { return detail::kmask(a.v ^ b.v); }
inline vbool<16> operator~(vbool<16> a) { return detail::kmask(~a.v); }
inline vbool<16> andnot(vbool<16> a, vbool<16> b) { return detail::kmask(a.v & ~b.v); }
inline vbool<16> operator==(vbool<16> a, vbool<16> b) { return detail::kmask(~(a.v ^ b.v)); }
inline vbool<16> operator!=(vbool<16> a, vbool<16> b) { return a ^ b; }
inline vbool<16>& operator&=(vbool<16>& a, vbool<16> b) { return a = a & b; }
inline vbool<16>& operator|=(vbool<16>& a, vbool<16> b) { return a = a | b; }
inline vbool<16>& operator^=(vbool<16>& a, vbool<16> b) { return a = a ^ b; }

inline uint32_t movemask(vbool<16> m) { return m.v; }
inline bool any(vbool<16> m) { return m.v != 0; }
inline bool all(vbool<16> m) { return m.v == 0xFFFF; }
inline bool none(vbool<16> m) { return m.v == 0; }
inline int popcount(vbool<16> m) { return __builtin_popcount(m.v); }

namespace detail {
// Mask of lanes [0, count), count clamped to [0, 16].
inline __mmask16 first_lanes16(int count) {
    return static_cast<__mmask16>((1u << clamp_count(count, 16)) - 1u);
}
}  // namespace detail

// ---------------------------------------------------------------------------------------------
// vint<16>

template <>
struct vint<16> {
    static constexpr int N = 16;
    __m512i v;

    vint() = default;
    vint(__m512i x) : v(x) {}
    vint(int32_t x) : v(_mm512_set1_epi32(x)) {}

    static vint step() { return _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15); }

    static vint load(const int32_t* p) { return _mm512_load_si512(p); }
    static vint loadu(const int32_t* p) { return _mm512_loadu_si512(p); }
    static void store(int32_t* p, vint x) { _mm512_store_si512(p, x.v); }
    static void storeu(int32_t* p, vint x) { _mm512_storeu_si512(p, x.v); }

    // Masked-off lanes are zeroed / not written and never fault.
    static vint load_masked(vbool<16> m, const int32_t* p) { return _mm512_maskz_loadu_epi32(m.v, p); }
    static void store_masked(vbool<16> m, int32_t* p, vint x) { _mm512_mask_storeu_epi32(p, m.v, x.v); }
    static vint load_partial(const int32_t* p, int count, vint fill) {
        return _mm512_mask_loadu_epi32(fill.v, detail::first_lanes16(count), p);
    }
    static void store_partial(int32_t* p, vint x, int count) {
        _mm512_mask_storeu_epi32(p, detail::first_lanes16(count), x.v);
    }

    static vint gather(const int32_t* base, vint idx) { return _mm512_i32gather_epi32(idx.v, base, 4); }
    static vint gather(vbool<16> m, const int32_t* base, vint idx) {
        return _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), m.v, idx.v, base, 4);
    }

    int32_t operator[](int i) const {
        alignas(64) int32_t lanes[16];
        store(lanes, *this);
        return lanes[i & 15];
    }
};

inline vint<16> operator+(vint<16> a, vint<16> b) { return _mm512_add_epi32(a.v, b.v); }
inline vint<16> operator-(vint<16> a, vint<16> b) { return _mm512_sub_epi32(a.v, b.v); }
inline vint<16> operator*(vint<16> a, vint<16> b) { return _mm512_mullo_epi32(a.v, b.v); }
inline vint<16> operator-(vint<16> a) { return _mm512_sub_epi32(_mm512_setzero_si512(), a.v); }
inline vint<16> operator&(vint<16> a, vint<16> b) { return _mm512_and_si512(a.v, b.v); }
inline vint<16> operator|(vint<16> a, vint<16> b) { return _mm512_or_si512(a.v, b.v); }
inline vint<16> operator^(vint<16> a, vint<16> b) { return _mm512_xor_si512(a.v, b.v); }
inline vint<16> operator~(vint<16> a) { return _mm512_xor_si512(a.v, _mm512_set1_epi32(-1)); }

// Shift-by-register: n >= 32 (or negative, seen as huge) gives 0 / the sign, as width 1.
inline vint<16> operator<<(vint<16> a, int n) { return _mm512_sll_epi32(a.v, _mm_cvtsi32_si128(n)); }
inline vint<16> operator>>(vint<16> a, int n) { return _mm512_sra_epi32(a.v, _mm_cvtsi32_si128(n)); }
inline vint<16> srl(vint<16> a, int n) { return _mm512_srl_epi32(a.v, _mm_cvtsi32_si128(n)); }

inline vint<16>& operator+=(vint<16>& a, vint<16> b) { return a = a + b; }
inline vint<16>& operator-=(vint<16>& a, vint<16> b) { return a = a - b; }
inline vint<16>& operator*=(vint<16>& a, vint<16> b) { return a = a * b; }
inline vint<16>& operator&=(vint<16>& a, vint<16> b) { return a = a & b; }
inline vint<16>& operator|=(vint<16>& a, vint<16> b) { return a = a | b; }
inline vint<16>& operator^=(vint<16>& a, vint<16> b) { return a = a ^ b; }

inline vbool<16> operator==(vint<16> a, vint<16> b) { return vbool<16>(_mm512_cmp_epi32_mask(a.v, b.v, _MM_CMPINT_EQ)); }
inline vbool<16> operator!=(vint<16> a, vint<16> b) { return vbool<16>(_mm512_cmp_epi32_mask(a.v, b.v, _MM_CMPINT_NE)); }
inline vbool<16> operator<(vint<16> a, vint<16> b) { return vbool<16>(_mm512_cmp_epi32_mask(a.v, b.v, _MM_CMPINT_LT)); }
inline vbool<16> operator<=(vint<16> a, vint<16> b) { return vbool<16>(_mm512_cmp_epi32_mask(a.v, b.v, _MM_CMPINT_LE)); }
inline vbool<16> operator>(vint<16> a, vint<16> b) { return vbool<16>(_mm512_cmp_epi32_mask(a.v, b.v, _MM_CMPINT_NLE)); }
inline vbool<16> operator>=(vint<16> a, vint<16> b) { return vbool<16>(_mm512_cmp_epi32_mask(a.v, b.v, _MM_CMPINT_NLT)); }

// mask_blend(k, x, y) takes y where k is set.
inline vint<16> select(vbool<16> m, vint<16> a, vint<16> b) { return _mm512_mask_blend_epi32(m.v, b.v, a.v); }
inline vint<16> min(vint<16> a, vint<16> b) { return _mm512_min_epi32(a.v, b.v); }
inline vint<16> max(vint<16> a, vint<16> b) { return _mm512_max_epi32(a.v, b.v); }

// ---------------------------------------------------------------------------------------------
// vfloat<16>

template <>
struct vfloat<16> {
    static constexpr int N = 16;
    static constexpr bool fused_madd = true;  // AVX-512F always has FMA
    __m512 v;

    vfloat() = default;
    vfloat(__m512 x) : v(x) {}
    vfloat(float x) : v(_mm512_set1_ps(x)) {}

    static vfloat load(const float* p) { return _mm512_load_ps(p); }
    static vfloat loadu(const float* p) { return _mm512_loadu_ps(p); }
    static void store(float* p, vfloat x) { _mm512_store_ps(p, x.v); }
    static void storeu(float* p, vfloat x) { _mm512_storeu_ps(p, x.v); }

    static vfloat load_masked(vbool<16> m, const float* p) { return _mm512_maskz_loadu_ps(m.v, p); }
    static void store_masked(vbool<16> m, float* p, vfloat x) { _mm512_mask_storeu_ps(p, m.v, x.v); }
    static vfloat load_partial(const float* p, int count, vfloat fill) {
        return _mm512_mask_loadu_ps(fill.v, detail::first_lanes16(count), p);
    }
    static void store_partial(float* p, vfloat x, int count) {
        _mm512_mask_storeu_ps(p, detail::first_lanes16(count), x.v);
    }

    static vfloat gather(const float* base, vint<16> idx) { return _mm512_i32gather_ps(idx.v, base, 4); }
    static vfloat gather(vbool<16> m, const float* base, vint<16> idx) {
        return _mm512_mask_i32gather_ps(_mm512_setzero_ps(), m.v, idx.v, base, 4);
    }

    float operator[](int i) const {
        alignas(64) float lanes[16];
        store(lanes, *this);
        return lanes[i & 15];
    }
};

namespace detail {
inline __m512 xor_bits(__m512 a, int32_t bits) {
    return _mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(a), _mm512_set1_epi32(bits)));
}
}  // namespace detail

inline vfloat<16> operator+(vfloat<16> a, vfloat<16> b) { return _mm512_add_ps(a.v, b.v); }
inline vfloat<16> operator-(vfloat<16> a, vfloat<16> b) { return _mm512_sub_ps(a.v, b.v); }
inline vfloat<16> operator*(vfloat<16> a, vfloat<16> b) { return _mm512_mul_ps(a.v, b.v); }
inline vfloat<16> operator/(vfloat<16> a, vfloat<16> b) { return _mm512_div_ps(a.v, b.v); }
inline vfloat<16> operator-(vfloat<16> a) { return detail::xor_bits(a.v, INT32_MIN); }
inline vfloat<16>& operator+=(vfloat<16>& a, vfloat<16> b) { return a = a + b; }
inline vfloat<16>& operator-=(vfloat<16>& a, vfloat<16> b) { return a = a - b; }
inline vfloat<16>& operator*=(vfloat<16>& a, vfloat<16> b) { return a = a * b; }
inline vfloat<16>& operator/=(vfloat<16>& a, vfloat<16> b) { return a = a / b; }

inline vfloat<16> madd(vfloat<16> a, vfloat<16> b, vfloat<16> c) { return _mm512_fmadd_ps(a.v, b.v, c.v); }
inline vfloat<16> msub(vfloat<16> a, vfloat<16> b, vfloat<16> c) { return _mm512_fmsub_ps(a.v, b.v, c.v); }
inline vfloat<16> nmadd(vfloat<16> a, vfloat<16> b, vfloat<16> c) { return _mm512_fnmadd_ps(a.v, b.v, c.v); }
inline vfloat<16> nmsub(vfloat<16> a, vfloat<16> b, vfloat<16> c) { return _mm512_fnmsub_ps(a.v, b.v, c.v); }

// vminps/vmaxps (zmm) keep the SSE rule: second operand when either is NaN or both equal.
inline vfloat<16> min(vfloat<16> a, vfloat<16> b) { return _mm512_min_ps(a.v, b.v); }
inline vfloat<16> max(vfloat<16> a, vfloat<16> b) { return _mm512_max_ps(a.v, b.v); }
inline vfloat<16> abs(vfloat<16> a) {
    return _mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(a.v), _mm512_set1_epi32(INT32_MAX)));
}
inline vfloat<16> sqrt(vfloat<16> a) { return _mm512_sqrt_ps(a.v); }
inline vfloat<16> rcp(vfloat<16> a) { return _mm512_div_ps(_mm512_set1_ps(1.0f), a.v); }
inline vfloat<16> rsqrt(vfloat<16> a) { return _mm512_div_ps(_mm512_set1_ps(1.0f), _mm512_sqrt_ps(a.v)); }
inline vfloat<16> floor(vfloat<16> a) { return _mm512_roundscale_ps(a.v, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC); }
inline vfloat<16> ceil(vfloat<16> a) { return _mm512_roundscale_ps(a.v, _MM_FROUND_TO_POS_INF | _MM_FROUND_NO_EXC); }

// Ordered-quiet predicates (false on NaN, like C++); != is unordered (true on NaN).
inline vbool<16> operator==(vfloat<16> a, vfloat<16> b) { return vbool<16>(_mm512_cmp_ps_mask(a.v, b.v, _CMP_EQ_OQ)); }
inline vbool<16> operator!=(vfloat<16> a, vfloat<16> b) { return vbool<16>(_mm512_cmp_ps_mask(a.v, b.v, _CMP_NEQ_UQ)); }
inline vbool<16> operator<(vfloat<16> a, vfloat<16> b) { return vbool<16>(_mm512_cmp_ps_mask(a.v, b.v, _CMP_LT_OQ)); }
inline vbool<16> operator<=(vfloat<16> a, vfloat<16> b) { return vbool<16>(_mm512_cmp_ps_mask(a.v, b.v, _CMP_LE_OQ)); }
inline vbool<16> operator>(vfloat<16> a, vfloat<16> b) { return vbool<16>(_mm512_cmp_ps_mask(a.v, b.v, _CMP_GT_OQ)); }
inline vbool<16> operator>=(vfloat<16> a, vfloat<16> b) { return vbool<16>(_mm512_cmp_ps_mask(a.v, b.v, _CMP_GE_OQ)); }

inline vfloat<16> select(vbool<16> m, vfloat<16> a, vfloat<16> b) { return _mm512_mask_blend_ps(m.v, b.v, a.v); }

// rcp14/rsqrt14 (relative error < 2^-14, denormal-correct) + one Newton-Raphson step; see
// simd4_sse.h for the NaN fix-up at 0 and inf.
inline vfloat<16> rcp_fast(vfloat<16> a) {
    const vfloat<16> r = _mm512_rcp14_ps(a.v);
    const vfloat<16> refined = madd(r, nmadd(a, r, 1.0f), r);
    return select(refined != refined, r, refined);
}
inline vfloat<16> rsqrt_fast(vfloat<16> a) {
    const vfloat<16> r = _mm512_rsqrt14_ps(a.v);
    const vfloat<16> refined = madd(r * 0.5f, nmadd(a * r, r, 1.0f), r);
    return select(refined != refined, r, refined);
}

// Halving order (vfloat.h), done with in-register shuffles: each step brings lane i + h down
// to lane i and combines it with lane i as the *second* operand (lane i first), which is what
// makes NaN / +-0 results match the width-1 fold bit for bit.
namespace detail {
template <typename Op>
inline float reduce16(__m512 a, Op op) {
    a = op(a, _mm512_shuffle_f32x4(a, a, _MM_SHUFFLE(1, 0, 3, 2)));  // h = 8: 256-bit halves
    a = op(a, _mm512_shuffle_f32x4(a, a, _MM_SHUFFLE(2, 3, 0, 1)));  // h = 4: 128-bit blocks
    a = op(a, _mm512_permute_ps(a, _MM_SHUFFLE(1, 0, 3, 2)));        // h = 2
    a = op(a, _mm512_permute_ps(a, _MM_SHUFFLE(2, 3, 0, 1)));        // h = 1
    return _mm512_cvtss_f32(a);
}
}  // namespace detail

inline float reduce_min(vfloat<16> a) {
    return detail::reduce16(a.v, [](__m512 x, __m512 y) { return _mm512_min_ps(x, y); });
}
inline float reduce_max(vfloat<16> a) {
    return detail::reduce16(a.v, [](__m512 x, __m512 y) { return _mm512_max_ps(x, y); });
}
inline float reduce_add(vfloat<16> a) {
    return detail::reduce16(a.v, [](__m512 x, __m512 y) { return _mm512_add_ps(x, y); });
}

// See simd4_sse.h: lanes outside the range (or NaN) are pinned to INT32_MIN even when GCC
// constant-folds the conversion (which it does with saturating semantics). The masked form
// converts only in-range lanes and takes INT32_MIN from the pass-through operand elsewhere.
inline vint<16> to_int(vfloat<16> a) {
    const vbool<16> in_range = (a >= vfloat<16>(-2147483648.0f)) & (a < vfloat<16>(2147483648.0f));
    return _mm512_mask_cvttps_epi32(_mm512_set1_epi32(INT32_MIN), in_range.v, a.v);
}
inline vfloat<16> to_float(vint<16> a) { return _mm512_cvtepi32_ps(a.v); }
inline vint<16> asInt(vfloat<16> a) { return _mm512_castps_si512(a.v); }
inline vfloat<16> asFloat(vint<16> a) { return _mm512_castsi512_ps(a.v); }

using vbool16 = vbool<16>;
using vint16 = vint<16>;
using vfloat16 = vfloat<16>;

}  // namespace WT_SIMD_ISA
}  // namespace wt::simd
