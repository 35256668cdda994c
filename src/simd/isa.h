#pragma once
// Which instruction set this translation unit is compiled for, which vector widths that
// allows, and the namespace that keeps code compiled for different ISAs apart.
//
// The kernels are compiled once per ISA, in separate translation units with their own target
// flags (none, -msse4.2, -mavx2 -mfma, -mavx512f -mavx512dq -mavx512bw -mavx512vl), and linked
// into one binary that picks an ISA at run time. Everything in src/simd is inline and lives in
// headers, so without care `vfloat<4>::operator+` would be one inline function defined in
// several TUs with *different machine code* (SSE encoding in one, AVX-512 EVEX in another).
// The linker keeps one arbitrary copy (the One Definition Rule says they are the same
// function), and the SSE4 kernel could end up calling the AVX-512 copy: SIGILL on a CPU
// without AVX-512. Even width 1 is affected (std::fma becomes vfmadd under -mfma).
// So all of src/simd lives in `wt::simd::<isa>`, an *inline* namespace named after the target
// flags: code still writes `wt::simd::vfloat<4>`, but the mangled names differ per ISA.
// Consequence: all TUs of one binary that map to the same ISA namespace below must use the
// same target flags (as with Embree's per-ISA namespaces).
//
// Tiers (highest one whose flags are all present wins):
//   isa_avx512  AVX-512 F+DQ+BW+VL: widths 1, 4, 8, 16
//   isa_avx2    AVX2 + FMA:        widths 1, 4, 8
//   isa_avx     AVX (no AVX2):     widths 1, 4 (suffix _fma if FMA is on; not a kernel target,
//                                  only here so such a TU cannot collide with isa_sse42)
//   isa_sse42   SSE4.2:            widths 1, 4
//   isa_scalar  anything less:     width 1 only

#if defined(__AVX512F__) || defined(__AVX512DQ__) || defined(__AVX512BW__) || defined(__AVX512VL__)
#if !(defined(__AVX512F__) && defined(__AVX512DQ__) && defined(__AVX512BW__) && defined(__AVX512VL__))
#error "wavetrace simd: AVX-512 builds need -mavx512f -mavx512dq -mavx512bw -mavx512vl together"
#endif
#define WT_SIMD_ISA isa_avx512
#define WT_SIMD_MAX_WIDTH 16
#elif defined(__AVX2__)
#if !defined(__FMA__)
// Every AVX2 CPU has FMA; a TU without it would silently give madd() different rounding
// from the other AVX2 TUs, so refuse rather than guess.
#error "wavetrace simd: AVX2 builds need -mfma as well (-mavx2 -mfma)"
#endif
#define WT_SIMD_ISA isa_avx2
#define WT_SIMD_MAX_WIDTH 8
#elif defined(__AVX__) && defined(__FMA__)
#define WT_SIMD_ISA isa_avx_fma
#define WT_SIMD_MAX_WIDTH 4
#elif defined(__AVX__)
#define WT_SIMD_ISA isa_avx
#define WT_SIMD_MAX_WIDTH 4
#elif defined(__SSE4_2__)
#define WT_SIMD_ISA isa_sse42
#define WT_SIMD_MAX_WIDTH 4
#else
#define WT_SIMD_ISA isa_scalar
#define WT_SIMD_MAX_WIDTH 1
#endif

// Widths available in this TU (width 1 always is).
#define WT_SIMD_HAS_WIDTH4 (WT_SIMD_MAX_WIDTH >= 4)
#define WT_SIMD_HAS_WIDTH8 (WT_SIMD_MAX_WIDTH >= 8)
#define WT_SIMD_HAS_WIDTH16 (WT_SIMD_MAX_WIDTH >= 16)

// Whether madd() and friends are fused (one rounding) in this TU. It is the same for every
// width of a TU, width 1 included, so width 1 stays a bit-exact reference for the others.
// GCC's -mavx512f does not imply -mfma, but AVX-512F has its own FMA instructions (and
// AVX-512VL their 128/256-bit forms), so the AVX-512 tier is fused too.
#if defined(__FMA__) || defined(__AVX512F__)
#define WT_SIMD_FUSED_MADD 1
#else
#define WT_SIMD_FUSED_MADD 0
#endif

namespace wt::simd {
inline namespace WT_SIMD_ISA {

// Lane count of the widest vector this TU supports.
inline constexpr int max_width = WT_SIMD_MAX_WIDTH;

// True when madd/msub/nmadd/nmsub round once (std::fma semantics) in this TU.
inline constexpr bool fused_madd = WT_SIMD_FUSED_MADD != 0;

}  // namespace WT_SIMD_ISA
}  // namespace wt::simd
