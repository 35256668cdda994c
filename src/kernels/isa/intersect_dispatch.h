#pragma once
// Choosing the intersection kernels for this CPU, and viewing the renderer's buffers as the
// plain SoA views the kernels take.

#include <optional>
#include <string>

#include "core/scene/scene.h"
#include "kernels/isa/intersect_kernels.h"
#include "kernels/queues/ray_queues.h"
#include "kernels/primitives/soa_views.h"
#include "kernels/primitives/triangle_rows.h"

namespace wt {

// The CPU and the OS (saved register state) support the ISA's instructions.
bool cpu_supports(Isa isa);
Isa best_supported_isa();
// Throws std::runtime_error naming the ISA if this CPU cannot run it.
const IntersectKernels& intersect_kernels(Isa isa, const AccuracySettings& accuracy = {});

// The scene as the flat kernels read it: its triangles copied into the rows of its test
// (triangle_rows.h), its spheres where the scene keeps them. Throws std::invalid_argument if the
// triangles were stored for another test than the scene's settings name.
class FlatScene {
public:
    explicit FlatScene(const Scene& scene);
    // Valid while this and the scene live.
    SceneView view() const;

private:
    TriangleRows triangles_;
    const SphereSoA* spheres_;
};

RayView ray_view(const RayQueue& rays);
HitView hit_view(HitQueue& hits);
RayView ray_view(const ShadowQueue& shadows);

}  // namespace wt
