#pragma once
// vbool<N>: one boolean per lane, the result of comparing vfloat<N> or vint<N>.
//
// Representation differs per ISA, on purpose:
//   N = 1   plain bool.
//   N = 4   __m128 (SSE) / N = 8 __m256 (AVX2): each lane all-ones or all-zeros. Before
//           AVX-512 there are no mask registers: compares write lane masks into an ordinary
//           vector register and blendv/and/or/movemask consume them from there, so keeping
//           the mask in that form costs nothing. (A float vector rather than an integer one
//           because the float compares and blendv_ps produce/consume it directly.)
//           Invariant: every lane is all-ones or all-zeros; only construct from raw
//           registers you know to be canonical.
//   N = 16  __mmask16 (AVX-512): compares write a k-register, one bit per lane, and every
//           AVX-512 instruction can take a k-register as its write mask (masked loads, stores,
//           blends, gathers). Expanding it into a vector would cost instructions for nothing.
//           The 4- and 8-wide masks keep their vector form under AVX-512 too, so each width
//           has exactly one representation.
//
// Operations (every width):
//   vbool<N>(bool)              broadcast (explicit: an int must not silently become a mask)
//   vbool<N>::from_bits(bits)   lane i = bit i of bits (bits above N ignored)
//   m[i]                        read lane i (tests, debugging)
//   a & b, a | b, a ^ b, ~a     lane-wise logic; also &=, |=, ^=
//   andnot(a, b)                a & ~b  -- NOTE: *not* Intel's _mm_andnot order (~a & b)
//   a == b, a != b              lane-wise equality of masks
//   any(m), all(m), none(m)     over the N lanes
//   movemask(m)                 uint32_t, bit i = lane i (bits >= N are zero)
//   popcount(m)                 number of active lanes

#include "simd/isa.h"

namespace wt::simd {
inline namespace WT_SIMD_ISA {

template <int N>
struct vbool;

}  // namespace WT_SIMD_ISA
}  // namespace wt::simd
