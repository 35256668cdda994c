#pragma once
// A description mesh's triangle pushed onto a texture coordinate table, in the space its vertices
// are in: the scene's for the scene's own triangles, the object space of a mesh that instances
// place (the shade stage takes an instance's density and tangents into world space).

#include <array>
#include <cstdint>

#include <glm/geometric.hpp>

#include "core/description/scene_description.h"
#include "core/textures/texture_coordinates.h"

namespace wt {

// Its vertices' coordinates, or (0, 0) thrice for a mesh without; its second set and vertex
// tangents where it has them (a texture on TEXCOORD_1, normal-mapped meshes).
inline void push_texture_coordinates(TextureCoordinateTable& table, const TriangleMesh& mesh, const std::array<uint32_t, 3>& tri) {
    const glm::vec3 e1 = mesh.vertices[tri[1]] - mesh.vertices[tri[0]], e2 = mesh.vertices[tri[2]] - mesh.vertices[tri[0]];
    const float area = 0.5f * glm::length(glm::cross(e1, e2));
    if (mesh.uvs.empty()) table.push({}, {}, {}, area);
    else table.push(mesh.uvs[tri[0]], mesh.uvs[tri[1]], mesh.uvs[tri[2]], area, e1, e2);
    if (!mesh.second_uvs.empty())
        table.set_second_coordinates(mesh.second_uvs[tri[0]], mesh.second_uvs[tri[1]], mesh.second_uvs[tri[2]], area);
    if (!mesh.uvs.empty() && !mesh.tangents.empty())
        table.set_vertex_tangents(mesh.tangents[tri[0]], mesh.tangents[tri[1]], mesh.tangents[tri[2]]);
}

}  // namespace wt
