#pragma once
// What a benchmark program builds before it measures (scenes, BVHs, ray sets) takes seconds for
// the big scenes; each step reports its time on stderr, so a slow set-up is visible and never
// mistaken for a slow benchmark.

#include <chrono>
#include <cstdio>
#include <string>

namespace wt::bench {

// Runs build(), prints "bench: SCENE: WHAT in S s (DETAILS)" to stderr, with DETAILS =
// details(result), and returns what build() returned.
template <typename Build, typename Details>
auto timed_step(const std::string& scene, const std::string& what, const Build& build, const Details& details) {
    const auto start = std::chrono::steady_clock::now();
    auto result = build();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "bench: %s: %s in %.2f s (%s)\n", scene.c_str(), what.c_str(), seconds, details(result).c_str());
    return result;
}

}  // namespace wt::bench
