#include "kernels/accel/instance_bvh.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/system/thread_pool.h"
#include "kernels/accel/bvh_boxes.h"
#include "kernels/accel/bvh_collapse.h"
#include "kernels/accel/sah_builder.h"

namespace wt {
namespace {

Box object_box(const TriangleSoA& t) {
    Box box;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const glm::vec3 v0 = t.vertex0(i);
        box.extend_point(v0), box.extend_point(t.vertex1(i)), box.extend_point(t.vertex2(i));
        box.extend_point(v0 + t.edge1(i)), box.extend_point(v0 + t.edge2(i));
    }
    return box;
}

// The scene's own primitives' box, as the flat tree's builder bounds them.
Box own_box(const Scene& scene) {
    Box box = object_box(scene.triangles);
    for (std::size_t i = 0; i < scene.triangles.parallelogram_count; ++i)
        box.extend_point(scene.triangles.vertex0(i) + scene.triangles.edge1(i) + scene.triangles.edge2(i));
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const glm::vec3 c = scene.spheres.center(i), r(scene.spheres.radius[i]);
        box.extend_point(c - r), box.extend_point(c + r);
    }
    return box;
}

glm::dvec3 corner(const Box& b, int k) {
    return {(k & 1) ? b.hi_at(0) : b.lo_at(0), (k & 2) ? b.hi_at(1) : b.lo_at(1), (k & 4) ? b.hi_at(2) : b.lo_at(2)};
}

glm::dvec3 apply(const AffineTransform& t, const glm::dvec3& p) {
    glm::dvec3 out;
    for (int r = 0; r < 3; ++r) out[r] = double(t.m[r][0]) * p.x + double(t.m[r][1]) * p.y + double(t.m[r][2]) * p.z + double(t.m[r][3]);
    return out;
}

// The box's corners placed by t, in double, rounded outward to float.
Box placed_box(const Box& b, const AffineTransform& t) {
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (int k = 0; k < 8; ++k) {
        const glm::dvec3 p = apply(t, corner(b, k));
        lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    Box out;
    out.extend_point(glm::vec3(std::nextafter(float(lo.x), -INFINITY), std::nextafter(float(lo.y), -INFINITY),
                               std::nextafter(float(lo.z), -INFINITY)));
    out.extend_point(glm::vec3(std::nextafter(float(hi.x), INFINITY), std::nextafter(float(hi.y), INFINITY),
                               std::nextafter(float(hi.z), INFINITY)));
    return out;
}

template <int W>
uint32_t collapse_top(const BinaryTree& tree, const PrimRefs& refs, float pad, AlignedVector<BvhNode<W>>& nodes) {
    nodes.reserve(refs.size() / 2 + 1);
    WideCollapser<W> c(tree, pad, nodes);
    return c.emit(tree.root);
}

}  // namespace

std::size_t InstanceBvh::mesh_bytes() const {
    std::size_t bytes = 0;
    for (const Bvh& b : meshes_) bytes += b.stats().node_bytes + b.stats().primitive_bytes;
    return bytes;
}

std::size_t InstanceBvh::instance_bytes() const {
    return nodes4_.size() * sizeof(BvhNode<4>) + nodes8_.size() * sizeof(BvhNode<8>) + records_.size() * sizeof(InstanceRecord);
}

std::unique_ptr<InstanceBvh> build_instance_bvh(const Scene& scene, const BvhBuildOptions& options, ThreadPool& pool) {
    const SceneInstances& in = scene.instances;
    if (in.empty()) return nullptr;
    auto out = std::make_unique<InstanceBvh>();
    const std::size_t mesh_count = in.meshes.size();

    // Where rays can start: anywhere in the world box (the scene's own primitives, every
    // instance's placed mesh box, the eye). Each mesh's pad is sized by the largest object-space
    // coordinate such a point has in any instance of it, as the flat tree's is by the world's.
    std::vector<Box> local(mesh_count);
    for (std::size_t m = 0; m < mesh_count; ++m) local[m] = object_box(in.meshes[m].triangles);
    Box world = own_box(scene);
    world.extend_point(scene.camera.eye());
    for (const Instance& k : in.instances) world.extend(placed_box(local[k.mesh], k.to_world));
    std::vector<glm::vec3> reach(mesh_count, glm::vec3(0.0f));
    for (const Instance& k : in.instances)
        for (int c = 0; c < 8; ++c) {
            const glm::dvec3 p = apply(k.to_object, corner(world, c));
            for (int a = 0; a < 3; ++a) reach[k.mesh][a] = std::max(reach[k.mesh][a], float(std::fabs(p[a])));
        }

    out->meshes_.reserve(mesh_count);
    out->mesh_views_.resize(mesh_count);
    const SphereSoA no_spheres;
    for (std::size_t m = 0; m < mesh_count; ++m) {
        out->meshes_.push_back(
            build_bvh(in.meshes[m].triangles, no_spheres, scene.settings.accuracy.triangles, reach[m], options, &pool));
        out->mesh_views_[m] = bvh_view(out->meshes_[m]);
    }

    // The top level: one instance per leaf, its box the mesh's padded object box placed.
    PrimRefs refs(in.instances.size());
    for (std::size_t k = 0; k < in.instances.size(); ++k) {
        const Instance& inst = in.instances[k];
        const Box padded = local[inst.mesh].padded(rounding_pad(local[inst.mesh], reach[inst.mesh]));
        const Box box = placed_box(padded, inst.to_world);
        PrimRef& r = refs[k];
        _mm_store_ps(r.lo, box.lo);
        _mm_store_ps(r.hi, box.hi);
        r.id = uint32_t(k);
        r.kind = uint8_t(BvhLeafKind::triangle);
    }
    if (refs.size() > kBvhMaxLeafPrimitives)
        throw std::invalid_argument("BVH: " + std::to_string(refs.size()) + " instances, more than the " +
                                    std::to_string(kBvhMaxLeafPrimitives) + " its leaf references can index");
    SahSettings sah;
    sah.max_leaf_size = 1;
    sah.leaf_block = 1;
    const BinaryTree tree = build_binary_sah(refs, sah, pool);
    if (tree.max_depth * uint32_t(options.node_width - 1) + 1 > uint32_t(kBvhStackSize))
        throw std::invalid_argument("BVH: instance tree too deep for the traversal stack (" + std::to_string(tree.max_depth) +
                                    " levels)");
    const float pad = rounding_pad(world, scene.camera.eye());
    const uint32_t root = options.node_width == 4 ? collapse_top<4>(tree, refs, pad, out->nodes4_)
                                                  : collapse_top<8>(tree, refs, pad, out->nodes8_);
    out->records_.resize(refs.size());
    for (std::size_t j = 0; j < refs.size(); ++j) {
        const Instance& inst = in.instances[refs[j].id];
        InstanceRecord& r = out->records_[j];
        for (int row = 0; row < 3; ++row)
            for (int c = 0; c < 4; ++c) r.to_object[row][c] = inst.to_object.m[row][c];
        r.mesh = inst.mesh;
        r.first_id = inst.first_id;
    }
    out->view_.nodes = options.node_width == 4 ? static_cast<const void*>(out->nodes4_.data())
                                               : static_cast<const void*>(out->nodes8_.data());
    out->view_.root = root;
    out->view_.records = out->records_.data();
    out->view_.meshes = out->mesh_views_.data();
    return out;
}

}  // namespace wt
