#pragma once
// A description mesh's coordinates added to a texture coordinate table, in the space its vertices
// are in: the scene's for the scene's own triangles, the object space of a mesh that instances
// place (the shade stage takes an instance's density and tangents into world space).

#include <array>
#include <cstdint>

#include <glm/geometric.hpp>

#include "core/description/scene_description.h"
#include "core/geometry/texture_coordinates.h"

namespace wt {

// Its vertices' coordinates, or (0, 0) for a mesh without; its second set and vertex tangents
// where it has them (a texture on TEXCOORD_1, normal-mapped meshes). In step with the
// TriangleSoA's add_vertices() for the same mesh.
inline void add_texture_vertices(TextureCoordinateTable& table, const TriangleMesh& mesh) {
    table.add_vertices(mesh.vertices.size(), mesh.uvs, mesh.second_uvs, mesh.uvs.empty() ? std::vector<glm::vec4>() : mesh.tangents);
}

// Triangle `tri` of the mesh, whose first vertex is vertex `first` of the table.
inline void push_texture_triangle(TextureCoordinateTable& table, const TriangleMesh& mesh, uint32_t first,
                                  const std::array<uint32_t, 3>& tri) {
    const glm::vec3 e1 = mesh.vertices[tri[1]] - mesh.vertices[tri[0]], e2 = mesh.vertices[tri[2]] - mesh.vertices[tri[0]];
    table.push_triangle({first + tri[0], first + tri[1], first + tri[2]}, 0.5f * glm::length(glm::cross(e1, e2)));
}

}  // namespace wt
