#pragma once
// glTF's node hierarchy (glTF 2.0, 3.5): which nodes a file's scene places, and each node's
// world transform, its parents' composed with its own. Meshes, lights and cameras are all
// placed by the nodes that name them; this walk is the one they share.

#include <functional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <tiny_gltf.h>

namespace wt {

// The node's own transform: its `matrix`, or translation * rotation * scale (3.5.2).
glm::dmat4 gltf_local_transform(const tinygltf::Node& node);

// The nodes the file's scene starts from: the default scene's, else scene 0's, else every node
// that is nobody's child. Throws MeshFileError naming `path` for a default scene that does not exist.
std::vector<int> gltf_scene_roots(const std::string& path, const tinygltf::Model& model);

// Calls `visit(index, node, world)` for every node reachable from `roots`, parents before
// children, depth first in the file's order; a node that several parents share is visited once
// per path to it. Throws MeshFileError naming `path` for a node that does not exist, a hierarchy
// deeper than 256 (a cycle) or more than 2^20 node visits (shared children can name
// exponentially many).
using GltfNodeVisit = std::function<void(int index, const tinygltf::Node& node, const glm::dmat4& world)>;
void walk_gltf_nodes(const std::string& path, const tinygltf::Model& model, const std::vector<int>& roots,
                     const GltfNodeVisit& visit);

}  // namespace wt
