# Test target for src/simd, meant to be include()d from the top-level CMakeLists.txt (after
# enable_testing()). Defines the gtest executable `simd_test`: one body
# (tests/simd_test_body.h) compiled into three TUs with different target flags, each testing
# the widths its flags allow and skipping at run time when the CPU lacks the ISA.
#
# WT_SOURCE_DIR is the repository root; it defaults to two levels above this file, so the
# file works both from the main project and from a scratch project that includes it by path.

if(NOT DEFINED WT_SOURCE_DIR)
    get_filename_component(WT_SOURCE_DIR "${CMAKE_CURRENT_LIST_DIR}/../.." ABSOLUTE)
endif()

if(NOT TARGET wavetrace_simd)
    add_subdirectory(${WT_SOURCE_DIR}/src/simd ${CMAKE_BINARY_DIR}/wavetrace_simd)
endif()

find_package(GTest REQUIRED)
include(GoogleTest)

set(WT_SIMD_TEST_SSE4 ${WT_SOURCE_DIR}/tests/simd_test_sse4.cpp)
set(WT_SIMD_TEST_AVX2 ${WT_SOURCE_DIR}/tests/simd_test_avx2.cpp)
set(WT_SIMD_TEST_AVX512 ${WT_SOURCE_DIR}/tests/simd_test_avx512.cpp)

# Keep the TUs in ascending ISA order. Inline/template code the TUs share (gtest, libstdc++)
# is emitted into each object compiled with that object's flags, and GNU ld keeps the *first*
# copy in link order: ascending order means every shared function comes from the lowest ISA
# that uses it, so the SSE4 tests never call an AVX-512 encoded std:: or gtest helper.
# (The library itself is safe from this: it lives in per-ISA namespaces, see isa.h.)
# Known limit of the run-time skip: the AVX2/AVX-512 TUs' static initialisers (gtest
# registration) are compiled with their flags too, and GCC uses VEX-encoded moves there, so
# the binary needs an AVX-capable CPU to start; beyond that, missing ISAs are GTEST_SKIPped.
add_executable(simd_test ${WT_SIMD_TEST_SSE4} ${WT_SIMD_TEST_AVX2} ${WT_SIMD_TEST_AVX512})
# Per-file ISA flags: these are the same flag sets the kernels use, one TU per ISA.
set_source_files_properties(${WT_SIMD_TEST_SSE4} PROPERTIES COMPILE_OPTIONS "-msse4.2")
set_source_files_properties(${WT_SIMD_TEST_AVX2} PROPERTIES COMPILE_OPTIONS "-mavx2;-mfma")
set_source_files_properties(${WT_SIMD_TEST_AVX512} PROPERTIES
    COMPILE_OPTIONS "-mavx512f;-mavx512dq;-mavx512bw;-mavx512vl")
target_include_directories(simd_test PRIVATE ${WT_SOURCE_DIR}/tests)
target_link_libraries(simd_test PRIVATE wavetrace_simd GTest::gtest_main)
target_compile_features(simd_test PRIVATE cxx_std_17)
target_compile_options(simd_test PRIVATE -Wall -Wextra)

gtest_discover_tests(simd_test)
