#include "scene_workloads.h"

#include <cstdio>
#include <iterator>
#include <map>

#include "bench_scene.h"
#include "kernels/isa/intersect_dispatch.h"
#include "timed_step.h"

namespace wt::bench {

namespace {

constexpr int kImageSize = 800;

}  // namespace

struct SceneWorkloads::Built {
    Scene scene;
    std::optional<Ball> solid;
    std::unique_ptr<Bvh> bvh4, bvh8;
    std::unique_ptr<RaySet> rays[std::size(kAllWorkloads)];  // indexed by Workload
};

SceneWorkloads::SceneWorkloads(std::string name) : name_(std::move(name)) {}
SceneWorkloads::~SceneWorkloads() = default;

const Scene& SceneWorkloads::scene() {
    if (unavailable_) throw SceneUnavailable(*unavailable_);
    if (built_) return built_->scene;
    auto build = [&] {
        BenchScene description = bench_scene(name_, kImageSize, kImageSize);
        auto built = std::make_unique<Built>();
        built->scene = build_scene(description.description);
        built->solid = description.solid;
        return built;
    };
    auto details = [](const std::unique_ptr<Built>& built) {
        return std::to_string(built->scene.triangles.size()) + " triangles and parallelograms, " +
               std::to_string(built->scene.spheres.size()) + " spheres";
    };
    try {
        built_ = timed_step(name_, "scene built", build, details);
    } catch (const SceneUnavailable& e) {
        std::fprintf(stderr, "bench: %s: skipped: %s\n", name_.c_str(), e.what());
        unavailable_ = e.what();
        throw;
    }
    return built_->scene;
}

const Bvh& SceneWorkloads::bvh(int node_width) {
    const Scene& built_scene = scene();
    std::unique_ptr<Bvh>& slot = node_width == 4 ? built_->bvh4 : built_->bvh8;
    if (!slot) {
        slot = timed_step(
            name_, "bvh" + std::to_string(node_width) + " built",
            [&] {
                BvhBuildOptions options;
                options.node_width = node_width;
                return std::make_unique<Bvh>(build_bvh(built_scene, options));
            },
            [](const std::unique_ptr<Bvh>& bvh) {
                return std::to_string(bvh->stats().node_count) + " nodes, " + std::to_string(bvh->stats().leaf_count) +
                       " leaves, SAH cost " + std::to_string(bvh->stats().sah_cost);
            });
    }
    return *slot;
}

const RaySet& SceneWorkloads::rays(Workload workload) {
    const Scene& built_scene = scene();
    std::unique_ptr<RaySet>& slot = built_->rays[int(workload)];
    if (!slot) {
        // The shading points of the shadow and bounce rays come from the scalar kernels, which give the
        // same bits as every other ISA, so the workload does not depend on the machine.
        const ClosestHitFunction closest = [&](const RayView& rays, const HitView& hits) {
            intersect_kernels(Isa::scalar).closest_bvh(bvh_view(bvh(8)), rays, hits);
        };
        slot = timed_step(
            name_, std::string(workload_name(workload)) + " rays generated",
            [&] { return std::make_unique<RaySet>(workload_rays(workload, built_scene, built_->solid, closest)); },
            [](const std::unique_ptr<RaySet>& rays) { return std::to_string(rays->size()) + " rays"; });
    }
    return *slot;
}

SceneWorkloads& scene_workloads(const std::string& name) {
    static std::map<std::string, std::unique_ptr<SceneWorkloads>> all;
    std::unique_ptr<SceneWorkloads>& slot = all[name];
    if (!slot) slot = std::make_unique<SceneWorkloads>(name);
    return *slot;
}

}  // namespace wt::bench
