#pragma once
// The statistics printed after a render: what was rendered, how fast, and the BVH.

#include <iosfwd>
#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "kernels/progressive_render.h"
#include "kernels/renderer.h"

namespace wt {

struct RenderSummary {
    std::string scene_path;
    std::string integrator_name;
    const Scene* scene = nullptr;
    const RenderOptions* options = nullptr;
    RenderResult result;
    ProgressiveResult progressive;
    uint32_t film_spp = 0;  // samples per pixel in the image written
    std::vector<std::string> written;
    const AdaptiveState* adaptive = nullptr;  // the film's, when it is of an adaptive render
};

void print_render_summary(std::ostream& out, const RenderSummary& summary);

// 1234567 -> "1.235 M": for counts and rates.
std::string with_si_prefix(double value);

}  // namespace wt
