#pragma once
// Width 4: vbool<4>, vint<4>, vfloat<4> on SSE4.2 (__m128 / __m128i).
//
// Compiled into the SSE4.2, AVX2 and AVX-512 TUs alike, so a few operations pick a better
// instruction when the TU has it (each #if says which):
//   AVX     masked load/store with vmaskmov (SSE has none: emulated lane by lane)
//   AVX2    gather instruction (SSE: emulated)
//   FMA     vfmadd (SSE: unfused); AVX-512 TUs spell it through AVX-512VL because GCC's
//           -mavx512f does not enable the plain FMA intrinsics
//   AVX512VL  rcp14/rsqrt14 estimates (2^-14 instead of 1.5*2^-12, and denormal-correct)
// Masks are lane masks in an __m128 (all-ones / all-zeros per lane); see vbool.h for why.

#if !defined(__SSE4_2__)
#error "simd4_sse.h needs -msse4.2 (include simd/simd.h, which only includes it when allowed)"
#endif

#include "simd/intrinsics.h"

#include <cstdint>

#include "simd/isa.h"
#include "simd/simd1_scalar.h"
#include "simd/vbool.h"
#include "simd/vfloat.h"
#include "simd/vint.h"

namespace wt::simd {
inline namespace WT_SIMD_ISA {

// ---------------------------------------------------------------------------------------------
// vbool<4>

template <>
struct vbool<4> {
    static constexpr int N = 4;
    __m128 v;  // per lane all-ones (true) or all-zeros (false)

    vbool() = default;
    explicit vbool(__m128 m) : v(m) {}
    explicit vbool(bool b) : v(_mm_castsi128_ps(_mm_set1_epi32(b ? -1 : 0))) {}
    static vbool from_bits(uint32_t bits) {
        const __m128i lane_bit = _mm_setr_epi32(1, 2, 4, 8);
        const __m128i b = _mm_and_si128(_mm_set1_epi32(static_cast<int>(bits)), lane_bit);
        return vbool(_mm_castsi128_ps(_mm_cmpeq_epi32(b, lane_bit)));
    }

    bool operator[](int i) const { return (_mm_movemask_ps(v) >> i) & 1; }
};

inline vbool<4> operator&(vbool<4> a, vbool<4> b) { return vbool<4>(_mm_and_ps(a.v, b.v)); }
inline vbool<4> operator|(vbool<4> a, vbool<4> b) { return vbool<4>(_mm_or_ps(a.v, b.v)); }
inline vbool<4> operator^(vbool<4> a, vbool<4> b) { return vbool<4>(_mm_xor_ps(a.v, b.v)); }
inline vbool<4> operator~(vbool<4> a) { return a ^ vbool<4>(true); }
inline vbool<4> andnot(vbool<4> a, vbool<4> b) { return vbool<4>(_mm_andnot_ps(b.v, a.v)); }
inline vbool<4> operator==(vbool<4> a, vbool<4> b) {
    return vbool<4>(_mm_castsi128_ps(_mm_cmpeq_epi32(_mm_castps_si128(a.v), _mm_castps_si128(b.v))));
}
inline vbool<4> operator!=(vbool<4> a, vbool<4> b) { return a ^ b; }
inline vbool<4>& operator&=(vbool<4>& a, vbool<4> b) { return a = a & b; }
inline vbool<4>& operator|=(vbool<4>& a, vbool<4> b) { return a = a | b; }
inline vbool<4>& operator^=(vbool<4>& a, vbool<4> b) { return a = a ^ b; }

inline uint32_t movemask(vbool<4> m) { return static_cast<uint32_t>(_mm_movemask_ps(m.v)); }
inline bool any(vbool<4> m) { return movemask(m) != 0; }
inline bool all(vbool<4> m) { return movemask(m) == 0xF; }
inline bool none(vbool<4> m) { return movemask(m) == 0; }
inline int popcount(vbool<4> m) { return __builtin_popcount(movemask(m)); }

// ---------------------------------------------------------------------------------------------
// vint<4>

template <>
struct vint<4> {
    static constexpr int N = 4;
    __m128i v;

    vint() = default;
    vint(__m128i x) : v(x) {}
    vint(int32_t x) : v(_mm_set1_epi32(x)) {}

    static vint step() { return _mm_setr_epi32(0, 1, 2, 3); }

    static vint load(const int32_t* p) { return _mm_load_si128(reinterpret_cast<const __m128i*>(p)); }
    static vint loadu(const int32_t* p) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p)); }
    static void store(int32_t* p, vint x) { _mm_store_si128(reinterpret_cast<__m128i*>(p), x.v); }
    static void storeu(int32_t* p, vint x) { _mm_storeu_si128(reinterpret_cast<__m128i*>(p), x.v); }

    // Forced, as load_partial below: in the large BVH walk functions g++'s growth limits left
    // both as calls in every leaf test, about 5-16 % more instructions in the SSE4 walks.
    [[gnu::always_inline]] static vint load_masked(vbool<4> m, const int32_t* p) {
#if defined(__AVX__)
        // vmaskmovps: masked-off lanes read as 0 and never fault.
        return _mm_castps_si128(_mm_maskload_ps(reinterpret_cast<const float*>(p), _mm_castps_si128(m.v)));
#else
        const uint32_t bits = movemask(m);
        alignas(16) int32_t lanes[4] = {0, 0, 0, 0};
        for (int i = 0; i < 4; ++i)
            if (bits & (1u << i)) lanes[i] = p[i];
        return load(lanes);
#endif
    }
    static void store_masked(vbool<4> m, int32_t* p, vint x) {
#if defined(__AVX__)
        _mm_maskstore_ps(reinterpret_cast<float*>(p), _mm_castps_si128(m.v), _mm_castsi128_ps(x.v));
#else
        // Not maskmovdqu: that one is a non-temporal store (evicts the line from the cache).
        const uint32_t bits = movemask(m);
        alignas(16) int32_t lanes[4];
        store(lanes, x);
        for (int i = 0; i < 4; ++i)
            if (bits & (1u << i)) p[i] = lanes[i];
#endif
    }
    static vint load_partial(const int32_t* p, int count, vint fill);
    static void store_partial(int32_t* p, vint x, int count);

    static vint gather(const int32_t* base, vint idx) {
#if defined(__AVX2__)
        return _mm_i32gather_epi32(base, idx.v, 4);
#else
        alignas(16) int32_t i[4];
        store(i, idx);
        return _mm_setr_epi32(base[i[0]], base[i[1]], base[i[2]], base[i[3]]);
#endif
    }
    static vint gather(vbool<4> m, const int32_t* base, vint idx) {
#if defined(__AVX2__)
        return _mm_mask_i32gather_epi32(_mm_setzero_si128(), base, idx.v, _mm_castps_si128(m.v), 4);
#else
        const uint32_t bits = movemask(m);
        alignas(16) int32_t i[4];
        alignas(16) int32_t lanes[4] = {0, 0, 0, 0};
        store(i, idx);
        for (int k = 0; k < 4; ++k)
            if (bits & (1u << k)) lanes[k] = base[i[k]];
        return load(lanes);
#endif
    }

    int32_t operator[](int i) const {
        alignas(16) int32_t lanes[4];
        store(lanes, *this);
        return lanes[i & 3];
    }
};

