#pragma once
// --debug-sample X,Y,S: one sample traced alone with the reference integrator, every vertex
// printed, so any pixel's sample of any render can be replayed and inspected.

#include <cstdint>
#include <string>

#include "core/scene/scene.h"
#include "kernels/render_options.h"

namespace wt {

struct DebugSample {
    int x = 0, y = 0;
    uint32_t sample = 0;
};

// Throws std::runtime_error naming the flag for malformed text or a pixel outside the image.
DebugSample parse_debug_sample(const std::string& text, int width, int height);

// Prints the path to stdout; returns the exit code.
int replay_sample(const Scene& scene, const RenderOptions& options, const DebugSample& sample);

}  // namespace wt
