#pragma once
// The scene's tree and, for a scene with instances, their two-level structure, with the view
// the kernels take (its `instances` set only then; its alpha test only for a scene with
// alpha-tested materials).

#include <memory>

#include "core/scene/alpha_test.h"
#include "core/scene/scene.h"
#include "core/system/thread_pool.h"
#include "kernels/accel/bvh.h"
#include "kernels/accel/bvh_view.h"
#include "kernels/accel/instance_bvh.h"

namespace wt {

class ThreadPool;

struct SceneBvh {
    Bvh tree;
    std::unique_ptr<InstanceBvh> instances;  // null without instances
    BvhView view{};
};

inline SceneBvh build_scene_bvh(const Scene& scene, const BvhBuildOptions& options, ThreadPool* pool) {
    SceneBvh b;
    b.tree = build_bvh(scene, options, pool);
    b.view = bvh_view(b.tree);
    if (scene.has_alpha_materials) b.view.alpha_keeps = &alpha_keeps_hit, b.view.alpha_context = &scene;
    if (!scene.instances.empty()) {
        std::unique_ptr<ThreadPool> own;
        if (!pool) own = std::make_unique<ThreadPool>(options.threads > 0 ? options.threads : 1), pool = own.get();
        b.instances = build_instance_bvh(scene, options, *pool);
        b.view.instances = &b.instances->view();
    }
    return b;
}

}  // namespace wt
