#pragma once
// vfloat<N>: N lanes of IEEE single precision. The contract below holds for every width;
// width 1 is plain scalar C++ and is the bit-exact reference the tests hold the others to.
// Do not compile kernels with -ffast-math / -ffinite-math-only: the NaN rules below (which
// ray-box and closest-hit code rely on) stop holding.
//
// Construction, memory (same as vint<N>, see vint.h):
//   vfloat<N>(float) broadcast (implicit, so `v * 2.0f` works), v[i], load, loadu, store,
//   storeu, load_masked, store_masked, load_partial, store_partial, gather (float table).
//
// Exactly rounded, bit-identical across widths (ISA instructions are IEEE-754 exact):
//   a + b, a - b, a * b, a / b, sqrt(a)
//   rcp(a)     = 1.0f / a      (a real division, so exact: rcp(+-0) = +-inf, rcp(+-inf) = +-0)
//   rsqrt(a)   = 1.0f / sqrt(a) (two correct roundings, not one: up to 1 ulp from the true
//                                value, but the same bits on every width)
//   floor(a), ceil(a)
//   -a, abs(a)  flip / clear the sign bit, NaN included
//
// Approximations (the hardware estimate followed by one Newton-Raphson step):
//   rcp_fast(a)   <= 4 ulp from rcp(a) for normal |a| in [2^-126, 2^125)
//   rsqrt_fast(a) <= 5 ulp from rsqrt(a) for normal positive a
//   The bounds follow from the estimate's specified error (1.5*2^-12) squared by the Newton
//   step, plus the roundings of the step (one more without FMA); the tests enforce them
//   (simd_test: every float of a binade, plus random), on whatever CPU runs them.
//   Use rcp/rsqrt when bits must match across ISAs.
//   0 -> +-inf, inf -> +-0 and NaN -> NaN exactly (the Newton step would give NaN there; the
//   estimate is kept instead). On SSE/AVX2 the estimate treats denormal inputs as 0 (result
//   +-inf) and flushes tiny results to 0 (so rcp_fast(|a| >= ~2^125.9) may be +-0); AVX-512
//   (rcp14) is accurate there too. Width 1 has no estimate instruction: it returns rcp/rsqrt.
//   The raw estimates (1.5*2^-12 relative error, 2^-14 on AVX-512) are deliberately not
//   exposed: they differ between Intel and AMD, so results would not be reproducible.
//
// Fused multiply-add: madd(a,b,c) = a*b+c, msub = a*b-c, nmadd = -(a*b)+c, nmsub = -(a*b)-c.
//   With FMA (the AVX2 and AVX-512 TUs) they round once, exactly like std::fma. Without it
//   (scalar and SSE4 TUs) they are a multiply then an add, rounded twice: the result then
//   differs from std::fma by the rounding of a*b, which under cancellation (a*b ~ -c) is
//   *all* of the result (std::fma gives the exact residual, the unfused form gives 0).
//   Every width of one TU makes the same choice (vfloat<N>::fused_madd, simd::fused_madd),
//   so width 1 is still the bit-exact reference for the others in that TU.
//   Plain `a * b + c` may or may not be contracted into an FMA by GCC (-ffp-contract=fast is
//   its default): call madd() when it matters, or build with -ffp-contract=off.
//
// min / max and NaN -- chosen to match the x86 instructions, and width 1 does the same:
//   min(a, b) = (a < b) ? a : b       max(a, b) = (a > b) ? a : b
//   If either operand is NaN the comparison is false and the *second* operand b is returned
//   (NaN or not). min(+0, -0) = -0 and min(-0, +0) = +0 (equal, so b). This is NOT std::min
//   (which returns a when the compare fails) nor std::fmin (which drops NaN symmetrically).
//   Use: put the value that may be NaN first to have it discarded. Ray-slab code computing
//   t = (bound - org) * rcp(dir) gets NaN when 0 * inf; max(t, tnear) then keeps tnear and
//   min(t, tfar) keeps tfar, so a NaN slab never narrows the interval.
//
// Compares <, <=, >, >=, == are false if either side is NaN; != is true (IEEE, like C++).
// select(m, a, b) = m ? a : b per lane (bits copied, NaN payloads included).
//
// Horizontal (return a scalar):
//   reduce_min / reduce_max / reduce_add fold by halving: for h = N/2, N/4, ..., 1 lane i < h
//   becomes op(lane i, lane i + h). The order is part of the contract, so a sum is the same
//   bits on every ISA for a given N (it is not the left-to-right sum). With NaN lanes
//   reduce_min/max follow the min/max rule above at each step.
//   select_min_index(m, v): the lowest lane index i with m[i] set whose v[i] equals the
//   minimum of v over the active non-NaN lanes; -1 if there is no such lane. NaN lanes never
//   win, ties (including -0 vs +0) go to the lowest index. This is "closest hit among N".
//
// Conversions:
//   to_int(a)   truncate toward zero; NaN and values outside [-2^31, 2^31) give INT32_MIN
//               (x86's "integer indefinite"; width 1 does the same instead of being UB)
//   asInt(a)    reinterpret the bits as vint<N>;  asFloat(vint) is the inverse
//
// Every width also has: the lane count `vfloat<N>::N`, `vfloat<N>::fused_madd`, the native
// register as member `v` (for dropping to intrinsics), += -= *= /=.

#include "simd/isa.h"

namespace wt::simd {
inline namespace WT_SIMD_ISA {

template <int N>
struct vfloat;

}  // namespace WT_SIMD_ISA
}  // namespace wt::simd
