#include "core/import/gltf_nodes.h"

#include <cstdint>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/import/imported_mesh.h"

namespace wt {

namespace {

constexpr int kMaxDepth = 256;
constexpr uint64_t kMaxVisits = uint64_t(1) << 20;

class NodeWalk {
public:
    NodeWalk(const std::string& path, const tinygltf::Model& model, const GltfNodeVisit& visit)
        : path_(path), model_(model), visit_(visit) {}

    void walk(int index, const glm::dmat4& parent, int depth) {
        if (index < 0 || std::size_t(index) >= model_.nodes.size()) fail("node " + std::to_string(index) + " does not exist");
        if (depth > kMaxDepth) fail("node " + std::to_string(index) + ": the node hierarchy is deeper than 256 (a cycle?)");
        if (++visits_ > kMaxVisits) fail("the node hierarchy places more than 2^20 node instances");
        const tinygltf::Node& node = model_.nodes[std::size_t(index)];
        const glm::dmat4 world = parent * gltf_local_transform(node);
        visit_(index, node, world);
        for (int child : node.children) walk(child, world, depth + 1);
    }

private:
    [[noreturn]] void fail(const std::string& what) const { throw MeshFileError(path_ + ": " + what); }

    const std::string& path_;
    const tinygltf::Model& model_;
    const GltfNodeVisit& visit_;
    uint64_t visits_ = 0;
};

}  // namespace

glm::dmat4 gltf_local_transform(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major, as glm
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3)
        m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4)  // glTF stores x, y, z, w
        m *= glm::mat4_cast(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
    if (node.scale.size() == 3) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

std::vector<int> gltf_scene_roots(const std::string& path, const tinygltf::Model& model) {
    if (!model.scenes.empty()) {
        const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
        if (std::size_t(scene) >= model.scenes.size())
            throw MeshFileError(path + ": scene " + std::to_string(scene) + " does not exist");
        return model.scenes[std::size_t(scene)].nodes;
    }
    // No scene: every node that is nobody's child is a root.
    std::vector<bool> is_child(model.nodes.size(), false);
    for (const tinygltf::Node& n : model.nodes)
        for (int c : n.children)
            if (c >= 0 && std::size_t(c) < is_child.size()) is_child[std::size_t(c)] = true;
    std::vector<int> roots;
    for (std::size_t i = 0; i < model.nodes.size(); ++i)
        if (!is_child[i]) roots.push_back(int(i));
    return roots;
}

void walk_gltf_nodes(const std::string& path, const tinygltf::Model& model, const std::vector<int>& roots,
                     const GltfNodeVisit& visit) {
    NodeWalk walk(path, model, visit);
    for (int root : roots) walk.walk(root, glm::dmat4(1.0), 0);
}

}  // namespace wt
