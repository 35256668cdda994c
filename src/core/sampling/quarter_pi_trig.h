#pragma once
// sin and cos of an angle in [-pi/4, pi/4], as polynomials the compiler inlines. The concentric
// disk map (sampling.h) only ever needs this octant, and a libm sincosf call there cost more
// than its own arithmetic: the call made every live float register spill around it (3.9 % of
// a hexroom render in sincosf itself, and sample_bsdf around it was a fifth).
//
// Taylor series to x^9 (sin) and x^10 (cos): on |x| <= pi/4 the truncation error is below
// 2e-9 and 1.2e-10, so what is left is float rounding in the Horner steps; the test checks
// 2 ulp against double-precision sin and cos on the whole range. Plain multiplies and adds
// (no fused multiply-add, like the rest of the renderer), so every build and ISA gets the same bits.
// A template over the float type: the SIMD shade kernels (kernels/shading) evaluate the same
// polynomial on vfloat<N>, so every lane gets the scalar code's bits.

namespace wt {

template <typename F>
struct SinCosOf {
    F sin, cos;
};
using SinCos = SinCosOf<float>;

template <typename F>
inline SinCosOf<F> sin_cos_quarter_pi(F x) {
    const F x2 = x * x;
    const F s = x + x * x2 * (-1.0f / 6.0f + x2 * (1.0f / 120.0f + x2 * (-1.0f / 5040.0f + x2 * (1.0f / 362880.0f))));
    const F c = 1.0f + x2 * (-0.5f + x2 * (1.0f / 24.0f + x2 * (-1.0f / 720.0f + x2 * (1.0f / 40320.0f + x2 * (-1.0f / 3628800.0f)))));
    return {s, c};
}

}  // namespace wt