inline vint<4> operator+(vint<4> a, vint<4> b) { return _mm_add_epi32(a.v, b.v); }
inline vint<4> operator-(vint<4> a, vint<4> b) { return _mm_sub_epi32(a.v, b.v); }
inline vint<4> operator*(vint<4> a, vint<4> b) { return _mm_mullo_epi32(a.v, b.v); }
inline vint<4> operator-(vint<4> a) { return _mm_sub_epi32(_mm_setzero_si128(), a.v); }
inline vint<4> operator&(vint<4> a, vint<4> b) { return _mm_and_si128(a.v, b.v); }
inline vint<4> operator|(vint<4> a, vint<4> b) { return _mm_or_si128(a.v, b.v); }
inline vint<4> operator^(vint<4> a, vint<4> b) { return _mm_xor_si128(a.v, b.v); }
inline vint<4> operator~(vint<4> a) { return _mm_xor_si128(a.v, _mm_set1_epi32(-1)); }

// Shift-by-register forms: the count is a 64-bit value, so n >= 32 (or negative n, seen as
// a large unsigned) gives 0 / the sign, which is what width 1 reproduces.
inline vint<4> operator<<(vint<4> a, int n) { return _mm_sll_epi32(a.v, _mm_cvtsi32_si128(n)); }
inline vint<4> operator>>(vint<4> a, int n) { return _mm_sra_epi32(a.v, _mm_cvtsi32_si128(n)); }
inline vint<4> srl(vint<4> a, int n) { return _mm_srl_epi32(a.v, _mm_cvtsi32_si128(n)); }

