#pragma once
// Everything bench_intersect measures one scene with, built on first use and then kept for the
// rest of the run: the scene, its BVHs and its three ray sets. Only the benchmarks that match
// --benchmark_filter ask for them, so a filtered run builds only what it measures, and no
// building is ever inside a timed loop. Each step's time goes to stderr.

#include <memory>
#include <optional>
#include <string>

#include "core/scene/scene.h"
#include "kernels/accel/bvh.h"
#include "workloads.h"

namespace wt::bench {

class SceneWorkloads {
public:
    explicit SceneWorkloads(std::string name);
    ~SceneWorkloads();
    SceneWorkloads(const SceneWorkloads&) = delete;
    SceneWorkloads& operator=(const SceneWorkloads&) = delete;

    const std::string& name() const { return name_; }
    // The scene at 800x800 (the primary rays' image). Throws SceneUnavailable (bench_scene.h)
    // if it cannot be built here, and then again on every call without trying again.
    const Scene& scene();
    // Built with the default options but for the width (4 or 8), on every hardware thread
    // (the tree is the same for any thread count).
    const Bvh& bvh(int node_width);
    const RaySet& rays(Workload workload);

private:
    struct Built;
    std::string name_;
    std::unique_ptr<Built> built_;
    std::optional<std::string> unavailable_;  // why the scene could not be built
};

// The one SceneWorkloads of scene `name` (a name from bench_scene_names()).
SceneWorkloads& scene_workloads(const std::string& name);

}  // namespace wt::bench
