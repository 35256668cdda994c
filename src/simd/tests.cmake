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

# Each TU is compiled with its ISA's flags and isolated (cmake/isa_object.cmake). The inline
# and template code the TUs share (gtest, libstdc++) is emitted into each object with that
# object's flags, and the linker kept the AVX-512 copy of vector<string>::emplace_back for the
# gtest registration of every TU: SIGILL on a CPU without AVX-512 (in the sanitizer build,
# where link order did not save us). Isolated, a TU's copies are local to it, so no other TU
# and no library code can call them (tests/isa_isolation_test.sh checks the binaries).
# Known limit: a TU's own static initialisers (its gtest registration) are compiled with its
# flags; GCC uses VEX-encoded (AVX) instructions there, never EVEX (the same script checks),
# so the binary starts on any AVX2 CPU; missing ISAs are GTEST_SKIPped at run time.
include(${WT_SOURCE_DIR}/cmake/isa_object.cmake)
# With a sanitizer (-O2 and its instrumentation), GCC does put EVEX instructions in the AVX-512
# TU's static initialisers: AddressSanitizer poisons their stack redzones with vmovdqu8 stores
# to the shadow. On a CPU without AVX-512 the binary died of SIGILL before main (a Zen 1
# machine); on one with it, isa_isolation_test.sh failed (CI, stop 23). So a sanitizer build
# made on a CPU without AVX-512 leaves that TU out (WAVETRACE_WITH_AVX512, top-level
# CMakeLists.txt), as nothing there could run it, and where it is built it has no stack
# instrumentation (below); the Release build always keeps it.
set(simd_test_isas sse4 avx2)
if(NOT DEFINED WAVETRACE_WITH_AVX512 OR WAVETRACE_WITH_AVX512)
  list(APPEND simd_test_isas avx512)
endif()
set(simd_test_flags_sse4 -msse4.2)
set(simd_test_flags_avx2 -mavx2 -mfma)
set(simd_test_flags_avx512 -mavx512f -mavx512dq -mavx512bw -mavx512vl)
# No stack instrumentation in the AVX-512 TU under AddressSanitizer (see above): its test bodies'
# stack use is still checked in the SSE4 and AVX2 TUs, which compile the same body for widths 4
# and 8, and its heap accesses here.
if(WAVETRACE_SANITIZE MATCHES "address" OR WAVETRACE_FUZZ)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    list(APPEND simd_test_flags_avx512 --param=asan-stack=0)
  else()
    list(APPEND simd_test_flags_avx512 "SHELL:-mllvm -asan-stack=0")
  endif()
endif()
set(simd_test_isa_objects)
foreach(isa IN LISTS simd_test_isas)
  # WAVETRACE_KERNEL_SANITIZE_OPTIONS: the same packet loops as the kernels (CMakeLists.txt).
  wavetrace_isa_object(simd_test_${isa} simd_test_${isa} ${WT_SOURCE_DIR}/tests/simd_test_${isa}.cpp
                       FLAGS ${simd_test_flags_${isa}} -Wall -Wextra ${WAVETRACE_KERNEL_SANITIZE_OPTIONS}
                       LINK wavetrace_simd GTest::gtest)
  target_include_directories(simd_test_${isa}_compile PRIVATE ${WT_SOURCE_DIR}/tests)
  list(APPEND simd_test_isa_objects ${simd_test_${isa}})
endforeach()
add_executable(simd_test ${simd_test_isa_objects})
target_include_directories(simd_test PRIVATE ${WT_SOURCE_DIR}/tests)
target_link_libraries(simd_test PRIVATE wavetrace_simd GTest::gtest_main)
target_compile_features(simd_test PRIVATE cxx_std_17)
target_compile_options(simd_test PRIVATE -Wall -Wextra)

gtest_discover_tests(simd_test)
