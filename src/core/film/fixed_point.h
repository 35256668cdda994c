#pragma once
// Exact, order-independent sums for the film. Each value is rounded once, to an integer count
// of 2^-40, and integers add associatively: a pixel's sum is the same bits whatever order its
// samples arrive in and however they are split, over passes, resumed checkpoints, partial
// renders merged later or MPI ranks. A double sum would depend on the order of additions
// ((a + b) + c != a + (b + c)), so a render split over two processes would differ from one
// process in the last bits.
//
// Range: 2^-40 (about 9e-13) resolution, and any value below 2^86 in magnitude converts. A
// sum is 128 bits, so 2^40 samples of 2^46 (7e13) each fit; adds are checked and an add that
// would overflow is refused, never wrapped.

#include <cstddef>
#include <cstdint>

#if defined(__x86_64__)
#include <emmintrin.h>
#else
#include <cmath>
#endif

namespace wt {

using FixedPoint = __int128;

constexpr int fixed_point_fraction_bits = 40;
constexpr double fixed_point_one = 0x1p40;

// Rounds `value` to the nearest multiple of 2^-40. False (and `out` untouched) for NaN, an
// infinity or a magnitude of 2^86 or more.
inline bool to_fixed_point(double value, FixedPoint& out) {
    const double scaled = value * fixed_point_one;
    if (scaled > -0x1p62 && scaled < 0x1p62) {
        // cvtsd2si rounds to nearest, in one instruction; std::llrint is a libm call here.
#if defined(__x86_64__)
        out = FixedPoint(_mm_cvtsd_si64(_mm_set_sd(scaled)));
#else
        out = FixedPoint(std::llrint(scaled));
#endif
        return true;
    }
    if (!(scaled > -0x1p126 && scaled < 0x1p126)) return false;  // also NaN
    out = FixedPoint(scaled);  // |scaled| >= 2^62 > 2^53: already an integer, converts exactly
    return true;
}

inline double from_fixed_point(FixedPoint value) { return double(value) / fixed_point_one; }

// a += b, unless that overflows: then false and `a` unchanged.
inline bool add_fixed_point(FixedPoint& a, FixedPoint b) {
    FixedPoint sum;
    if (__builtin_add_overflow(a, b, &sum)) return false;
    a = sum;
    return true;
}

// Takes back what add_fixed_point(sums, values, n) added: each value converts to the same
// integer again, and an integer subtraction exactly undoes an addition that did not overflow.
template <typename Value>
inline void subtract_fixed_point(FixedPoint* sums, const Value* values, std::size_t n) {
    for (std::size_t c = 0; c < n; ++c) {
        FixedPoint v = 0;
        to_fixed_point(double(values[c]), v);
        sums[c] -= v;
    }
}

// sums[c] += values[c] for every c < n, or nothing: false, and the sums as they were, when a
// value does not convert or a sum would overflow. Added in place and taken back on a refusal,
// so the common case, where every value goes in, makes no copy of the sums.
template <typename Value>
inline bool add_fixed_point(FixedPoint* sums, const Value* values, std::size_t n) {
    for (std::size_t c = 0; c < n; ++c) {
        FixedPoint v;
        if (!to_fixed_point(double(values[c]), v) || !add_fixed_point(sums[c], v)) {
            subtract_fixed_point(sums, values, c);
            return false;
        }
    }
    return true;
}

}  // namespace wt
