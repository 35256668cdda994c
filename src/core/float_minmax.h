#pragma once
// std::fmax and std::fmin, inline. g++ calls libm for them unless NaNs are ruled out
// (-ffinite-math-only, which the renderer must not use), and the shading code calls them a few
// times per path vertex: a call, a compare and a branch each time for one maxss / minss.
//
// The results are glibc's on x86-64 (sysdeps/x86_64/fpu/s_fmaxf.S, s_fminf.S, which are
// maxss / minss with a NaN check): the larger (smaller) operand, y when the two compare equal
// (so fmax(+0, -0) is -0 in both), and the other operand when exactly one is NaN.

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
