#pragma once
// What a replayed path (--debug-sample, --debug-light-path) traces against: the same hits either
// way, but a big scene is replayed through a BVH, as a render would trace it, so a replay takes
// no longer than the render's own start.

#include "kernels/accel/accel_choice.h"
#include "kernels/accel/bvh.h"
#include "kernels/accel/bvh_view.h"
#include "kernels/accel/scene_bvh.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/render_options.h"

namespace wt {

struct ReplayAccel {
    SceneBvh bvh;
    bool use_bvh = false;

    ReplayAccel(const Scene& scene, const RenderOptions& options) {
        const int width = intersect_kernels(options.isa.value_or(best_supported_isa())).width;
        use_bvh = resolve_accel(options.accel, scene.primitive_count(), width, !scene.instances.empty()) == Accel::bvh;
        BvhBuildOptions bvh_options = options.bvh;
        bvh_options.parallelograms_beside = parallelograms_beside_tree(width);
        if (use_bvh) bvh = build_scene_bvh(scene, bvh_options, nullptr);
    }
    // The tree, or null for the flat list.
    const BvhView* view() const { return use_bvh ? &bvh.view : nullptr; }
};

}  // namespace wt
