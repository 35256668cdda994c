// src/simd tests for widths 1, 4, 8 and 16, compiled with -mavx512f -mavx512dq -mavx512bw
// -mavx512vl (see src/simd/tests.cmake). Widths 4 and 8 are tested here again: in an AVX-512
// TU they use rcp14/rsqrt14 and the AVX-512VL spelling of FMA.
#if !defined(__AVX512F__) || !defined(__AVX512DQ__) || !defined(__AVX512BW__) || !defined(__AVX512VL__)
#error "compile simd_test_avx512.cpp with -mavx512f -mavx512dq -mavx512bw -mavx512vl"
#endif

namespace {
bool tu_cpu_supported() {
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
           __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl");
}
}  // namespace
#define WT_SIMD_TEST_ISA_NAME "AVX-512 F/DQ/BW/VL"

#include "simd_test_body.h"

namespace {
using TestedWidths = ::testing::Types<Width<4>, Width<8>, Width<16>>;
INSTANTIATE_TYPED_TEST_SUITE_P(Avx512, SimdWidth, TestedWidths, WidthName);
INSTANTIATE_TYPED_TEST_SUITE_P(Avx512, ScalarReference, ::testing::Types<Width<1>>, WidthName);
}  // namespace