inline vint<4>& operator+=(vint<4>& a, vint<4> b) { return a = a + b; }
inline vint<4>& operator-=(vint<4>& a, vint<4> b) { return a = a - b; }
inline vint<4>& operator*=(vint<4>& a, vint<4> b) { return a = a * b; }
inline vint<4>& operator&=(vint<4>& a, vint<4> b) { return a = a & b; }
inline vint<4>& operator|=(vint<4>& a, vint<4> b) { return a = a | b; }
inline vint<4>& operator^=(vint<4>& a, vint<4> b) { return a = a ^ b; }

inline vbool<4> operator==(vint<4> a, vint<4> b) { return vbool<4>(_mm_castsi128_ps(_mm_cmpeq_epi32(a.v, b.v))); }
inline vbool<4> operator<(vint<4> a, vint<4> b) { return vbool<4>(_mm_castsi128_ps(_mm_cmplt_epi32(a.v, b.v))); }
inline vbool<4> operator>(vint<4> a, vint<4> b) { return vbool<4>(_mm_castsi128_ps(_mm_cmpgt_epi32(a.v, b.v))); }
inline vbool<4> operator!=(vint<4> a, vint<4> b) { return ~(a == b); }
inline vbool<4> operator<=(vint<4> a, vint<4> b) { return ~(a > b); }
inline vbool<4> operator>=(vint<4> a, vint<4> b) { return ~(a < b); }

inline vint<4> select(vbool<4> m, vint<4> a, vint<4> b) {
    return _mm_blendv_epi8(b.v, a.v, _mm_castps_si128(m.v));  // canonical masks: bytes agree
}
inline vint<4> min(vint<4> a, vint<4> b) { return _mm_min_epi32(a.v, b.v); }
inline vint<4> max(vint<4> a, vint<4> b) { return _mm_max_epi32(a.v, b.v); }

namespace detail {
// Mask of lanes [0, count): the shared core of load_partial / store_partial.
inline vbool<4> first_lanes4(int count) { return vint<4>::step() < vint<4>(count); }
}  // namespace detail

[[gnu::always_inline]] inline vint<4> vint<4>::load_partial(const int32_t* p, int count, vint fill) {
    if (count >= 4) return loadu(p);
    const vbool<4> m = detail::first_lanes4(count);
    return select(m, load_masked(m, p), fill);
}
inline void vint<4>::store_partial(int32_t* p, vint x, int count) {
    if (count >= 4) return storeu(p, x);
    store_masked(detail::first_lanes4(count), p, x);
}

// ---------------------------------------------------------------------------------------------
// vfloat<4>

template <>
struct vfloat<4> {
    static constexpr int N = 4;
    static constexpr bool fused_madd = WT_SIMD_FUSED_MADD != 0;
    __m128 v;

    vfloat() = default;
    vfloat(__m128 x) : v(x) {}
    vfloat(float x) : v(_mm_set1_ps(x)) {}

    static vfloat load(const float* p) { return _mm_load_ps(p); }
    static vfloat loadu(const float* p) { return _mm_loadu_ps(p); }
    static void store(float* p, vfloat x) { _mm_store_ps(p, x.v); }
    static void storeu(float* p, vfloat x) { _mm_storeu_ps(p, x.v); }

    // The integer versions move the same 32-bit lanes; reuse them.
    static vfloat load_masked(vbool<4> m, const float* p) {
        return _mm_castsi128_ps(vint<4>::load_masked(m, reinterpret_cast<const int32_t*>(p)).v);
    }
    static void store_masked(vbool<4> m, float* p, vfloat x) {
        vint<4>::store_masked(m, reinterpret_cast<int32_t*>(p), _mm_castps_si128(x.v));
    }
    static vfloat load_partial(const float* p, int count, vfloat fill) {
        return _mm_castsi128_ps(
            vint<4>::load_partial(reinterpret_cast<const int32_t*>(p), count, _mm_castps_si128(fill.v)).v);
    }
    static void store_partial(float* p, vfloat x, int count) {
        vint<4>::store_partial(reinterpret_cast<int32_t*>(p), _mm_castps_si128(x.v), count);
    }

