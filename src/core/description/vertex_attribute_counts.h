#pragma once
// A description mesh's per-vertex attributes (normals, both coordinate sets, tangents) are each
// absent or one per vertex: the scene builder indexes them by vertex, so a count that differs is
// refused before any triangle is read.

#include <stdexcept>
#include <string>

#include "core/description/scene_description.h"

namespace wt {

// Throws std::invalid_argument "build_scene: WHAT N normals for V vertices" (and likewise for
// the other attributes), `what` naming the mesh ("mesh 3 has").
inline void check_vertex_attribute_counts(const TriangleMesh& mesh, const std::string& what) {
    const auto check = [&](std::size_t count, const char* attribute) {
        if (count != 0 && count != mesh.vertices.size())
            throw std::invalid_argument("build_scene: " + what + " " + std::to_string(count) + " " + attribute + " for " +
                                        std::to_string(mesh.vertices.size()) + " vertices");
    };
    check(mesh.normals.size(), "normals");
    check(mesh.uvs.size(), "texture coordinates");
    check(mesh.second_uvs.size(), "second texture coordinates");
    check(mesh.tangents.size(), "tangents");
}

}  // namespace wt
