// src/simd tests for widths 1 and 4, compiled with -msse4.2 (see src/simd/tests.cmake).
#if !defined(__SSE4_2__) || defined(__AVX__)
#error "compile simd_test_sse4.cpp with -msse4.2 and nothing higher"
#endif

namespace {
bool tu_cpu_supported() { return __builtin_cpu_supports("sse4.2"); }
}  // namespace
#define WT_SIMD_TEST_ISA_NAME "SSE4.2"

#include "simd_test_body.h"

namespace {
using TestedWidths = ::testing::Types<Width<4>>;
INSTANTIATE_TYPED_TEST_SUITE_P(Sse4, SimdWidth, TestedWidths, WidthName);
INSTANTIATE_TYPED_TEST_SUITE_P(Sse4, ScalarReference, ::testing::Types<Width<1>>, WidthName);
}  // namespace