    static vfloat gather(const float* base, vint<4> idx) {
#if defined(__AVX2__)
        return _mm_i32gather_ps(base, idx.v, 4);
#else
        alignas(16) int32_t i[4];
        vint<4>::store(i, idx);
        return _mm_setr_ps(base[i[0]], base[i[1]], base[i[2]], base[i[3]]);
#endif
    }
    static vfloat gather(vbool<4> m, const float* base, vint<4> idx) {
#if defined(__AVX2__)
        return _mm_mask_i32gather_ps(_mm_setzero_ps(), base, idx.v, m.v, 4);
#else
        return _mm_castsi128_ps(vint<4>::gather(m, reinterpret_cast<const int32_t*>(base), idx).v);
#endif
    }

    float operator[](int i) const {
        alignas(16) float lanes[4];
        store(lanes, *this);
        return lanes[i & 3];
    }
};

inline vfloat<4> operator+(vfloat<4> a, vfloat<4> b) { return _mm_add_ps(a.v, b.v); }
inline vfloat<4> operator-(vfloat<4> a, vfloat<4> b) { return _mm_sub_ps(a.v, b.v); }
inline vfloat<4> operator*(vfloat<4> a, vfloat<4> b) { return _mm_mul_ps(a.v, b.v); }
inline vfloat<4> operator/(vfloat<4> a, vfloat<4> b) { return _mm_div_ps(a.v, b.v); }
inline vfloat<4> operator-(vfloat<4> a) { return _mm_xor_ps(a.v, _mm_set1_ps(-0.0f)); }
inline vfloat<4>& operator+=(vfloat<4>& a, vfloat<4> b) { return a = a + b; }
inline vfloat<4>& operator-=(vfloat<4>& a, vfloat<4> b) { return a = a - b; }
inline vfloat<4>& operator*=(vfloat<4>& a, vfloat<4> b) { return a = a * b; }
inline vfloat<4>& operator/=(vfloat<4>& a, vfloat<4> b) { return a = a / b; }

#if defined(__FMA__)
inline vfloat<4> madd(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return _mm_fmadd_ps(a.v, b.v, c.v); }
inline vfloat<4> msub(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return _mm_fmsub_ps(a.v, b.v, c.v); }
inline vfloat<4> nmadd(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return _mm_fnmadd_ps(a.v, b.v, c.v); }
inline vfloat<4> nmsub(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return _mm_fnmsub_ps(a.v, b.v, c.v); }
#elif defined(__AVX512VL__)
// Same vfmadd instructions, reached through the AVX-512VL intrinsics (all lanes enabled).
inline vfloat<4> madd(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return _mm_mask_fmadd_ps(a.v, 0xF, b.v, c.v); }
inline vfloat<4> msub(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return _mm_mask_fmsub_ps(a.v, 0xF, b.v, c.v); }
inline vfloat<4> nmadd(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return _mm_mask_fnmadd_ps(a.v, 0xF, b.v, c.v); }
inline vfloat<4> nmsub(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return _mm_mask_fnmsub_ps(a.v, 0xF, b.v, c.v); }
#else
// No FMA: two roundings (documented in vfloat.h; width 1 does the same in such a TU).
inline vfloat<4> madd(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return a * b + c; }
inline vfloat<4> msub(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return a * b - c; }
inline vfloat<4> nmadd(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return c - a * b; }
inline vfloat<4> nmsub(vfloat<4> a, vfloat<4> b, vfloat<4> c) { return -(a * b) - c; }
#endif

// minps/maxps return the second operand when either is NaN or both are equal (+-0).
inline vfloat<4> min(vfloat<4> a, vfloat<4> b) { return _mm_min_ps(a.v, b.v); }
inline vfloat<4> max(vfloat<4> a, vfloat<4> b) { return _mm_max_ps(a.v, b.v); }
inline vfloat<4> abs(vfloat<4> a) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), a.v); }
inline vfloat<4> sqrt(vfloat<4> a) { return _mm_sqrt_ps(a.v); }
inline vfloat<4> rcp(vfloat<4> a) { return _mm_div_ps(_mm_set1_ps(1.0f), a.v); }
inline vfloat<4> rsqrt(vfloat<4> a) { return _mm_div_ps(_mm_set1_ps(1.0f), _mm_sqrt_ps(a.v)); }
inline vfloat<4> floor(vfloat<4> a) { return _mm_floor_ps(a.v); }
inline vfloat<4> ceil(vfloat<4> a) { return _mm_ceil_ps(a.v); }

