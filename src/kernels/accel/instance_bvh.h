#pragma once
// The two-level acceleration structure of a scene with instances: each mesh's own tree, built
// once in object space however many instances place it, and a tree over the instances' world
// boxes (one instance per leaf) that the traversal (instance_traverse.h) walks after the
// scene's own tree. Same node width and builder as the scene's tree (bvh.h).

#include <cstddef>
#include <vector>

#include "core/base/aligned_vector.h"
#include "core/scene/scene.h"
#include "kernels/accel/bvh.h"
#include "kernels/accel/bvh_view.h"

namespace wt {

class ThreadPool;

class InstanceBvh {
public:
    // The view the traversal reads; valid while this object lives and is not moved.
    const InstanceView& view() const { return view_; }
    std::size_t instance_count() const { return records_.size(); }
    // Nodes and leaf blocks of the meshes' trees (each once), and the top level's nodes and
    // instance records.
    std::size_t mesh_bytes() const;
    std::size_t instance_bytes() const;

private:
    friend std::unique_ptr<InstanceBvh> build_instance_bvh(const Scene&, const BvhBuildOptions&, ThreadPool&);

    std::vector<Bvh> meshes_;
    std::vector<BvhView> mesh_views_;
    AlignedVector<BvhNode<4>> nodes4_;
    AlignedVector<BvhNode<8>> nodes8_;
    std::vector<InstanceRecord> records_;  // in top-level leaf order
    InstanceView view_{};
};

// Null for a scene without instances; the caller points its scene tree's view's `instances` at
// the result's view (scene_bvh.h). Throws std::invalid_argument as build_bvh.
std::unique_ptr<InstanceBvh> build_instance_bvh(const Scene& scene, const BvhBuildOptions& options, ThreadPool& pool);

}  // namespace wt
