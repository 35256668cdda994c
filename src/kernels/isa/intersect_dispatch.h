#pragma once
// Choosing the intersection kernels for this CPU, and viewing the renderer's buffers as the
// plain SoA views the kernels take.

#include <optional>
#include <string>

#include "core/scene/scene.h"
#include "kernels/isa/intersect_kernels.h"
#include "kernels/queues/ray_queues.h"
#include "kernels/primitives/soa_views.h"

namespace wt {

const char* isa_name(Isa isa);
// "scalar", "sse4", "avx2", "avx512"; empty for anything else ("auto" is the caller's business).
std::optional<Isa> parse_isa(const std::string& name);
// The CPU and the OS (saved register state) support the ISA's instructions.
bool cpu_supports(Isa isa);
Isa best_supported_isa();
// Throws std::runtime_error naming the ISA if this CPU cannot run it.
const IntersectKernels& intersect_kernels(Isa isa, const AccuracySettings& accuracy = {});

SceneView scene_view(const Scene& scene);
RayView ray_view(const RayQueue& rays);
HitView hit_view(HitQueue& hits);
RayView ray_view(const ShadowQueue& shadows);

}  // namespace wt
