// src/simd tests for widths 1, 4 and 8, compiled with -mavx2 -mfma (see src/simd/tests.cmake).
// Width 4 is tested here again: in an AVX2 TU it uses other instructions (vmaskmov, gathers,
// FMA) than in the SSE4 one.
#if !defined(__AVX2__) || !defined(__FMA__) || defined(__AVX512F__)
#error "compile simd_test_avx2.cpp with -mavx2 -mfma and nothing higher"
#endif

namespace {
bool tu_cpu_supported() { return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"); }
}  // namespace
#define WT_SIMD_TEST_ISA_NAME "AVX2+FMA"

#include "simd_test_body.h"

namespace {
using TestedWidths = ::testing::Types<Width<4>, Width<8>>;
INSTANTIATE_TYPED_TEST_SUITE_P(Avx2, SimdWidth, TestedWidths, WidthName);
INSTANTIATE_TYPED_TEST_SUITE_P(Avx2, ScalarReference, ::testing::Types<Width<1>>, WidthName);
}  // namespace
