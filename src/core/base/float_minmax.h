#pragma once
// std::fmax and std::fmin, inline. g++ calls libm for them unless NaNs are ruled out
// (-ffinite-math-only, which the renderer must not use), and the shading code calls them a few
// times per path vertex: a call, a compare and a branch each time for one maxss / minss.
//
// The contract (tests/sampling_test.cpp): the larger (smaller) operand, the other operand when
// exactly one is NaN, and y when the two compare equal, so fmax(+0, -0) is -0. C leaves the
// sign of that zero unspecified, and std::fmax's differs between builds (glibc's x86-64
// assembly, maxss with a NaN check, gives -0; the sanitizer build's did not): ours is the same
// everywhere.

namespace wt {

inline float fmax_float(float x, float y) {
    if (y != y) return x;    // y is NaN
    return x > y ? x : y;    // maxss: y when x is NaN or the two are equal
}

inline float fmin_float(float x, float y) {
    if (y != y) return x;
    return x < y ? x : y;    // minss
}

}  // namespace wt
