#pragma once
// Umbrella header: include this. It pulls in every vector width the current translation
// unit's target flags allow (see isa.h):
//   always                       vfloat<1>, vint<1>, vbool<1>  (scalar; the test reference)
//   -msse4.2 and above           vfloat<4>, vint<4>, vbool<4>  (SSE4.2)
//   -mavx2 -mfma and above       vfloat<8>, vint<8>, vbool<8>  (AVX2 + FMA)
//   -mavx512f/dq/bw/vl           vfloat<16>, vint<16>, vbool<16> (AVX-512)
// plus `wt::simd::max_width` and the aliases vfloatx / vintx / vboolx for the widest one.
// The contract of each type is documented in vfloat.h, vint.h and vbool.h.
//
// Everything is in namespace wt::simd (really wt::simd::isa_<name>, an inline namespace that
// keeps TUs compiled for different ISAs from sharing inline functions; see isa.h).

#include "simd/isa.h"
#include "simd/vbool.h"
#include "simd/vfloat.h"
#include "simd/vint.h"

#include "simd/simd1_scalar.h"
#if WT_SIMD_HAS_WIDTH4
#include "simd/simd4_sse.h"
#endif
#if WT_SIMD_HAS_WIDTH8
#include "simd/simd8_avx2.h"
#endif
#if WT_SIMD_HAS_WIDTH16
#include "simd/simd16_avx512.h"
#endif

#include "simd/algorithms.h"

namespace wt::simd {
inline namespace WT_SIMD_ISA {

using vfloatx = vfloat<max_width>;
using vintx = vint<max_width>;
using vboolx = vbool<max_width>;

}  // namespace WT_SIMD_ISA
}  // namespace wt::simd
