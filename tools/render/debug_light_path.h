#pragma once
// --debug-light-path I,S: light path I of sample S traced alone, every vertex and its connection
// to the camera printed, as --debug-sample does for a camera path (light paths are keyed by
// (seed, index, sample), kernels/caustics/light_path.h).

#include <cstdint>
#include <string>

#include "core/scene/scene.h"
#include "kernels/render_options.h"

namespace wt {

struct DebugLightPath {
    uint64_t index = 0;
    uint32_t sample = 0;
};

// Throws std::runtime_error naming the flag for malformed text, an index past the paths a sample
// traces, or a scene that traces none.
DebugLightPath parse_debug_light_path(const std::string& text, const Scene& scene);

// Prints the path to stdout; returns the exit code.
int replay_light_path(const Scene& scene, const RenderOptions& options, const DebugLightPath& path);

}  // namespace wt
