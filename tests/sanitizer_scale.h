#pragma once
// The kernel comparisons (bvh_test, packet_intersect_test) under a sanitizer trace an eighth of
// their rays. What a sanitizer looks for (out-of-bounds reads, uninitialised lanes, overflow)
// shows on the code paths the rays take, and the smaller sets still take every one of them
// (every ISA, width, layout, query and partial packet); what needs the full sets, the
// bit-for-bit agreement on rare geometry, the Release suite checks with every ray. At full
// size these were the ASan suite's longest tests.
// WT_SANITIZED_BUILD comes from tests/CMakeLists.txt when WAVETRACE_SANITIZE is set.

#ifndef WT_SANITIZED_BUILD
#define WT_SANITIZED_BUILD 0
#endif

namespace wt::test {

constexpr int kSanitizerRayDivisor = WT_SANITIZED_BUILD ? 8 : 1;

constexpr int sanitizer_scaled(int rays) { return rays / kSanitizerRayDivisor; }

}  // namespace wt::test