inline vbool<4> operator==(vfloat<4> a, vfloat<4> b) { return vbool<4>(_mm_cmpeq_ps(a.v, b.v)); }
inline vbool<4> operator!=(vfloat<4> a, vfloat<4> b) { return vbool<4>(_mm_cmpneq_ps(a.v, b.v)); }
inline vbool<4> operator<(vfloat<4> a, vfloat<4> b) { return vbool<4>(_mm_cmplt_ps(a.v, b.v)); }
inline vbool<4> operator<=(vfloat<4> a, vfloat<4> b) { return vbool<4>(_mm_cmple_ps(a.v, b.v)); }
inline vbool<4> operator>(vfloat<4> a, vfloat<4> b) { return vbool<4>(_mm_cmpgt_ps(a.v, b.v)); }
inline vbool<4> operator>=(vfloat<4> a, vfloat<4> b) { return vbool<4>(_mm_cmpge_ps(a.v, b.v)); }

inline vfloat<4> select(vbool<4> m, vfloat<4> a, vfloat<4> b) { return _mm_blendv_ps(b.v, a.v, m.v); }

// Estimate + one Newton-Raphson step r' = r + r * (1 - a*r). Where the step yields NaN
// although the estimate did not (a = +-0 gives r = +-inf, a = +-inf gives r = +-0: 0 * inf),
// the estimate is already the exact answer and is kept.
inline vfloat<4> rcp_fast(vfloat<4> a) {
#if defined(__AVX512VL__)
    const vfloat<4> r = _mm_rcp14_ps(a.v);
#else
    const vfloat<4> r = _mm_rcp_ps(a.v);
#endif
    const vfloat<4> refined = madd(r, nmadd(a, r, 1.0f), r);
    return select(refined != refined, r, refined);
}
// r' = r + 0.5 * r * (1 - a*r*r); same fix-up (a = +-0 -> +-inf, a = inf -> 0).
inline vfloat<4> rsqrt_fast(vfloat<4> a) {
#if defined(__AVX512VL__)
    const vfloat<4> r = _mm_rsqrt14_ps(a.v);
#else
    const vfloat<4> r = _mm_rsqrt_ps(a.v);
#endif
    const vfloat<4> refined = madd(r * 0.5f, nmadd(a * r, r, 1.0f), r);
    return select(refined != refined, r, refined);
}

// Halving order (vfloat.h): lanes (0,1) = op(lane 0, lane 2), op(lane 1, lane 3); then
// op(lane 0, lane 1). The lower lane is always the first operand.
inline float reduce_min(vfloat<4> a) {
    const __m128 h = _mm_min_ps(a.v, _mm_movehl_ps(a.v, a.v));
    return _mm_cvtss_f32(_mm_min_ss(h, _mm_shuffle_ps(h, h, 1)));
}
inline float reduce_max(vfloat<4> a) {
    const __m128 h = _mm_max_ps(a.v, _mm_movehl_ps(a.v, a.v));
    return _mm_cvtss_f32(_mm_max_ss(h, _mm_shuffle_ps(h, h, 1)));
}
inline float reduce_add(vfloat<4> a) {
    const __m128 h = _mm_add_ps(a.v, _mm_movehl_ps(a.v, a.v));
    return _mm_cvtss_f32(_mm_add_ss(h, _mm_shuffle_ps(h, h, 1)));
}

// cvttps2dq returns INT32_MIN ("integer indefinite") for NaN and out-of-range lanes when it
// runs, but GCC constant-folds it with saturating semantics (INT32_MAX for 2^31, 0 for NaN)
// when the input is known at compile time. The explicit range select makes the result the
// same either way, and the same as width 1. Cost: two compares and a blend.
inline vint<4> to_int(vfloat<4> a) {
    const vbool<4> in_range = (a >= vfloat<4>(-2147483648.0f)) & (a < vfloat<4>(2147483648.0f));
    return select(in_range, vint<4>(_mm_cvttps_epi32(a.v)), vint<4>(INT32_MIN));
}
inline vfloat<4> to_float(vint<4> a) { return _mm_cvtepi32_ps(a.v); }
inline vint<4> asInt(vfloat<4> a) { return _mm_castps_si128(a.v); }
inline vfloat<4> asFloat(vint<4> a) { return _mm_castsi128_ps(a.v); }

using vbool4 = vbool<4>;
using vint4 = vint<4>;
using vfloat4 = vfloat<4>;

}  // namespace WT_SIMD_ISA
}  // namespace wt::simd
