#pragma once
// <immintrin.h>, included with one GCC false positive silenced.
//
// GCC 12.1/12.2 warn "'__Y' is used uninitialized [-Wuninitialized]" inside many AVX-512
// intrinsics (_mm512_min_ps, _mm512_sqrt_ps, gathers, ... : every one whose pass-through
// operand is _mm512_undefined_ps(), written `__m512 __Y = __Y;`) once they are inlined with
// optimisation on: GCC bug PR 105593, fixed in 12.3. The warning is reported at a line of the
// intrinsic header, and GCC applies the diagnostic pragmas in force at the *location* of a
// warning, so disabling it around the include silences exactly those lines and nothing in
// our code or the caller's. (If <immintrin.h> was already included earlier without this,
// the include guard makes this a no-op and the warnings come back: include simd/simd.h first.)

#if defined(__GNUC__) && !defined(__clang__)  // clang has neither the bug nor -Wmaybe-uninitialized
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>
#pragma GCC diagnostic pop
#else
#include <immintrin.h>
#endif
