#pragma once
// Helpers written once for every width, using only the per-width primitives.

#include <cstdint>
#include <limits>

#include "simd/isa.h"
#include "simd/vbool.h"
#include "simd/vfloat.h"
#include "simd/vint.h"

namespace wt::simd {
inline namespace WT_SIMD_ISA {

// Lane index of the smallest v among the lanes set in `active` ("closest hit among N
// primitives"): the lowest such index on ties (-0 and +0 tie), NaN lanes never win, and -1
// when no active lane holds a number. Cost: one reduction, a compare and a bit scan.
template <int N>
inline int select_min_index(const vbool<N>& active, const vfloat<N>& v) {
    const vbool<N> valid = active & (v == v);  // v == v is false exactly for NaN
    const vfloat<N> candidates = select(valid, v, vfloat<N>(std::numeric_limits<float>::infinity()));
    const float smallest = reduce_min(candidates);
    // Re-checking `valid` matters when every valid lane is +inf: inactive lanes hold +inf too.
    const uint32_t hits = movemask(valid & (candidates == vfloat<N>(smallest)));
    return hits != 0 ? __builtin_ctz(hits) : -1;
}

// `a` with its sign flipped in the lanes where `sign` has its sign bit set (-0, negatives, -NaN):
// a bitwise xor, so exact, and it keeps a comparison against 0 meaning the same after a
// quotient's sign has been moved from the denominator onto the numerator.
template <int N>
inline vfloat<N> flip_sign(const vfloat<N>& a, const vfloat<N>& sign) {
    return asFloat(asInt(a) ^ (asInt(sign) & vint<N>(INT32_MIN)));
}

}  // namespace WT_SIMD_ISA
}  // namespace wt::simd
