#pragma once
// vint<N>: N lanes of int32_t. Arithmetic wraps around (two's complement), like the SIMD
// instructions; width 1 computes through uint32_t so it wraps too instead of being UB.
//
// Operations (every width):
//   vint<N>(int32_t)            broadcast (implicit, so `v + 1` works)
//   vint<N>::step()             (0, 1, ..., N-1)
//   v[i]                        read lane i
//   load(p) / loadu(p)          aligned (N*4 bytes) / unaligned load: static members
//   store(p, v) / storeu(p, v)  aligned / unaligned store: static members
//   load_masked(m, p)           active lanes from p, inactive lanes 0; inactive lanes are
//                               never read (no fault past the end of a buffer)
//   store_masked(m, p, v)       writes active lanes only; inactive memory is untouched
//   load_partial(p, count, fill)  lanes [0, count) from p, the rest `fill`; reads exactly
//                               `count` elements. count is clamped to [0, N].
//   store_partial(p, v, count)  writes lanes [0, count) only; count clamped to [0, N]
//   gather(base, idx)           lane i = base[idx[i]] (idx: signed element offsets).
//                               AVX2 / AVX-512 use the gather instruction, SSE emulates.
//   gather(m, base, idx)        active lanes gathered, inactive lanes 0 and not read
//   a + b, a - b, a * b, -a     wrapping; a * b keeps the low 32 bits
//   a & b, a | b, a ^ b, ~a     bitwise; also +=, -=, *=, &=, |=, ^=
//   a << n, a >> n, srl(a, n)   shift all lanes by the same count n. >> is arithmetic,
//                               srl logical. Defined for every n (taken as unsigned 32-bit,
//                               like the SSE shift-by-register instructions): n >= 32 gives
//                               0 for << and srl, and the sign (0 or -1) for >>.
//   ==, !=, <, <=, >, >=        signed compares -> vbool<N>
//   select(m, a, b)             m ? a : b per lane
//   min(a, b), max(a, b)        signed
//   to_float(v)                 int -> float, round to nearest even (exact below 2^24)
//   asFloat(v)                  reinterpret the bits as vfloat<N>

#include <cstdint>

#include "simd/isa.h"

namespace wt::simd {
inline namespace WT_SIMD_ISA {

template <int N>
struct vint;

}  // namespace WT_SIMD_ISA
}  // namespace wt::simd
